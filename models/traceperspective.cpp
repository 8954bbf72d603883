// TraceController's perspective calibration (issue #22), kept apart from tracecontroller.cpp, which
// holds the other tools: four marks on the corners of a known rectangle become a homography that
// places the picture rectified and in real units (models/perspective.h); a corner of the calibration
// can be dragged to refine it.
#include "io/records.h"
#include "models/backgroundcontroller.h"
#include "models/commands.h"
#include "models/perspective.h"
#include "models/tracecontroller.h"

#include <QLocale>

#include <algorithm>
#include <cmath>

namespace kontur {

namespace {

// Millimetres per unit of the units a rectangle can be given in (mm, cm, in; pt too).
double millimetres(const QString &unit)
{
    return io::millimetresPerUnit(unit);
}

bool parseNumber(const QString &text, double &out)
{
    bool ok = false;
    const QString t = text.trimmed();
    out = QLocale().toDouble(t, &ok);
    if (!ok)
        out = QLocale::c().toDouble(t, &ok);
    return ok && std::isfinite(out);
}

// The area of a polygon (shoelace formula), unsigned.
double area(const std::vector<geo::Point> &p)
{
    double twice = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const geo::Point &a = p[i], &b = p[(i + 1) % p.size()];
        twice += a.x() * b.y() - a.y() * b.x();
    }
    return std::abs(twice) / 2.0;
}

} // namespace

bool TraceController::backgroundPerspective() const
{
    return document() && document()->background().perspective;
}

std::vector<geo::Point> TraceController::perspectiveHandles() const
{
    if (!m_perspective.empty() || !backgroundPerspective())
        return m_perspective;
    const Background &bg = document()->background();
    std::vector<geo::Point> corners;
    for (const QPointF &c : bg.corners)
        corners.push_back(bg.toWorld(c));
    return corners;
}

bool TraceController::perspectiveLandscape() const
{
    if (m_perspective.size() != 4 || !document())
        return false;
    const Background &bg = document()->background();
    perspective::Quad image;
    for (int i = 0; i < 4; ++i)
        image[i] = bg.toImage(m_perspective[i]);
    const auto ordered = perspective::orderCorners(image);
    return ordered && perspective::looksLandscape(*ordered);
}

QString TraceController::rectangleUnit(Rectangle rectangle)
{
    switch (rectangle) {
    case Letter:
    case Mat1in:
    case Mat6in:
        return QStringLiteral("in");
    default:
        return QStringLiteral("mm");
    }
}

bool TraceController::rectangleSize(Rectangle rectangle, const QString &unit, double &shortSide, double &longSide)
{
    double a = 0.0, b = 0.0; // in millimetres
    switch (rectangle) {
    case A4: // ISO 216
        a = 210.0, b = 297.0;
        break;
    case A3:
        a = 297.0, b = 420.0;
        break;
    case Letter: // ANSI/ASME Y14.1
        a = 8.5 * 25.4, b = 11.0 * 25.4;
        break;
    case Mat1cm:
        a = b = 10.0;
        break;
    case Mat10cm:
        a = b = 100.0;
        break;
    case Mat1in:
        a = b = 25.4;
        break;
    case Mat6in:
        a = b = 6 * 25.4;
        break;
    case CustomRectangle:
        return false;
    }
    const double per = millimetres(unit);
    if (per <= 0.0)
        return false;
    shortSide = a / per;
    longSide = b / per;
    return true;
}

bool TraceController::calibratePerspective(int rectangle, int orientation, const QString &widthText,
                                           const QString &heightText, const QString &unit)
{
    if (!document())
        return false;
    if (m_perspective.size() != 4) {
        setMessage(Note::NoCorners);
        return false;
    }
    const auto r = static_cast<Rectangle>(std::clamp(rectangle, 0, int(CustomRectangle)));
    double width = 0.0, height = 0.0;
    QString u = unit;
    if (r == CustomRectangle) {
        if (!parseNumber(widthText, width) || !parseNumber(heightText, height) || !(width > 0.0) || !(height > 0.0)) {
            setMessage(Note::SidesNotPositive);
            return false;
        }
    } else {
        // A preset keeps the document's real unit, or brings its own.
        u = millimetres(units()) > 0.0 ? units() : rectangleUnit(r);
        if (!rectangleSize(r, u, width, height)) {
            setMessage(Note::UnknownUnit);
            return false;
        }
    }
    const Background &bg = document()->background();
    std::array<QPointF, 4> image;
    for (int i = 0; i < 4; ++i)
        image[i] = bg.toImage(m_perspective[i]);
    if (!calibratePerspectiveImage(image, width, height, u,
                                   static_cast<Orientation>(std::clamp(orientation, 0, int(Landscape)))))
        return false;
    m_perspective.clear();
    Q_EMIT perspectiveChanged();
    Q_EMIT overlayChanged();
    return true;
}

bool TraceController::calibratePerspectiveImage(const std::array<QPointF, 4> &image, double width, double height,
                                                const QString &unit, Orientation orientation)
{
    Document *doc = document();
    if (!doc)
        return false;
    const Background before = doc->background();
    if (before.file.isEmpty()) {
        setMessage(Note::NoPicture);
        return false;
    }
    if (before.locked) {
        setMessage(Note::LockedCalibrate);
        return false;
    }
    if (millimetres(unit) <= 0.0) {
        setMessage(Note::UnknownUnit);
        return false;
    }
    if (!(width > 0.0) || !(height > 0.0) || !std::isfinite(width) || !std::isfinite(height)) {
        setMessage(Note::SidesNotPositive);
        return false;
    }
    const auto ordered = perspective::orderCorners(image);
    if (!ordered) {
        setMessage(Note::NotConvex);
        return false;
    }
    const bool landscape =
        orientation == Landscape || (orientation == AutoOrientation && perspective::looksLandscape(*ordered));
    // The sides as given say the rectangle's size; its orientation comes from the marks (or the choice).
    const double shortSide = std::min(width, height), longSide = std::max(width, height);
    width = landscape ? longSide : shortSide;
    height = landscape ? shortSide : longSide;
    // Where the marks lay in the world before, to keep the picture about where it was on the screen:
    // the world is scaled by k (as the two-point calibration does, p ↦ k p) so that the quadrilateral's
    // area becomes the rectangle's, and the rectangle is centred where the quadrilateral's centre goes.
    std::vector<geo::Point> world;
    geo::Point centre(0.0, 0.0);
    for (const QPointF &c : *ordered) {
        world.push_back(before.toWorld(c));
        centre += world.back() / 4.0;
    }
    const double worldArea = area(world);
    if (!(worldArea > 0.0)) {
        setMessage(Note::NotConvex);
        return false;
    }
    const double k = std::sqrt(width * height / worldArea);
    Background after = before;
    after.origin = before.origin * k;
    after.scale = before.scale * k;
    after.perspective = true;
    after.corners = *ordered;
    after.rectWidth = width;
    after.rectHeight = height;
    after.rectOrigin = QPointF(k * centre.x() - width / 2, k * centre.y() + height / 2);
    if (!after.placedInPerspective()) {
        setMessage(Note::NotConvex);
        return false;
    }
    if (!pushCalibration(tr("Calibrate perspective"), before, after, unit, k, 0.0))
        return false;
    setMessage(Note::None);
    return true;
}

void TraceController::clearPerspective()
{
    if (!m_editor || !backgroundPerspective())
        return;
    if (backgroundLocked()) {
        setMessage(Note::LockedCalibrate);
        return;
    }
    Background bg = document()->background();
    bg.perspective = false;
    bg.corners = {};
    bg.rectWidth = bg.rectHeight = 0.0;
    bg.rectOrigin = {};
    m_editor->background()->setBackground(bg);
    setMessage(Note::None);
}

bool TraceController::beginCornerDrag(QPointF world, double radius)
{
    m_cornerDrag = -1;
    if (!m_editor || m_tool != Tool::Perspective)
        return false;
    const std::vector<geo::Point> handles = perspectiveHandles();
    const geo::Point w(world.x(), world.y());
    double best = radius;
    for (std::size_t i = 0; i < handles.size(); ++i) {
        const double d = (handles[i] - w).norm();
        if (d <= best) {
            best = d;
            m_cornerDrag = static_cast<int>(i);
        }
    }
    if (m_cornerDrag < 0)
        return false;
    if (m_perspective.empty() && backgroundLocked()) {
        m_cornerDrag = -1;
        setMessage(Note::LockedCalibrate);
        return false;
    }
    setMessage(Note::None);
    m_cornerDragPoint = world;
    Q_EMIT perspectiveChanged();
    Q_EMIT overlayChanged();
    return true;
}

void TraceController::dragCornerTo(QPointF world)
{
    if (m_cornerDrag < 0)
        return;
    m_cornerDragPoint = world;
    // A mark being placed follows the finger; a calibration's corner is shown there and moved when
    // the finger lifts (moving it now would warp the picture under the finger and the magnifier).
    if (!m_perspective.empty() && m_cornerDrag < static_cast<int>(m_perspective.size()))
        m_perspective[static_cast<std::size_t>(m_cornerDrag)] = geo::Point(world.x(), world.y());
    Q_EMIT perspectiveChanged();
    Q_EMIT overlayChanged();
}

void TraceController::endCornerDrag()
{
    if (m_cornerDrag < 0)
        return;
    const int index = m_cornerDrag;
    m_cornerDrag = -1;
    if (m_perspective.empty() && backgroundPerspective()) {
        // The picture point now under the finger becomes that corner of the rectangle: one undo step.
        Background bg = document()->background();
        perspective::Quad image = bg.corners;
        image[static_cast<std::size_t>(index)] = bg.toImage(geo::Point(m_cornerDragPoint.x(), m_cornerDragPoint.y()));
        const auto ordered = perspective::orderCorners(image);
        Background after = bg;
        if (ordered)
            after.corners = *ordered;
        if (!ordered || !after.placedInPerspective()) {
            setMessage(Note::CornerNotConvex);
        } else if (after != bg) {
            auto *command = new BackgroundCommand(document(), bg, after);
            command->setText(tr("Refine perspective corner"));
            m_editor->push(command);
        }
    }
    Q_EMIT perspectiveChanged();
    Q_EMIT overlayChanged();
}

void TraceController::cancelCornerDrag()
{
    if (m_cornerDrag < 0)
        return;
    m_cornerDrag = -1;
    Q_EMIT perspectiveChanged();
    Q_EMIT overlayChanged();
}

} // namespace kontur
