// Exporter: the document's curves written for other programs — SVG, DXF (exact splines or
// polylines), AAMA DXF pieces, the selected curve's points as CSV or appended to a points text, and
// a PNG picture of the canvas. It asks DocumentFiles (`files`) where to write, so that every export
// starts in, and leaves behind, the folder the other file dialogs use; it reports on the
// EditController's message line. Without an editor or `files` nothing is written.
#pragma once

#include "io/drawncurve.h"
#include "io/dxf.h"
#include "io/error.h"
#include "models/controllers/documentfiles.h"
#include "models/controllers/editcontroller.h"

#include <QObject>
#include <QPointer>
#include <QUrl>
#include <QtQml/qqmlregistration.h>

#include <optional>
#include <vector>

class QImage;

namespace kontur {

// Not final: QML (Qt 6.4) derives from registered types.
class Exporter : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(kontur::EditController *editor READ editor WRITE setEditor NOTIFY editorChanged)
    // Where the exports are written (DocumentFiles::writePath) and which folder comes next.
    Q_PROPERTY(kontur::DocumentFiles *files READ files WRITE setFiles NOTIFY filesChanged)

public:
    explicit Exporter(QObject *parent = nullptr);

    [[nodiscard]] EditController *editor() const { return m_editor; }
    void setEditor(EditController *editor);
    [[nodiscard]] DocumentFiles *files() const { return m_files; }
    void setFiles(DocumentFiles *files);

    // Every export writes where DocumentFiles::writePath says (savepath.h): the format's extension
    // appended to a name without it, an absolute path typed in the dialog taken as it is.
    // All visible curves as SVG; the selected curve's points as CSV; the selected curve appended as a
    // record to a points text file (never truncating it, seed T09).
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
    // A PNG picture of `canvas` at `scale` times its size (".png" added when the name has no such
    // suffix), of the whole document when `wholeDocument` (the view is put back afterwards). The
    // grab finishes a frame later; then the file is written and Saved or FileWriteError is shown.
    // False when no grab could be started (no canvas, an empty size, a hidden window).
    Q_INVOKABLE bool exportPng(QObject *canvas, const QUrl &file, double scale = 1.0, bool wholeDocument = false);

Q_SIGNALS:
    void editorChanged();
    void filesChanged();

private:
    // The path to write (DocumentFiles::writePath); empty without `files` or when none is named.
    QString writePath(const QUrl &file, const QString &extension);
    // Saved, or FileWriteError with the writer's reason, on the message line; whether it was written.
    bool reportWritten(const QString &path, const io::Result<io::Ok> &written);
    // The curves the SVG and DXF exports write (io::curvesToExport, the rule kontur-cli follows too);
    // nothing, with the reason on the message line, when one of them does not draw.
    std::optional<std::vector<io::DrawnCurve>> curvesToExport(const QString &path);
    // The pieces exportAamaDxf writes; nothing, with the reason on the message line (FileWriteError
    // naming `name`, or NoPieces), when a curve does not draw or there is no piece.
    std::optional<std::vector<io::AamaPiece>> piecesToExport(const QString &name);
    // Writes `image` to `path` as PNG through a temporary file and reports it.
    bool writePng(const QImage &image, const QString &path);

    QPointer<EditController> m_editor;
    QPointer<DocumentFiles> m_files;
};

} // namespace kontur
