// The Kontur document inside a pattern PDF (issue 22): the PDF Kontur prints carries the whole
// document as XMP metadata (the .kontur JSON, base64, in the element kontur:document of the namespace
// kPdfNamespace), so that Open, Import and `kontur-cli convert` read it back. Qt's PDF engine writes
// the metadata stream uncompressed, so reading needs no PDF parser: the packet is found in the bytes.
// A PDF without it (not written by Kontur, or rewritten by another program that compressed it) is
// refused with NotKonturPdf. Writing the PDF itself needs Qt Gui: models/patternpdf.*.
#pragma once

#include "io/error.h"
#include "io/limits.h"
#include "io/records.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QString>

namespace kontur::io {

inline constexpr char kPdfNamespace[] = "urn:kontur:pattern-pdf:1";

// A whole XMP packet (UTF-8) holding the document as JSON (documentToJson with `documentPath`, so a
// background is written relative to the PDF's folder), with `title` as dc:title.
[[nodiscard]] QByteArray pdfXmpPacket(const DocumentData &doc, const QString &title, const QString &documentPath);

// The document in a PDF's bytes. Errors: NotKonturPdf (not a PDF, or no Kontur packet), and those
// of documentFromJson for the embedded document (relative background paths resolved against
// `documentPath`).
[[nodiscard]] Result<DocumentData> documentFromPdf(QByteArrayView pdf, const QString &documentPath = {},
                                                   const Limits &limits = {});
[[nodiscard]] Result<DocumentData> openPdfDocument(const QString &path, const Limits &limits = {});

} // namespace kontur::io
