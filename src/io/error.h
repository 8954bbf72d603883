// Typed errors of the file-format layer: a stable code the UI translates, an English message for logs
// and the CLI, and where it happened (file, line and column for text formats, the JSON path for
// documents). Nothing in src/io throws; every operation that can fail returns io::Result.
#pragma once

#include "geometry/result.h"
#include "io/skipped.h"

#include <QString>

#include <utility>
#include <variant>

namespace kontur::io {

enum class ErrorCode {
    // Files
    CannotOpen,    // the file does not exist or cannot be read
    CannotWrite,   // the file cannot be written (the old file, if any, is left intact)
    FileTooLarge,  // larger than Limits::maxFileBytes
    TooManyPoints, // more points than Limits::maxPoints
    TooManyCurves, // more curves than Limits::maxCurves
    TooDeep,       // JSON or XML nested deeper than Limits::maxDepth
    NotUtf8,       // the text is not valid UTF-8
    // Points text and CSV
    ExpectedNumber,     // a number was expected here
    NumberOutOfRange,   // a number that is not finite as a double (1e999, inf, nan)
    TrailingText,       // more on the line than a point (often a decimal comma)
    UnknownDirective,   // a word at the start of a line that is no directive
    MissingValue,       // a directive without its value
    UnterminatedString, // a quoted string or CSV field without its closing quote
    EmptyRecord,        // a curve record with no points
    NoPoints,           // a file with no points at all
    MissingHeader,      // a CSV file whose first row is not the x,y header
    WrongFieldCount,    // a CSV row with more or fewer than two fields
    // Values of curves, shared by all formats
    UnknownKind,             // a curve kind this version does not know
    UnknownParameterization, // not uniform, chord or centripetal
    UnknownNodeType,         // not smooth, symmetric or corner
    UnknownPointKind,        // not knots or control
    WrongPointCount,         // too few or too many points for the kind
    WrongPointKind,          // control points of a fitted curve, knots of a Bézier curve
    InvalidValue,            // any other value outside its range (a colour, an opacity, …)
    // Kontur documents
    JsonSyntax,         // not well-formed JSON
    NotKontur,          // no "format": "kontur"
    UnsupportedVersion, // written by a newer Kontur (a version this one does not read)
    MissingField,       // a required member is absent
    WrongType,          // a member of the wrong JSON type
    // SVG
    XmlSyntax,       // not well-formed XML
    NotSvg,          // the root element is not <svg>
    PathSyntax,      // malformed path data
    TransformSyntax, // malformed transform attribute
    NoPaths,         // no <path> with drawable segments
    // PDF
    NotKonturPdf, // a PDF that holds no Kontur document (not printed by Kontur), or no PDF at all
    // DXF
    DxfSyntax,      // a group code that is no integer, a value that is no number, a file cut short
    DxfUnsupported, // a binary DXF, a rational spline, fit points only, an entity off the drawing plane
    // Conversions
    UnsupportedKind, // no curve shape for this kind yet (spline kinds, until the geometry has them)
    GeometryError,   // the geometry refused the points (coincident knots of a fitted curve, …)
};

// A stable identifier of the code ("expected-number"), for logs, tests and the CLI.
[[nodiscard]] const char *codeName(ErrorCode code);

struct Error
{
    ErrorCode code = ErrorCode::InvalidValue;
    QString message; // English, without the location
    QString file;    // the file as the caller named it; empty when parsing from memory without a name
    int line = 0;    // 1-based; 0 when the format has no lines (documents use `path`)
    int column = 0;  // 1-based, in characters (UTF-8 code points) of the line; 0 when unknown
    QString path;    // the JSON path of a document error, e.g. curves[3].points[7][1]
    // A drawing refused for holding nothing Kontur draws (NoPaths): what it held instead.
    SkippedCounts skipped{};

    // "file:line:column: message", "file: curves[3].kind: message", or just the message.
    [[nodiscard]] QString toString() const;
};

// The geometry's value-or-error type with the file layer's error.
template <typename T> using Result = geo::Expected<T, Error>;
// For operations with no value to return.
using geo::Ok;

} // namespace kontur::io
