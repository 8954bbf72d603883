// CalibrationTool: see calibrationtool.h.
#include "models/trace/calibrationtool.h"

#include "models/text/numbers.h"
#include "models/text/units.h"

#include <QCoreApplication>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kontur {

using namespace tracepoints;

CalibrationTool::CalibrationTool(TraceContext *context, QObject *parent)
    : QObject(parent)
    , m_context(context)
{
    connect(this, &CalibrationTool::marksChanged, this, &CalibrationTool::textsChanged);
    connect(this, &CalibrationTool::marksChanged, this, &CalibrationTool::overlayChanged);
}

double CalibrationTool::imageDistance() const
{
    const Document *doc = m_context->document();
    if (m_marks.size() != 2 || !doc)
        return 0.0;
    const Background &bg = doc->background();
    const QPointF d = bg.toImage(m_marks[1]) - bg.toImage(m_marks[0]);
    return std::hypot(d.x(), d.y());
}

QString CalibrationTool::imageDistanceText() const
{
    return fixedNumber(imageDistance(), 1);
}

void CalibrationTool::tap(QPointF world, double hitRadius)
{
    if (!m_context->pictureOrSay())
        return;
    if (m_marks.size() >= 2)
        m_marks.clear();
    m_marks.push_back(toPoint(m_context->snap(world, hitRadius)));
    Q_EMIT marksChanged();
}

void CalibrationTool::clear()
{
    m_marks.clear();
    Q_EMIT marksChanged();
}

QPointF CalibrationTool::labelAnchor() const
{
    return m_marks.size() == 2 ? toQPoint((m_marks[0] + m_marks[1]) / 2) : QPointF();
}

bool CalibrationTool::calibrate(const QString &distanceText, const QString &unit, int align)
{
    const Document *doc = m_context->document();
    if (!doc)
        return false;
    if (m_marks.size() != 2) {
        m_context->say(Message::NoMarks);
        return false;
    }
    double distance = 0.0;
    if (parseNumber(distanceText, distance) != Parsed::Number || !(distance > 0.0)) {
        m_context->say(Message::DistanceNotPositive);
        return false;
    }
    const Background &bg = doc->background();
    const bool ok = calibrateImagePoints(bg.toImage(m_marks[0]), bg.toImage(m_marks[1]), distance, unit,
                                         static_cast<Align>(std::clamp(align, 0, 2)));
    if (ok)
        clear();
    return ok;
}

bool CalibrationTool::calibrateImagePoints(QPointF imageA, QPointF imageB, double distance, const QString &unit,
                                           Align align)
{
    const Background *picture = m_context->pictureOrSay();
    if (!picture)
        return false;
    const Background before = *picture;
    if (before.locked) {
        m_context->say(Message::LockedCalibrate);
        return false;
    }
    if (before.perspective) {
        m_context->say(Message::PerspectiveSet);
        return false;
    }
    if (unit != QLatin1String("mm") && unit != QLatin1String("cm") && unit != QLatin1String("in")) {
        m_context->say(Message::UnknownUnit);
        return false;
    }
    const geo::Point wa = before.toWorld(imageA), wb = before.toWorld(imageB);
    const double worldDistance = (wb - wa).norm();
    if (!(worldDistance > 0.0) || !(distance > 0.0) || !std::isfinite(distance)) {
        m_context->say(Message::SamePoints);
        return false;
    }
    // The world is scaled by k and turned by θ about its origin: p ↦ k R(θ) p.
    const double k = distance / worldDistance;
    const double phi = std::atan2(wb.y() - wa.y(), wb.x() - wa.x());
    double theta = 0.0;
    if (align == Horizontal)
        theta = std::round(phi / std::numbers::pi) * std::numbers::pi - phi;
    else if (align == Vertical)
        theta =
            std::round((phi - std::numbers::pi / 2) / std::numbers::pi) * std::numbers::pi + std::numbers::pi / 2 - phi;
    const Eigen::Matrix2d linear = k * Eigen::Rotation2Dd(theta).toRotationMatrix();

    Background after = before;
    after.origin = toQPoint(linear * toPoint(before.origin));
    after.scale = before.scale * k;
    after.rotation = std::remainder(before.rotation + theta * 180.0 / std::numbers::pi, 360.0);
    after.calibrated = true;
    after.calibrationA = imageA;
    after.calibrationB = imageB;
    after.calibrationDistance = distance;

    // The undo text keeps TraceController's translation context, where it was translated.
    if (!m_context->pushCalibration(QCoreApplication::translate("kontur::TraceController", "Calibrate background"),
                                    before, after, unit, k, theta))
        return false;
    m_context->say(Message::None);
    return true;
}

} // namespace kontur
