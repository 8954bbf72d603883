// PrintController: File → Print pattern… (issue 22). Holds the choices of the print dialog (paper,
// orientation, overlap; remembered between sessions), answers what they give (pages, rows, columns,
// the orientation Auto chose) before anything is written, and writes the PDF (models/patternpdf.h).
// The dialog only shows these properties and calls refresh() and print().
#pragma once

#include "models/controllers/editcontroller.h"
#include "models/text/shownmessage.h"

#include <QObject>
#include <QPointer>
#include <QUrl>
#include <QtQml/qqmlregistration.h>

namespace kontur {

// Not final: QML (Qt 6.4) derives from registered types.
class PrintController : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(kontur::EditController *editor READ editor WRITE setEditor NOTIFY editorChanged)
    Q_PROPERTY(Paper paper READ paper WRITE setPaper NOTIFY settingsChanged)
    Q_PROPERTY(Orientation orientation READ orientation WRITE setOrientation NOTIFY settingsChanged)
    Q_PROPERTY(double overlap READ overlap WRITE setOverlap NOTIFY settingsChanged)
    Q_PROPERTY(double maxOverlap READ maxOverlap CONSTANT)
    Q_PROPERTY(bool ready READ ready NOTIFY planChanged)
    Q_PROPERTY(int pageCount READ pageCount NOTIFY planChanged)
    Q_PROPERTY(int pdfPageCount READ pdfPageCount NOTIFY planChanged)
    Q_PROPERTY(int rows READ rows NOTIFY planChanged)
    Q_PROPERTY(int columns READ columns NOTIFY planChanged)
    Q_PROPERTY(bool landscape READ landscape NOTIFY planChanged)
    Q_PROPERTY(bool pixelUnits READ pixelUnits NOTIFY planChanged)
    // Why the document cannot be printed (empty: it can); the dialog shows `problem.text`.
    Q_PROPERTY(kontur::Message problem READ problem NOTIFY planChanged)

public:
    enum Paper { A4, Letter };
    Q_ENUM(Paper)
    enum Orientation { Auto, Portrait, Landscape };
    Q_ENUM(Orientation)

    explicit PrintController(QObject *parent = nullptr);
    ~PrintController() override;
    Q_DISABLE_COPY_MOVE(PrintController)

    [[nodiscard]] EditController *editor() const { return m_editor; }
    void setEditor(EditController *editor);
    [[nodiscard]] Paper paper() const { return m_paper; }
    void setPaper(Paper paper);
    [[nodiscard]] Orientation orientation() const { return m_orientation; }
    void setOrientation(Orientation orientation);
    [[nodiscard]] double overlap() const { return m_overlap; }
    // Clamped to 0 … maxOverlap mm.
    void setOverlap(double mm);
    [[nodiscard]] static double maxOverlap() { return 50.0; }

    // Whether the document can be printed with these choices; the counts are 0 when not.
    [[nodiscard]] bool ready() const { return m_pageCount > 0; }
    // The pages to tape together, and with the first page (test square, overview) the PDF's pages.
    [[nodiscard]] int pageCount() const { return m_pageCount; }
    [[nodiscard]] int pdfPageCount() const { return m_pageCount > 0 ? m_pageCount + 1 : 0; }
    [[nodiscard]] int rows() const { return m_rows; }
    [[nodiscard]] int columns() const { return m_columns; }
    [[nodiscard]] bool landscape() const { return m_landscape; }
    // The document is in px, printed at 96 px per inch.
    [[nodiscard]] bool pixelUnits() const { return m_pixelUnits; }
    // Why the document cannot be printed, or empty; its text is made when read.
    [[nodiscard]] Message problem() const { return m_problem.message(); }

    // The tiling as the options and the document are now (the dialog calls it when it opens).
    Q_INVOKABLE void refresh();
    // Writes the PDF (".pdf" added when the name has none); shows Saved or the write error.
    Q_INVOKABLE bool print(const QUrl &file);

Q_SIGNALS:
    void editorChanged();
    void settingsChanged();
    void planChanged();

private:
    void saveSettings() const;

    QPointer<EditController> m_editor;
    Paper m_paper = A4;
    Orientation m_orientation = Auto;
    double m_overlap = 10.0;
    int m_pageCount = 0, m_rows = 0, m_columns = 0;
    bool m_landscape = false;
    bool m_pixelUnits = false;
    // Announced with the plan, and again after a language switch.
    ShownMessage m_problem{this, [this] { Q_EMIT planChanged(); }};
};

} // namespace kontur
