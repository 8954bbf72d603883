// Tests of the .kontur document: random documents of every kind round-trip exactly and save → open →
// save is byte-identical; malformed documents fail with the expected code and JSON path; newer
// versions are refused; the background path is relative on disk; a refused save keeps the old file.
#include "geometry/composite.h"
#include "io/document.h"
#include "io/piece.h"
#include "iotestutil.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace kontur;
using namespace kontur::io;

class TestDocument final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void roundTrip_data();
    void roundTrip();
    void byteIdenticalOnDisk();
    void malformed_data();
    void malformed();
    void newerVersionRefused();
    void pieceMarksRoundTrip();
    void malformedPieceMarksLeftOut();
    void placesAlongTheCurve();
    void ruleHandlesWrittenAsNull();
    void nullOnlyForRuleHandles_data();
    void nullOnlyForRuleHandles();
    void millionKnotsCompact();
    void backgroundPathRelative();
    void failedSaveKeepsOldFile();
    void limits();
};

void TestDocument::roundTrip_data()
{
    test::addSeedRows(40);
}

void TestDocument::roundTrip()
{
    QFETCH(int, seed);
    test::RandomDocuments random(static_cast<std::uint32_t>(seed));
    for (int i = 0; i < 10; ++i) {
        const DocumentData doc = random.document();
        QVERIFY(!validateDocument(doc));
        const QByteArray json = documentToJson(doc);
        auto back = documentFromJson(json);
        QVERIFY2(back.ok(), qPrintable(back.ok() ? QString() : back.error().toString()));
        // The records compare exactly, settings as JSON text (integers and doubles compare by text).
        QCOMPARE(back->curves.size(), doc.curves.size());
        for (std::size_t c = 0; c < doc.curves.size(); ++c) {
            CurveRecord a = doc.curves[c], b = back->curves[c];
            QCOMPARE(QJsonDocument(b.settings).toJson(), QJsonDocument(a.settings).toJson());
            a.settings = b.settings = {};
            QVERIFY(a == b);
        }
        QCOMPARE(back->background, doc.background);
        QCOMPARE(back->units, doc.units);
        QCOMPARE(documentToJson(*back), json); // byte-identical
    }
}

void TestDocument::byteIdenticalOnDisk()
{
    QTemporaryDir dir;
    test::RandomDocuments random(99);
    for (int i = 0; i < 20; ++i) {
        const QString path = dir.filePath(QStringLiteral("doc%1.kontur").arg(i));
        DocumentData doc = random.document();
        if (doc.background && !doc.background->file.isEmpty())
            doc.background->file = dir.filePath(doc.background->file);
        QVERIFY(saveDocument(path, doc).ok());
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray first = f.readAll();
        f.close();
        auto opened = openDocument(path);
        QVERIFY2(opened.ok(), qPrintable(opened.ok() ? QString() : opened.error().toString()));
        QVERIFY(saveDocument(path, *opened).ok());
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), first);
    }
}

void TestDocument::malformed_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("code");
    QTest::addColumn<QString>("path");
    QTest::addColumn<int>("line");
    const QByteArray head = R"({"format": "kontur", "version": 1, )";
    const auto curve = [&](const char *c) { return head + R"("curves": [)" + c + "]}"; };
    QTest::addRow("syntax") << QByteArray("{\n  \"format\": \"kontur\",\n  oops\n}") << "json-syntax"
                            << "" << 3;
    QTest::addRow("not an object") << QByteArray("[1, 2]") << "not-kontur"
                                   << "" << 0;
    QTest::addRow("no format") << QByteArray(R"({"version": 1, "curves": []})") << "not-kontur"
                               << "format" << 0;
    QTest::addRow("other format") << QByteArray(R"({"format": "svg", "version": 1, "curves": []})") << "not-kontur"
                                  << "format" << 0;
    QTest::addRow("no version") << QByteArray(R"({"format": "kontur", "curves": []})") << "missing-field"
                                << "version" << 0;
    QTest::addRow("version string") << QByteArray(R"({"format": "kontur", "version": "1", "curves": []})")
                                    << "wrong-type"
                                    << "version" << 0;
    QTest::addRow("version 1.5") << QByteArray(R"({"format": "kontur", "version": 1.5, "curves": []})") << "wrong-type"
                                 << "version" << 0;
    QTest::addRow("version 0") << QByteArray(R"({"format": "kontur", "version": 0, "curves": []})") << "invalid-value"
                               << "version" << 0;
    QTest::addRow("no curves") << QByteArray(head + R"("units": "px"})") << "missing-field"
                               << "curves" << 0;
    QTest::addRow("curves object") << QByteArray(head + R"("curves": {}})") << "wrong-type"
                                   << "curves" << 0;
    QTest::addRow("bad units") << QByteArray(head + R"("units": "furlong", "curves": []})") << "invalid-value"
                               << "units" << 0;
    QTest::addRow("curve not object") << curve("1") << "wrong-type"
                                      << "curves[0]" << 0;
    QTest::addRow("no kind") << curve(R"({"points": []})") << "missing-field"
                             << "curves[0].kind" << 0;
    QTest::addRow("unknown kind") << curve(R"({"kind": "nurbs", "points": []})") << "unknown-kind"
                                  << "curves[0].kind" << 0;
    QTest::addRow("no points") << curve(R"({"kind": "bezier"})") << "missing-field"
                               << "curves[0].points" << 0;
    QTest::addRow("point string")
        << curve(R"({"kind": "bezier", "points": [[0, 0], [1, 1]]}, {"kind": "bezier", "points": [[0, 0], [1, "2"]]})")
        << "wrong-type"
        << "curves[1].points[1][1]" << 0;
    QTest::addRow("point 3d") << curve(R"({"kind": "bezier", "points": [[0, 0, 0], [1, 1]]})") << "wrong-type"
                              << "curves[0].points[0]" << 0;
    QTest::addRow("one point") << curve(R"({"kind": "bezier", "points": [[0, 0]]})") << "wrong-point-count"
                               << "curves[0].points" << 0;
    QTest::addRow("interpolating 5")
        << curve(R"({"kind": "interpolating", "parameterization": "chord", "points": [[0,0],[1,1],[2,0],[3,1],[4,0]]})")
        << "wrong-point-count"
        << "curves[0].points" << 0;
    QTest::addRow("no parameterization") << curve(R"({"kind": "least-squares", "points": [[0,0],[1,1],[2,0],[3,1]]})")
                                         << "missing-field"
                                         << "curves[0].parameterization" << 0;
    QTest::addRow("bad parameterization")
        << curve(R"({"kind": "least-squares", "parameterization": "arc", "points": [[0,0],[1,1],[2,0],[3,1]]})")
        << "unknown-parameterization"
        << "curves[0].parameterization" << 0;
    QTest::addRow("parameterization on bezier")
        << curve(R"({"kind": "bezier", "parameterization": "chord", "points": [[0,0],[1,1]]})") << "invalid-value"
        << "curves[0].parameterization" << 0;
    QTest::addRow("composite count")
        << curve(R"({"kind": "composite", "nodeTypes": ["smooth", "smooth"], "points": [[0,0],[1,1],[2,0]]})")
        << "wrong-point-count"
        << "curves[0].points" << 0;
    QTest::addRow("composite node count")
        << curve(R"({"kind": "composite", "nodeTypes": ["smooth"], "points": [[0,0],[1,1],[2,0],[3,3]]})")
        << "wrong-point-count"
        << "curves[0].nodeTypes" << 0;
    QTest::addRow("composite node type")
        << curve(R"({"kind": "composite", "nodeTypes": ["smooth", "pointy"], "points": [[0,0],[1,1],[2,0],[3,3]]})")
        << "unknown-node-type"
        << "curves[0].nodeTypes[1]" << 0;
    QTest::addRow("composite no nodes") << curve(R"({"kind": "composite", "points": [[0,0],[1,1],[2,0],[3,3]]})")
                                        << "missing-field"
                                        << "curves[0].nodeTypes" << 0;
    QTest::addRow("closed bezier") << curve(R"({"kind": "bezier", "closed": true, "points": [[0,0],[1,1]]})")
                                   << "invalid-value"
                                   << "curves[0].closed" << 0;
    QTest::addRow("bad colour") << curve(R"({"kind": "bezier", "color": "red", "points": [[0,0],[1,1]]})")
                                << "invalid-value"
                                << "curves[0].color" << 0;
    QTest::addRow("visible string") << curve(R"({"kind": "bezier", "visible": "yes", "points": [[0,0],[1,1]]})")
                                    << "wrong-type"
                                    << "curves[0].visible" << 0;
    QTest::addRow("settings array") << curve(R"({"kind": "bezier", "settings": [], "points": [[0,0],[1,1]]})")
                                    << "wrong-type"
                                    << "curves[0].settings" << 0;
    QTest::addRow("background opacity") << QByteArray(head +
                                                      R"("curves": [], "background": {"file": "a.png", "opacity": 2}})")
                                        << "invalid-value"
                                        << "background.opacity" << 0;
    QTest::addRow("background scale") << QByteArray(head +
                                                    R"("curves": [], "background": {"file": "a.png", "scale": 0}})")
                                      << "invalid-value"
                                      << "background.scale" << 0;
    QTest::addRow("background no file") << QByteArray(head + R"("curves": [], "background": {}})") << "missing-field"
                                        << "background.file" << 0;
    QTest::addRow("calibration point")
        << QByteArray(
               head +
               R"("curves": [], "background": {"file": "", "calibration": {"a": [0], "b": [1, 1], "distance": 1}}})")
        << "wrong-type"
        << "background.calibration.a" << 0;
    QTest::addRow("calibration distance")
        << QByteArray(
               head +
               R"("curves": [], "background": {"file": "", "calibration": {"a": [0, 0], "b": [1, 1], "distance": 0}}})")
        << "invalid-value"
        << "background.calibration.distance" << 0;
    QTest::addRow("too deep") << QByteArray(head + R"("curves": [], "x": )" + QByteArray(100, '[') +
                                            QByteArray(100, ']') + "}")
                              << "too-deep"
                              << "" << 1;
}

void TestDocument::malformed()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, code);
    QFETCH(QString, path);
    QFETCH(int, line);
    auto r = documentFromJson(json, QStringLiteral("doc.kontur"));
    QVERIFY(!r.ok());
    QCOMPARE(QLatin1String(codeName(r.error().code)), code);
    QCOMPARE(r.error().path, path);
    QCOMPARE(r.error().line, line);
    QVERIFY(!r.error().message.isEmpty());
    QVERIFY(r.error().toString().startsWith(QLatin1String("doc.kontur")));
}

void TestDocument::newerVersionRefused()
{
    auto r = documentFromJson(R"({"format": "kontur", "version": 4, "curves": [], "new": {}})");
    QVERIFY(!r.ok());
    QCOMPARE(r.error().code, ErrorCode::UnsupportedVersion);
    QVERIFY(r.error().message.contains(QLatin1String("newer Kontur")));
}

namespace {

PieceMarks sampleMarks()
{
    PieceMarks m;
    m.size = QStringLiteral("38");
    m.quantity = 2;
    m.material = QStringLiteral("vilna / шерсть");
    m.fold = Segment{geo::Point(0, 0), geo::Point(0, 400.25)};
    m.grainline = Segment{geo::Point(100.125, 50), geo::Point(100.125, 350.5)};
    m.notches = {{120.5, NotchKind::V, 0.0}, {333.0 / 7.0, NotchKind::Castle, -12.5}, {0.0, NotchKind::Slit, 30}};
    m.drillHoles = {geo::Point(80.0 / 3.0, 200), geo::Point(-1e-7, 1e9)};
    m.seamWidths = {std::nullopt, 30.0, 0.0, 12.5 / 3.0};
    m.hems = {0, 2};
    return m;
}

} // namespace

// Every mark comes back bit for bit through the file, the document says version 3, and one without
// pieces keeps its version (1).
void TestDocument::pieceMarksRoundTrip()
{
    DocumentData doc;
    doc.units = QStringLiteral("mm");
    CurveRecord c;
    c.kind = QStringLiteral("interpolating");
    c.name = QStringLiteral("Front");
    c.parameterization = QStringLiteral("chord");
    c.points = {geo::Point(0, 0), geo::Point(200, 0), geo::Point(200, 400), geo::Point(0, 400)};
    c.settings.insert(QLatin1String(kPieceKey), pieceToJson(sampleMarks()));
    doc.curves.push_back(c);
    const QByteArray json = documentToJson(doc);
    QVERIFY(json.contains(R"("version": 3)"));
    auto back = documentFromJson(json);
    QVERIFY2(back.ok(), qPrintable(back.ok() ? QString() : back.error().toString()));
    QCOMPARE(back->curves.size(), std::size_t(1));
    const auto marks = pieceFromSettings(back->curves[0].settings);
    QVERIFY(marks.has_value());
    QVERIFY(*marks == sampleMarks());
    QCOMPARE(documentToJson(*back), json);

    doc.curves[0].settings = {};
    QVERIFY(documentToJson(doc).contains(R"("version": 1)"));
    // A piece without widths of its own per seam writes no "seamWidths" (files as before).
    PieceMarks plain = sampleMarks();
    plain.seamWidths.clear();
    plain.hems.clear();
    QVERIFY(!pieceToJson(plain).contains(QLatin1String("seamWidths")));
    QVERIFY(!pieceToJson(plain).contains(QLatin1String("hems")));
    QVERIFY(pieceToJson(sampleMarks()).value(QLatin1String("seamWidths")).toArray().size() == 4);
    // An empty piece (no marks yet) is still a piece: quantity 1.
    const auto empty = pieceFromSettings(QJsonObject{{QLatin1String(kPieceKey), pieceToJson(PieceMarks{})}});
    QVERIFY(empty.has_value());
    QCOMPARE(empty->quantity, 1);
    QVERIFY(!empty->grainline.has_value());
}

// Nothing Kontur writes is refused, and a hand-edited mark that makes no sense is left out, not the file.
void TestDocument::malformedPieceMarksLeftOut()
{
    const QByteArray json =
        R"({"format": "kontur", "version": 3, "units": "mm", "curves": [{"kind": "bezier", "points": [[0,0],[1,1]],
        "settings": {"piece": {"quantity": 0, "grainline": [[0, 0]], "fold": "left",
        "notches": [{"at": 5, "kind": "w"}, {"at": "x", "kind": "v"}, {"at": 7, "kind": "castle", "angle": 120}],
        "drillHoles": [[1, 2], [3], "x"], "seamWidths": [-1, "x", 5, null], "hems": [2, -1, 1.5, "x", 2, 0]}}}]})";
    auto r = documentFromJson(json);
    QVERIFY2(r.ok(), qPrintable(r.ok() ? QString() : r.error().toString()));
    const auto marks = pieceFromSettings(r->curves[0].settings);
    QVERIFY(marks.has_value());
    QCOMPARE(marks->quantity, 1);
    QVERIFY(!marks->grainline && !marks->fold);
    QCOMPARE(marks->notches.size(), std::size_t(1));
    QCOMPARE(marks->notches[0].position, 7.0);
    QCOMPARE(marks->notches[0].kind, NotchKind::Castle);
    QCOMPARE(marks->notches[0].angle, 89.0);
    QCOMPARE(marks->drillHoles.size(), std::size_t(1));
    // Widths that are no number from 0 up are the allowance's own; trailing ones are not kept.
    QCOMPARE(marks->seamWidths, (std::vector<std::optional<double>>{std::nullopt, std::nullopt, 5.0}));
    QCOMPARE(marks->hems, (std::vector<int>{0, 2}));
}

// Arc length to a place and back, on a square of side 100 (counter-clockwise): the notch square to
// the seam points inside, and turned by 90° it runs along the seam.
void TestDocument::placesAlongTheCurve()
{
    const auto line = [](geo::Point a, geo::Point b) { return geo::Bezier(std::vector<geo::Point>{a, b}); };
    const geo::PiecewiseBezier square({line({0, 0}, {100, 0}), line({100, 0}, {100, 100}),
                                       line({100, 100}, {0, 100}), line({0, 100}, {0, 0})},
                                      true);
    const CurvePlace p = placeAtLength(square, 150);
    QVERIFY((p.point - geo::Point(100, 50)).norm() < 1e-9);
    QVERIFY((p.tangent - geo::Point(0, 1)).norm() < 1e-9);
    QVERIFY((placeAtLength(square, 450).point - geo::Point(50, 0)).norm() < 1e-9); // wraps round
    QVERIFY(std::abs(lengthAtNearest(square, geo::Point(130, 72)) - 172) < 1e-9);
    QVERIFY(std::abs(signedArea(square) - 10000) < 1e-6);
    QVERIFY((notchDirection(square, p, 0) - geo::Point(-1, 0)).norm() < 1e-12);
    QVERIFY((notchDirection(square, p, 90) - geo::Point(0, -1)).norm() < 1e-12);
    // Clockwise, the inside is on the other side.
    std::vector<geo::Bezier> reversed;
    for (auto it = square.segments().rbegin(); it != square.segments().rend(); ++it)
        reversed.push_back(line(it->controlPoints().back(), it->controlPoints().front()));
    const geo::PiecewiseBezier cw(reversed, true);
    const CurvePlace q = placeAtLength(cw, 50); // (0, 50) going down
    QVERIFY((q.point - geo::Point(0, 50)).norm() < 1e-9);
    QVERIFY((notchDirection(cw, q, 0) - geo::Point(1, 0)).norm() < 1e-12);
}

namespace {

// A composite record whose handles follow the construction rule, for `knots`.
CurveRecord ruleComposite(const std::vector<geo::Point> &knots, bool closed)
{
    geo::CompositeCurve curve(knots);
    if (closed)
        (void)curve.close();
    CurveRecord r;
    r.kind = QStringLiteral("composite");
    r.points = curve.controlPoints();
    if (closed)
        r.points.pop_back();
    r.closed = closed;
    r.nodeTypes.assign(knots.size(), QStringLiteral("smooth"));
    return r;
}

} // namespace

// A composite curve's handles where the rule puts them are written as null (version 2) and come back
// bit for bit; a moved handle is written as its number; a document without such handles stays version 1.
void TestDocument::ruleHandlesWrittenAsNull()
{
    const std::vector<geo::Point> knots{{0.1, 0.2}, {10.3, 20.7}, {25.123456789, 22.5}, {40, 5}, {55.5, -10.25}};
    for (bool closed : {false, true}) {
        DocumentData doc;
        doc.curves.push_back(ruleComposite(knots, closed));
        doc.curves.back().points[4] += geo::Point(0.5, -0.25); // the user moved one handle
        const QByteArray json = documentToJson(doc);
        QVERIFY(json.contains(R"("version": 2)"));
        // 5 knots open: 8 handles, one moved; closed: 10 handles, one moved.
        QCOMPARE(json.count("null"), closed ? 9 : 7);
        auto back = documentFromJson(json);
        QVERIFY2(back.ok(), qPrintable(back.ok() ? QString() : back.error().toString()));
        QCOMPARE(back->curves.size(), std::size_t(1));
        QCOMPARE(back->curves[0].points.size(), doc.curves[0].points.size());
        for (std::size_t i = 0; i < doc.curves[0].points.size(); ++i)
            QCOMPARE(back->curves[0].points[i], doc.curves[0].points[i]); // exactly
        QCOMPARE(documentToJson(*back), json);
    }
    // Handles not on the rule (an imported path's corners): numbers, version 1.
    DocumentData plain;
    CurveRecord r = ruleComposite(knots, false);
    for (std::size_t i = 0; i < r.points.size(); ++i)
        if (i % 3 != 0)
            r.points[i] += geo::Point(1, 1);
    plain.curves.push_back(r);
    const QByteArray json = documentToJson(plain);
    QVERIFY(json.contains(R"("version": 1)"));
    QVERIFY(json.contains(R"("points": [[0.1,0.2],[)"));
    QCOMPARE(json.count("null"), 0);
}

void TestDocument::nullOnlyForRuleHandles_data()
{
    QTest::addColumn<QByteArray>("curve");
    QTest::addColumn<QString>("path");
    QTest::addRow("a knot")
        << QByteArray(R"({"kind": "composite", "nodeTypes": ["smooth", "smooth"], "points": [[0,0],null,null,null]})")
        << "curves[0].points[3]";
    QTest::addRow("a Bezier point") << QByteArray(R"({"kind": "bezier", "points": [[0,0],null,[1,1]]})")
                                    << "curves[0].points[1]";
    QTest::addRow("a count that is no composite curve")
        << QByteArray(R"({"kind": "composite", "nodeTypes": ["smooth", "smooth"], "points": [[0,0],null,[1,1]]})")
        << "curves[0].points[1]";
}

void TestDocument::nullOnlyForRuleHandles()
{
    QFETCH(QByteArray, curve);
    QFETCH(QString, path);
    auto r = documentFromJson(R"({"format": "kontur", "version": 2, "curves": [)" + curve + "]}");
    QVERIFY(!r.ok());
    QCOMPARE(r.error().path, path);
}

// Issue 17: a composite curve through 10^6 points (the stated limit), coordinates with 17 significant
// digits, is written in at most 60 MB (it was 145 MB, more than the reader took) and read back equal.
void TestDocument::millionKnotsCompact()
{
    std::vector<geo::Point> knots;
    knots.reserve(1'000'000);
    for (int i = 0; i < 1'000'000; ++i)
        knots.emplace_back(0.01 * i + 0.123456789, 50.0 * std::sin(0.001 * i) + 1.0 / 3.0);
    DocumentData doc;
    doc.curves.push_back(ruleComposite(knots, false));
    const QByteArray json = documentToJson(doc);
    QVERIFY2(json.size() <= 60'000'000, qPrintable(QString::number(json.size())));
    auto back = documentFromJson(json);
    QVERIFY2(back.ok(), qPrintable(back.ok() ? QString() : back.error().toString()));
    QVERIFY(back->curves[0].points == doc.curves[0].points);
}

void TestDocument::backgroundPathRelative()
{
    QTemporaryDir dir;
    QVERIFY(QDir(dir.path()).mkpath(QStringLiteral("docs/sub")));
    DocumentData doc;
    doc.background = BackgroundRecord{};
    doc.background->file = dir.filePath(QStringLiteral("scans/front.png"));
    const QString path = dir.filePath(QStringLiteral("docs/sub/a.kontur"));
    QVERIFY(saveDocument(path, doc).ok());
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QVERIFY(f.readAll().contains(R"("file": "../../scans/front.png")"));
    auto opened = openDocument(path);
    QVERIFY(opened.ok());
    QCOMPARE(opened->background->file, doc.background->file);
}

void TestDocument::failedSaveKeepsOldFile()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("a.kontur"));
    test::RandomDocuments random(5);
    DocumentData doc = random.document();
    doc.background.reset();
    QVERIFY(saveDocument(path, doc).ok());
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QByteArray before = f.readAll();
    f.close();
    DocumentData bad = doc;
    CurveRecord c;
    c.kind = QStringLiteral("bezier");
    c.points = {{0, 0}, {std::nan(""), 1}};
    bad.curves.push_back(c);
    auto r = saveDocument(path, bad);
    QVERIFY(!r.ok());
    QCOMPARE(r.error().path, QStringLiteral("curves[%1].points[1][0]").arg(bad.curves.size() - 1));
    // A write into a folder that does not exist fails too, and creates nothing.
    QVERIFY(!saveDocument(dir.filePath(QStringLiteral("missing/b.kontur")), doc).ok());
    QVERIFY(f.open(QIODevice::ReadOnly));
    QCOMPARE(f.readAll(), before);
}

void TestDocument::limits()
{
    Limits small;
    small.maxPoints = 3;
    small.maxCurves = 1;
    small.maxFileBytes = 400;
    auto r = documentFromJson(
        R"({"format": "kontur", "version": 1, "curves": [{"kind": "bezier", "points": [[0,0],[1,1],[2,2],[3,3]]}]})",
        {}, small);
    QVERIFY(!r.ok());
    QCOMPARE(r.error().code, ErrorCode::TooManyPoints);
    QCOMPARE(r.error().path, QStringLiteral("curves[0].points"));
    r = documentFromJson(
        R"({"format": "kontur", "version": 1, "curves": [{"kind": "bezier", "points": [[0,0],[1,1]]}, {"kind": "bezier", "points": [[0,0],[1,1]]}]})",
        {}, small);
    QVERIFY(!r.ok());
    QCOMPARE(r.error().code, ErrorCode::TooManyCurves);
    r = documentFromJson(QByteArray(500, ' '), {}, small);
    QVERIFY(!r.ok());
    QCOMPARE(r.error().code, ErrorCode::FileTooLarge);
    QTemporaryDir dir;
    QFile big(dir.filePath(QStringLiteral("big.kontur")));
    QVERIFY(big.open(QIODevice::WriteOnly));
    big.write(QByteArray(1000, ' '));
    big.close();
    r = openDocument(big.fileName(), small);
    QVERIFY(!r.ok());
    QCOMPARE(r.error().code, ErrorCode::FileTooLarge);
    r = openDocument(dir.filePath(QStringLiteral("none.kontur")));
    QVERIFY(!r.ok());
    QCOMPARE(r.error().code, ErrorCode::CannotOpen);
}

QTEST_GUILESS_MAIN(TestDocument)
#include "tst_document.moc"
