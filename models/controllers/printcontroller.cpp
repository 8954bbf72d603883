// PrintController: the print dialog's choices and the pattern PDF (see printcontroller.h).
#include "models/controllers/printcontroller.h"

#include "models/controllers/savepath.h"
#include "models/document/documentio.h"
#include "models/text/errortext.h"
#include "models/text/numbers.h"
#include "print/patternpdf.h"

#include <QFileInfo>
#include <QSettings>

#include <algorithm>
#include <cmath>

namespace kontur {

namespace {

geo::TilingOptions tilingOptions(PrintController::Paper paper, PrintController::Orientation orientation, double overlap)
{
    geo::TilingOptions o;
    o.paper = paper == PrintController::Letter ? geo::kPaperLetter : geo::kPaperA4;
    o.orientation = orientation == PrintController::Portrait    ? geo::PageOrientation::Portrait
                    : orientation == PrintController::Landscape ? geo::PageOrientation::Landscape
                                                                : geo::PageOrientation::Auto;
    o.overlap = overlap;
    return o;
}

// Why a print plan failed, as a message made in the current language when shown.
Message problemOf(const io::Error &error, int maxPages)
{
    switch (error.code) {
    case io::ErrorCode::NoPaths:
        return Message::NothingToPrint;
    case io::ErrorCode::InvalidValue:
        return {Message::TooManyPages, {maxPages}};
    default:
        return {Message::CannotPrint, {errorDetail(error)}};
    }
}

} // namespace

PrintController::PrintController(QObject *parent)
    : QObject(parent)
{
    QSettings settings;
    m_paper = settings.value(QStringLiteral("print/paper")).toString() == QLatin1String("letter") ? Letter : A4;
    m_overlap = std::clamp(settings.value(QStringLiteral("print/overlap"), 10.0).toDouble(), 0.0, maxOverlap());
}

PrintController::~PrintController() = default;

void PrintController::setEditor(EditController *editor)
{
    if (editor == m_editor)
        return;
    m_editor = editor;
    Q_EMIT editorChanged();
    refresh();
}

void PrintController::setPaper(Paper paper)
{
    if (paper == m_paper)
        return;
    m_paper = paper;
    saveSettings();
    Q_EMIT settingsChanged();
    refresh();
}

void PrintController::setOrientation(Orientation orientation)
{
    if (orientation == m_orientation)
        return;
    m_orientation = orientation;
    Q_EMIT settingsChanged();
    refresh();
}

void PrintController::setOverlap(double mm)
{
    if (!std::isfinite(mm))
        return;
    mm = std::clamp(mm, 0.0, maxOverlap());
    if (mm == m_overlap)
        return;
    m_overlap = mm;
    saveSettings();
    Q_EMIT settingsChanged();
    refresh();
}

void PrintController::saveSettings() const
{
    QSettings settings;
    settings.setValue(QStringLiteral("print/paper"),
                      m_paper == Letter ? QStringLiteral("letter") : QStringLiteral("a4"));
    settings.setValue(QStringLiteral("print/overlap"), m_overlap);
}

void PrintController::refresh()
{
    int pages = 0, rows = 0, columns = 0;
    bool landscape = false, pixels = false;
    Message problem;
    if (m_editor) {
        const io::DocumentData doc = toDocumentData(*m_editor->document());
        pixels = doc.units == QLatin1String("px");
        const geo::TilingOptions options = tilingOptions(m_paper, m_orientation, m_overlap);
        const auto plan = planPrint(doc, options);
        if (plan) {
            pages = plan->tiling.pageCount();
            rows = plan->tiling.rows;
            columns = plan->tiling.columns;
            landscape = plan->tiling.landscape;
        } else {
            problem = problemOf(plan.error(), options.maxPages);
        }
    }
    if (pages == m_pageCount && rows == m_rows && columns == m_columns && landscape == m_landscape &&
        pixels == m_pixelUnits && problem == m_problem.message())
        return;
    m_pageCount = pages;
    m_rows = rows;
    m_columns = columns;
    m_landscape = landscape;
    m_pixelUnits = pixels;
    if (problem != m_problem.message())
        m_problem.show(std::move(problem)); // announces planChanged
    else
        Q_EMIT planChanged();
}

bool PrintController::print(const QUrl &file)
{
    if (!m_editor)
        return false;
    // As every save: the dialog's answer normalised and ".pdf" appended when missing (savepath.h).
    const QString path = savePathFor(file, QStringLiteral("pdf"));
    if (path.isEmpty()) {
        m_editor->showMessage(Message::FileWriteError, {file.fileName(), QVariant::fromValue(Message(Message::NoFileName))});
        return false;
    }
    const QString name = QFileInfo(path).fileName();
    m_editor->document()->settleAllowances(); // what is printed is exact, even right after a drag
    const auto written =
        writePatternPdf(path, toDocumentData(*m_editor->document()), tilingOptions(m_paper, m_orientation, m_overlap),
                        QFileInfo(path).completeBaseName());
    if (!written) {
        const QVariant detail = written.error().code == io::ErrorCode::CannotWrite
                                    ? QVariant(errorDetail(written.error()))
                                    : QVariant::fromValue(problemOf(written.error(), geo::TilingOptions{}.maxPages));
        m_editor->showMessage(Message::FileWriteError, {name, detail});
        return false;
    }
    m_editor->showMessage(Message::FileSaved, {name});
    return true;
}

} // namespace kontur
