// Limits of what one file holds (issues 7 and 17). Readers check them against hostile or broken files
// and answer a clear error instead of exhausting memory or the stack; writers check the same limits,
// so that everything Kontur writes, Kontur reads back. Points and curves are counted; the byte limit
// only follows from them: the largest file Kontur can write within them, with margin.
#pragma once

#include <QtGlobal>

namespace kontur::io {

// Defining points of one curve (knots of a composite curve), as the kinds' table allows
// (geometry/curvekinds.h, kManyPoints) and the files' kinds say (records.cpp). A composite curve
// stores 3 points per knot.
inline constexpr qint64 kMaxCurvePoints = 1'000'000;
// The longest text of one point or segment Kontur writes: an SVG cubic (" C " and six numbers of at
// most 24 characters, "-2.2250738585072014e-308", and their spaces) is 156 bytes; a document point
// with its node type ("[x,y],\n" and "\"symmetric\",") 65.
inline constexpr qint64 kMaxBytesPerPoint = 160;
// Everything of one curve but its points: name, colour, settings, keys (a points text record refuses
// settings over 64 KiB; names and settings are short in practice, and the writers check the total).
inline constexpr qint64 kBytesPerCurve = 1024;

struct Limits
{
    // Stored points in one file, all curves together (a composite curve's whole control vector, an
    // SVG's segments): two of the largest curves, closed composite curves of kMaxCurvePoints knots.
    qint64 maxPoints = 2 * 3 * kMaxCurvePoints;
    qint64 maxCurves = 100'000; // curves (records, subpaths) in one file
    int maxDepth = 64;          // nesting of JSON arrays/objects and of XML elements
    // Bytes read from one file: the largest file within the counts above, and 16 MiB of margin.
    qint64 maxFileBytes = maxPoints * kMaxBytesPerPoint + maxCurves * kBytesPerCurve + 16 * 1024 * 1024;
};

} // namespace kontur::io
