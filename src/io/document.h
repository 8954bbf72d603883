// The Kontur document (.kontur, issue 7): JSON with "format": "kontur" and "version": 1 holding all
// of DocumentData (units, curves with their kinds, settings, points and style, the background with
// placement and calibration). Written by Kontur's own JSON writer, numbers in the shortest round-trip
// form (std::to_chars), so save → open → save is byte-identical; saved atomically through QSaveFile.
// Opening validates everything and every error names the JSON path (curves[3].points[7][1]).
// Layout in docs/file-formats.md.
#pragma once

#include "io/error.h"
#include "io/limits.h"
#include "io/records.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QString>

namespace kontur::io {

// The newest version this Kontur reads. Version 2 writes a composite curve's handles that follow the
// construction rule as null; version 3 holds pieces' marks (a curve's "piece" settings, io/piece.h).
// A document is written with the lowest version that holds what it has, which older versions read.
inline constexpr int kDocumentVersion = 3;

// The document as JSON text. With a `documentPath`, an absolute background path is written relative
// to the document's folder. Callers validate first (saveDocument does).
[[nodiscard]] QByteArray documentToJson(const DocumentData &doc, const QString &documentPath = {});
// Parses and validates. With a `documentPath`, a relative background path is resolved against the
// document's folder. `fileName` (defaults to documentPath) only names the file in errors.
[[nodiscard]] Result<DocumentData> documentFromJson(QByteArrayView json, const QString &documentPath = {},
                                                    const Limits &limits = {});
// Validates the whole document (curves, units, background): the first problem, with its JSON path.
[[nodiscard]] std::optional<Error> validateDocument(const DocumentData &doc);

// Validates, then writes atomically: on any failure the old file is intact. A document beyond the
// limits openDocument reads (points, curves, bytes) is refused: Kontur never writes what it cannot open.
[[nodiscard]] Result<Ok> saveDocument(const QString &path, const DocumentData &doc, const Limits &limits = {});
[[nodiscard]] Result<DocumentData> openDocument(const QString &path, const Limits &limits = {});

} // namespace kontur::io
