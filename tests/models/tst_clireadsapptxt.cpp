// kontur-cli's fit, composite and spline read the .txt files the app writes (the File menu's "Append
// to a points file", Exporter::appendPoints): Kontur's curve records, read by the app's own
// reader, not only hand-written lists. The real binary is run on files the app wrote.
#include "../ownfolders.h"
#include "models/controllers/documentfiles.h"
#include "models/controllers/editcontroller.h"
#include "models/controllers/exporter.h"
#include "models/controllers/placement.h"
#include "models/controllers/recovery.h"
#include "models/document/document.h"
#include "models/document/selection.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

using kontur::CurveKind;
using kontur::DocumentFiles;
using kontur::EditController;
using kontur::Exporter;
using kontur::geo::Point;

namespace {

struct Run
{
    QJsonObject json;
    QString err;
    int code = -1;
};

Run runCli(const QStringList &args)
{
    QProcess p;
    p.start(QStringLiteral(KONTUR_CLI), args);
    Run run;
    if (!p.waitForFinished(60000))
        return run;
    run.code = p.exitCode();
    run.json = QJsonDocument::fromJson(p.readAllStandardOutput()).object();
    run.err = QString::fromUtf8(p.readAllStandardError());
    return run;
}

Point pointOf(const QJsonValue &xy)
{
    return {xy.toArray().at(0).toDouble(), xy.toArray().at(1).toDouble()};
}

QVariantList rowsOf(const std::vector<Point> &points)
{
    QVariantList rows;
    for (const Point &p : points)
        rows << QVariant(QVariantList{p.x(), p.y()});
    return rows;
}

} // namespace

class TestCliReadsAppTxt final : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    EditController m_editor;
    DocumentFiles m_files;
    Exporter m_exporter;

    // A curve of `kind` through (or by) `points`, made as the panel's table makes one, selected and
    // appended to `file` by the app.
    bool appendCurve(CurveKind kind, const std::vector<Point> &points, const QString &file)
    {
        if (!m_editor.placement()->createFromCoordinates(static_cast<int>(kind), rowsOf(points)))
            return false;
        m_editor.selection()->select(m_editor.document()->idAt(m_editor.document()->curveCount() - 1));
        return m_exporter.appendPoints(QUrl::fromLocalFile(m_dir.filePath(file)));
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(kontur::test::inOwnFolders(kontur::Recovery::recoveryPath()));
        QVERIFY(m_dir.isValid());
        m_files.setEditor(&m_editor);
        m_exporter.setEditor(&m_editor);
        m_exporter.setFiles(&m_files);
    }

    // fit --method interpolate through a Bézier curve's four control points, as the app wrote them:
    // the fitted curve starts and ends at the first and the last.
    void fitReadsABezierRecord()
    {
        const std::vector<Point> control{{-200, -100}, {-100, 150}, {100, 150}, {200, -100}};
        QVERIFY(appendCurve(CurveKind::Bezier, control, QStringLiteral("bezier.txt")));
        const Run run = runCli({QStringLiteral("fit"), QStringLiteral("--method"), QStringLiteral("interpolate"),
                                QStringLiteral("--in"), m_dir.filePath(QStringLiteral("bezier.txt"))});
        QVERIFY2(run.code == 0, qPrintable(run.err));
        const QJsonArray fitted = run.json.value(QStringLiteral("control_points")).toArray();
        QCOMPARE(fitted.size(), 4);
        // The solve interpolates to rounding (a few units in the last place of 200).
        QVERIFY((pointOf(fitted.at(0)) - control.front()).norm() < 1e-9);
        QVERIFY((pointOf(fitted.at(3)) - control.back()).norm() < 1e-9);
    }

    // composite --in a composite curve the app wrote (its control vector in the file): the knots are
    // read, and the command's curve passes through them.
    void compositeReadsACompositeRecord()
    {
        const std::vector<Point> knots{{0, 0}, {50, 80}, {120, 10}, {200, 60}};
        QVERIFY(appendCurve(CurveKind::Composite, knots, QStringLiteral("composite.txt")));
        const Run run = runCli(
            {QStringLiteral("composite"), QStringLiteral("--in"), m_dir.filePath(QStringLiteral("composite.txt"))});
        QVERIFY2(run.code == 0, qPrintable(run.err));
        const QJsonArray control = run.json.value(QStringLiteral("control_points")).toArray();
        QCOMPARE(control.size(), qsizetype(3 * knots.size() - 2));
        for (std::size_t k = 0; k < knots.size(); ++k)
            QCOMPARE(pointOf(control.at(qsizetype(3 * k))), knots[k]);
    }

    // spline --kind natural --in a file of two records the app appended: the first record's points are
    // read (the segments run through them), and stderr says that the file holds more.
    void splineReadsTheFirstOfTwoRecords()
    {
        const std::vector<Point> through{{0, 0}, {40, 60}, {90, -20}, {150, 30}, {210, 0}};
        QVERIFY(appendCurve(CurveKind::NaturalSpline, through, QStringLiteral("two.txt")));
        QVERIFY(appendCurve(CurveKind::Composite, {{0, 0}, {10, 10}}, QStringLiteral("two.txt")));
        const Run run = runCli({QStringLiteral("spline"), QStringLiteral("--kind"), QStringLiteral("natural"),
                                QStringLiteral("--in"), m_dir.filePath(QStringLiteral("two.txt"))});
        QVERIFY2(run.code == 0, qPrintable(run.err));
        const QJsonArray segments = run.json.value(QStringLiteral("segments")).toArray();
        QCOMPARE(segments.size(), qsizetype(through.size() - 1));
        for (qsizetype s = 0; s < segments.size(); ++s) {
            const QJsonArray b = segments.at(s).toArray();
            QCOMPARE(pointOf(b.at(0)), through[std::size_t(s)]);
            QCOMPARE(pointOf(b.at(3)), through[std::size_t(s) + 1]);
        }
        QVERIFY2(run.err.contains(QStringLiteral("several curves in the file (2)")), qPrintable(run.err));
    }

    // A hand-written list is read as before, and a record the app's reader refuses is refused with
    // the reader's message (file and line), not taken as a list of numbers.
    void plainListsAndBadRecords()
    {
        QFile plain(m_dir.filePath(QStringLiteral("plain.txt")));
        QVERIFY(plain.open(QIODevice::WriteOnly));
        plain.write("# a hand-written list\n0 0\n1 2\n3 1\n4 4\n");
        plain.close();
        Run run = runCli({QStringLiteral("fit"), QStringLiteral("--in"), plain.fileName()});
        QVERIFY2(run.code == 0, qPrintable(run.err));
        QCOMPARE(run.json.value(QStringLiteral("params")).toArray().size(), 4);
        QFile bad(m_dir.filePath(QStringLiteral("bad.txt")));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write("curve no-such-kind\n0 0\n1 1\n");
        bad.close();
        run = runCli({QStringLiteral("fit"), QStringLiteral("--in"), bad.fileName()});
        QVERIFY(run.code != 0);
        QVERIFY2(run.err.contains(QStringLiteral("bad.txt")), qPrintable(run.err));
    }
};

QTEST_GUILESS_MAIN(TestCliReadsAppTxt)
#include "tst_clireadsapptxt.moc"
