// The records a DXF's curves become, with ASTM D6673 (AAMA) pieces as pieces: the sew line (else the
// cut line) is the piece's curve, named after the piece and holding its marks (io/piece.h: size,
// quantity, material, fold, grainline, notches, drill holes); a cut line around a sew line at one
// distance is its seam allowance (linked, io/seam.h), else a curve of its own. The curves the marks
// came from (grain, mirror, notch and drill-hole lines) are not kept as curves.
#pragma once

#include "io/dxf.h"
#include "io/records.h"

#include <vector>

namespace kontur::io {

// Every curve of `dxf` as a record (recordFromDxfCurve), pieces as above. Errors name `path` and
// the curve's line.
[[nodiscard]] Result<std::vector<CurveRecord>> dxfRecords(const DxfImport &dxf, const QString &path);

// A record scaled by `factor` about the origin (an import into other units): its points, its piece's
// marks and its seam allowance's distances.
void scaleRecord(CurveRecord &record, double factor);

} // namespace kontur::io
