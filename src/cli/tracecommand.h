// kontur-cli trace: a pattern photographed beside a reference sheet, traced into a document in mm:
// the sheet found, the photo rectified, every piece outlined; with --json the figures.
#pragma once

#include <QStringList>

namespace kontur::cli {

int runTrace(const QStringList &args);

} // namespace kontur::cli
