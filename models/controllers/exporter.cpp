#include "models/controllers/exporter.h"

#include "io/csv.h"
#include "io/pointstext.h"
#include "io/shapes.h"
#include "io/svg.h"
#include "models/controllers/picturesource.h"
#include "models/document/documentio.h"
#include "models/text/errortext.h"

#include <QFileInfo>
#include <QImageWriter>
#include <QSaveFile>

#include <cmath>

namespace kontur {

Exporter::Exporter(QObject *parent)
    : QObject(parent)
{
}

void Exporter::setEditor(EditController *editor)
{
    if (editor == m_editor)
        return;
    m_editor = editor;
    Q_EMIT editorChanged();
}

void Exporter::setFiles(DocumentFiles *files)
{
    if (files == m_files)
        return;
    m_files = files;
    Q_EMIT filesChanged();
}

QString Exporter::writePath(const QUrl &file, const QString &extension)
{
    return m_files ? m_files->writePath(file, extension) : QString();
}

bool Exporter::reportWritten(const QString &path, const io::Result<io::Ok> &written)
{
    if (!written.ok()) {
        m_editor->showMessage(Message::FileWriteError, {QFileInfo(path).fileName(), errorDetail(written.error())});
        return false;
    }
    m_editor->showMessage(Message::FileSaved, {QFileInfo(path).fileName()});
    return true;
}

std::optional<std::vector<io::DrawnCurve>> Exporter::curvesToExport(const QString &path)
{
    m_editor->document()->settleAllowances();
    auto curves = io::curvesToExport(toDocumentData(*m_editor->document()).curves);
    if (!curves) {
        m_editor->showMessage(Message::FileWriteError, {QFileInfo(path).fileName(), errorDetail(curves.error())});
        return std::nullopt;
    }
    return std::move(curves).value();
}

bool Exporter::exportSvg(const QUrl &file)
{
    if (!m_editor)
        return false;
    const QString path = writePath(file, QStringLiteral("svg"));
    if (path.isEmpty())
        return false;
    const auto curves = curvesToExport(path);
    if (!curves)
        return false;
    io::SvgExportOptions options;
    options.units = m_editor->document()->units();
    return reportWritten(path, io::writeSvg(path, *curves, options));
}

bool Exporter::exportDxf(const QUrl &file, bool polylines)
{
    if (!m_editor)
        return false;
    const QString path = writePath(file, QStringLiteral("dxf"));
    if (path.isEmpty())
        return false;
    const auto curves = curvesToExport(path);
    if (!curves)
        return false;
    io::DxfExportOptions options;
    options.units = m_editor->document()->units();
    options.flavour = polylines ? io::DxfFlavour::Polyline : io::DxfFlavour::Spline;
    return reportWritten(path, io::writeDxf(path, *curves, options));
}

std::optional<std::vector<io::AamaPiece>> Exporter::piecesToExport(const QString &name)
{
    m_editor->document()->settleAllowances();
    auto pieces = io::aamaPieces(toDocumentData(*m_editor->document()).curves);
    if (!pieces) {
        m_editor->showMessage(Message::FileWriteError, {name, errorDetail(pieces.error())});
        return std::nullopt;
    }
    if (pieces->empty()) {
        m_editor->showMessage(Message::NoPieces);
        return std::nullopt;
    }
    return std::move(pieces).value();
}

bool Exporter::hasPieces()
{
    if (!m_editor)
        return false;
    // A curve that does not draw is said by the export itself, with the file's name.
    const auto pieces = io::aamaPieces(toDocumentData(*m_editor->document()).curves);
    if (pieces && pieces->empty()) {
        m_editor->showMessage(Message::NoPieces);
        return false;
    }
    return true;
}

bool Exporter::exportAamaDxf(const QUrl &file)
{
    if (!m_editor)
        return false;
    const QString path = writePath(file, QStringLiteral("dxf"));
    if (path.isEmpty())
        return false;
    const auto pieces = piecesToExport(QFileInfo(path).fileName());
    if (!pieces)
        return false;
    io::DxfExportOptions options;
    options.units = m_editor->document()->units();
    options.aama = true;
    // Polylines within 0.05 mm (the default tolerance): what the standard's readers expect.
    options.flavour = io::DxfFlavour::Polyline;
    if (!reportWritten(path, io::writeAamaDxf(path, *pieces, options)))
        return false;
    // No grain line is invented for a piece without one: the user is told which pieces lack it.
    if (const auto bare = io::piecesWithoutGrainline(*pieces); !bare.empty()) {
        QStringList names;
        for (const QString &name : bare)
            names << (name.isEmpty() ? QStringLiteral("—") : name);
        m_editor->showMessage(
            Message::PiecesWithoutGrainline,
            {QFileInfo(path).fileName(), names.join(QStringLiteral(", ")), static_cast<int>(bare.size())});
    }
    return true;
}

bool Exporter::exportCsv(const QUrl &file)
{
    const Curve *selected = m_editor ? m_editor->selection()->curve() : nullptr;
    if (!selected)
        return false;
    const QString path = writePath(file, QStringLiteral("csv"));
    if (path.isEmpty())
        return false;
    const Curve &curve = *selected;
    return reportWritten(path, io::writeCsvPoints(path, curve.definingPoints()));
}

bool Exporter::appendPoints(const QUrl &file)
{
    const Curve *selected = m_editor ? m_editor->selection()->curve() : nullptr;
    if (!selected)
        return false;
    const QString path = writePath(file, QStringLiteral("txt"));
    if (path.isEmpty())
        return false;
    const Curve &curve = *selected;
    std::vector<geo::Point> derived;
    if (curve.fit())
        derived.assign(curve.fit()->control.begin(), curve.fit()->control.end());
    const auto written = io::appendPointsRecord(path, toRecord(curve), derived);
    if (!written.ok()) {
        m_editor->showMessage(Message::OutputError, {QFileInfo(path).fileName(), errorDetail(written.error())});
        return false;
    }
    m_editor->showMessage(Message::FileSaved, {QFileInfo(path).fileName()});
    return true;
}

bool Exporter::exportPng(QObject *canvas, const QUrl &file, double scale, bool wholeDocument)
{
    auto *source = dynamic_cast<PictureSource *>(canvas);
    if (!m_editor || !source)
        return false;
    const QString path = writePath(file, QStringLiteral("png"));
    if (path.isEmpty())
        return false;
    const QSizeF size = source->pictureSize() * scale;
    if (!std::isfinite(scale) || scale <= 0.0 || size.toSize().isEmpty())
        return false;
    const QPointer<Exporter> self(this);
    return source->makePicture(size.toSize(), wholeDocument, [self, path](const QImage &image) {
        if (self)
            (void)self->writePng(image, path);
    });
}

bool Exporter::writePng(const QImage &image, const QString &path)
{
    const QString name = QFileInfo(path).fileName();
    QSaveFile out(path);
    QString error;
    if (!out.open(QIODevice::WriteOnly)) {
        error = out.errorString();
    } else {
        QImageWriter writer(&out, "png");
        if (!writer.write(image)) {
            error = writer.errorString();
            out.cancelWriting();
        } else if (!out.commit()) {
            error = out.errorString();
        }
    }
    if (!m_editor)
        return error.isEmpty();
    if (!error.isEmpty()) {
        m_editor->showMessage(Message::FileWriteError, {name, error});
        return false;
    }
    m_editor->showMessage(Message::FileSaved, {name});
    return true;
}

} // namespace kontur
