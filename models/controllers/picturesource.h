// PictureSource: what the PNG export needs of the canvas, without the models knowing Qt Quick. The
// canvas (src/app/curvecanvas.*) implements it: it draws every curve directly at the picture's scale
// instead of from its cached layer (which a grab at 2× would enlarge pixel by pixel), may show the
// whole document for the picture, grabs itself and hands the image back.
#pragma once

#include <QImage>
#include <QSizeF>

#include <functional>

namespace kontur {

class PictureSource
{
public:
    virtual ~PictureSource() = default;
    // The size of the drawing on screen, in device-independent pixels.
    [[nodiscard]] virtual QSizeF pictureSize() const = 0;
    // Draws the picture at `size` pixels (all curves in view with `wholeDocument`), then calls `done`
    // with it once, later, from the event loop; the view on screen is as before afterwards. False when
    // no picture can be made (nothing is called then).
    [[nodiscard]] virtual bool makePicture(QSize size, bool wholeDocument,
                                           std::function<void(const QImage &)> done) = 0;

protected:
    PictureSource() = default;
    PictureSource(const PictureSource &) = default;
    PictureSource &operator=(const PictureSource &) = default;
    PictureSource(PictureSource &&) = default;
    PictureSource &operator=(PictureSource &&) = default;
};

} // namespace kontur
