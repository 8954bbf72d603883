// FreehandTool: see freehandtool.h.
#include "models/trace/freehandtool.h"

#include "geometry/strokefit.h"
#include "io/records.h"
#include "models/controllers/curvecommands.h"
#include "models/controllers/pieceedits.h"
#include "models/text/numbers.h"
#include "models/trace/photoimage.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace kontur {

using namespace tracepoints;

FreehandTool::FreehandTool(TraceContext *context, QObject *parent)
    : QObject(parent)
    , m_context(context)
{
    connect(this, &FreehandTool::toleranceChanged, this, &FreehandTool::effectiveToleranceChanged);
}

void FreehandTool::setTolerance(double tolerance)
{
    if (!(tolerance > 0.0) || !std::isfinite(tolerance) || tolerance == m_tolerance)
        return;
    m_tolerance = tolerance;
    Q_EMIT toleranceChanged();
}

void FreehandTool::setPixelSize(double size)
{
    if (!(size >= 0.0) || !std::isfinite(size) || size == m_pixelSize)
        return;
    m_pixelSize = size;
    Q_EMIT effectiveToleranceChanged();
}

double FreehandTool::effectiveTolerance() const
{
    return std::max(m_tolerance, inputPrecision * m_pixelSize);
}

double FreehandTool::defaultTolerance(const QString &units)
{
    if (units == QLatin1String("mm"))
        return 0.5;
    if (units == QLatin1String("cm"))
        return 0.05;
    if (units == QLatin1String("in"))
        return 0.02;
    if (units == QLatin1String("pt"))
        return 1.5;
    return 1.0;
}

bool FreehandTool::setToleranceText(const QString &text)
{
    double value = 0.0;
    if (parseNumber(text, value) != Parsed::Number || !(value > 0.0)) {
        m_context->say(Message::ToleranceNotPositive);
        return false;
    }
    setTolerance(value);
    m_context->say(Message::None);
    return true;
}

void FreehandTool::beginStroke(QPointF world, double snapRadius)
{
    m_stroke.clear();
    m_stroke.push_back(toPoint(m_context->snap(world, snapRadius)));
    m_strokeTolerance = effectiveTolerance(); // at the zoom the stroke is drawn at
    m_drawing = true;
    m_context->say(Message::None);
    Q_EMIT strokeChanged();
    Q_EMIT overlayChanged();
}

void FreehandTool::extendStroke(QPointF world)
{
    if (!m_drawing)
        return;
    const geo::Point p = toPoint(world);
    if (!p.allFinite() || p == m_stroke.back())
        return;
    m_stroke.push_back(p);
    Q_EMIT overlayChanged();
}

geo::Result<Curve> FreehandTool::curveFromStroke(const std::vector<geo::Point> &stroke, double tolerance)
{
    geo::StrokeFitOptions options;
    options.tolerance = tolerance;
    const auto fit = geo::fitStroke(stroke, options);
    if (!fit)
        return fit.error();
    std::vector<geo::NodeType> types;
    for (bool corner : fit->corner)
        types.push_back(corner ? geo::NodeType::Corner : geo::NodeType::Smooth);
    auto composite = geo::CompositeCurve::fromParts(fit->control, std::move(types), false);
    if (!composite)
        return composite.error();
    composite->finish();
    return Curve::makeComposite(std::move(*composite));
}

void FreehandTool::setSnapToEdges(bool on)
{
    if (m_snapToEdges == on)
        return;
    m_snapToEdges = on;
    Q_EMIT snapToEdgesChanged();
}

std::optional<Curve> FreehandTool::snappedCurve(const std::vector<geo::Point> &stroke)
{
    const cv::Mat *gray = m_context->pictureGray();
    const Document *doc = m_context->document();
    if (!gray || !doc)
        return std::nullopt;
    const Background &bg = doc->background();
    const double mmPerUnit = io::millimetresPerUnit(doc->units());
    const Eigen::Matrix2d j = bg.imageToWorld().jacobian(bg.worldToImage().map(stroke.front()));
    const double unitsPerPhotoPixel = std::sqrt(std::abs(j.determinant()));
    if (!(unitsPerPhotoPixel > 0.0) || !std::isfinite(unitsPerPhotoPixel))
        return std::nullopt;
    // As far as a finger misses at this zoom, and at least a few millimetres.
    const double radius =
        std::max(mmPerUnit > 0.0 ? edgeSearchMm / mmPerUnit : 8.0 * unitsPerPhotoPixel, 12.0 * m_pixelSize);
    geo::Box box;
    for (const geo::Point &p : stroke)
        box.extend(p);
    box.extend(box.min() - 2.0 * geo::Point(radius, radius));
    box.extend(box.max() + 2.0 * geo::Point(radius, radius));
    const double pxPerUnit = mmPerUnit > 0.0 ? 8.0 * mmPerUnit : 2.0 / unitsPerPhotoPixel;
    const auto patch = worldPatch(*gray, bg, box.min(), box.max(), pxPerUnit);
    if (!patch)
        return std::nullopt;
    vision::OutlineOptions options = outlineOptionsIn(mmPerUnit, unitsPerPhotoPixel);
    options.tolerance = std::max(options.tolerance, 0.5 * m_strokeTolerance);
    const auto outline = vision::snapStrokeToEdges(patch->image, patch->mapping, stroke, radius, options);
    if (!outline)
        return std::nullopt;
    auto curve = curveFromOutline(*outline);
    if (!curve)
        return std::nullopt;
    return std::move(*curve);
}

bool FreehandTool::endStroke(double snapRadius)
{
    if (!m_drawing)
        return false;
    m_drawing = false;
    std::vector<geo::Point> stroke = std::move(m_stroke);
    m_stroke.clear();
    Q_EMIT strokeChanged();
    Q_EMIT overlayChanged();
    if (stroke.size() >= 2)
        stroke.back() = toPoint(m_context->snap(toQPoint(stroke.back()), snapRadius));
    // A stroke shorter than the tolerance is a tap, not a curve.
    double length = 0.0;
    for (std::size_t i = 1; i < stroke.size(); ++i)
        length += (stroke[i] - stroke[i - 1]).norm();
    EditController *editor = m_context->editor();
    if (!editor || stroke.size() < 2 || length <= m_strokeTolerance) {
        m_context->say(Message::StrokeTooShort);
        return false;
    }
    std::optional<Curve> snapped;
    if (m_snapToEdges && !editor->document()->background().file.isEmpty()) {
        snapped = snappedCurve(stroke);
        if (!snapped)
            m_context->say(Message::SnapFailed);
    }
    auto curve = snapped ? geo::Result<Curve>(std::move(*snapped)) : curveFromStroke(stroke, m_strokeTolerance);
    if (!curve) {
        m_context->say(Message::StrokeNotFitted);
        return false;
    }
    m_lastSegments = curve->segmentCount();
    // The texts keep TraceController's translation context, where they were translated.
    curve->name =
        //: Automatic name of a curve drawn freehand over the picture: %1 is a running number.
        QCoreApplication::translate("kontur::TraceController", "Traced %1").arg(editor->document()->curveCount() + 1);
    // A stroke from (or to) an open curve's end extends that curve; otherwise it is a new curve,
    // added by appendCurve, not addCurves, which announces a new document (the view would jump to
    // show every curve while the user traces).
    PieceEdits::addOrExtend(editor, std::move(*curve), snapRadius,
                            QCoreApplication::translate("kontur::TraceController", "Freehand curve"));
    Q_EMIT lastSegmentCountChanged();
    return true;
}

void FreehandTool::cancelStroke()
{
    if (!m_drawing && m_stroke.empty())
        return;
    m_drawing = false;
    m_stroke.clear();
    Q_EMIT strokeChanged();
    Q_EMIT overlayChanged();
}

} // namespace kontur
