// TraceContext: what the tracing tools share — the editor they work on, the one message channel
// (a Message, its text made when shown), snapping to knots, calibration marks and the grid, the
// background's lock, and the calibration push that maps the world and the curves together. Each tool
// (models/trace/*tool.h) holds a pointer to the one context its TraceController owns.
#pragma once

#include "models/controllers/editcontroller.h"
#include "models/document/document.h"
#include "models/text/shownmessage.h"

#include <QObject>
#include <QPointF>
#include <QPointer>
#include <QString>

#include <memory>

namespace cv {
class Mat;
}

namespace kontur {

class PhotoCache;

class TraceContext final : public QObject
{
    Q_OBJECT

public:
    explicit TraceContext(QObject *parent = nullptr);
    ~TraceContext() override;
    Q_DISABLE_COPY_MOVE(TraceContext)

    [[nodiscard]] EditController *editor() const { return m_editor; }
    void setEditor(EditController *editor) { m_editor = editor; }
    [[nodiscard]] Document *document() const { return m_editor ? m_editor->document() : nullptr; }
    // The picture, or nothing when there is none (with the NoPicture message).
    [[nodiscard]] const Background *pictureOrSay();
    [[nodiscard]] QString units() const;
    // The background picture in grey (8-bit, decoded once per file), or nothing with a message
    // (NoPicture, PictureUnreadable).
    [[nodiscard]] const cv::Mat *pictureGrayOrSay();
    // The same without a message (nothing when there is no readable picture).
    [[nodiscard]] const cv::Mat *pictureGray();
    // The background picture in colour (8-bit BGR; grey for a grey picture), or nothing with a message.
    [[nodiscard]] const cv::Mat *pictureColourOrSay();
    // The camera's focal length in the picture's pixels, from its EXIF; 0 when unknown or no picture.
    [[nodiscard]] double pictureFocalPx();

    // Shows the tools' message (None clears it); its text is made when read, in the current language.
    void say(Message message) { m_message.show(std::move(message)); }
    // The last refusal or problem (empty: none).
    [[nodiscard]] const Message &message() const { return m_message.message(); }

    [[nodiscard]] bool snapping() const { return m_snapping; }
    void setSnapping(bool on);
    [[nodiscard]] double gridStep() const { return m_gridStep; }
    void setGridStep(double step);
    // The knot, calibration mark or grid crossing within `radius` of `world` while snapping is on.
    [[nodiscard]] QPointF snap(QPointF world, double radius) const;

    [[nodiscard]] bool backgroundLocked() const;
    void setBackgroundLocked(bool locked);

    // Pushes a calibration: the world mapped by p ↦ scale · R(radians) p (the curves with it), the
    // background and the units changed; one undo step named `text`. False (with a message) when a
    // curve cannot be mapped.
    bool pushCalibration(const QString &text, const Background &before, const Background &after, const QString &unit,
                         double scale, double radians);

Q_SIGNALS:
    void messageChanged();
    void snappingChanged();
    void gridStepChanged();
    // A calibration mapped the world by p ↦ scale · R(radians) p: the view may follow, so that the
    // picture stays where it was on the screen.
    void worldMapped(double scale, double radians);

private:
    QPointer<EditController> m_editor;
    // Announced again after a language switch (messageChanged).
    ShownMessage m_message{this, [this] { Q_EMIT messageChanged(); }};
    // The picture in colour or in grey, or nothing with a message.
    const cv::Mat *pictureMatOrSay(bool colour);
    bool m_snapping = false;
    double m_gridStep = 0.0;
    std::unique_ptr<PhotoCache> m_photos;
};

// Between Qt's points and the geometry's, for the tools' sources.
namespace tracepoints {
[[nodiscard]] inline geo::Point toPoint(QPointF p)
{
    return {p.x(), p.y()};
}
[[nodiscard]] inline QPointF toQPoint(const geo::Point &p)
{
    return {p.x(), p.y()};
}
} // namespace tracepoints

} // namespace kontur
