// FileController: documents, imports, exports, recent files and crash recovery. Over 600 lines
// because opening, saving and the recovery copies (one per instance, under a lock) share the
// document's conversion and the messages of every file error; the formats themselves are src/io's.
#include "models/controllers/filecontroller.h"

#include "io/aama.h"
#include "io/csv.h"
#include "io/document.h"
#include "io/dxf.h"
#include "io/formats.h"
#include "io/pdf.h"
#include "io/pointstext.h"
#include "io/shapes.h"
#include "io/svg.h"
#include "models/controllers/picturesource.h"
#include "models/controllers/savepath.h"
#include "models/document/documentio.h"
#include "models/text/errortext.h"
#include "picture/picture.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImageWriter>
#include <QSaveFile>
#include <QSettings>
#include <QStandardPaths>
#include <QTimer>
#include <QUndoStack>
#include <QUuid>

#include <algorithm>
#include <cmath>

namespace kontur {

namespace {

constexpr int kRecentCount = 8;

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

FileController::FileController(QObject *parent)
    : QObject(parent)
{
    QSettings settings;
    m_recent = settings.value(QStringLiteral("recentFiles")).toStringList();
    // Whole labs set it in kontur.conf, scripts in the environment: a bad value (0 made the timer
    // fire continuously, a negative one turned autosave off) is clamped and said.
    QString note;
    if (const QVariant stored = settings.value(QStringLiteral("autosaveSeconds")); stored.isValid()) {
        m_autosaveSeconds = autosaveSecondsFrom(
            stored.toString(), QStringLiteral("autosaveSeconds in ") + QDir::toNativeSeparators(settings.fileName()),
            note);
        if (!note.isEmpty())
            m_autosaveGiven = stored.toString();
    }
    if (const QByteArray env = qgetenv("KONTUR_AUTOSAVE_SECONDS"); !env.isEmpty()) {
        QString envNote;
        m_autosaveSeconds =
            autosaveSecondsFrom(QString::fromLocal8Bit(env), QStringLiteral("KONTUR_AUTOSAVE_SECONDS"), envNote);
        // The environment wins over the file, and so does what is said about it.
        note = envNote;
        m_autosaveGiven = envNote.isEmpty() ? QString() : QString::fromLocal8Bit(env);
    }
    m_autosaveNote = note;
    if (!note.isEmpty())
        qWarning("kontur: %s", qPrintable(note));
    // This instance's recovery copy: a name of its own (process id and a random part).
    m_ownRecovery = QDir(recoveryFolder())
                        .filePath(QStringLiteral("%1-%2.kontur")
                                      .arg(QCoreApplication::applicationPid())
                                      .arg(QUuid::createUuid().toString(QUuid::Id128).left(8)));
    findOrphans();
    m_autosave.setSingleShot(false);
    connect(&m_autosave, &QTimer::timeout, this, [this] { (void)autosaveNow(); });
    updateTimer();
}

FileController::~FileController() = default;

void FileController::setEditor(EditController *editor)
{
    if (editor == m_editor)
        return;
    m_editor = editor;
    if (m_editor && !m_autosaveNote.isEmpty())
        m_editor->showMessage(Message::AutosaveSettingClamped, {m_autosaveGiven, m_autosaveSeconds});
    Q_EMIT editorChanged();
}

QString FileController::displayName() const
{
    //: The name of a document that has not been saved yet (also the suggested file name).
    return m_file.isEmpty() ? QCoreApplication::translate("kontur", "Untitled")
                            : QFileInfo(localPath(m_file)).fileName();
}

int FileController::autosaveSecondsFrom(const QString &text, const QString &source, QString &note)
{
    bool ok = false;
    const double value = text.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(value)) {
        note = QStringLiteral("%1 = \"%2\" is not a number of seconds; autosaving every %3 seconds")
                   .arg(source, text)
                   .arg(kDefaultAutosaveSeconds);
        return kDefaultAutosaveSeconds;
    }
    const int seconds =
        static_cast<int>(std::clamp(std::round(value), double(kMinAutosaveSeconds), double(kMaxAutosaveSeconds)));
    if (seconds != value)
        note = QStringLiteral("%1 = %2 is outside %3 to %4 seconds (or not whole); autosaving every %5 seconds")
                   .arg(source, text)
                   .arg(kMinAutosaveSeconds)
                   .arg(kMaxAutosaveSeconds)
                   .arg(seconds);
    return seconds;
}

QString FileController::recoveryFolder()
{
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    return QDir(dir).filePath(QStringLiteral("recovery"));
}

QString FileController::recoveryPath()
{
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    return QDir(dir).filePath(QStringLiteral("recovery.kontur"));
}

QStringList FileController::recoveryFiles()
{
    QStringList files;
    const QDir folder(recoveryFolder());
    for (const QString &name : folder.entryList({QStringLiteral("*.kontur")}, QDir::Files, QDir::Name))
        files.append(folder.filePath(name));
    // The one copy of versions before per-instance copies.
    const QString legacy = recoveryPath();
    if (QFileInfo::exists(legacy))
        files.append(legacy);
    return files;
}

void FileController::findOrphans()
{
    const QStringList before = m_orphans;
    for (const QString &file : recoveryFiles()) {
        if (file == m_ownRecovery || m_orphanLocks.count(file) > 0)
            continue;
        auto lock = std::make_unique<QLockFile>(file + QStringLiteral(".lock"));
        // Stale only when its process is gone (not by age: a live instance keeps it for days).
        lock->setStaleLockTime(0);
        if (!lock->tryLock(0))
            continue; // a running instance's copy
        m_orphans.append(file);
        m_orphanLocks.emplace(file, std::move(lock));
    }
    if (m_orphans != before)
        Q_EMIT recoveryChanged();
}

void FileController::setAutosaveSeconds(int seconds)
{
    seconds = std::clamp(seconds, kMinAutosaveSeconds, kMaxAutosaveSeconds);
    if (seconds == m_autosaveSeconds)
        return;
    m_autosaveSeconds = seconds;
    QSettings().setValue(QStringLiteral("autosaveSeconds"), seconds);
    updateTimer();
    Q_EMIT autosaveSecondsChanged();
}

void FileController::updateTimer()
{
    m_autosave.start(m_autosaveSeconds * 1000);
}

void FileController::setFile(const QUrl &file)
{
    if (file == m_file)
        return;
    m_file = file;
    Q_EMIT fileChanged();
}

void FileController::addRecent(const QString &path)
{
    const QString absolute = QFileInfo(path).absoluteFilePath();
    m_recent.removeAll(absolute);
    m_recent.prepend(absolute);
    while (m_recent.size() > kRecentCount)
        m_recent.removeLast();
    QSettings().setValue(QStringLiteral("recentFiles"), m_recent);
    Q_EMIT recentFilesChanged();
}

void FileController::readError(const QString &path, const QVariant &detail)
{
    if (m_editor)
        m_editor->showMessage(Message::FileReadError, {QFileInfo(path).fileName(), detail});
}

QString FileController::photoPath() const
{
    return m_editor ? m_editor->document()->background().file : QString();
}

QUrl FileController::startFolder() const
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

QUrl FileController::suggestedFile(const QString &extension) const
{
    // An unsaved document traced from a photo is named after the photo.
    const QString photo = photoPath();
    const QUrl named = m_file.isEmpty() && !photo.isEmpty() ? QUrl::fromLocalFile(photo) : m_file;
    return QUrl::fromLocalFile(
        QDir(startFolder().toLocalFile())
            .filePath(suggestedFileName(named, extension, QCoreApplication::translate("kontur", "Untitled"))));
}

void FileController::rememberFolder(const QUrl &file)
{
    const QString path = localPath(file);
    if (!path.isEmpty())
        m_lastFolder = QFileInfo(path).absolutePath();
}

QString FileController::writePath(const QUrl &file, const QString &extension)
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

void FileController::newDocument()
{
    if (!m_editor)
        return;
    m_editor->replaceDocument({}, Background{}, QStringLiteral("px"), false);
    m_unitlessRead.reset();
    setFile({});
    discardOwnRecovery();
}

bool FileController::open(const QUrl &file)
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

bool FileController::save()
{
    if (m_file.isEmpty())
        return false;
    return saveAs(m_file);
}

bool FileController::saveAs(const QUrl &file)
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
    discardOwnRecovery();
    m_editor->showMessage(Message::FileSaved, {QFileInfo(path).fileName()});
    return true;
}

QString FileController::unitlessUnits(const QString &suffix)
{
    const QString units = QSettings().value(QStringLiteral("unitlessUnits/") + suffix).toString();
    return units.isEmpty() ? QStringLiteral("px") : units;
}

bool FileController::needsUnits(const QUrl &file) const
{
    const QString path = localPath(file);
    if (suffixOf(path) != QLatin1String("dxf") ||
        QSettings().contains(QStringLiteral("unitlessUnits/") + suffixOf(path)))
        return false;
    const auto dxf = io::readDxf(path);
    return dxf.ok() && !dxf->declaredUnits;
}

void FileController::rememberUnits(const QUrl &file, const QString &units)
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

void FileController::setDxfUnitlessUnits(const QString &units)
{
    rememberUnits(QUrl::fromLocalFile(QStringLiteral("file.dxf")), units);
}

void FileController::changeUnitlessUnits(const QString &units)
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

static_assert(io::kSkippedKinds == Message::SkippedOther + 1, "the message names every skipped kind");

bool FileController::readCurves(const QString &path, int kind, std::vector<Curve> &out, QVariant &error, QString *units,
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

bool FileController::importFile(const QUrl &file, int kind)
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

void FileController::reportRead(const QString &path, int count, const QVariantList &skipped, const QString &assumed,
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

bool FileController::reportWritten(const QString &path, const io::Result<io::Ok> &written)
{
    if (!written.ok()) {
        m_editor->showMessage(Message::FileWriteError, {QFileInfo(path).fileName(), errorDetail(written.error())});
        return false;
    }
    m_editor->showMessage(Message::FileSaved, {QFileInfo(path).fileName()});
    return true;
}

std::optional<std::vector<io::DrawnCurve>> FileController::curvesToExport(const QString &path)
{
    m_editor->document()->settleAllowances();
    auto curves = io::curvesToExport(toDocumentData(*m_editor->document()).curves);
    if (!curves) {
        m_editor->showMessage(Message::FileWriteError, {QFileInfo(path).fileName(), errorDetail(curves.error())});
        return std::nullopt;
    }
    return std::move(curves).value();
}

bool FileController::exportSvg(const QUrl &file)
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

bool FileController::exportDxf(const QUrl &file, bool polylines)
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

std::optional<std::vector<io::AamaPiece>> FileController::piecesToExport(const QString &name)
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

bool FileController::hasPieces()
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

bool FileController::exportAamaDxf(const QUrl &file)
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
        m_editor->showMessage(Message::PiecesWithoutGrainline, {QFileInfo(path).fileName(),
                                                                names.join(QStringLiteral(", ")),
                                                                static_cast<int>(bare.size())});
    }
    return true;
}

bool FileController::exportCsv(const QUrl &file)
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

QString FileController::filePatterns(bool documents) const
{
    return io::filePatterns(documents);
}

bool FileController::appendPoints(const QUrl &file)
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

bool FileController::exportPng(QObject *canvas, const QUrl &file, double scale, bool wholeDocument)
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
    const QPointer<FileController> self(this);
    return source->makePicture(size.toSize(), wholeDocument, [self, path](const QImage &image) {
        if (self)
            (void)self->writePng(image, path);
    });
}

bool FileController::writePng(const QImage &image, const QString &path)
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

bool FileController::autosaveNow()
{
    if (!m_editor || !m_editor->isModified())
        return false;
    QDir().mkpath(recoveryFolder());
    if (!m_ownLock) {
        auto lock = std::make_unique<QLockFile>(m_ownRecovery + QStringLiteral(".lock"));
        lock->setStaleLockTime(0);
        if (!lock->tryLock(0))
            return false;
        m_ownLock = std::move(lock);
    }
    return io::saveDocument(m_ownRecovery, toDocumentData(*m_editor->document())).ok();
}

bool FileController::recover()
{
    if (!m_editor || !hasRecovery())
        return false;
    const QString orphan = m_orphans.front();
    const auto data = io::openDocument(orphan);
    if (!data.ok()) {
        readError(orphan, errorDetail(data.error()));
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
    // The work is this instance's now: in its own copy before the orphan goes.
    if (autosaveNow())
        discardRecovery();
    return true;
}

void FileController::discardRecovery()
{
    if (!hasRecovery())
        return;
    const QString orphan = m_orphans.takeFirst();
    QFile::remove(orphan);
    m_orphanLocks.erase(orphan); // unlocks and removes the lock file
    Q_EMIT recoveryChanged();
}

void FileController::discardOwnRecovery()
{
    QFile::remove(m_ownRecovery);
}

void FileController::closing()
{
    m_autosave.stop();
    discardOwnRecovery();
    m_ownLock.reset();
    m_orphanLocks.clear(); // not answered: offered again next time
    if (!m_orphans.isEmpty()) {
        m_orphans.clear();
        Q_EMIT recoveryChanged();
    }
}

} // namespace kontur
