// PerspectiveTool's marks found and moved by the picture: a dragged corner snapped to where the
// sheet's edges meet, and the calibration's estimated error. The marks' placing and the calibration
// itself are in perspectivetool.cpp.
#include "models/trace/perspectivetool.h"

#include "io/records.h"
#include "models/controllers/backgroundcontroller.h"
#include "models/document/commands.h"
#include "models/text/numbers.h"
#include "models/trace/perspective.h"
#include "vision/sheet.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <limits>

namespace kontur {

using namespace tracepoints;

QPointF PerspectiveTool::snapped(QPointF image)
{
    const cv::Mat *gray = m_context->pictureGray();
    if (!gray)
        return image;
    // As far as the finger's reach in the picture (its touch target), at least 15 photo px.
    const Background &bg = m_context->document()->background();
    const Eigen::Matrix2d j = bg.imageToWorld().jacobian(toPoint(image));
    const double worldPerPixel = std::sqrt(std::abs(j.determinant()));
    const double radius = std::clamp(worldPerPixel > 0.0 ? m_dragRadius / worldPerPixel : 0.0, 15.0, 120.0);
    const auto corner = vision::snapCorner(*gray, toPoint(image), radius);
    if (!corner) {
        m_context->say(Message::CornerNotSnapped);
        return image;
    }
    return toQPoint(*corner);
}

double PerspectiveTool::calibrationError() const
{
    const Document *doc = m_context->document();
    if (!doc || !doc->background().perspective)
        return -1.0;
    const Background &bg = doc->background();
    if (bg == m_errorFor && doc->units() == m_errorUnits)
        return m_error;
    m_errorFor = bg;
    m_errorUnits = doc->units();
    m_error = -1.0;
    const double mmPerUnit = io::millimetresPerUnit(doc->units());
    const cv::Mat *gray = m_context->pictureGray();
    if (!gray || !(mmPerUnit > 0.0))
        return m_error;
    // The sheet's edges measured near the corners in use.
    vision::SheetOptions options;
    options.sizeMm = geo::Point(bg.rectWidth * mmPerUnit, bg.rectHeight * mmPerUnit);
    std::array<geo::Point, 4> hints;
    for (std::size_t i = 0; i < 4; ++i)
        hints[i] = toPoint(bg.corners[i]);
    options.cornerHints = hints;
    options.checkProportions = false; // the user's rectangle, as applied
    const auto sheet = vision::findSheet(*gray, options);
    if (!sheet)
        return m_error;
    // The mapping the edges imply, in the world: each fitted corner goes where its corner in use
    // goes (the nearest one).
    geo::Quad from, to;
    std::array<bool, 4> used{};
    for (std::size_t i = 0; i < 4; ++i) {
        std::size_t nearest = 0;
        for (std::size_t k = 1; k < 4; ++k)
            if ((hints[k] - sheet->corners[i]).norm() < (hints[nearest] - sheet->corners[i]).norm())
                nearest = k;
        if (used[nearest])
            return m_error;
        used[nearest] = true;
        from[i] = sheet->corners[i];
        to[i] = bg.toWorld(bg.corners[nearest]);
    }
    const auto fitted = geo::Projective2D::fromPointPairs(from, to);
    if (!fitted)
        return m_error;
    const geo::Projective2D inUse = bg.imageToWorld();
    const geo::Point centre(0.5 * (gray->cols - 1), 0.5 * (gray->rows - 1));
    const double side = inUse.denominator(centre);
    double worst = 0.0;
    for (const geo::Point &p : {geo::Point(0, 0), geo::Point(gray->cols - 1, 0),
                                geo::Point(gray->cols - 1, gray->rows - 1), geo::Point(0, gray->rows - 1)}) {
        if (!(inUse.denominator(p) * side > 0.0)) { // beyond the horizon: no bound
            worst = std::numeric_limits<double>::infinity();
            break;
        }
        // One sigma of the edge fits, and the distance between the fitted and the used mapping.
        const std::vector<double> sigma =
            vision::calibrationErrorMm(*sheet, std::vector<geo::Point>{vision::apply(sheet->photoToSheet, p)});
        const double d = (inUse.map(p) - fitted->map(p)).norm() * mmPerUnit;
        worst = std::max(worst, std::hypot(sigma.at(0), d));
    }
    m_error = std::isfinite(worst) ? worst : 1e6;
    return m_error;
}

void PerspectiveTool::warnIfImprecise()
{
    const double error = calibrationError();
    if (error > errorWarningMm)
        m_context->say({Message::CalibrationImprecise, {error}});
}

bool PerspectiveTool::beginCornerDrag(QPointF world, double radius)
{
    m_drag = -1;
    if (!m_context->editor())
        return false;
    const std::vector<geo::Point> corners = handles();
    const geo::Point w = toPoint(world);
    double best = radius;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const double d = (corners[i] - w).norm();
        if (d <= best) {
            best = d;
            m_drag = static_cast<int>(i);
        }
    }
    if (m_drag < 0)
        return false;
    if (m_marks.empty() && m_context->backgroundLocked()) {
        m_drag = -1;
        m_context->say(Message::LockedCalibrate);
        return false;
    }
    m_context->say(Message::None);
    m_dragPoint = world;
    m_dragRadius = radius;
    Q_EMIT marksChanged();
    return true;
}

void PerspectiveTool::dragCornerTo(QPointF world)
{
    if (m_drag < 0)
        return;
    m_dragPoint = world;
    // A mark being placed follows the finger; a calibration's corner is shown there and moved when
    // the finger lifts (moving it now would warp the picture under the finger and the magnifier).
    if (!m_marks.empty() && m_drag < static_cast<int>(m_marks.size()))
        m_marks[static_cast<std::size_t>(m_drag)] = toPoint(world);
    Q_EMIT marksChanged();
}

void PerspectiveTool::endCornerDrag()
{
    if (m_drag < 0)
        return;
    const int index = m_drag;
    m_drag = -1;
    EditController *editor = m_context->editor();
    if (!m_marks.empty() && index < static_cast<int>(m_marks.size()) && m_context->document()) {
        // The mark goes to the corner of the picture's edges near where it was dropped.
        const Background &bg = m_context->document()->background();
        m_marks[static_cast<std::size_t>(index)] = bg.toWorld(snapped(bg.toImage(toPoint(m_dragPoint))));
    } else if (m_marks.empty() && calibrated() && editor) {
        // The picture point now under the finger becomes that corner of the rectangle: one undo step.
        Document *doc = editor->document();
        const Background bg = doc->background();
        perspective::Quad image = bg.corners;
        image[static_cast<std::size_t>(index)] = snapped(bg.toImage(toPoint(m_dragPoint)));
        const auto ordered = perspective::orderCorners(image);
        Background after = bg;
        if (ordered)
            after.corners = *ordered;
        if (!ordered || !after.placedInPerspective()) {
            m_context->say(Message::CornerNotConvex);
        } else if (after != bg) {
            auto *command = new BackgroundCommand(doc, bg, after);
            // The undo texts keep TraceController's translation context, where they were translated.
            command->setText(QCoreApplication::translate("kontur::TraceController", "Refine perspective corner"));
            editor->push(command);
            if (m_context->message().isEmpty())
                warnIfImprecise();
        }
    }
    Q_EMIT marksChanged();
}

void PerspectiveTool::cancelCornerDrag()
{
    if (m_drag < 0)
        return;
    m_drag = -1;
    Q_EMIT marksChanged();
}

} // namespace kontur
