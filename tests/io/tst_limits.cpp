// Everything Kontur writes, Kontur reads back (issue 17): a file at each stated limit (the most points
// in one curve, the most points in one file, the most curves) is written and read back equal in every
// format that can hold it, and one more is refused by the writer, not written for the reader to refuse.
#include "geometry/composite.h"
#include "io/csv.h"
#include "io/document.h"
#include "io/pointstext.h"
#include "io/svg.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <random>

using namespace kontur;
using namespace kontur::io;

namespace {

// Knots along a wavy line with full-precision coordinates (the longest numbers a file holds), and
// some at the ends of the double range: subnormal, 1e300, -0.
std::vector<geo::Point> knots(std::size_t n, std::uint32_t seed)
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> jitter(0.0, 1.0);
    std::vector<geo::Point> out(n);
    for (std::size_t i = 0; i < n; ++i)
        out[i] = geo::Point(static_cast<double>(i) + jitter(rng), 100.0 * std::sin(0.01 * static_cast<double>(i)));
    return out;
}

CurveRecord composite(std::size_t knotCount, bool closed, std::uint32_t seed)
{
    geo::CompositeCurve curve(knots(knotCount, seed));
    if (closed)
        (void)curve.close();
    CurveRecord r;
    r.kind = QStringLiteral("composite");
    r.name = QStringLiteral("largest");
    r.closed = closed;
    r.points = curve.controlPoints();
    if (closed)
        r.points.pop_back(); // the repeated first knot is not stored
    r.nodeTypes.assign(knotCount, QStringLiteral("smooth"));
    return r;
}

CurveRecord bezier(double x)
{
    CurveRecord r;
    r.kind = QStringLiteral("bezier");
    r.points = {{x, 4.9406564584124654e-324}, {x + 1e300, -1e-300}};
    return r;
}

QString describe(const Error &e)
{
    return e.toString() + QStringLiteral(" [") + QLatin1String(codeName(e.code)) + QLatin1Char(']');
}

} // namespace

class TestLimits final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void statedLimits();
    void documentAtEachLimit_data();
    void documentAtEachLimit();
    void documentOverTheLimits();
    void pointsTextAtTheCurveLimit();
    void pointsTextAtTheCurveCount();
    void csvAtTheLimit();
    void svgAtTheCurveLimit();
    void svgAtTheCurveCount();

private:
    QTemporaryDir m_dir;
};

// The limits as documented (docs/file-formats.md, README): written out, not derived from each other.
void TestLimits::statedLimits()
{
    const Limits limits;
    QCOMPARE(kMaxCurvePoints, qint64(1'000'000));
    QCOMPARE(limits.maxPoints, qint64(6'000'000));
    QCOMPARE(limits.maxCurves, qint64(100'000));
    // 6e6 points of at most 160 bytes, 100,000 curves of 1 KiB, 16 MiB margin.
    QCOMPARE(limits.maxFileBytes, qint64(960'000'000 + 102'400'000 + 16'777'216));
}

void TestLimits::documentAtEachLimit_data()
{
    QTest::addColumn<int>("largest"); // composite curves of kMaxCurvePoints knots
    QTest::addColumn<bool>("closed");
    QTest::addColumn<int>("small"); // two-point Bézier curves besides
    const int most = static_cast<int>(Limits{}.maxCurves);
    QTest::addRow("one open composite curve of 1e6 knots") << 1 << false << 0;
    // 3e6 stored points each: exactly the 6e6 points one file holds.
    QTest::addRow("two closed composite curves of 1e6 knots") << 2 << true << 0;
    QTest::addRow("100000 curves") << 0 << false << most;
}

void TestLimits::documentAtEachLimit()
{
    QFETCH(int, largest);
    QFETCH(bool, closed);
    QFETCH(int, small);
    DocumentData doc;
    for (int i = 0; i < largest; ++i)
        doc.curves.push_back(composite(static_cast<std::size_t>(kMaxCurvePoints), closed, 7u + i));
    for (int i = 0; i < small; ++i)
        doc.curves.push_back(bezier(i));
    if (largest > 0)
        QCOMPARE(doc.curves.front().points.size(), closed ? std::size_t(3'000'000) : std::size_t(2'999'998));
    const QString path = m_dir.filePath(QStringLiteral("limit.kontur"));
    const auto saved = saveDocument(path, doc);
    QVERIFY2(saved.ok(), qPrintable(saved.ok() ? QString() : describe(saved.error())));
    const auto opened = openDocument(path);
    QVERIFY2(opened.ok(), qPrintable(opened.ok() ? QString() : describe(opened.error())));
    QCOMPARE(opened->curves.size(), doc.curves.size());
    QVERIFY(*opened == doc);
}

// One point or one curve more than a file holds: the writer refuses with the reader's error code, and
// the reader refuses the same text (written without the writer's check).
void TestLimits::documentOverTheLimits()
{
    const Limits limits;
    DocumentData doc;
    doc.curves.push_back(composite(static_cast<std::size_t>(kMaxCurvePoints), true, 1));
    doc.curves.push_back(composite(static_cast<std::size_t>(kMaxCurvePoints), true, 2));
    doc.curves.push_back(bezier(0)); // 2 points over
    const QString path = m_dir.filePath(QStringLiteral("over.kontur"));
    auto saved = saveDocument(path, doc);
    QVERIFY(!saved.ok());
    QCOMPARE(saved.error().code, ErrorCode::TooManyPoints);
    QVERIFY(!QFile::exists(path));
    auto read = documentFromJson(documentToJson(doc));
    QVERIFY(!read.ok());
    QCOMPARE(read.error().code, ErrorCode::TooManyPoints);
    QCOMPARE(read.error().path, QStringLiteral("curves[2].points"));

    DocumentData many;
    for (qint64 i = 0; i <= limits.maxCurves; ++i)
        many.curves.push_back(bezier(static_cast<double>(i)));
    saved = saveDocument(path, many);
    QVERIFY(!saved.ok());
    QCOMPARE(saved.error().code, ErrorCode::TooManyCurves);
    read = documentFromJson(documentToJson(many));
    QVERIFY(!read.ok());
    QCOMPARE(read.error().code, ErrorCode::TooManyCurves);

    // Counted while scanning, before the JSON is parsed: a text whose curve after the last one allowed
    // is broken (and then cut off) is refused for the count, not for its syntax, at that curve.
    Limits three;
    three.maxCurves = 3;
    QByteArray text = "{\"format\":\"kontur\",\"version\":1,\"units\":\"px\",\"curves\":[";
    for (int i = 0; i < 3; ++i)
        text += "{\"kind\":\"bezier\",\"points\":[[0,0],[1,1]]},\n";
    text += "{\"kind\":";
    read = documentFromJson(text, {}, three);
    QVERIFY(!read.ok());
    QCOMPARE(read.error().code, ErrorCode::TooManyCurves);
    QCOMPARE(read.error().line, 3); // the comma after the third curve
}

// The points text holds the largest curve as Kontur appends it (its control vector) and reads it back.
void TestLimits::pointsTextAtTheCurveLimit()
{
    const CurveRecord largest = composite(static_cast<std::size_t>(kMaxCurvePoints), false, 3);
    const QString path = m_dir.filePath(QStringLiteral("largest.txt"));
    QFile::remove(path);
    const auto written = appendPointsRecord(path, largest);
    QVERIFY2(written.ok(), qPrintable(written.ok() ? QString() : describe(written.error())));
    const auto read = readPointsText(path);
    QVERIFY2(read.ok(), qPrintable(read.ok() ? QString() : describe(read.error())));
    QCOMPARE(read->size(), std::size_t(1));
    QVERIFY(read->front().curve == largest);
}

void TestLimits::pointsTextAtTheCurveCount()
{
    const Limits limits;
    QByteArray text;
    for (qint64 i = 0; i < limits.maxCurves; ++i)
        text += formatPointsRecord(bezier(static_cast<double>(i)));
    auto read = parsePointsText(text);
    QVERIFY2(read.ok(), qPrintable(read.ok() ? QString() : describe(read.error())));
    QCOMPARE(static_cast<qint64>(read->size()), limits.maxCurves);
    QVERIFY(read->back().curve == bezier(static_cast<double>(limits.maxCurves - 1)));
    read = parsePointsText(text + formatPointsRecord(bezier(-1.0)));
    QVERIFY(!read.ok());
    QCOMPARE(read.error().code, ErrorCode::TooManyCurves);
}

// CSV holds one curve's points: the largest control vector, and one file's worth of points.
void TestLimits::csvAtTheLimit()
{
    const Limits limits;
    std::vector<geo::Point> points = composite(static_cast<std::size_t>(kMaxCurvePoints), true, 4).points;
    const std::vector<geo::Point> more = composite(static_cast<std::size_t>(kMaxCurvePoints), true, 5).points;
    points.insert(points.end(), more.begin(), more.end());
    QCOMPARE(static_cast<qint64>(points.size()), limits.maxPoints);
    const QString path = m_dir.filePath(QStringLiteral("limit.csv"));
    auto written = writeCsvPoints(path, points);
    QVERIFY2(written.ok(), qPrintable(written.ok() ? QString() : describe(written.error())));
    const auto read = readCsvPoints(path);
    QVERIFY2(read.ok(), qPrintable(read.ok() ? QString() : describe(read.error())));
    QVERIFY(*read == points);
    points.emplace_back(1.0, 2.0);
    written = writeCsvPoints(path, points);
    QVERIFY(!written.ok());
    QCOMPARE(written.error().code, ErrorCode::TooManyPoints);
}

// SVG: the largest composite curve as one path of 999,999 cubics re-imports to the same segments.
void TestLimits::svgAtTheCurveLimit()
{
    geo::CompositeCurve curve(knots(static_cast<std::size_t>(kMaxCurvePoints), 6));
    const SvgCurve svg{QStringLiteral("largest"), QStringLiteral("#112233"), curve.toPiecewise()};
    const QString path = m_dir.filePath(QStringLiteral("largest.svg"));
    const auto written = writeSvg(path, std::span(&svg, 1));
    QVERIFY2(written.ok(), qPrintable(written.ok() ? QString() : describe(written.error())));
    const auto read = readSvg(path);
    QVERIFY2(read.ok(), qPrintable(read.ok() ? QString() : describe(read.error())));
    QCOMPARE(read->curves.size(), std::size_t(1));
    const auto &segments = read->curves.front().curve.segments();
    QCOMPARE(segments.size(), std::size_t(kMaxCurvePoints - 1));
    for (std::size_t i = 0; i < segments.size(); ++i)
        if (segments[i].controlPoints() != curve.segment(static_cast<int>(i)).controlPoints())
            QFAIL(qPrintable(QStringLiteral("segment %1 differs").arg(i)));
}

// SVG: as many curves as a file holds, one subpath each, re-import as many; one more is not written.
void TestLimits::svgAtTheCurveCount()
{
    const Limits limits;
    std::vector<SvgCurve> curves;
    for (qint64 i = 0; i < limits.maxCurves; ++i) {
        const double x = static_cast<double>(i);
        curves.push_back({{}, QStringLiteral("#000000"), geo::PiecewiseBezier({geo::Bezier({{x, 0.0}, {x, 1.0}})})});
    }
    const QString path = m_dir.filePath(QStringLiteral("many.svg"));
    auto written = writeSvg(path, curves);
    QVERIFY2(written.ok(), qPrintable(written.ok() ? QString() : describe(written.error())));
    const auto read = readSvg(path);
    QVERIFY2(read.ok(), qPrintable(read.ok() ? QString() : describe(read.error())));
    QCOMPARE(static_cast<qint64>(read->curves.size()), limits.maxCurves);
    QCOMPARE(read->curves.back().curve.segments().front().controlPoints(),
             (std::vector<geo::Point>{{99'999.0, -0.0}, {99'999.0, 1.0}}));
    curves.push_back(curves.front());
    written = writeSvg(path, curves);
    QVERIFY(!written.ok());
    QCOMPARE(written.error().code, ErrorCode::TooManyCurves);
}

QTEST_GUILESS_MAIN(TestLimits)
#include "tst_limits.moc"
