// Tests of the points text format: hand-written lists in every separator style, Kontur's records,
// several records in one file, a table of malformed inputs with code, line and column, random records
// round-tripping, and appending that never truncates (seed T09).
#include "io/pointstext.h"
#include "iotestutil.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QTest>

#include <chrono>
#include <cmath>
#include <random>
#include <thread>

#ifdef Q_OS_UNIX
#include <csignal>
#include <sys/wait.h>
#include <unistd.h>
#endif

using namespace kontur;
using namespace kontur::io;

class TestPointsText final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void handWritten_data();
    void handWritten();
    void records();
    void composite();
    void malformed_data();
    void malformed();
    void roundTrip_data();
    void roundTrip();
    void appendNeverTruncates();
    void curveFromPointsBuildsComposite();
    void limits();
    void pointLimitCountsEachPointOnce();
    void appendRefusesWhatTheReaderRefuses();
    void appendSurvivesKill();
};

void TestPointsText::handWritten_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<int>("count");
    QTest::addColumn<double>("lastX");
    QTest::addColumn<double>("lastY");
    QTest::addRow("spaces") << QByteArray("0 0\n1 2\n3 4\n") << 3 << 3.0 << 4.0;
    QTest::addRow("semicolons") << QByteArray("0;0\n1 ; 2\n3;4") << 3 << 3.0 << 4.0;
    QTest::addRow("commas") << QByteArray("0,0\n1, 2\n-3.5,4e1\n") << 3 << -3.5 << 40.0;
    QTest::addRow("tabs") << QByteArray("0\t0\n1\t\t2\n") << 2 << 1.0 << 2.0;
    QTest::addRow("comments and blanks") << QByteArray("# points\n\n  1 2  # first\n\n3 4\n#end") << 2 << 3.0 << 4.0;
    QTest::addRow("crlf and bom") << QByteArray("\xEF\xBB\xBF"
                                                "1 2\r\n3 4\r\n")
                                  << 2 << 3.0 << 4.0;
    QTest::addRow("header") << QByteArray("x y\n1 2\n") << 1 << 1.0 << 2.0;
    QTest::addRow("csv header") << QByteArray("X;Y\n1;2\n") << 1 << 1.0 << 2.0;
    QTest::addRow("signs and forms") << QByteArray("+1 -.5\n1e-3 .25\n") << 2 << 0.001 << 0.25;
    QTest::addRow("no final newline") << QByteArray("5 6") << 1 << 5.0 << 6.0;
}

void TestPointsText::handWritten()
{
    QFETCH(QByteArray, text);
    QFETCH(int, count);
    QFETCH(double, lastX);
    QFETCH(double, lastY);
    auto r = parsePointsText(text, QStringLiteral("list.txt"));
    QVERIFY2(r.ok(), qPrintable(r.ok() ? QString() : r.error().toString()));
    QCOMPARE(r->size(), std::size_t(1));
    const TextRecord &rec = r->front();
    QVERIFY(rec.curve.kind.isEmpty());
    QCOMPARE(rec.pointKind, PointKind::Unspecified);
    QCOMPARE(static_cast<int>(rec.curve.points.size()), count);
    QCOMPARE(rec.curve.points.back().x(), lastX);
    QCOMPARE(rec.curve.points.back().y(), lastY);
}

void TestPointsText::records()
{
    const QByteArray text = "0 0\n1 1\n\n"
                            "curve least-squares centripetal\n"
                            "name \"Sleeve \\\"A\\\" #2\"\n"
                            "color \"#A0b0C0\"\n"
                            "points knots\n0 0\n1 2\n2 1\n3 3\n4 0\n"
                            "# control points …\n#   C0 0 0\n"
                            "curve bezier\n"
                            "settings {\"degree\": 3, \"note\": \"a # b\"}\n"
                            "0 0\n1 1\n2 0\n"
                            "curve\n5 5\n6 6\n";
    auto r = parsePointsText(text);
    QVERIFY2(r.ok(), qPrintable(r.ok() ? QString() : r.error().toString()));
    QCOMPARE(r->size(), std::size_t(4));
    QVERIFY((*r)[0].curve.kind.isEmpty());
    QCOMPARE((*r)[0].line, 1);
    const CurveRecord &ls = (*r)[1].curve;
    QCOMPARE(ls.kind, QStringLiteral("least-squares"));
    QCOMPARE(ls.parameterization, QStringLiteral("centripetal"));
    QCOMPARE(ls.name, QStringLiteral("Sleeve \"A\" #2"));
    QCOMPARE(ls.color, QStringLiteral("#a0b0c0"));
    QCOMPARE(ls.points.size(), std::size_t(5));
    QCOMPARE((*r)[1].pointKind, PointKind::Knots);
    QCOMPARE((*r)[1].line, 4);
    QCOMPARE((*r)[2].curve.settings.value(QStringLiteral("degree")).toInt(), 3);
    QCOMPARE((*r)[2].curve.settings.value(QStringLiteral("note")).toString(), QStringLiteral("a # b"));
    QVERIFY((*r)[3].curve.kind.isEmpty());
    QCOMPARE((*r)[3].curve.points.size(), std::size_t(2));
}

void TestPointsText::composite()
{
    // By knots (the default for a composite curve): the seed's construction gives 3n - 2 points.
    auto r = parsePointsText("curve composite\n0 0\n1 1\n2 0\n3 1\n");
    QVERIFY(r.ok());
    QCOMPARE(r->front().curve.points.size(), std::size_t(10));
    QCOMPARE(r->front().curve.nodeTypes.size(), std::size_t(4));
    QCOMPARE(r->front().curve.points[3], geo::Point(1, 1));
    // Closed, by knots: 3n points (the repeated first knot is not stored).
    r = parsePointsText("curve composite closed\n0 0\n1 1\n2 0\n");
    QVERIFY2(r.ok(), qPrintable(r.ok() ? QString() : r.error().toString()));
    QCOMPARE(r->front().curve.points.size(), std::size_t(9));
    QVERIFY(r->front().curve.closed);
    // By control vector with node types.
    r = parsePointsText("curve composite\nnodes corner smooth\npoints control\n0 0\n1 1\n2 1\n3 0\n");
    QVERIFY(r.ok());
    QCOMPARE(r->front().curve.nodeTypes.front(), QStringLiteral("corner"));
    QCOMPARE(r->front().curve.points.size(), std::size_t(4));
}

void TestPointsText::malformed_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QString>("code");
    QTest::addColumn<int>("line");
    QTest::addColumn<int>("column");
    QTest::addRow("word") << QByteArray("1 2\nhello 3\n") << "unknown-directive" << 2 << 1;
    QTest::addRow("one number") << QByteArray("1 2\n  3\n") << "expected-number" << 2 << 4;
    QTest::addRow("bad number") << QByteArray("1 2\n3 4x\n") << "expected-number" << 2 << 3;
    QTest::addRow("decimal comma") << QByteArray("1,5 2,5\n") << "trailing-text" << 1 << 5;
    QTest::addRow("three numbers") << QByteArray("1 2 3\n") << "trailing-text" << 1 << 5;
    QTest::addRow("double separator") << QByteArray("1,,2\n") << "expected-number" << 1 << 3;
    QTest::addRow("inf") << QByteArray("inf 2\n") << "unknown-directive" << 1 << 1;
    QTest::addRow("out of range") << QByteArray("1e999 2\n") << "number-out-of-range" << 1 << 1;
    QTest::addRow("nan after sign") << QByteArray("-nan 2\n") << "expected-number" << 1 << 1;
    QTest::addRow("hex") << QByteArray("0x10 2\n") << "expected-number" << 1 << 1;
    QTest::addRow("empty") << QByteArray("") << "no-points" << 1 << 0;
    QTest::addRow("only comments") << QByteArray("# a\n# b\n") << "no-points" << 2 << 0;
    QTest::addRow("unknown kind") << QByteArray("curve nurbs\n1 2\n") << "unknown-kind" << 1 << 7;
    QTest::addRow("kind syntax") << QByteArray("curve Bezier\n1 2\n") << "unknown-kind" << 1 << 7;
    QTest::addRow("bad parameterization")
        << QByteArray("curve least-squares arc\n") << "unknown-parameterization" << 1 << 21;
    QTest::addRow("empty record") << QByteArray("curve bezier\n\ncurve bezier\n0 0\n1 1\n") << "empty-record" << 1 << 0;
    QTest::addRow("too few") << QByteArray("curve bezier\n0 0\n") << "wrong-point-count" << 1 << 0;
    QTest::addRow("interpolating 5") << QByteArray("curve interpolating chord\n0 0\n1 1\n2 0\n3 1\n4 0\n")
                                     << "wrong-point-count" << 1 << 0;
    QTest::addRow("no parameterization") << QByteArray("curve interpolating\n0 0\n1 1\n2 0\n3 1\n")
                                         << "unknown-parameterization" << 1 << 0;
    QTest::addRow("control of fitted") << QByteArray("curve least-squares chord\npoints control\n0 0\n1 1\n2 0\n3 1\n")
                                       << "wrong-point-kind" << 2 << 0;
    QTest::addRow("knots of bezier") << QByteArray("curve bezier\npoints knots\n0 0\n1 1\n") << "wrong-point-kind" << 2
                                     << 0;
    QTest::addRow("point kind") << QByteArray("points handles\n") << "unknown-point-kind" << 1 << 8;
    QTest::addRow("node type") << QByteArray("curve composite\nnodes smooth sharp\n") << "unknown-node-type" << 2 << 14;
    QTest::addRow("node count") << QByteArray("curve composite\nnodes smooth\n0 0\n1 1\n") << "wrong-point-count" << 2
                                << 0;
    QTest::addRow("control count") << QByteArray("curve composite\npoints control\n0 0\n1 1\n2 2\n")
                                   << "wrong-point-count" << 1 << 0;
    QTest::addRow("unterminated name") << QByteArray("name \"abc\n") << "unterminated-string" << 1 << 6;
    QTest::addRow("missing name") << QByteArray("name\n") << "missing-value" << 1 << 5;
    QTest::addRow("bad colour") << QByteArray("color \"red\"\n") << "invalid-value" << 1 << 7;
    QTest::addRow("settings") << QByteArray("settings {1}\n") << "json-syntax" << 1 << 12;
    QTest::addRow("not utf8") << QByteArray("1 2 \xff\n") << "not-utf8" << 0 << 0;
    QTest::addRow("unicode column") << QByteArray("name \"Līkne\" x\n") << "trailing-text" << 1 << 14;
}

void TestPointsText::malformed()
{
    QFETCH(QByteArray, text);
    QFETCH(QString, code);
    QFETCH(int, line);
    QFETCH(int, column);
    auto r = parsePointsText(text, QStringLiteral("in.txt"));
    QCOMPARE(test::errorPlace(r), test::errorPlace(code, line, column));
    QCOMPARE(r.error().file, QStringLiteral("in.txt"));
    QVERIFY(!r.error().message.isEmpty());
}

void TestPointsText::roundTrip_data()
{
    test::addSeedRows(20);
}

void TestPointsText::roundTrip()
{
    QFETCH(int, seed);
    test::RandomDocuments random(static_cast<std::uint32_t>(seed));
    QByteArray file;
    std::vector<CurveRecord> written;
    for (const QString &kind : knownKinds()) {
        CurveRecord c = random.curve(kind);
        // The text format keeps no visibility or lock (they are document state).
        c.visible = true;
        c.locked = false;
        written.push_back(c);
        file += formatPointsRecord(c, std::vector<geo::Point>{random.point()}) + '\n';
    }
    auto r = parsePointsText(file);
    QVERIFY2(r.ok(), qPrintable(r.ok() ? QString() : r.error().toString()));
    QCOMPARE(r->size(), written.size());
    for (std::size_t i = 0; i < written.size(); ++i) {
        CurveRecord a = written[i], b = (*r)[i].curve;
        QCOMPARE(QJsonDocument(b.settings).toJson(), QJsonDocument(a.settings).toJson());
        a.settings = b.settings = {};
        // Names lose line breaks and tabs stay; compare everything else exactly.
        a.name.replace(QLatin1Char('\n'), QLatin1Char(' '));
        QCOMPARE(b.name, a.name);
        QVERIFY2(a == b, qPrintable(a.kind));
    }
}

void TestPointsText::appendNeverTruncates()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("out.txt"));
    {
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("# my own notes\n1 2\n3 4"); // no final newline
    }
    test::RandomDocuments random(7);
    std::vector<CurveRecord> written;
    for (int i = 0; i < 3; ++i) {
        CurveRecord c = random.curve(QStringLiteral("composite"));
        c.visible = true;
        c.locked = false;
        written.push_back(c);
        QVERIFY(appendPointsRecord(path, c).ok());
    }
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QByteArray all = f.readAll();
    QVERIFY(all.startsWith("# my own notes\n1 2\n3 4\n"));
    auto r = readPointsText(path);
    QVERIFY2(r.ok(), qPrintable(r.ok() ? QString() : r.error().toString()));
    QCOMPARE(r->size(), std::size_t(4));
    QCOMPARE(r->front().curve.points.size(), std::size_t(2));
    for (std::size_t i = 0; i < written.size(); ++i)
        QCOMPARE((*r)[i + 1].curve.points, written[i].points);
    // An invalid record is not written at all.
    CurveRecord bad;
    bad.kind = QStringLiteral("bezier");
    bad.points = {{0, 0}};
    QVERIFY(!appendPointsRecord(path, bad).ok());
    QCOMPARE(QFile(path).size(), all.size());
}

void TestPointsText::curveFromPointsBuildsComposite()
{
    auto c = curveFromPoints(QStringLiteral("composite"), {}, {{0, 0}, {1, 1}, {2, 0}});
    QVERIFY(c.ok());
    QCOMPARE(c->points.size(), std::size_t(7));
    auto bad = curveFromPoints(QStringLiteral("interpolating"), QStringLiteral("chord"), {{0, 0}, {1, 1}});
    QVERIFY(!bad.ok());
    QCOMPARE(bad.error().code, ErrorCode::WrongPointCount);
    QVERIFY(!curveFromPoints(QStringLiteral("nurbs"), {}, {{0, 0}, {1, 1}}).ok());
}

void TestPointsText::limits()
{
    Limits small;
    small.maxPoints = 3;
    small.maxCurves = 2;
    auto r = parsePointsText("1 1\n2 2\n3 3\n4 4\n", {}, small);
    QVERIFY(!r.ok());
    QCOMPARE(r.error().code, ErrorCode::TooManyPoints);
    QCOMPARE(r.error().line, 4);
    r = parsePointsText("curve\n1 1\ncurve\n1 1\ncurve\n1 1\n", {}, small);
    QVERIFY(!r.ok());
    QCOMPARE(r.error().code, ErrorCode::TooManyCurves);
    QCOMPARE(r.error().line, 5);
    small.maxFileBytes = 10;
    QTemporaryDir dir;
    QFile f(dir.filePath(QStringLiteral("big.txt")));
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(QByteArray(100, '\n'));
    f.close();
    r = readPointsText(f.fileName(), small);
    QVERIFY(!r.ok());
    QCOMPARE(r.error().code, ErrorCode::FileTooLarge);
}

// Several records together at exactly the point limit are read; one point more is refused. The
// limit counts points as stored: a composite curve's 3 knots are its 7-point control vector.
void TestPointsText::pointLimitCountsEachPointOnce()
{
    Limits limits;
    limits.maxPoints = 10;
    // A Bézier curve of 3 points and a composite curve of 3 knots (7 stored points): 10.
    const QByteArray atLimit = "curve bezier\n0 0\n1 1\n2 0\ncurve composite\n0 0\n1 1\n2 0\n";
    auto r = parsePointsText(atLimit, {}, limits);
    QVERIFY2(r.ok(), qPrintable(r.ok() ? QString() : r.error().toString()));
    QCOMPARE(r->size(), std::size_t(2));
    QCOMPARE((*r)[0].curve.points.size() + (*r)[1].curve.points.size(), std::size_t(10));

    // Hand-written lists: five records of two points each, exactly 10.
    const QByteArray tenPoints = "curve\n1 1\n2 2\ncurve\n3 3\n4 4\ncurve\n5 5\n6 6\ncurve\n7 7\n8 8\n"
                                 "curve\n9 9\n10 10\n";
    r = parsePointsText(tenPoints, {}, limits);
    QVERIFY2(r.ok(), qPrintable(r.ok() ? QString() : r.error().toString()));
    QCOMPARE(r->size(), std::size_t(5));

    // One more point, in the last record (line 16) or as a fourth knot (7 + 3 = 10 stored becomes 13).
    r = parsePointsText(tenPoints + "11 11\n", {}, limits);
    QVERIFY(!r.ok());
    QCOMPARE(r.error().code, ErrorCode::TooManyPoints);
    QCOMPARE(r.error().line, 16);
    r = parsePointsText("curve bezier\n0 0\n1 1\n2 0\ncurve composite\n0 0\n1 1\n2 0\n3 1\n", {}, limits);
    QVERIFY(!r.ok());
    QCOMPARE(r.error().code, ErrorCode::TooManyPoints);
    QCOMPARE(r.error().line, 5); // the record that went over
    r = parsePointsText("curve bezier\n0 0\n1 1\n2 0\n3 3\ncurve composite\n0 0\n1 1\n2 0\n", {}, limits);
    QVERIFY(!r.ok());
    QCOMPARE(r.error().code, ErrorCode::TooManyPoints);
}

// A record the reader would refuse is not appended: more points than a file holds, or a file that
// would grow past the bytes the reader takes. The file is left as it was.
void TestPointsText::appendRefusesWhatTheReaderRefuses()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("limits.txt"));
    CurveRecord curve;
    curve.kind = QStringLiteral("bezier");
    curve.points = {{0, 0}, {1, 1}, {2, 0}, {3, 1}};
    Limits limits;
    limits.maxPoints = 3;
    auto r = appendPointsRecord(path, curve, {}, limits);
    QVERIFY(!r.ok());
    QCOMPARE(r.error().code, ErrorCode::TooManyPoints);
    QVERIFY(!QFile::exists(path));
    limits.maxPoints = 4;
    r = appendPointsRecord(path, curve, {}, limits);
    QVERIFY(r.ok());
    const qint64 size = QFileInfo(path).size();
    // The points already in the file count: 4 + 4 is more than the 4 a file holds.
    r = appendPointsRecord(path, curve, {}, limits);
    QVERIFY(!r.ok());
    QCOMPARE(r.error().code, ErrorCode::TooManyPoints);
    QCOMPARE(QFileInfo(path).size(), size);
    limits.maxPoints = 100;
    limits.maxFileBytes = 2 * size; // a second record and its blank line need one byte more
    r = appendPointsRecord(path, curve, {}, limits);
    QVERIFY(!r.ok());
    QCOMPARE(r.error().code, ErrorCode::FileTooLarge);
    QCOMPARE(QFileInfo(path).size(), size);
    limits.maxFileBytes = 2 * size + 1;
    QVERIFY(appendPointsRecord(path, curve, {}, limits).ok());
    QCOMPARE(QFileInfo(path).size(), 2 * size + 1);
    // The records already in the file count too: a third one where a file holds two is refused.
    limits.maxFileBytes = 1 << 20;
    limits.maxCurves = 2;
    r = appendPointsRecord(path, curve, {}, limits);
    QVERIFY(!r.ok());
    QCOMPARE(r.error().code, ErrorCode::TooManyCurves);
    QCOMPARE(QFileInfo(path).size(), 2 * size + 1);
    // Everything appended reads back under the same limits.
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const auto back = parsePointsText(file.readAll(), path, limits);
    QVERIFY(back.ok());
    QCOMPARE(back->size(), std::size_t(2));
}

// A writer killed (SIGKILL) at random moments while it appends: the file always reads back whole,
// every record complete, none lost that was there before. Appending in place let a kill land
// inside the write of a record of several pages, and the partial record made the whole file
// unreadable (2 of 88 kills).
void TestPointsText::appendSurvivesKill()
{
#ifdef Q_OS_UNIX
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("killed.txt"));
    // About 1 MB of text: its write spans hundreds of pages, where a kill can stop it.
    CurveRecord c;
    c.kind = QStringLiteral("least-squares");
    c.parameterization = QStringLiteral("chord");
    const std::size_t count = 40000;
    for (std::size_t i = 0; i < count; ++i)
        c.points.emplace_back(static_cast<double>(i) * 0.001234567891, std::sin(static_cast<double>(i) * 0.1) * 12.345);
    std::mt19937 rng(33);
    std::uniform_int_distribution<int> delay(0, 40000);
    std::size_t before = 0;
    int checked = 0;
    // Until 60 kills found a file to check (a busy machine gives the writer less time per round).
    int round = 0;
    for (; checked < 60 && round < 3000; ++round) {
        if (QFileInfo(path).size() > 5'000'000) { // a new file now and then keeps each append cheap
            QVERIFY(QFile::remove(path));
            before = 0;
        }
        const pid_t child = fork();
        QVERIFY(child >= 0);
        if (child == 0) {
            for (;;)
                (void)appendPointsRecord(path, c);
        }
        std::this_thread::sleep_for(std::chrono::microseconds(delay(rng)));
        QCOMPARE(::kill(child, SIGKILL), 0);
        int status = 0;
        QCOMPARE(waitpid(child, &status, 0), child);
        if (!QFileInfo::exists(path))
            continue;
        const auto records = readPointsText(path);
        if (!records.ok())
            QFAIL(qPrintable(QStringLiteral("after kill %1: %2").arg(round).arg(records.error().toString())));
        for (const TextRecord &r : *records)
            QCOMPARE(r.curve.points.size(), count);
        QVERIFY(records->size() >= before);
        before = records->size();
        ++checked;
    }
    QVERIFY2(checked >= 60, qPrintable(QStringLiteral("%1 of %2 rounds").arg(checked).arg(round)));
#else
    QSKIP("fork and SIGKILL are POSIX");
#endif
}

QTEST_GUILESS_MAIN(TestPointsText)
#include "tst_pointstext.moc"
