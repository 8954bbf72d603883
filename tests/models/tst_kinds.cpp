// The one table of curve kinds (geometry/curvekinds.h) and their names (models/document/kindnames.h):
// every kind has its entry, its id reads back, each fact of the table is what the shape builder and
// the document's curves do, the files know the same kinds, and every kind's name is translated in
// every language.
#include "geometry/curvekinds.h"
#include "geometry/curveshape.h"
#include "io/records.h"
#include "models/controllers/editcontroller.h"
#include "models/controllers/placement.h"
#include "models/document/curve.h"
#include "models/document/kindnames.h"

#include <QFile>
#include <QSet>
#include <QXmlStreamReader>
#include <QtTest>

#include <cmath>

using kontur::Curve;
using kontur::PointRole;
using kontur::geo::CurveKind;
using kontur::geo::KindTraits;
using kontur::geo::Point;
namespace geo = kontur::geo;

Q_DECLARE_METATYPE(CurveKind)

namespace {

// Knots with increasing x and uneven steps, so that the parameterizations differ and the function
// form applies; 4 of them for the kind that takes exactly 4.
std::vector<Point> pointsFor(const KindTraits &t)
{
    // The last y equals the first, so that the periodic spline has its function form too.
    std::vector<Point> p{{0, 0}, {3, 8}, {11, 10}, {14, 2}, {30, 0}};
    p.resize(static_cast<std::size_t>(std::min(t.maxPoints, 5)));
    return p;
}

geo::CurveParts partsOf(CurveKind kind, geo::Parameterization parameterization, bool function = false)
{
    geo::CurveParts parts;
    parts.kind = kind;
    parts.points = pointsFor(geo::traitsOf(kind));
    parts.parameterization = parameterization;
    parts.function = function;
    parts.order = geo::defaultOrder(parts.points.size());
    parts.tangentEnds = geo::defaultTangentEnds(parts);
    return parts;
}

double largestDistance(const geo::CurveShape &a, const geo::CurveShape &b)
{
    double most = 0.0;
    for (int i = 0; i <= 40; ++i) {
        const double ua = a.parameters().front() + (a.parameters().back() - a.parameters().front()) * i / 40.0;
        const double ub = b.parameters().front() + (b.parameters().back() - b.parameters().front()) * i / 40.0;
        most = std::max(most, (a.eval(ua) - b.eval(ub)).norm());
    }
    return most;
}

// The translations of context "kontur" in one .ts file: source → translation, without the unfinished ones.
QHash<QString, QString> finishedTranslations(const QString &path)
{
    QHash<QString, QString> out;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return out;
    QXmlStreamReader xml(&file);
    QString context, source;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement())
            continue;
        if (xml.name() == QLatin1String("name")) {
            context = xml.readElementText();
        } else if (xml.name() == QLatin1String("source")) {
            source = xml.readElementText();
        } else if (xml.name() == QLatin1String("translation")) {
            const bool unfinished = xml.attributes().value(QLatin1String("type")) == QLatin1String("unfinished");
            const QString text = xml.readElementText(QXmlStreamReader::IncludeChildElements);
            if (context == QLatin1String("kontur") && !unfinished)
                out.insert(source, text);
        }
    }
    return out;
}

} // namespace

class TestKinds final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void everyKindHasItsEntry();
    void factsAreWhatTheShapesDo_data();
    void factsAreWhatTheShapesDo();
    void filesKnowTheSameKinds();
    void everyKindIsNamedInEveryLanguage();
    void placementListsEveryKindWithNameAndIcon();
};

void TestKinds::everyKindHasItsEntry()
{
    QSet<QString> ids;
    for (int k = 0; k < geo::kKindCount; ++k) {
        const auto kind = static_cast<CurveKind>(k);
        const KindTraits &t = geo::traitsOf(kind);
        QCOMPARE(t.kind, kind);
        const QString id = QString::fromLatin1(t.id);
        QVERIFY2(!id.isEmpty(), qPrintable(QString::number(k)));
        QVERIFY2(!ids.contains(id), qPrintable(id));
        ids.insert(id);
        QCOMPARE(geo::kindId(kind), t.id);
        QVERIFY(geo::kindFromId(t.id) == kind);
        QVERIFY(t.minPoints >= 2 && t.minPoints <= t.maxPoints);
        QVERIFY(t.maxPoints <= geo::kManyPoints);
        QVERIFY(t.placementCount == 0 || (t.placementCount >= t.minPoints && t.placementCount <= t.maxPoints));
        // Tangents and the function form belong to the kinds whose points are knots.
        QVERIFY(!t.controlPolygon || (t.tangents == geo::KindTangents::None && !t.functionForm && !t.fitted));
    }
    QVERIFY(!geo::kindFromId("Bezier")); // ids are exact, lower case
    QVERIFY(!geo::kindFromId(""));
    QVERIFY(!geo::kindFromId("spline"));
}

void TestKinds::factsAreWhatTheShapesDo_data()
{
    QTest::addColumn<CurveKind>("kind");
    for (int k = 0; k < geo::kKindCount; ++k)
        if (static_cast<CurveKind>(k) != CurveKind::Composite) // built from its control vector, not by buildShape
            QTest::newRow(geo::kindId(static_cast<CurveKind>(k))) << static_cast<CurveKind>(k);
}

void TestKinds::factsAreWhatTheShapesDo()
{
    QFETCH(CurveKind, kind);
    const KindTraits &t = geo::traitsOf(kind);
    const geo::CurveParts parts = partsOf(kind, geo::Parameterization::Uniform);
    const auto shape = geo::buildShape(parts);
    QVERIFY2(shape.ok(), shape.ok() ? "" : shape.error().message.c_str());
    const int n = static_cast<int>(parts.points.size());

    // The tangent ends a new curve has.
    const int tangents = t.tangents == geo::KindTangents::AtEnds        ? 2
                         : t.tangents == geo::KindTangents::AtEveryKnot ? n
                                                                        : 0;
    QCOMPARE(static_cast<int>(parts.tangentEnds.size()), tangents);
    QCOMPARE(shape->closed, t.closed);
    QCOMPARE(shape->fit.has_value(), t.fitted);
    QCOMPARE(shape->hermite.has_value(), t.hermiteForm);
    if (t.takesOrder)
        QVERIFY(shape->bspline.has_value());
    if (t.knotToKnot)
        QCOMPARE(shape->segmentCount(), n - 1 + (t.closed ? 1 : 0));

    // A parameterization changes the curve exactly where it applies.
    const auto centripetal = geo::buildShape(partsOf(kind, geo::Parameterization::Centripetal));
    QVERIFY(centripetal.ok());
    QCOMPARE(largestDistance(*shape, *centripetal) > 1e-6, t.usesParameterization);

    // The function form y(x): built where the kind has one, refused elsewhere.
    const auto function = geo::buildShape(partsOf(kind, geo::Parameterization::Uniform, true));
    QCOMPARE(function.ok(), t.functionForm);

    // Each point's parameter: the curve passes through the point there.
    if (t.knotParameters) {
        const auto s = geo::knotParameters(parts);
        QVERIFY(s.ok());
        for (int i = 0; i < n; ++i)
            QVERIFY2(
                (shape->eval((*s)[static_cast<std::size_t>(i)]) - parts.points[static_cast<std::size_t>(i)]).norm() <
                    1e-9,
                qPrintable(QString::number(i)));
    }

    // The document's curve of the kind: what its rows are, whether it takes an order.
    Curve curve = Curve::make(kind, parts.points, geo::Parameterization::ChordLength);
    QVERIFY(!curve.problem());
    QCOMPARE(curve.row(0).role, t.controlPolygon ? PointRole::ControlPoint : PointRole::Knot);
    QCOMPARE(curve.row(0).editable, true);
    QCOMPARE(curve.isClosed(), t.closed);
    QCOMPARE(curve.tangentEnds().size(), static_cast<std::size_t>(tangents));
    QCOMPARE(curve.parameterization(),
             t.usesParameterization ? geo::Parameterization::ChordLength : geo::Parameterization::Uniform);
    QCOMPARE(curve.setOrder(3).ok(), t.takesOrder);
}

void TestKinds::filesKnowTheSameKinds()
{
    const std::vector<QString> known = kontur::io::knownKinds();
    QCOMPARE(static_cast<int>(known.size()), geo::kKindCount);
    for (int k = 0; k < geo::kKindCount; ++k) {
        const KindTraits &t = geo::traitsOf(static_cast<CurveKind>(k));
        QCOMPARE(known[static_cast<std::size_t>(k)], QString::fromLatin1(t.id));
        const kontur::io::KindInfo *info = kontur::io::kindInfo(QString::fromLatin1(t.id));
        QVERIFY(info);
        QCOMPARE(info->minPoints, t.minPoints);
        QCOMPARE(info->usesParameterization, t.usesParameterization);
        // The files' 0 is "no limit of its own", the table's kManyPoints.
        QVERIFY2(info->maxPoints == t.maxPoints || (info->maxPoints == 0 && t.maxPoints == geo::kManyPoints), t.id);
    }
}

void TestKinds::everyKindIsNamedInEveryLanguage()
{
    // English is the source text.
    QSet<QString> names;
    for (int k = 0; k < geo::kKindCount; ++k) {
        const auto kind = static_cast<CurveKind>(k);
        const QString name = kontur::kindName(kind);
        QVERIFY2(!name.isEmpty(), geo::kindId(kind));
        QVERIFY2(!names.contains(name), qPrintable(name));
        names.insert(name);
        const QString made = kontur::newCurveName(kind, 17);
        QVERIFY2(made.endsWith(QLatin1String(" 17")) && made.size() > 3, qPrintable(made));
        // The icon is one of the app's.
        const QString icon = QStringLiteral(KONTUR_SOURCE_DIR "/qml/icons/%1.svg").arg(kontur::kindIconName(kind));
        QVERIFY2(QFile::exists(icon), qPrintable(icon));
    }
    for (const char *language : {"lv", "sk", "bg", "ru"}) {
        const QString path = QStringLiteral(KONTUR_SOURCE_DIR "/i18n/kontur_%1.ts").arg(QLatin1String(language));
        const QHash<QString, QString> translations = finishedTranslations(path);
        QVERIFY2(!translations.isEmpty(), qPrintable(path));
        for (const QString &name : std::as_const(names)) {
            const QString translated = translations.value(name);
            QVERIFY2(!translated.trimmed().isEmpty(), qPrintable(QStringLiteral("%1: %2").arg(path, name)));
        }
    }
}

void TestKinds::placementListsEveryKindWithNameAndIcon()
{
    kontur::EditController editor;
    const QVariantList kinds = editor.placement()->kinds();
    QCOMPARE(kinds.size(), geo::kKindCount);
    for (int k = 0; k < geo::kKindCount; ++k) {
        const QVariantMap entry = kinds[k].toMap();
        QCOMPARE(entry.value(QStringLiteral("kind")).toInt(), k);
        QCOMPARE(entry.value(QStringLiteral("name")).toString(), kontur::kindName(static_cast<CurveKind>(k)));
        QCOMPARE(entry.value(QStringLiteral("icon")).toString(), kontur::kindIconName(static_cast<CurveKind>(k)));
        QCOMPARE(entry.value(QStringLiteral("usesParameterization")).toBool(),
                 geo::traitsOf(static_cast<CurveKind>(k)).usesParameterization);
    }
}

QTEST_GUILESS_MAIN(TestKinds)
#include "tst_kinds.moc"
