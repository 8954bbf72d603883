// TraceContext: see tracecontext.h.
#include "models/trace/tracecontext.h"

#include "models/controllers/backgroundcontroller.h"
#include "models/document/commands.h"
#include "models/trace/photoimage.h"
#include "models/trace/tracecommands.h"

#include <Eigen/Geometry>

#include <cmath>

namespace kontur {

using namespace tracepoints;

namespace {

// The curve mapped by p ↦ k R p (a similarity about the world origin): its defining points are
// mapped, and every kind's construction commutes with similarities, so the shape maps exactly.
geo::Result<Curve> mapCurve(const Curve &curve, const Eigen::Matrix2d &linear)
{
    auto map = [&](std::vector<geo::Point> pts) {
        for (geo::Point &p : pts)
            p = linear * p;
        return pts;
    };
    geo::Result<Curve> mapped = [&]() -> geo::Result<Curve> {
        if (curve.kind() == CurveKind::Composite) {
            const geo::CompositeCurve &c = curve.composite();
            std::vector<geo::NodeType> types;
            for (int k = 0; k < c.knotCount(); ++k)
                types.push_back(c.nodeType(k));
            auto composite = geo::CompositeCurve::fromParts(map(c.controlPoints()), types, c.isClosed());
            if (!composite)
                return composite.error();
            if (c.isFinished())
                composite->finish();
            return Curve::makeComposite(std::move(*composite));
        }
        return Curve::restore(curve.kind(), map(curve.placedPoints()), map(curve.tangentEnds()),
                              curve.order() > 0 ? curve.order() : 4, curve.parameterization());
    }();
    if (!mapped)
        return mapped;
    mapped->name = curve.name;
    mapped->color = curve.color;
    mapped->visible = curve.visible;
    mapped->locked = curve.locked;
    return mapped;
}

} // namespace

TraceContext::TraceContext(QObject *parent)
    : QObject(parent)
    , m_photos(std::make_unique<PhotoCache>())
{
}

TraceContext::~TraceContext() = default;

const cv::Mat *TraceContext::pictureGray()
{
    const Document *doc = document();
    if (!doc || doc->background().file.isEmpty())
        return nullptr;
    const cv::Mat &gray = m_photos->gray(doc->background().file);
    return gray.empty() ? nullptr : &gray;
}

double TraceContext::pictureFocalPx()
{
    const Document *doc = document();
    if (!doc || doc->background().file.isEmpty())
        return 0.0;
    return m_photos->focalPx(doc->background().file);
}

const cv::Mat *TraceContext::pictureGrayOrSay()
{
    return pictureMatOrSay(false);
}

const cv::Mat *TraceContext::pictureColourOrSay()
{
    return pictureMatOrSay(true);
}

const cv::Mat *TraceContext::pictureMatOrSay(bool colour)
{
    const Background *picture = pictureOrSay();
    if (!picture)
        return nullptr;
    const cv::Mat &mat = colour ? m_photos->colour(picture->file) : m_photos->gray(picture->file);
    if (mat.empty()) {
        say(Message::PictureUnreadable);
        return nullptr;
    }
    return &mat;
}

const Background *TraceContext::pictureOrSay()
{
    const Document *doc = document();
    if (!doc)
        return nullptr;
    if (doc->background().file.isEmpty()) {
        say(Message::NoPicture);
        return nullptr;
    }
    return &doc->background();
}

QString TraceContext::units() const
{
    return document() ? document()->units() : QStringLiteral("px");
}

void TraceContext::setSnapping(bool on)
{
    if (m_snapping == on)
        return;
    m_snapping = on;
    Q_EMIT snappingChanged();
}

void TraceContext::setGridStep(double step)
{
    if (m_gridStep == step)
        return;
    m_gridStep = step;
    Q_EMIT gridStepChanged();
}

QPointF TraceContext::snap(QPointF world, double radius) const
{
    if (!m_snapping || !m_editor || !(radius > 0.0))
        return world;
    const geo::Point w = toPoint(world);
    // Knots and control points first: joining a new curve to an existing one matters most.
    const PointRef hit = m_editor->hitTest(w, radius);
    if (hit.isValid())
        return toQPoint(document()->find(hit.curve)->row(hit.point).position);
    // Then the calibration marks.
    const Background &bg = document()->background();
    if (bg.calibrated && !bg.file.isEmpty()) {
        for (const QPointF &mark : {bg.calibrationA, bg.calibrationB}) {
            const geo::Point m = bg.toWorld(mark);
            if ((m - w).norm() <= radius)
                return toQPoint(m);
        }
    }
    // Then the grid's crossings.
    if (m_gridStep > 0.0 && std::isfinite(m_gridStep)) {
        const geo::Point g(std::round(w.x() / m_gridStep) * m_gridStep, std::round(w.y() / m_gridStep) * m_gridStep);
        if ((g - w).norm() <= radius)
            return toQPoint(g);
    }
    return world;
}

bool TraceContext::backgroundLocked() const
{
    return document() && document()->background().locked;
}

void TraceContext::setBackgroundLocked(bool locked)
{
    if (!m_editor || backgroundLocked() == locked || document()->background().file.isEmpty())
        return;
    Background bg = document()->background();
    bg.locked = locked;
    m_editor->background()->setBackground(bg);
}

bool TraceContext::pushCalibration(const QString &text, const Background &before, const Background &after,
                                   const QString &unit, double scale, double radians)
{
    Document *doc = document();
    const Eigen::Matrix2d linear = scale * Eigen::Rotation2Dd(radians).toRotationMatrix();
    // The curves follow the picture, so that what was traced stays on it.
    std::vector<std::pair<int, Curve>> mapped;
    for (int c = 0; c < doc->curveCount(); ++c) {
        auto m = mapCurve(doc->curve(c), linear);
        if (!m) {
            say({Message::CurveNotTurnable, {doc->curve(c).name}});
            return false;
        }
        mapped.emplace_back(c, std::move(*m));
    }
    auto *calibration = new QUndoCommand(text);
    for (auto &[index, curve] : mapped)
        new ReplaceCurveCommand(doc, doc->idAt(index), doc->curve(index), std::move(curve), QString(), calibration);
    // The view follows the mapping on the first redo, on undo and on redo.
    new CalibrationCommand(
        doc, before, after, doc->units(), unit, scale, radians,
        [self = QPointer<TraceContext>(this)](double s, double r) {
            if (self)
                Q_EMIT self->worldMapped(s, r);
        },
        calibration);
    m_editor->push(calibration);
    return true;
}

} // namespace kontur
