// What a phone's EXIF block says about its lens, for the sheet finder: the focal length as on a 35 mm
// film camera (EXIF 2.3 tag 0xA405, FocalLengthIn35mmFilm), which gives the focal length in the
// photo's pixels for any resize of the photo (not for a crop). Read from a JPEG's APP1 segment or from
// a TIFF-structured EXIF block (a HEIF file's "Exif" item); nothing else of EXIF is read.
// Reference: JEITA CP-3451C (Exif 2.3), §4.6.2 (IFD structure) and §4.6.5 (tag 0xA405).
#pragma once

#include <QByteArray>

namespace kontur {

// The 35 mm equivalent focal length in mm from a TIFF-structured EXIF block ("II*\0" or "MM\0*" first),
// or 0 when it is absent, zero ("unknown" in the standard) or the block is malformed.
[[nodiscard]] double exifFocal35mm(const QByteArray &tiff);

// The TIFF-structured EXIF block of a JPEG file's APP1 "Exif\0\0" segment, empty when there is none.
// `jpeg` may be only the file's head: the segment comes before the image data.
[[nodiscard]] QByteArray jpegExifBlock(const QByteArray &jpeg);

// A full-frame 35 mm film's diagonal (36 × 24 mm), in mm: the 35 mm equivalent focal length is the
// lens's focal length scaled by this over the sensor's diagonal.
inline constexpr double kFullFrameDiagonalMm = 43.2666;

} // namespace kontur
