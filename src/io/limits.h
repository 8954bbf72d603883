// Limits against hostile or broken files (issue 7): every reader checks them and answers a clear
// error instead of exhausting memory or the stack. The defaults are far above any real drawing
// (a traced pattern has thousands of points; the geometry handles a million-point fit).
#pragma once

#include <QtGlobal>

namespace kontur::io {

struct Limits
{
    qint64 maxFileBytes = 64 * 1024 * 1024; // bytes read from one file
    qint64 maxPoints = 2'000'000;           // points in one file, all curves together
    qint64 maxCurves = 100'000;             // curves (records, subpaths) in one file
    int maxDepth = 64;                      // nesting of JSON arrays/objects and of XML elements
};

} // namespace kontur::io
