// The typed result of the image functions: a value, or an error code with an English message (the
// UI and the CLI map the code to their own translated text). Same shape as geo::Result.
#pragma once

#include "geometry/result.h"

#include <string>

namespace kontur::vision {

enum class ErrorCode {
    InvalidImage,     // empty, or not 8-bit gray / BGR / BGRA
    InvalidArgument,  // a size, radius or scale outside its documented range
    NoSheetFound,     // no bright quadrilateral whose four edges fit straight lines
    SheetNotFlat,     // a bright quadrilateral whose edges are not straight (a curled or hand-held sheet)
    WrongProportions, // a rectangle, but not of the sheet's proportions (Error::seenAspect says which)
    NoCornerFound,    // no two straight edges meeting near the given point
    Degenerate,       // the corners do not form a convex quadrilateral (no homography)
    NoPieceFound,     // no region distinct from the table besides the sheet
};

struct Error
{
    ErrorCode code;
    std::string message;
    double seenAspect = 0; // WrongProportions: the rectangle's long side over its short side, as seen
};

template <typename T> using Result = geo::Expected<T, Error>;

} // namespace kontur::vision
