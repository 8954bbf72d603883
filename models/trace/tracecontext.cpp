// TraceContext: see tracecontext.h.
#include "models/trace/tracecontext.h"

#include "models/controllers/backgroundcontroller.h"
#include "models/document/commands.h"
#include "models/trace/photoimage.h"
#include "models/trace/tracecommands.h"

#include <QCoreApplication>

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
        say(Note::PictureUnreadable);
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
        say(Note::NoPicture);
        return nullptr;
    }
    return &doc->background();
}

QString TraceContext::units() const
{
    return document() ? document()->units() : QStringLiteral("px");
}

void TraceContext::say(Note note, const QString &arg, const QString &arg2)
{
    if (m_note == note && m_noteArg == arg && m_noteArg2 == arg2)
        return;
    m_note = note;
    m_noteArg = arg;
    m_noteArg2 = arg2;
    Q_EMIT messageChanged();
}

QString TraceContext::message() const
{
    // The texts keep the translation context they were written in (TraceController's), so that the
    // translations stay as they are.
    // Translated here, when shown, so that a message follows a language switch.
    switch (m_note) {
    case Note::None:
        return {};
    case Note::ToleranceNotPositive:
        return QCoreApplication::translate("kontur::TraceController", "The tolerance must be a positive number.");
    case Note::StrokeTooShort:
        return QCoreApplication::translate("kontur::TraceController",
                                           "Draw along the contour with one finger, a stylus or the mouse.");
    case Note::StrokeNotFitted:
        return QCoreApplication::translate("kontur::TraceController", "The stroke could not be fitted.");
    case Note::NoPicture:
        return QCoreApplication::translate("kontur::TraceController", "Load a background picture first.");
    case Note::TapKnot:
        return QCoreApplication::translate("kontur::TraceController", "Tap a knot of the curve.");
    case Note::TapCurve:
        return QCoreApplication::translate("kontur::TraceController", "Tap a curve.");
    case Note::TapOtherCurve:
        return QCoreApplication::translate("kontur::TraceController", "Tap a second, different curve.");
    case Note::NoKnots:
        return QCoreApplication::translate("kontur::TraceController",
                                           "This kind of curve has no knots to measure between.");
    case Note::NotComparable:
        return QCoreApplication::translate("kontur::TraceController", "These curves cannot be compared.");
    case Note::NoMarks:
        return QCoreApplication::translate("kontur::TraceController", "Tap two points on the picture first.");
    case Note::DistanceNotPositive:
        return QCoreApplication::translate("kontur::TraceController",
                                           "Type the real distance between the two points as a positive number.");
    case Note::LockedCalibrate:
        return QCoreApplication::translate("kontur::TraceController",
                                           "The background is locked. Unlock it to calibrate again.");
    case Note::UnknownUnit:
        return QCoreApplication::translate("kontur::TraceController", "Choose mm, cm or in.");
    case Note::SamePoints:
        return QCoreApplication::translate("kontur::TraceController", "The two points must be different.");
    case Note::LockedMove:
        return QCoreApplication::translate("kontur::TraceController",
                                           "The background is locked. Unlock it to move it.");
    case Note::CurveNotTurnable:
        return QCoreApplication::translate("kontur::TraceController",
                                           "Curve \"%1\" cannot be turned; calibrate without aligning.")
            .arg(m_noteArg);
    case Note::NotConvex:
        return QCoreApplication::translate(
            "kontur::TraceController",
            "The four points are not the corners of a rectangle seen in the picture. Tap them again.");
    case Note::NoCorners:
        return QCoreApplication::translate("kontur::TraceController", "Tap the four corners of the rectangle first.");
    case Note::SidesNotPositive:
        return QCoreApplication::translate("kontur::TraceController",
                                           "Type the rectangle's width and height as positive numbers.");
    case Note::PerspectiveSet:
        return QCoreApplication::translate(
            "kontur::TraceController",
            "The picture has a perspective calibration. Clear it to calibrate by two points.");
    case Note::CornerNotConvex:
        return QCoreApplication::translate(
            "kontur::TraceController", "There the corners would not make a rectangle; the corner stays where it was.");
    case Note::PictureUnreadable:
        return QCoreApplication::translate("kontur::TraceController", "The background picture cannot be read.");
    case Note::NoSheetFound:
        return QCoreApplication::translate("kontur::TraceController",
                                           "No sheet found in the picture (a white rectangle with four straight, "
                                           "clear edges). Tap its four corners instead.");
    case Note::SheetNotFlat:
        return QCoreApplication::translate("kontur::TraceController",
                                           "The sheet in the picture is not flat: its edges bend. Lay it flat and "
                                           "take the photo again, or tap its four corners.");
    case Note::SheetProportions:
        //: %1 and %2 are proportions, long side to short side, such as 2.35 and 1.41.
        return QCoreApplication::translate("kontur::TraceController",
                                           "The rectangle found is about %1 : 1, the chosen one %2 : 1. Choose the "
                                           "sheet's size, or tap its four corners.")
            .arg(m_noteArg, m_noteArg2);
    case Note::CornerNotSnapped:
        return QCoreApplication::translate("kontur::TraceController",
                                           "No corner found near the mark; it stays where you dropped it.");
    case Note::CalibrationImprecise:
        return QCoreApplication::translate("kontur::TraceController",
                                           "The calibration may be off by %1 mm at the far side of the picture. "
                                           "Find the sheet again or refine its corners.")
            .arg(m_noteArg);
    case Note::NoPieceFound:
        return QCoreApplication::translate("kontur::TraceController",
                                           "No pattern piece found there. Tap inside a piece that stands out "
                                           "from the table.");
    case Note::OutlineNotFitted:
        return QCoreApplication::translate("kontur::TraceController", "The outline could not be made into a curve.");
    case Note::SnapFailed:
        return QCoreApplication::translate("kontur::TraceController",
                                           "No edge found along the stroke; it was fitted as drawn.");
    }
    return {};
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
            say(Note::CurveNotTurnable, doc->curve(c).name);
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
