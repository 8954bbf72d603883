// PictureSource: an item that draws itself differently for a picture than on screen. The canvas
// draws every curve directly at the picture's scale instead of from its cached layer (which a grab
// at 2× would enlarge pixel by pixel), and may show the whole document for the picture.
// FileController::exportPng asks for it around its grab of the item.
#pragma once

namespace kontur {

class PictureSource
{
public:
    virtual ~PictureSource() = default;
    // Before the grab; `wholeDocument` asks for every curve in view.
    virtual void beginPicture(bool wholeDocument) = 0;
    // After the grab: the view and drawing as before beginPicture.
    virtual void endPicture() = 0;

protected:
    PictureSource() = default;
    PictureSource(const PictureSource &) = default;
    PictureSource &operator=(const PictureSource &) = default;
    PictureSource(PictureSource &&) = default;
    PictureSource &operator=(PictureSource &&) = default;
};

} // namespace kontur
