// FileController: keeping work — open and save documents, import and export curves and pictures,
// the recent files, and the recovery copy written while there are unsaved changes. Errors come as
// messages on the EditController; a failed read changes nothing, a failed write leaves the old file
// intact.
#pragma once

#include "io/drawncurve.h"
#include "io/dxf.h"
#include "io/error.h"
#include "models/controllers/editcontroller.h"

#include <QLockFile>
#include <QObject>
#include <QPointer>
#include <QTimer>
#include <QUrl>
#include <QtQml/qqmlregistration.h>

#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace kontur {

// Not final: QML (Qt 6.4) derives from registered types.
class FileController : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(kontur::EditController *editor READ editor WRITE setEditor NOTIFY editorChanged)
    Q_PROPERTY(QUrl fileUrl READ fileUrl NOTIFY fileChanged)
    Q_PROPERTY(QString displayName READ displayName NOTIFY fileChanged)
    Q_PROPERTY(QStringList recentFiles READ recentFiles NOTIFY recentFilesChanged)
    // A recovery copy of an instance that ended without closing (a crash) is waiting to be offered.
    Q_PROPERTY(bool hasRecovery READ hasRecovery NOTIFY recoveryChanged)
    Q_PROPERTY(int autosaveSeconds READ autosaveSeconds WRITE setAutosaveSeconds NOTIFY autosaveSecondsChanged)
    // The units a DXF that names none is read in: "mm", "cm", "in" or "px" (px until the user chose),
    // kept in the settings (unitlessUnits/dxf) as autosaveSeconds is; the next import uses them.
    Q_PROPERTY(QString dxfUnitlessUnits READ dxfUnitlessUnits WRITE setDxfUnitlessUnits NOTIFY dxfUnitlessUnitsChanged)

public:
    explicit FileController(QObject *parent = nullptr);
    ~FileController() override;
    Q_DISABLE_COPY_MOVE(FileController)

    [[nodiscard]] EditController *editor() const { return m_editor; }
    void setEditor(EditController *editor);
    [[nodiscard]] QUrl fileUrl() const { return m_file; }
    [[nodiscard]] QString displayName() const;
    [[nodiscard]] QStringList recentFiles() const { return m_recent; }
    [[nodiscard]] bool hasRecovery() const { return !m_orphans.isEmpty(); }
    [[nodiscard]] int autosaveSeconds() const { return m_autosaveSeconds; }
    void setAutosaveSeconds(int seconds);
    [[nodiscard]] QString dxfUnitlessUnits() const { return unitlessUnits(QStringLiteral("dxf")); }
    // Units that are not one of the four are ignored.
    void setDxfUnitlessUnits(const QString &units);
    // The range autosaveSeconds is kept in, and its default.
    static constexpr int kMinAutosaveSeconds = 1, kMaxAutosaveSeconds = 3600, kDefaultAutosaveSeconds = 30;
    // The autosave interval from a setting's text (kontur.conf or KONTUR_AUTOSAVE_SECONDS): a whole
    // number in range as it is; a number out of range clamped; anything else the default. `note`
    // gets an English sentence saying what was wrong and what is used (empty when nothing was).
    [[nodiscard]] static int autosaveSecondsFrom(const QString &text, const QString &source, QString &note);
    // Why the autosave setting was not used as it was given (empty when it was); also on stderr.
    [[nodiscard]] QString autosaveNote() const { return m_autosaveNote; }

    // Recovery copies: one per running instance, <folder>/<id>.kontur, beside a lock file
    // (QLockFile, <id>.kontur.lock) held while the instance runs. A copy whose lock nobody holds is
    // an orphan of an instance that crashed; each one is offered (and its lock taken, so that no
    // other instance offers it too). A live instance's copy is never offered or removed.
    [[nodiscard]] static QString recoveryFolder();
    // The single recovery copy of versions before per-instance copies (offered as an orphan).
    [[nodiscard]] static QString recoveryPath();
    // Every recovery copy in the folder, live or not (also the single recovery.kontur of older versions).
    [[nodiscard]] static QStringList recoveryFiles();
    // This instance's own copy (written by autosaveNow).
    [[nodiscard]] QString ownRecoveryPath() const { return m_ownRecovery; }
    // The orphaned copies taken to be offered, the first one next.
    [[nodiscard]] QStringList orphanedRecoveries() const { return m_orphans; }

    // The folder every file dialog starts in: the document's, else the one a file was last opened,
    // imported, saved or exported in (the picture dialog's too, by rememberFolder), else the
    // background photo's, else the documents folder.
    Q_INVOKABLE QUrl startFolder() const;
    // The file a save dialog offers first for a file with `extension` ("dxf", no dot): the
    // document's name with that extension (while unsaved, the background photo's name, else
    // "Untitled" translated) in startFolder(). Every save dialog starts from it anew, so that a second
    // export never keeps the first one's name.
    Q_INVOKABLE QUrl suggestedFile(const QString &extension) const;
    // A file chosen in a dialog that FileController does not read itself (the background picture):
    // its folder is where the next dialog starts.
    Q_INVOKABLE void rememberFolder(const QUrl &file);

    // A new, empty document (the UI asks about unsaved changes first).
    Q_INVOKABLE void newDocument();
    // Opens a .kontur document or a pattern PDF Kontur printed (unsaved: Save asks for a .kontur
    // file), or imports any other supported file into a new document.
    Q_INVOKABLE bool open(const QUrl &file);
    // Saves to the current file; false when there is none yet (the UI then asks for one).
    Q_INVOKABLE bool save();
    Q_INVOKABLE bool saveAs(const QUrl &file);
    // Adds the curves of a points text (.txt), CSV (.csv, one curve of `kind`), SVG, DXF, .kontur or
    // printed PDF file to the document as one undo step. Hand-written point lists become curves of
    // `kind`; a DXF's curves are converted to the document's units when both are lengths (mm, cm, in, pt).
    Q_INVOKABLE bool importFile(const QUrl &file, int kind);
    // Whether the UI must ask which units `file` is in before it is opened or imported: a DXF that
    // names none ($INSUNITS), when no choice for DXF files was remembered yet.
    Q_INVOKABLE bool needsUnits(const QUrl &file) const;
    // Remembers (QSettings, per file kind: the file's extension) the units the user chose for files
    // of `file`'s kind that name none: "mm", "cm", "in" or "px".
    Q_INVOKABLE void rememberUnits(const QUrl &file, const QString &units);
    // The banner's offer after a DXF was read in the remembered units (Message::FileImportedUnitless):
    // remembers `units` and, while the document is as that read left it (nothing done or undone
    // since), reads the file again in them: the import undone and done again, or the file opened
    // again. Otherwise the new units apply from the next import on, and the message says so.
    Q_INVOKABLE void changeUnitlessUnits(const QString &units);
    // Saves and exports write where savePathFor (savepath.h) says: the format's extension appended
    // to a name without it, an absolute path typed in the dialog taken as it is.
    // Exports: all visible curves as SVG; the selected curve's points as CSV; the selected curve
    // appended as a record to a points text file (never truncating it, seed T09).
    Q_INVOKABLE bool exportSvg(const QUrl &file);
    // All visible curves as DXF in the document's units: exact SPLINE entities, or (`polylines`)
    // LWPOLYLINE entities within 0.05 mm (for plotters and pattern software without splines).
    Q_INVOKABLE bool exportDxf(const QUrl &file, bool polylines);
    // The document's pattern pieces as ASTM D6673 (AAMA) DXF for pattern software and cutters: each
    // visible closed curve a block, its seam allowance the cut line, the curve the sew line
    // (io::aamaPieces and io::writeAamaDxf, as kontur-cli convert --aama), as polylines within
    // 0.05 mm as the standard's readers expect. Without a piece nothing is written (NoPieces).
    Q_INVOKABLE bool exportAamaDxf(const QUrl &file);
    // Whether the document has a piece for exportAamaDxf; when it has none, NoPieces is shown, so
    // that the UI asks for no file name.
    Q_INVOKABLE bool hasPieces();
    Q_INVOKABLE bool exportCsv(const QUrl &file);
    Q_INVOKABLE bool appendPoints(const QUrl &file);
    // "*.kontur *.pdf" (the formats Open reads as a document) or the others' patterns, from the one
    // table of formats (io/formats.h): the file dialogs' filters.
    Q_INVOKABLE QString filePatterns(bool documents) const;
    // A PNG picture of `canvas` at `scale` times its size (".png" added when the name has no such
    // suffix), of the whole document when `wholeDocument` (the view is put back afterwards). The
    // grab finishes a frame later; then the file is written and Saved or FileWriteError is shown.
    // False when no grab could be started (no canvas, an empty size, a hidden window).
    Q_INVOKABLE bool exportPng(QObject *canvas, const QUrl &file, double scale = 1.0, bool wholeDocument = false);
    // The first orphaned recovery copy: open it (unsaved; it becomes this instance's own copy) or
    // throw it away. The others stay offered (hasRecovery).
    Q_INVOKABLE bool recover();
    Q_INVOKABLE void discardRecovery();
    // Writes the recovery copy now when there are unsaved changes (the timer calls this).
    Q_INVOKABLE bool autosaveNow();
    // Called when the application closes normally: its own recovery copy is removed; orphans not
    // yet answered stay for the next start.
    Q_INVOKABLE void closing();

Q_SIGNALS:
    void editorChanged();
    void fileChanged();
    void recentFilesChanged();
    void recoveryChanged();
    void autosaveSecondsChanged();
    void dxfUnitlessUnitsChanged();

private:
    // Saved, or FileWriteError with the writer's reason, on the message line; whether it was written.
    bool reportWritten(const QString &path, const io::Result<io::Ok> &written);
    // The curves the SVG and DXF exports write (io::curvesToExport, the rule kontur-cli follows too);
    // nothing, with the reason on the message line, when one of them does not draw.
    std::optional<std::vector<io::DrawnCurve>> curvesToExport(const QString &path);
    // The pieces exportAamaDxf writes; nothing, with the reason on the message line (FileWriteError
    // naming `name`, or NoPieces), when a curve does not draw or there is no piece.
    std::optional<std::vector<io::AamaPiece>> piecesToExport(const QString &name);
    void setFile(const QUrl &file);
    // The background photo's path, empty without one.
    [[nodiscard]] QString photoPath() const;
    // The path to write for a save dialog's answer (savePathFor); empty, with the reason on the
    // message line, when it names no file. A written path's folder is the next suggestion's.
    QString writePath(const QUrl &file, const QString &extension);
    void addRecent(const QString &path);
    void readError(const QString &path, const QVariant &detail);
    // Reads the curves of any supported file without touching the document. `units`, when given:
    // the units to convert a DXF's lengths into (empty: keep the file's), and then the curves' units.
    // `skipped`, when given: what the file held that is not drawn (the counts of Message::SkippedKind),
    // empty when nothing was skipped.
    // `assumed`, when given: the units a file that names none was read in (empty when it names its own).
    bool readCurves(const QString &path, int kind, std::vector<Curve> &out, QVariant &error, QString *units = nullptr,
                    QVariantList *skipped = nullptr, QString *assumed = nullptr) const;
    // Says what a read brought (FileImported, FileImportedSkipped or FileImportedUnitless) and
    // remembers a read in assumed units for changeUnitlessUnits.
    void reportRead(const QString &path, int count, const QVariantList &skipped, const QString &assumed, bool opened,
                    int kind);
    // The units remembered for files of `suffix` that name none ("px" until the user chose).
    static QString unitlessUnits(const QString &suffix);
    void updateTimer();
    // Takes the lock of every recovery copy nobody holds (orphans) into m_orphans.
    void findOrphans();
    // Removes this instance's own copy (the work is saved, or there is none).
    void discardOwnRecovery();
    // Writes `image` to `path` as PNG through a temporary file and reports it.
    bool writePng(const QImage &image, const QString &path);

    // The last file read in units it does not name, and the undo stack's state right after, so that
    // changeUnitlessUnits reads it again only while nothing has been done or undone since.
    struct UnitlessRead
    {
        QString path;
        bool opened = false; // opened as the document, else imported into it
        int kind = 0;        // the kind an import was asked for
        int undoIndex = 0, undoCount = 0;
    };
    std::optional<UnitlessRead> m_unitlessRead;

    QPointer<EditController> m_editor;
    QUrl m_file;
    QStringList m_recent;
    QString m_lastFolder; // where the last file was opened, saved or exported (for startFolder)
    QTimer m_autosave;
    int m_autosaveSeconds = kDefaultAutosaveSeconds;
    QString m_autosaveNote;
    QString m_autosaveGiven; // the bad setting's text, for the message line
    QString m_ownRecovery;
    std::unique_ptr<QLockFile> m_ownLock;
    QStringList m_orphans;
    std::map<QString, std::unique_ptr<QLockFile>> m_orphanLocks;
};

} // namespace kontur
