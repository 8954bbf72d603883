// PerspectiveTool: see perspectivetool.h.
#include "models/trace/perspectivetool.h"

#include "io/records.h"
#include "models/controllers/backgroundcontroller.h"
#include "models/document/commands.h"
#include "models/text/numbers.h"
#include "models/trace/perspective.h"
#include "models/trace/photoimage.h"
#include "vision/sheet.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <limits>

namespace kontur {

using namespace tracepoints;

namespace {

// Millimetres per unit of the units a rectangle can be given in (mm, cm, in; pt too).
double millimetres(const QString &unit)
{
    return io::millimetresPerUnit(unit);
}

// A custom rectangle's sides as typed (the UI language's format): false unless both are positive numbers.
bool typedSides(const QString &widthText, const QString &heightText, double &width, double &height)
{
    return parseNumber(widthText, width) == Parsed::Number && parseNumber(heightText, height) == Parsed::Number &&
           width > 0.0 && height > 0.0;
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

PerspectiveTool::PerspectiveTool(TraceContext *context, QObject *parent)
    : QObject(parent)
    , m_context(context)
{
    connect(this, &PerspectiveTool::marksChanged, this, &PerspectiveTool::overlayChanged);
}

bool PerspectiveTool::calibrated() const
{
    return m_context->document() && m_context->document()->background().perspective;
}

std::vector<geo::Point> PerspectiveTool::handles() const
{
    if (!m_marks.empty() || !calibrated())
        return m_marks;
    const Background &bg = m_context->document()->background();
    std::vector<geo::Point> corners;
    for (const QPointF &c : bg.corners)
        corners.push_back(bg.toWorld(c));
    return corners;
}

bool PerspectiveTool::landscape() const
{
    if (m_marks.size() != 4 || !m_context->document())
        return false;
    const Background &bg = m_context->document()->background();
    perspective::Quad image;
    for (std::size_t i = 0; i < 4; ++i)
        image[i] = bg.toImage(m_marks[i]);
    const auto ordered = perspective::orderCorners(image);
    return ordered && perspective::looksLandscape(*ordered);
}

QString PerspectiveTool::rectangleUnit(Rectangle rectangle)
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

bool PerspectiveTool::rectangleSize(Rectangle rectangle, const QString &unit, double &shortSide, double &longSide)
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

void PerspectiveTool::tap(QPointF world)
{
    if (!m_context->pictureOrSay())
        return;
    if (m_marks.size() >= 4)
        m_marks.clear();
    m_marks.push_back(toPoint(world));
    Q_EMIT marksChanged();
}

bool PerspectiveTool::findSheet(int rectangle, const QString &widthText, const QString &heightText)
{
    const cv::Mat *photo = m_context->pictureColourOrSay();
    if (!photo)
        return false;
    // The chosen rectangle's proportions tell the sheet from other rectangles in the picture.
    const auto r = static_cast<Rectangle>(std::clamp(rectangle, 0, int(CustomRectangle)));
    double shortSide = 0.0, longSide = 0.0;
    if (r == CustomRectangle) {
        if (!typedSides(widthText, heightText, shortSide, longSide)) {
            m_context->say(Message::SidesNotPositive);
            return false;
        }
    } else if (!rectangleSize(r, QStringLiteral("mm"), shortSide, longSide)) {
        return false;
    }
    vision::SheetOptions options;
    options.sizeMm = geo::Point(std::min(shortSide, longSide), std::max(shortSide, longSide));
    options.focalPx = m_context->pictureFocalPx();
    const auto sheet = vision::findSheet(*photo, options);
    if (!sheet) {
        switch (sheet.error().code) {
        case vision::ErrorCode::SheetNotFlat:
            m_context->say(Message::SheetNotFlat);
            break;
        case vision::ErrorCode::WrongProportions:
            m_context->say(
                {Message::SheetProportions, {sheet.error().seenAspect, options.sizeMm.y() / options.sizeMm.x()}});
            break;
        default:
            m_context->say(Message::NoSheetFound);
            break;
        }
        return false;
    }
    const Background &bg = m_context->document()->background();
    m_marks.clear();
    for (const geo::Point &c : sheet->corners)
        m_marks.push_back(bg.toWorld(toQPoint(c)));
    m_drag = -1;
    m_context->say(Message::None);
    Q_EMIT marksChanged();
    return true;
}

void PerspectiveTool::clear()
{
    m_marks.clear();
    m_drag = -1;
    Q_EMIT marksChanged();
}

bool PerspectiveTool::calibratePerspective(int rectangle, int orientation, const QString &widthText,
                                           const QString &heightText, const QString &unit)
{
    const Document *doc = m_context->document();
    if (!doc)
        return false;
    if (m_marks.size() != 4) {
        m_context->say(Message::NoCorners);
        return false;
    }
    const auto r = static_cast<Rectangle>(std::clamp(rectangle, 0, int(CustomRectangle)));
    double width = 0.0, height = 0.0;
    QString u = unit;
    if (r == CustomRectangle) {
        if (!typedSides(widthText, heightText, width, height)) {
            m_context->say(Message::SidesNotPositive);
            return false;
        }
    } else {
        // A preset keeps the document's real unit, or brings its own.
        const QString units = m_context->units();
        u = millimetres(units) > 0.0 ? units : rectangleUnit(r);
        if (!rectangleSize(r, u, width, height)) {
            m_context->say(Message::UnknownUnit);
            return false;
        }
    }
    const Background &bg = doc->background();
    std::array<QPointF, 4> image;
    for (std::size_t i = 0; i < 4; ++i)
        image[i] = bg.toImage(m_marks[i]);
    if (!calibratePerspectiveImage(image, width, height, u,
                                   static_cast<Orientation>(std::clamp(orientation, 0, int(Landscape)))))
        return false;
    clear();
    return true;
}

bool PerspectiveTool::calibratePerspectiveImage(const std::array<QPointF, 4> &image, double width, double height,
                                                const QString &unit, Orientation orientation)
{
    const Background *picture = m_context->pictureOrSay();
    if (!picture)
        return false;
    const Background before = *picture;
    if (before.locked) {
        m_context->say(Message::LockedCalibrate);
        return false;
    }
    if (millimetres(unit) <= 0.0) {
        m_context->say(Message::UnknownUnit);
        return false;
    }
    if (!(width > 0.0) || !(height > 0.0) || !std::isfinite(width) || !std::isfinite(height)) {
        m_context->say(Message::SidesNotPositive);
        return false;
    }
    const auto ordered = perspective::orderCorners(image);
    if (!ordered) {
        m_context->say(Message::NotConvex);
        return false;
    }
    const bool wide =
        orientation == Landscape || (orientation == AutoOrientation && perspective::looksLandscape(*ordered));
    // The sides as given say the rectangle's size; its orientation comes from the marks (or the choice).
    const double shortSide = std::min(width, height), longSide = std::max(width, height);
    width = wide ? longSide : shortSide;
    height = wide ? shortSide : longSide;
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
        m_context->say(Message::NotConvex);
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
        m_context->say(Message::NotConvex);
        return false;
    }
    if (!m_context->pushCalibration(QCoreApplication::translate("kontur::TraceController", "Calibrate perspective"),
                                    before, after, unit, k, 0.0))
        return false;
    m_context->say(Message::None);
    warnIfImprecise();
    return true;
}

void PerspectiveTool::clearPerspective()
{
    EditController *editor = m_context->editor();
    if (!editor || !calibrated())
        return;
    if (m_context->backgroundLocked()) {
        m_context->say(Message::LockedCalibrate);
        return;
    }
    Background bg = editor->document()->background();
    bg.perspective = false;
    bg.corners = {};
    bg.rectWidth = bg.rectHeight = 0.0;
    bg.rectOrigin = {};
    editor->background()->setBackground(bg);
    m_context->say(Message::None);
}

} // namespace kontur
