#include "models/controllers/documentfiles.h"

#include "io/aama.h" // scaleRecord
#include "io/document.h"
#include "io/dxf.h"
#include "io/formats.h"
#include "io/records.h"
#include "models/controllers/savepath.h"
#include "models/document/documentio.h"
#include "models/text/errortext.h"
#include "picture/picture.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>
#include <QUndoStack>

namespace kontur {

namespace {

QString localPath(const QUrl &url)
{
    return url.isLocalFile() ? url.toLocalFile() : url.toString();
}

// Why the `number`-th curve of a file whose numbers overflow (knots near the largest double, a handle
// past it) is not taken: the models never hold a coordinate that is not finite.
QVariantMap tooLarge(int number)
{
    return errorDetail(geo::Error{geo::ErrorCode::NonFiniteInput, {}}, number);
}

QString suffixOf(const QString &path)
{
    return QFileInfo(path).suffix().toLower();
}

// A .kontur document, or the document inside a pattern PDF Kontur printed.
io::Result<io::DocumentData> readDocument(const QString &path)
{
    auto read = io::readFile(path); // a .kontur document or a pattern PDF (io/formats.h)
    if (!read)
        return read.error();
    return std::move(read->document);
}

} // namespace

DocumentFiles::DocumentFiles(QObject *parent)
    : QObject(parent)
{
}

DocumentFiles::~DocumentFiles() = default;

void DocumentFiles::setEditor(EditController *editor)
{
    if (editor == m_editor)
        return;
    m_editor = editor;
    Q_EMIT editorChanged();
}

void DocumentFiles::setRecent(RecentFiles *recent)
{
    if (recent == m_recent)
        return;
    m_recent = recent;
    Q_EMIT recentChanged();
}

QString DocumentFiles::displayName() const
{
    //: The name of a document that has not been saved yet (also the suggested file name).
    return m_file.isEmpty() ? QCoreApplication::translate("kontur", "Untitled")
                            : QFileInfo(localPath(m_file)).fileName();
}

void DocumentFiles::setFile(const QUrl &file)
{
    if (file == m_file)
        return;
    m_file = file;
    Q_EMIT fileChanged();
}

void DocumentFiles::addRecent(const QString &path)
{
    if (m_recent)
        m_recent->add(path);
}

void DocumentFiles::readError(const QString &path, const QVariant &detail)
{
    if (m_editor)
        m_editor->showMessage(Message::FileReadError, {QFileInfo(path).fileName(), detail});
}

QString DocumentFiles::photoPath() const
{
    return m_editor ? m_editor->document()->background().file : QString();
}

QUrl DocumentFiles::startFolder() const
{
    const QString photo = photoPath();
    QString folder = !m_file.isEmpty()         ? QFileInfo(localPath(m_file)).absolutePath()
                     : !m_lastFolder.isEmpty() ? m_lastFolder
                     : !photo.isEmpty()        ? QFileInfo(photo).absolutePath()
                                               : QString();
    if (folder.isEmpty() || !QFileInfo(folder).isDir())
        folder = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    if (folder.isEmpty() || !QFileInfo(folder).isDir())
        folder = QDir::homePath();
    return QUrl::fromLocalFile(folder);
}

QUrl DocumentFiles::suggestedFile(const QString &extension) const
{
    // An unsaved document traced from a photo is named after the photo.
    const QString photo = photoPath();
    const QUrl named = m_file.isEmpty() && !photo.isEmpty() ? QUrl::fromLocalFile(photo) : m_file;
    return QUrl::fromLocalFile(
        QDir(startFolder().toLocalFile())
            .filePath(suggestedFileName(named, extension, QCoreApplication::translate("kontur", "Untitled"))));
}

void DocumentFiles::rememberFolder(const QUrl &file)
{
    const QString path = localPath(file);
    if (!path.isEmpty())
        m_lastFolder = QFileInfo(path).absolutePath();
}

QString DocumentFiles::writePath(const QUrl &file, const QString &extension)
{
    const QUrl suggested = suggestedFile(extension);
    const QString path = savePathFor(file, extension, QFileInfo(suggested.toLocalFile()).absolutePath());
    if (path.isEmpty()) {
        if (m_editor)
            m_editor->showMessage(Message::FileWriteError,
                                  {file.fileName(), QVariant::fromValue(Message(Message::NoFileName))});
        return {};
    }
    m_lastFolder = QFileInfo(path).absolutePath();
    return path;
}

void DocumentFiles::newDocument()
{
    if (!m_editor)
        return;
    m_editor->replaceDocument({}, Background{}, QStringLiteral("px"), false);
    m_unitlessRead.reset();
    setFile({});
    Q_EMIT unsavedWorkGone();
}

bool DocumentFiles::open(const QUrl &file)
{
    if (!m_editor)
        return false;
    m_unitlessRead.reset();
    const QString path = localPath(file);
    rememberFolder(file);
    const io::FormatInfo *format = io::formatOf(path);
    const bool pdf = format && format->format == io::Format::Pdf;
    if (!format || !format->document) {
        // Any other format starts a new, unsaved document holding what the file has.
        std::vector<Curve> curves;
        QVariant error;
        QString units; // a DXF's own units become the document's
        QVariantList skipped;
        QString assumed;
        const int kind = static_cast<int>(CurveKind::Composite);
        if (!readCurves(path, kind, curves, error, &units, &skipped, &assumed)) {
            readError(path, error);
            return false;
        }
        const int count = static_cast<int>(curves.size());
        m_editor->replaceDocument(std::move(curves), Background{}, units.isEmpty() ? QStringLiteral("px") : units,
                                  true);
        setFile({});
        addRecent(path);
        // A new document says nothing when it came whole in its own units.
        if (!skipped.isEmpty() || !assumed.isEmpty())
            reportRead(path, count, skipped, assumed, true, kind);
        return true;
    }
    const auto data = readDocument(path);
    if (!data.ok()) {
        readError(path, errorDetail(data.error()));
        return false;
    }
    std::vector<Curve> curves;
    for (std::size_t i = 0; i < data->curves.size(); ++i) {
        auto curve = fromRecord(data->curves[i]);
        if (!curve.ok()) {
            readError(path, errorDetail(curve.error(), static_cast<int>(i) + 1));
            return false;
        }
        if (!curve->isFinite()) {
            readError(path, tooLarge(static_cast<int>(i) + 1));
            return false;
        }
        curves.push_back(std::move(curve.value()));
    }
    const Background background = data->background ? fromRecord(*data->background) : Background{};
    m_editor->replaceDocument(std::move(curves), background, data->units, false);
    // The picture stays in the document (saving keeps it), but its absence is said, not silent.
    if (!background.file.isEmpty() && !readImageSize(background.file).ok())
        m_editor->showMessage(Message::BackgroundUnreadable, {QFileInfo(background.file).fileName()});
    // A printed PDF is not where the document is saved: Save asks for a .kontur file.
    setFile(pdf ? QUrl() : QUrl::fromLocalFile(QFileInfo(path).absoluteFilePath()));
    addRecent(path);
    return true;
}

bool DocumentFiles::save()
{
    if (m_file.isEmpty())
        return false;
    return saveAs(m_file);
}

bool DocumentFiles::saveAs(const QUrl &file)
{
    if (!m_editor)
        return false;
    const QString path = writePath(file, QStringLiteral("kontur"));
    if (path.isEmpty())
        return false;
    m_editor->document()->settleAllowances(); // what is written is exact, even right after a drag
    const auto saved = io::saveDocument(path, toDocumentData(*m_editor->document()));
    if (!saved.ok()) {
        m_editor->showMessage(Message::FileWriteError, {QFileInfo(path).fileName(), errorDetail(saved.error())});
        return false;
    }
    m_editor->markSaved();
    m_unitlessRead.reset(); // saved as a document of its own: not read again from the DXF
    setFile(QUrl::fromLocalFile(QFileInfo(path).absoluteFilePath()));
    addRecent(path);
    Q_EMIT unsavedWorkGone();
    m_editor->showMessage(Message::FileSaved, {QFileInfo(path).fileName()});
    return true;
}

QString DocumentFiles::unitlessUnits(const QString &suffix)
{
    const QString units = QSettings().value(QStringLiteral("unitlessUnits/") + suffix).toString();
    return units.isEmpty() ? QStringLiteral("px") : units;
}

bool DocumentFiles::needsUnits(const QUrl &file) const
{
    const QString path = localPath(file);
    if (suffixOf(path) != QLatin1String("dxf") ||
        QSettings().contains(QStringLiteral("unitlessUnits/") + suffixOf(path)))
        return false;
    const auto dxf = io::readDxf(path);
    return dxf.ok() && !dxf->declaredUnits;
}

void DocumentFiles::rememberUnits(const QUrl &file, const QString &units)
{
    static const QStringList known{QStringLiteral("mm"), QStringLiteral("cm"), QStringLiteral("in"),
                                   QStringLiteral("px")};
    const QString suffix = suffixOf(localPath(file));
    if (!known.contains(units))
        return;
    const bool changed = QSettings().value(QStringLiteral("unitlessUnits/") + suffix).toString() != units;
    QSettings().setValue(QStringLiteral("unitlessUnits/") + suffix, units);
    if (changed && suffix == QLatin1String("dxf"))
        Q_EMIT dxfUnitlessUnitsChanged();
}

void DocumentFiles::setDxfUnitlessUnits(const QString &units)
{
    rememberUnits(QUrl::fromLocalFile(QStringLiteral("file.dxf")), units);
}

void DocumentFiles::changeUnitlessUnits(const QString &units)
{
    if (!m_editor)
        return;
    const QString before = dxfUnitlessUnits();
    setDxfUnitlessUnits(units);
    if (dxfUnitlessUnits() == before && QSettings().contains(QStringLiteral("unitlessUnits/dxf")))
        return; // the same units: nothing to read again
    const std::optional<UnitlessRead> last = m_unitlessRead;
    const QUndoStack *stack = m_editor->undoStack();
    if (last && stack->index() == last->undoIndex && stack->count() == last->undoCount &&
        QFileInfo::exists(last->path)) {
        const QUrl url = QUrl::fromLocalFile(last->path);
        if (last->opened) {
            (void)open(url);
            return;
        }
        m_editor->undo(); // the import, the last command on the stack
        (void)importFile(url, last->kind);
        return;
    }
    m_editor->showMessage(Message::UnitlessUnitsChanged, {dxfUnitlessUnits()});
}

bool DocumentFiles::readCurves(const QString &path, int kind, std::vector<Curve> &out, QVariant &error, QString *units,
                               QVariantList *skipped, QString *assumed) const
{
    const QString suffix = suffixOf(path);
    const QString kindName = (kind >= 0 && kind < kKindCount)
                                 ? QString::fromLatin1(kindId(static_cast<CurveKind>(kind)))
                                 : QStringLiteral("composite");
    // Hand-written lists get the parameterization chosen for new curves, where the kind uses one.
    const io::KindInfo *info = io::kindInfo(kindName);
    const QString parameterization =
        info && info->usesParameterization && m_editor
            ? QString::fromLatin1(
                  geo::nameOf(static_cast<geo::Parameterization>(m_editor->placement()->parameterization())))
            : QString();
    // Every format through the one reader of io/formats.h (kontur-cli's too); a file of no known
    // suffix is read as points text, the format a hand-written list has.
    io::ReadOptions options;
    options.kind = kindName;
    options.parameterization = parameterization;
    options.unitlessUnits = unitlessUnits(suffix);
    options.cubicOnly = true; // SVG: composite curves are cubic
    options.otherSuffix = io::Format::PointsText;
    const auto read = io::readFile(path, options);
    if (!read.ok()) {
        error = errorDetail(read.error());
        return false;
    }
    std::vector<io::CurveRecord> records = read->document.curves;
    if (skipped && io::anySkipped(read->skipped))
        for (int n : read->skipped)
            skipped->append(n);
    if (read->format->format == io::Format::Dxf) {
        // Into the document's units when both are lengths; else the numbers as they are.
        const double from = io::millimetresPerUnit(read->document.units);
        const double to = units ? io::millimetresPerUnit(*units) : 0.0;
        const double scale = from > 0 && to > 0 ? from / to : 1.0;
        if (scale != 1.0)
            for (io::CurveRecord &record : records)
                io::scaleRecord(record, scale);
        if (units && (units->isEmpty() || scale == 1.0))
            *units = read->document.units;
        if (assumed && !read->declaredUnits)
            *assumed = read->document.units;
    }
    std::vector<Curve> curves;
    for (std::size_t i = 0; i < records.size(); ++i) {
        auto curve = fromRecord(records[i]);
        if (!curve.ok()) {
            error = errorDetail(curve.error(), static_cast<int>(i) + 1);
            return false;
        }
        if (curve->problem()) {
            error = errorDetail(*curve->problem(), static_cast<int>(i) + 1);
            return false;
        }
        if (!curve->isFinite()) {
            error = tooLarge(static_cast<int>(i) + 1);
            return false;
        }
        curves.push_back(std::move(curve.value()));
    }
    out = std::move(curves);
    return true;
}

bool DocumentFiles::importFile(const QUrl &file, int kind)
{
    if (!m_editor)
        return false;
    m_unitlessRead.reset();
    const QString path = localPath(file);
    rememberFolder(file);
    std::vector<Curve> curves;
    QVariant error;
    QString units = m_editor->document()->units();
    QVariantList skipped;
    QString assumed;
    if (!readCurves(path, kind, curves, error, &units, &skipped, &assumed)) {
        readError(path, error);
        return false;
    }
    const int count = static_cast<int>(curves.size());
    m_editor->commands()->addCurves(std::move(curves),
                                    //: Undo text: %1 is the name of the imported file.
                                    QCoreApplication::translate("kontur", "Import %1").arg(QFileInfo(path).fileName()));
    reportRead(path, count, skipped, assumed, false, kind);
    return true;
}

void DocumentFiles::reportRead(const QString &path, int count, const QVariantList &skipped, const QString &assumed,
                               bool opened, int kind)
{
    const QString name = QFileInfo(path).fileName();
    m_unitlessRead.reset();
    if (!assumed.isEmpty()) {
        const QUndoStack *stack = m_editor->undoStack();
        m_unitlessRead = UnitlessRead{QFileInfo(path).absoluteFilePath(), opened, kind, stack->index(), stack->count()};
        m_editor->showMessage(Message::FileImportedUnitless, {count, name, assumed, skipped});
    } else if (skipped.isEmpty()) {
        m_editor->showMessage(Message::FileImported, {count, name});
    } else {
        m_editor->showMessage(Message::FileImportedSkipped, {count, name, skipped});
    }
}

QString DocumentFiles::filePatterns(bool documents) const
{
    return io::filePatterns(documents);
}

bool DocumentFiles::openRecovered(const QString &path)
{
    if (!m_editor)
        return false;
    const auto data = io::openDocument(path);
    if (!data.ok()) {
        readError(path, errorDetail(data.error()));
        return false;
    }
    std::vector<Curve> curves;
    for (const io::CurveRecord &record : data->curves) {
        auto curve = fromRecord(record);
        if (curve.ok() && curve->isFinite())
            curves.push_back(std::move(curve.value()));
    }
    const Background background = data->background ? fromRecord(*data->background) : Background{};
    m_editor->replaceDocument(std::move(curves), background, data->units, true);
    m_unitlessRead.reset();
    if (!background.file.isEmpty() && !readImageSize(background.file).ok())
        m_editor->showMessage(Message::BackgroundUnreadable, {QFileInfo(background.file).fileName()});
    setFile({});
    return true;
}

} // namespace kontur
