// kontur-cli convert and info: the file formats of src/io from the command line. Each takes the
// arguments after its name and returns the exit code (0 success, 1 bad input, 2 bad usage).
#pragma once

#include <QStringList>

namespace kontur::io {
struct DocumentData;
}

namespace kontur::cli {

class Json;

int runConvert(const QStringList &args);
int runInfo(const QStringList &args);
// offset IN OUT: seam allowances (geometry/offset.h) appended to the input's curves.
int runOffset(const QStringList &args);
// What `info` prints of a document read from `path`: its curves' kinds, point counts, lengths to
// `accuracy`, bounding boxes and continuity (also timed by `bench info-1e6`).
void describeDocument(Json &json, const QString &path, const io::DocumentData &doc, double accuracy);

} // namespace kontur::cli
