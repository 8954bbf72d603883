// kontur-cli bench sheets DIR LABELS.json: the sheet finder (vision::findSheet) on real photos whose
// sheet corners were labelled by hand (tests/data/realphotos/sheets.json; the photos themselves are
// fetched from their sources, see docs/vision.md "Real photos"). Reports, per photo and in all, whether
// the sheet was found with every corner within 2 px of the label, found less precisely, a wrong
// rectangle taken, or nothing, with the corner errors and the time findSheet took.
#pragma once

#include <QStringList>

namespace kontur::cli {

// args: "kontur-cli bench", "sheets", DIR, LABELS.json, options.
[[nodiscard]] int runSheetBench(const QStringList &args);

} // namespace kontur::cli
