// Conversion between the document's curves and the file layer's plain records (src/io), so that
// the formats need not know the models and the models need not know the formats.
#pragma once

#include "io/records.h"
#include "models/document/document.h"

namespace kontur {

// Every curve of the document and its background, as records (background file made relative by
// the writer).
[[nodiscard]] io::DocumentData toDocumentData(const Document &document);
[[nodiscard]] io::CurveRecord toRecord(const Curve &curve);

// A curve from a record; a typed error (with the English reason) when the record does not make one.
[[nodiscard]] geo::Result<Curve> fromRecord(const io::CurveRecord &record);
[[nodiscard]] Background fromRecord(const io::BackgroundRecord &record);
[[nodiscard]] std::optional<CurveKind> kindFromId(const QString &id);

} // namespace kontur
