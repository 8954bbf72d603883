// The .kontur document's insides (see document.h), shared by its writer (documentwrite.cpp), its fast
// point scanner (documentscan.cpp) and its validating reader (document.cpp), and by nothing else:
// they agree on one grammar and its limits.
#pragma once

#include "io/limits.h"
#include "io/records.h"

#include <QByteArray>
#include <QString>

#include <cstddef>
#include <map>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace kontur::io::documentjson {

// The points of one curve, read straight from the text (see scanDocument).
struct FastPoints
{
    qint64 count = 0;               // points in the array
    std::vector<geo::Point> points; // empty when the file's points went over the limit
    std::vector<std::size_t> ruled; // the indices written as null (see ruleControlPoints)
};

// One pass over the text before Qt's parser: nesting deeper than the limit is refused before anything
// is built (Qt's own limit is far higher, and every level costs memory), and each curve's "points"
// array is read straight into points, its text replaced by a placeholder 0 for Qt's parser (the
// cuts are kept to map its error offsets back to the file). A QJsonArray per point would make a million-knot document
// take seconds and a gigabyte to open.
struct Scan
{
    std::optional<std::size_t> tooDeepAt;
    // Where the curve after the last one a file may hold begins: counted while scanning, so that a
    // document of a million curves is refused before Qt's parser builds them (1.4 GB before).
    std::optional<std::size_t> tooManyCurvesAt;
    QByteArray rest;                        // the text for Qt's parser (empty: the original text)
    std::map<qsizetype, FastPoints> points; // by curve index
    std::map<qsizetype, std::vector<QString>> nodeTypes;
    // Where the cut arrays were: {offset in rest just after the placeholder, bytes cut before it},
    // so that an offset of Qt's parser maps back to the file.
    std::vector<std::pair<qsizetype, qsizetype>> cuts;

    [[nodiscard]] std::size_t originalOffset(qsizetype restOffset) const
    {
        qsizetype shift = 0;
        for (const auto &[at, cut] : cuts)
            if (restOffset >= at)
                shift = cut;
        return static_cast<std::size_t>(restOffset + shift);
    }
};

[[nodiscard]] Scan scanDocument(std::string_view text, const Limits &limits);

// A composite curve's handles are mostly where the construction rule (docs/requirements.md 1.2) puts them; a
// document writes those as null and the reader computes them again from the knots, so a curve of a
// million knots takes 40 % of the space (issue 17: 145 MB, above the reader's limit, became under
// 60 MB). The rule is computed by the same function when writing and reading, so the points come
// back bit for bit; a handle the user moved differs from the rule and is written as a number.
// The control vector the rule gives for `c`'s knots, or an empty one when `c` is no well-formed
// composite record (then every point is written as a number).
[[nodiscard]] std::vector<geo::Point> ruleControlPoints(const CurveRecord &c);

// The folder relative background paths are taken from: the document's.
[[nodiscard]] QString documentFolder(const QString &documentPath);

} // namespace kontur::io::documentjson
