// Random well-formed records and documents of every curve kind for the round-trip property tests of
// src/io, from a seeded generator so a failing case can be replayed by its seed; the rows of those
// tests and the place of a reader's error as one comparable text.
#pragma once

#include "io/error.h"
#include "io/records.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QTest>

#include <bit>
#include <cstdint>
#include <random>

namespace kontur::io::test {

class RandomDocuments final
{
public:
    explicit RandomDocuments(std::uint32_t seed)
        : m_rng(seed)
    {
    }

    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(m_rng); }
    bool coin() { return integer(0, 1) == 1; }

    // Doubles that are hard to print: plain, tiny, huge, integral, subnormal, any finite bit pattern.
    double number()
    {
        switch (integer(0, 6)) {
        case 0:
            return std::uniform_real_distribution<double>(-1000, 1000)(m_rng);
        case 1:
            return integer(-100, 100);
        case 2:
            return integer(-9, 9) / 10.0;
        case 3:
            return std::ldexp(std::uniform_real_distribution<double>(-1, 1)(m_rng), integer(-1074, 1023));
        case 4:
            return std::uniform_real_distribution<double>(-1, 1)(m_rng) * 1e-300;
        case 5: {
            double v = 0;
            do {
                v = std::bit_cast<double>(std::uniform_int_distribution<std::uint64_t>()(m_rng));
            } while (!std::isfinite(v));
            return v;
        }
        default:
            return 0.1 * integer(-30, 30);
        }
    }
    geo::Point point() { return {number(), number()}; }

    QString text()
    {
        static const QString pieces[] = {QStringLiteral("Curve"),  QStringLiteral(" "),      QStringLiteral("\"q\""),
                                         QStringLiteral("\\"),     QStringLiteral("#1"),     QStringLiteral("Līkne"),
                                         QStringLiteral("Кривая"), QStringLiteral("křivka"), QStringLiteral("\t")};
        QString s;
        for (int i = integer(0, 4); i > 0; --i)
            s += pieces[integer(0, 8)];
        return s;
    }
    QString color() { return QStringLiteral("#%1").arg(integer(0, 0xffffff), 6, 16, QLatin1Char('0')); }

    QJsonObject settings(int depth = 0)
    {
        QJsonObject o;
        for (int i = integer(0, depth == 0 ? 4 : 2); i > 0; --i) {
            const QString key = QStringLiteral("k%1").arg(integer(0, 20));
            switch (integer(0, depth < 3 ? 5 : 3)) {
            case 0:
                o.insert(key, number());
                break;
            case 1:
                o.insert(key, text());
                break;
            case 2:
                o.insert(key, coin());
                break;
            case 3:
                o.insert(key, integer(-5, 5));
                break;
            case 4:
                o.insert(key, settings(depth + 1));
                break;
            default:
                o.insert(key, QJsonArray{number(), text(), QJsonValue()});
                break;
            }
        }
        return o;
    }

    // A well-formed record of the given kind (validateCurve accepts it).
    CurveRecord curve(const QString &kind)
    {
        CurveRecord c;
        c.kind = kind;
        c.name = text();
        c.color = color();
        c.visible = coin();
        c.locked = coin();
        c.settings = coin() ? settings() : QJsonObject{};
        static const QString params[] = {QStringLiteral("uniform"), QStringLiteral("chord"),
                                         QStringLiteral("centripetal")};
        static const QString types[] = {QStringLiteral("smooth"), QStringLiteral("symmetric"),
                                        QStringLiteral("corner")};
        int n = 0;
        if (kind == QLatin1String("bezier")) {
            n = integer(2, 8);
        } else if (kind == QLatin1String("interpolating")) {
            n = 4;
            c.parameterization = params[integer(0, 2)];
        } else if (kind == QLatin1String("least-squares")) {
            n = integer(4, 20);
            c.parameterization = params[integer(0, 2)];
        } else if (kind == QLatin1String("composite")) {
            c.closed = coin();
            const int knots = integer(c.closed ? 3 : 2, 8);
            n = c.closed ? 3 * knots : 3 * knots - 2;
            for (int i = 0; i < knots; ++i)
                c.nodeTypes.push_back(types[integer(0, 2)]);
        } else if (const KindInfo *info = kindInfo(kind)) {
            // The spline kinds: their own point limits and parameterization.
            const int most = info->maxPoints > 0 ? info->maxPoints : info->minPoints + 8;
            n = integer(info->minPoints, std::min(most, info->minPoints + 8));
            if (info->usesParameterization)
                c.parameterization = params[integer(0, 2)];
        }
        for (int i = 0; i < n; ++i)
            c.points.push_back(point());
        return c;
    }

    DocumentData document()
    {
        DocumentData d;
        static const QString units[] = {QStringLiteral("px"), QStringLiteral("mm"), QStringLiteral("cm"),
                                        QStringLiteral("in"), QStringLiteral("pt")};
        d.units = units[integer(0, 4)];
        const std::vector<QString> kinds = knownKinds();
        for (int i = integer(0, 6); i > 0; --i)
            d.curves.push_back(curve(kinds[static_cast<std::size_t>(integer(0, static_cast<int>(kinds.size()) - 1))]));
        if (coin()) {
            BackgroundRecord b;
            b.file = coin() ? QString() : QStringLiteral("pictures/scan %1.png").arg(integer(0, 9));
            b.visible = coin();
            b.opacity = std::uniform_real_distribution<double>(0, 1)(m_rng);
            b.originX = number();
            b.originY = number();
            b.scale = std::abs(number()) + 1e-3;
            b.rotation = number();
            b.calibrated = coin();
            if (b.calibrated) {
                b.ax = number();
                b.ay = number();
                b.bx = number();
                b.by = number();
                b.distance = std::abs(number()) + 1.0;
            }
            d.background = b;
        }
        return d;
    }

private:
    std::mt19937 m_rng;
};

// The rows "seed 1" … "seed count" of a round-trip property test, in the column "seed".
inline void addSeedRows(int count)
{
    QTest::addColumn<int>("seed");
    for (int seed = 1; seed <= count; ++seed)
        QTest::addRow("seed %d", seed) << seed;
}

// "code line:column" of a reader's error ("ok" for a result), so that one QCOMPARE checks all three
// and a failure shows all three.
inline QString errorPlace(const QString &code, int line, int column)
{
    return QStringLiteral("%1 %2:%3").arg(code).arg(line).arg(column);
}
template <typename T> QString errorPlace(const Result<T> &r)
{
    if (r.ok())
        return QStringLiteral("ok");
    return errorPlace(QLatin1String(codeName(r.error().code)), r.error().line, r.error().column);
}

} // namespace kontur::io::test
