// The document in a pattern PDF's XMP metadata (see pdf.h).
#include "io/pdf.h"

#include "io/document.h"
#include "io/fileio.h"

#include <QStringView>

namespace kontur::io {

namespace {

constexpr char kOpen[] = "<kontur:document>";
constexpr char kClose[] = "</kontur:document>";

QByteArray xmlEscaped(const QString &text)
{
    return text.toHtmlEscaped().toUtf8();
}

Error notKonturPdf(const QString &path, const QString &why)
{
    Error e;
    e.code = ErrorCode::NotKonturPdf;
    e.file = path;
    e.message = why;
    return e;
}

} // namespace

QByteArray pdfXmpPacket(const DocumentData &doc, const QString &title, const QString &documentPath)
{
    // XMP (ISO 16684-1): a packet wrapper around RDF/XML. Base64 keeps the JSON free of anything
    // XML or the PDF stream syntax could misread ("<", "]]>", "endstream").
    QByteArray x;
    x += "<?xpacket begin=\"\xEF\xBB\xBF\" id=\"W5M0MpCehiHzreSzNTczkc9d\"?>\n";
    x += "<x:xmpmeta xmlns:x=\"adobe:ns:meta/\">\n";
    x += " <rdf:RDF xmlns:rdf=\"http://www.w3.org/1999/02/22-rdf-syntax-ns#\">\n";
    x += "  <rdf:Description rdf:about=\"\"\n";
    x += "    xmlns:dc=\"http://purl.org/dc/elements/1.1/\"\n";
    x += "    xmlns:pdf=\"http://ns.adobe.com/pdf/1.3/\"\n";
    x += "    xmlns:kontur=\"";
    x += kPdfNamespace;
    x += "\">\n";
    x += "   <dc:title><rdf:Alt><rdf:li xml:lang=\"x-default\">" + xmlEscaped(title) +
         "</rdf:li></rdf:Alt></dc:title>\n";
    x += "   <pdf:Producer>Kontur</pdf:Producer>\n";
    x += "   <kontur:documentEncoding>base64 of the .kontur JSON</kontur:documentEncoding>\n";
    x += "   ";
    x += kOpen;
    x += documentToJson(doc, documentPath).toBase64();
    x += kClose;
    x += "\n  </rdf:Description>\n </rdf:RDF>\n</x:xmpmeta>\n<?xpacket end=\"r\"?>";
    return x;
}

Result<DocumentData> documentFromPdf(QByteArrayView pdf, const QString &documentPath, const Limits &limits)
{
    if (!pdf.startsWith("%PDF-"))
        return notKonturPdf(documentPath, QStringLiteral("not a PDF file"));
    // The first Kontur packet; a PDF holds one (Qt writes the document's metadata once).
    const qsizetype open = pdf.indexOf(QByteArrayView(kOpen));
    const qsizetype close = open < 0 ? -1 : pdf.indexOf(QByteArrayView(kClose), open);
    if (open < 0 || close < 0 || pdf.indexOf(QByteArrayView(kPdfNamespace)) < 0)
        return notKonturPdf(documentPath,
                            QStringLiteral("the PDF was not written by Kontur: it holds no Kontur document"));
    const QByteArrayView encoded =
        pdf.sliced(open + qsizetype(sizeof kOpen - 1), close - open - qsizetype(sizeof kOpen - 1));
    const auto decoded = QByteArray::fromBase64Encoding(encoded.toByteArray(), QByteArray::AbortOnBase64DecodingErrors);
    if (!decoded)
        return notKonturPdf(documentPath, QStringLiteral("the Kontur document in the PDF is damaged (not base64)"));
    return documentFromJson(*decoded, documentPath, limits);
}

Result<DocumentData> openPdfDocument(const QString &path, const Limits &limits)
{
    // The PDF holds the document (base64: 4/3 of its size) and its drawing: allow three times the
    // document limit for the container; the document inside keeps the normal limits.
    Limits container = limits;
    container.maxFileBytes = limits.maxFileBytes * 3;
    auto bytes = readFileBytes(path, container);
    if (!bytes)
        return bytes.error();
    return documentFromPdf(*bytes, path, limits);
}

} // namespace kontur::io
