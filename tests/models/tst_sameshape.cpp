// One record, one curve: every kind the app creates, with each setting that changes its shape, is made
// through the app's editing API (typed coordinates, the parameterization and order settings, edited
// tangent ends, Close) and through the real kontur-cli binary (`spline` on a points file), and the two
// curves are sampled and compared to 1e-12 of the drawing's size. The function-spline teaching view's
// splines are compared with `kontur-cli spline --function` the same way.
#include "../curveids.h"
#include "geometry/parameterization.h"
#include "geometry/splines/knots.h"
#include "models/controllers/curvecommands.h"
#include "models/controllers/editcontroller.h"
#include "models/controllers/placement.h"
#include "models/document/document.h"
#include "models/teaching/functionspline.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <optional>

using kontur::CurveKind;
using kontur::EditController;
using kontur::PointRole;
using kontur::geo::Bezier;
using kontur::geo::Parameterization;
using kontur::geo::Point;

namespace {

// What a curve is made of and how it is set up, in the app and on the command line alike.
struct Case
{
    CurveKind kind = CurveKind::Bezier;
    std::vector<Point> points = {};
    Parameterization param = Parameterization::Uniform;
    int order = 0;                    // B-spline: set in the app, --order on the command line (0: the default)
    std::vector<Point> tangents = {}; // derivatives by the parameter: 2 (clamped, global B-spline) or one per knot
    bool closed = false;              // composite: Close
    QString cliKind = {};             // the --kind given (default the kind's id)
    QStringList cliExtra = {};        // more options for the command line
};

const std::vector<Point> kFive{{0, 0}, {10, 12}, {25, 15}, {40, 5}, {55, 9}};
const std::vector<Point> kSeven{{0, 0}, {3, 7}, {9, 11}, {16, 10}, {22, 4}, {27, -1}, {35, 2}};
const std::vector<Point> kLoop{{0, 0}, {20, -3}, {34, 10}, {28, 27}, {8, 30}, {-6, 14}};

std::vector<Point> far(const std::vector<Point> &points)
{
    std::vector<Point> out;
    for (const Point &p : points)
        out.push_back(Point(3.1e5, -7.7e4) + 1234.5 * p);
    return out;
}

QString number(double v)
{
    return QString::number(v, 'g', 17);
}

QString paramName(Parameterization p)
{
    return QString::fromLatin1(kontur::geo::nameOf(p));
}

// The tangent end the app keeps for a derivative m at knot k: the Bézier handle E = P + h·m/3 over the
// parameter step h next to the knot (the one after it; at the last knot the one before).
std::vector<Point> tangentEnds(const Case &c)
{
    const auto s = kontur::geo::splineParameters(c.points, c.param);
    if (!s)
        return {};
    const std::size_t n = c.points.size();
    const auto end = [&](std::size_t k, const Point &m) {
        const double h = k + 1 < n ? (*s)[k + 1] - (*s)[k] : (*s)[k] - (*s)[k - 1];
        return c.points[k] + m * (h / 3.0);
    };
    std::vector<Point> ends;
    if (c.tangents.size() == 2 && c.kind != CurveKind::HermiteSpline)
        return {end(0, c.tangents[0]), end(n - 1, c.tangents[1])};
    for (std::size_t k = 0; k < c.tangents.size(); ++k)
        ends.push_back(end(k, c.tangents[k]));
    return ends;
}

bool writePoints(const QString &path, const std::vector<Point> &points)
{
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Text))
        return false;
    for (const Point &p : points)
        f.write((number(p.x()) + QLatin1Char(' ') + number(p.y()) + QLatin1Char('\n')).toUtf8());
    return true;
}

// The curve as the command line draws it: its Bézier segments and whether it is closed.
struct Drawn
{
    std::vector<Bezier> segments;
    bool closed = false;
    QString error; // empty on success
};

Drawn runCli(const QStringList &args)
{
    QProcess p;
    p.start(QStringLiteral(KONTUR_CLI), args);
    Drawn out;
    if (!p.waitForFinished(60000) || p.exitCode() != 0) {
        out.error = QStringLiteral("exit %1: %2").arg(p.exitCode()).arg(QString::fromUtf8(p.readAllStandardError()));
        return out;
    }
    const QJsonObject json = QJsonDocument::fromJson(p.readAllStandardOutput()).object();
    out.closed = json.value(QStringLiteral("closed")).toBool();
    for (const QJsonValue &segment : json.value(QStringLiteral("segments")).toArray()) {
        std::vector<Point> control;
        for (const QJsonValue &xy : segment.toArray())
            control.emplace_back(xy.toArray().at(0).toDouble(), xy.toArray().at(1).toDouble());
        out.segments.emplace_back(std::move(control));
    }
    if (out.segments.empty())
        out.error = QStringLiteral("no segments");
    return out;
}

Drawn runCli(const Case &c, const QTemporaryDir &dir)
{
    const QString in = dir.filePath(QStringLiteral("points.txt"));
    if (!writePoints(in, c.points))
        return {{}, false, QStringLiteral("cannot write the points")};
    QStringList args{QStringLiteral("spline"),
                     QStringLiteral("--kind"),
                     c.cliKind.isEmpty() ? QString::fromLatin1(kontur::geo::kindId(c.kind)) : c.cliKind,
                     QStringLiteral("--param"),
                     paramName(c.param),
                     QStringLiteral("--in"),
                     in};
    if (c.order > 0)
        args << QStringLiteral("--order") << QString::number(c.order);
    if (c.closed)
        args << QStringLiteral("--closed");
    if (c.tangents.size() == 2 && c.kind != CurveKind::HermiteSpline) {
        args << QStringLiteral("--start-tangent=%1,%2").arg(number(c.tangents[0].x()), number(c.tangents[0].y()))
             << QStringLiteral("--end-tangent=%1,%2").arg(number(c.tangents[1].x()), number(c.tangents[1].y()));
    } else if (!c.tangents.empty()) {
        const QString file = dir.filePath(QStringLiteral("tangents.txt"));
        if (!writePoints(file, c.tangents))
            return {{}, false, QStringLiteral("cannot write the tangents")};
        args << QStringLiteral("--tangents") << file;
    }
    return runCli(args + c.cliExtra);
}

// The largest distance between two curves sampled at the same 33 parameters of each segment; NaN when
// their segment counts differ.
double largestDistance(const std::vector<Bezier> &a, const std::vector<Bezier> &b)
{
    if (a.size() != b.size())
        return std::nan("");
    double most = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
        for (int k = 0; k <= 32; ++k)
            most = std::max(most, (a[i].eval(k / 32.0) - b[i].eval(k / 32.0)).norm());
    return most;
}

// The size the tolerance is relative to: the larger side of the points' bounding box.
double sizeOf(const std::vector<Point> &points)
{
    Point lo = points.front(), hi = points.front();
    for (const Point &p : points) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    return std::max((hi - lo).maxCoeff(), 1.0);
}

} // namespace

Q_DECLARE_METATYPE(Case)

class TestSameShape final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void appAndCliDrawTheSameCurve_data();
    void appAndCliDrawTheSameCurve();
    void everyKindIsCovered();
    void functionViewAndCliDrawTheSameCurve_data();
    void functionViewAndCliDrawTheSameCurve();

private:
    QList<CurveKind> m_covered;
};

void TestSameShape::appAndCliDrawTheSameCurve_data()
{
    QTest::addColumn<Case>("c");
    const Parameterization params[] = {Parameterization::Uniform, Parameterization::ChordLength,
                                       Parameterization::Centripetal};
    const auto add = [](const QString &name, const Case &c) { QTest::newRow(qPrintable(name)) << c; };
    add(QStringLiteral("bezier"), {CurveKind::Bezier, kFive});
    add(QStringLiteral("bezier quadratic"), {CurveKind::Bezier, {{0, 0}, {5, 9}, {12, 1}}});
    add(QStringLiteral("composite"), {CurveKind::Composite, kFive});
    add(QStringLiteral("composite closed"), {CurveKind::Composite, kLoop, {}, 0, {}, true});
    add(QStringLiteral("contour"), {CurveKind::Contour, kFive});
    add(QStringLiteral("contour even"), {CurveKind::Contour, kLoop});
    add(QStringLiteral("function-spline"), {CurveKind::FunctionSpline, kFive});
    add(QStringLiteral("function-spline as natural --function"), {CurveKind::FunctionSpline,
                                                                  kFive,
                                                                  {},
                                                                  0,
                                                                  {},
                                                                  false,
                                                                  QStringLiteral("natural"),
                                                                  {QStringLiteral("--function")}});
    for (int order : {0, 2, 3, 4, 5})
        add(QStringLiteral("bspline order %1").arg(order), {CurveKind::BSpline, kSeven, {}, order});
    add(QStringLiteral("bspline 3 points, default order"), {CurveKind::BSpline, {{0, 0}, {5, 9}, {12, 1}}});
    for (Parameterization p : params) {
        const QString pn = paramName(p);
        add(QStringLiteral("interpolating %1").arg(pn),
            {CurveKind::Interpolating, {kFive.begin(), kFive.end() - 1}, p});
        add(QStringLiteral("least-squares %1").arg(pn), {CurveKind::LeastSquares, kSeven, p});
        add(QStringLiteral("natural %1").arg(pn), {CurveKind::NaturalSpline, kFive, p});
        add(QStringLiteral("not-a-knot %1").arg(pn), {CurveKind::NotAKnotSpline, kSeven, p});
        add(QStringLiteral("periodic %1").arg(pn), {CurveKind::PeriodicSpline, kLoop, p});
        std::vector<Point> repeated = kLoop;
        repeated.push_back(kLoop.front());
        add(QStringLiteral("periodic %1, first point repeated").arg(pn), {CurveKind::PeriodicSpline, repeated, p});
        add(QStringLiteral("catmull-rom %1").arg(pn), {CurveKind::CatmullRom, kSeven, p});
        add(QStringLiteral("hermite %1").arg(pn), {CurveKind::HermiteSpline, kSeven, p});
        add(QStringLiteral("hermite %1 far from the origin").arg(pn), {CurveKind::HermiteSpline, far(kSeven), p});
        add(QStringLiteral("hermite %1 with tangents").arg(pn),
            {CurveKind::HermiteSpline, kFive, p, 0, {{1, 2}, {3, -1}, {0.5, 0.25}, {2, 0}, {-1, 4}}});
        add(QStringLiteral("clamped %1").arg(pn), {CurveKind::ClampedSpline, kFive, p});
        add(QStringLiteral("clamped %1 with tangents").arg(pn),
            {CurveKind::ClampedSpline, kFive, p, 0, {{0, 3}, {2, 2}}});
        add(QStringLiteral("global-bspline %1").arg(pn), {CurveKind::GlobalBSpline, kSeven, p});
        add(QStringLiteral("global-bspline %1 with tangents").arg(pn),
            {CurveKind::GlobalBSpline, kSeven, p, 0, {{1, -1}, {0.2, 3}}});
        add(QStringLiteral("polynomial %1").arg(pn), {CurveKind::Polynomial, kFive, p});
    }
}

void TestSameShape::appAndCliDrawTheSameCurve()
{
    QFETCH(Case, c);
    m_covered << c.kind;

    // The app: typed coordinates make the curve (Placement), then its settings as the side panel sets them.
    EditController editor;
    editor.placement()->setParameterization(static_cast<int>(c.param));
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(c.kind), kontur::test::rowsOf(c.points)));
    const int id = kontur::test::idAt(editor, 0);
    if (c.order > 0)
        QVERIFY(editor.commands()->setCurveOrder(id, c.order));
    if (c.closed)
        QVERIFY(editor.commands()->closeCurve(id));
    if (!c.tangents.empty()) {
        const std::vector<Point> ends = tangentEnds(c);
        QVariantList edits;
        std::size_t next = 0;
        const kontur::Curve &curve = editor.document()->curve(0);
        for (int row = 0; row < curve.rowCount() && next < ends.size(); ++row)
            if (curve.row(row).role == PointRole::TangentEnd) {
                edits << QVariantMap{{QStringLiteral("row"), row},
                                     {QStringLiteral("x"), ends[next].x()},
                                     {QStringLiteral("y"), ends[next].y()}};
                ++next;
            }
        QCOMPARE(next, ends.size());
        QVERIFY(editor.commands()->applyEdits(id, edits));
        QCOMPARE(editor.document()->curve(0).tangentEnds(), ends);
    }
    const kontur::Curve &curve = editor.document()->curve(0);
    QVERIFY2(!curve.problem(), curve.problem() ? curve.problem()->message.c_str() : "");
    const kontur::geo::PiecewiseBezier app = curve.toPiecewise();
    QVERIFY(!app.segments().empty());

    // The command line, on a file of the same points with the same settings.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const Drawn cli = runCli(c, dir);
    QVERIFY2(cli.error.isEmpty(), qPrintable(cli.error));
    QCOMPARE(cli.closed, app.isClosed());
    QCOMPARE(cli.segments.size(), app.segments().size());
    const double distance = largestDistance(app.segments(), cli.segments);
    const double size = sizeOf(c.points);
    qInfo("largest distance %.3g (%.3g of the size)", distance, distance / size);
    QVERIFY2(distance <= 1e-12 * size, qPrintable(QStringLiteral("the curves differ by %1").arg(distance)));
}

void TestSameShape::everyKindIsCovered()
{
    // Every kind the app can create appeared above (the rows ran before this function).
    for (int k = 0; k < kontur::geo::kKindCount; ++k)
        QVERIFY2(m_covered.contains(static_cast<CurveKind>(k)), kontur::geo::kindId(static_cast<CurveKind>(k)));
}

void TestSameShape::functionViewAndCliDrawTheSameCurve_data()
{
    QTest::addColumn<int>("method");
    QTest::addColumn<std::vector<double>>("derivatives");
    QTest::addColumn<int>("solver");
    QTest::addColumn<QStringList>("cli");
    using Plot = kontur::FunctionSplinePlot;
    QTest::newRow("natural") << int(Plot::Natural) << std::vector<double>{} << int(Plot::Classical)
                             << QStringList{QStringLiteral("--kind"), QStringLiteral("function-spline")};
    QTest::newRow("clamped") << int(Plot::Clamped) << std::vector<double>{0.5, -2.0} << int(Plot::Classical)
                             << QStringList{QStringLiteral("--kind"), QStringLiteral("clamped"),
                                            QStringLiteral("--function"), QStringLiteral("--start-tangent=1,0.5"),
                                            QStringLiteral("--end-tangent=1,-2")};
    QTest::newRow("clamped, Török") << int(Plot::Clamped) << std::vector<double>{0.5, -2.0} << int(Plot::Torok)
                                    << QStringList{QStringLiteral("--kind"),
                                                   QStringLiteral("clamped"),
                                                   QStringLiteral("--function"),
                                                   QStringLiteral("--solver"),
                                                   QStringLiteral("torok"),
                                                   QStringLiteral("--start-tangent=1,0.5"),
                                                   QStringLiteral("--end-tangent=1,-2")};
    QTest::newRow("hermite") << int(Plot::Hermite) << std::vector<double>{1, -0.5, 0, 2, 0.25, -1}
                             << int(Plot::Classical)
                             << QStringList{QStringLiteral("--kind"), QStringLiteral("hermite"),
                                            QStringLiteral("--function"), QStringLiteral("--tangents")};
    QTest::newRow("global B-spline") << int(Plot::GlobalBSpline) << std::vector<double>{-1, 3} << int(Plot::Classical)
                                     << QStringList{QStringLiteral("--kind"), QStringLiteral("global-bspline"),
                                                    QStringLiteral("--function"),
                                                    QStringLiteral("--start-tangent=1,-1"),
                                                    QStringLiteral("--end-tangent=1,3")};
}

void TestSameShape::functionViewAndCliDrawTheSameCurve()
{
    QFETCH(int, method);
    QFETCH(std::vector<double>, derivatives);
    QFETCH(int, solver);
    QFETCH(QStringList, cli);
    // Six values over evenly spaced knots on [0, 3] (Török's solver needs them even).
    kontur::FunctionSplineInput input;
    input.method = method;
    input.uniform = true;
    input.a = 0.0;
    input.b = 3.0;
    input.values = {1.0, 2.5, -0.5, 0.75, 3.0, 2.0};
    input.derivatives = derivatives;
    input.solver = solver;
    kontur::FunctionSplinePlot plot;
    plot.setInput(input);
    const std::vector<Bezier> view = plot.exactPieces();
    QVERIFY(!view.empty());

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    std::vector<Point> points = {};
    const std::vector<double> x = plot.dotX();
    QCOMPARE(x.size(), input.values.size());
    for (std::size_t i = 0; i < x.size(); ++i)
        points.emplace_back(x[i], input.values[i]);
    const QString in = dir.filePath(QStringLiteral("values.txt"));
    QVERIFY(writePoints(in, points));
    QStringList args{QStringLiteral("spline"), QStringLiteral("--in"), in};
    if (cli.endsWith(QStringLiteral("--tangents"))) {
        std::vector<Point> slopes;
        for (double d : derivatives)
            slopes.emplace_back(1.0, d);
        const QString file = dir.filePath(QStringLiteral("slopes.txt"));
        QVERIFY(writePoints(file, slopes));
        cli << file;
    }
    const Drawn drawn = runCli(args + cli);
    QVERIFY2(drawn.error.isEmpty(), qPrintable(drawn.error));
    QCOMPARE(drawn.segments.size(), view.size());
    const double distance = largestDistance(view, drawn.segments);
    qInfo("largest distance %.3g", distance);
    QVERIFY2(distance <= 1e-12 * sizeOf(points), qPrintable(QStringLiteral("the curves differ by %1").arg(distance)));
}

QTEST_GUILESS_MAIN(TestSameShape)
#include "tst_sameshape.moc"
