// kontur-cli trace: a pattern photographed beside a reference sheet. For now the sheet part: the
// sheet's corners (found, or refined from --corners hints) and the calibration error, as JSON.
#pragma once

#include <QStringList>

namespace kontur::cli {

int runTrace(const QStringList &args);

} // namespace kontur::cli
