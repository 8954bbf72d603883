// DocumentFiles: the document's file — new, open, save, save as and import, the units a DXF that
// names none is read in, and the folder and name every file dialog starts from. Errors come as
// messages on the EditController; a failed read changes nothing, a failed write leaves the old file
// intact. The exports (Exporter), the recovery copy (Recovery) and the recent files (RecentFiles)
// are objects of their own; Exporter asks this one where to write (writePath), Recovery has it open
// a recovered copy (openRecovered) and drops its copy when the unsaved work is gone.
#pragma once

#include "models/controllers/editcontroller.h"
#include "models/controllers/recentfiles.h"

#include <QObject>
#include <QPointer>
#include <QUrl>
#include <QtQml/qqmlregistration.h>

#include <optional>
#include <vector>

namespace kontur {

// Not final: QML (Qt 6.4) derives from registered types.
class DocumentFiles : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(kontur::EditController *editor READ editor WRITE setEditor NOTIFY editorChanged)
    // Where a file opened, imported or saved is added (none: nothing is kept).
    Q_PROPERTY(kontur::RecentFiles *recent READ recent WRITE setRecent NOTIFY recentChanged)
    Q_PROPERTY(QUrl fileUrl READ fileUrl NOTIFY fileChanged)
    Q_PROPERTY(QString displayName READ displayName NOTIFY fileChanged)
    // The units a DXF that names none is read in: "mm", "cm", "in" or "px" (px until the user chose),
    // kept in the settings (unitlessUnits/dxf); the next import uses them.
    Q_PROPERTY(QString dxfUnitlessUnits READ dxfUnitlessUnits WRITE setDxfUnitlessUnits NOTIFY dxfUnitlessUnitsChanged)

public:
    explicit DocumentFiles(QObject *parent = nullptr);
    ~DocumentFiles() override;
    Q_DISABLE_COPY_MOVE(DocumentFiles)

    [[nodiscard]] EditController *editor() const { return m_editor; }
    void setEditor(EditController *editor);
    [[nodiscard]] RecentFiles *recent() const { return m_recent; }
    void setRecent(RecentFiles *recent);
    [[nodiscard]] QUrl fileUrl() const { return m_file; }
    [[nodiscard]] QString displayName() const;
    [[nodiscard]] QString dxfUnitlessUnits() const { return unitlessUnits(QStringLiteral("dxf")); }
    // Units that are not one of the four are ignored.
    void setDxfUnitlessUnits(const QString &units);

    // The folder every file dialog starts in: the document's, else the one a file was last opened,
    // imported, saved or exported in (the picture dialog's too, by rememberFolder), else the
    // background photo's, else the documents folder.
    Q_INVOKABLE QUrl startFolder() const;
    // The file a save dialog offers first for a file with `extension` ("dxf", no dot): the
    // document's name with that extension (while unsaved, the background photo's name, else
    // "Untitled" translated) in startFolder(). Every save dialog starts from it anew, so that a second
    // export never keeps the first one's name.
    Q_INVOKABLE QUrl suggestedFile(const QString &extension) const;
    // A file chosen in a dialog that DocumentFiles does not read itself (the background picture):
    // its folder is where the next dialog starts.
    Q_INVOKABLE void rememberFolder(const QUrl &file);
    // Saves and exports write where savePathFor (savepath.h) says: the format's extension appended
    // to a name without it, an absolute path typed in the dialog taken as it is. The path to write
    // for a save dialog's answer; empty, with the reason on the message line, when it names no file.
    // A written path's folder is the next suggestion's.
    QString writePath(const QUrl &file, const QString &extension);

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
    // A recovery copy (Recovery::recover) as the document: unsaved, with no file, the curves that
    // cannot be read left out. False, with the reason on the message line, when it cannot be read.
    bool openRecovered(const QString &path);
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
    // "*.kontur *.pdf" (the formats Open reads as a document) or the others' patterns, from the one
    // table of formats (io/formats.h): the file dialogs' filters.
    Q_INVOKABLE QString filePatterns(bool documents) const;

Q_SIGNALS:
    void editorChanged();
    void recentChanged();
    void fileChanged();
    void dxfUnitlessUnitsChanged();
    // The unsaved changes are gone: saved (saveAs) or given up for a new document, so that no copy
    // of them is needed any more (Recovery removes its own).
    void unsavedWorkGone();

private:
    void setFile(const QUrl &file);
    void addRecent(const QString &path);
    // The background photo's path, empty without one.
    [[nodiscard]] QString photoPath() const;
    void readError(const QString &path, const QVariant &detail);
    // Reads the curves of any supported file without touching the document. `units`, when given:
    // the units to convert a DXF's lengths into (empty: keep the file's), and then the curves' units.
    // `skipped`, when given: what the file held that is not drawn (the counts in the order of io::SkippedKind),
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
    QPointer<RecentFiles> m_recent;
    QUrl m_file;
    QString m_lastFolder; // where the last file was opened, saved or exported (for startFolder)
};

} // namespace kontur
