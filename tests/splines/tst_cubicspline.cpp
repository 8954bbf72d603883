// Interpolating cubic splines (issue 4): natural, clamped, not-a-knot and periodic, parametric and
// y(x); interpolation, C² joints, the end conditions, exact reproduction of lines and cubics, the
// O(n) solvers against dense ones, conversion to Bézier pieces, bad input and a million points.
#include "geometry/splines/cubicspline.h"
#include "geometry/splines/knots.h"
#include "geometry/splines/tridiagonal.h"
#include "splinetestutil.h"

#include <Eigen/Dense>
#include <QtTest>

#include <cmath>
#include <limits>

using namespace kontur::geo;
using namespace kontur::test;

Q_DECLARE_METATYPE(kontur::geo::EndCondition)
Q_DECLARE_METATYPE(kontur::geo::Parameterization)

namespace {

// splineParameters as it was before its two passes (the steps, then their running sum) became
// one: the reference for parametersMatchTwoPassReference.
Result<std::vector<double>> referenceSplineParameters(std::span<const Point> points, Parameterization p, bool closed)
{
    const std::size_t n = points.size();
    const std::size_t need = closed ? 3 : 2;
    if (n < need)
        return Error{ErrorCode::TooFewPoints, "at least " + std::to_string(need) + " points are needed",
                     static_cast<int>(n)};
    const double alpha = exponentOf(p);
    std::vector<double> s(closed ? n + 1 : n);
    s[0] = 0.0;
    const std::size_t steps = closed ? n : n - 1;
    // Pass 1, the steps |Δp|^α with no dependency between iterations, so that the loops (one per
    // common exponent: std::pow would dominate a million-point spline) vectorise.
    // (The closing step of a closed curve, i = n, wraps to the first point.)
    // Distances on the points scaled to unit size by 2^-k (exact; no squares overflow at 1e160 or
    // underflow at 1e-170), then scaled back: chord steps by 2^k, centripetal ones by 2^(k/2).
    const int k = scaleExponent(points);
    const double unit = std::ldexp(1.0, -k);
    const double back = std::ldexp(1.0, k);
    const double backRoot = std::ldexp((k & 1) != 0 ? std::sqrt(2.0) : 1.0, (k - (k & 1)) / 2); // 2^(k/2)
    auto distance = [&](std::size_t i) { return unitDistance(points[i - 1], points[i], unit); };
    const double closing = closed ? unitDistance(points[n - 1], points[0], unit) : 0.0;
    const std::size_t open = n - 1;
    std::size_t zeroSteps = 0;
    if (alpha == 1.0) {
        for (std::size_t i = 1; i <= open; ++i) {
            const double d = distance(i);
            zeroSteps += d == 0.0 ? 1 : 0;
            s[i] = d * back;
        }
    } else if (alpha == 0.5) {
        for (std::size_t i = 1; i <= open; ++i) {
            const double d = distance(i);
            zeroSteps += d == 0.0 ? 1 : 0;
            s[i] = std::sqrt(d) * backRoot;
        }
    } else {
        for (std::size_t i = 1; i <= open; ++i) {
            const double d = distance(i);
            zeroSteps += d == 0.0 ? 1 : 0;
            s[i] = alpha == 0.0 ? (d - d) + 1.0 : std::pow(d * back, alpha); // (d - d) + 1: NaN for a non-finite d
        }
    }
    if (closed) {
        zeroSteps += closing == 0.0 ? 1 : 0;
        s[n] = alpha == 1.0   ? closing * back
               : alpha == 0.5 ? std::sqrt(closing) * backRoot
               : alpha == 0.0 ? (closing - closing) + 1.0
                              : std::pow(closing * back, alpha);
    }
    const bool zeroStep = zeroSteps > 0;
    // Pass 2, the running sum; a step below the rounding of the sum would repeat a parameter.
    bool increasing = true;
    for (std::size_t i = 1; i <= steps; ++i) {
        s[i] += s[i - 1];
        increasing = increasing && s[i] > s[i - 1];
    }
    if (!std::isfinite(s[steps]) || !points[0].allFinite()) {
        // The normalised parameterization names the culprit (a non-finite point, or an overflow).
        auto normalised = parameterize(points, p);
        if (!normalised)
            return normalised.error();
        return Error{ErrorCode::NonFiniteInput, "the points are too far apart to measure", -1};
    }
    if (zeroStep) {
        auto normalised = parameterize(points, p);
        if (!normalised)
            return normalised.error(); // all points equal, or coincident (chord, centripetal)
        for (std::size_t i = 1; i <= steps; ++i) {
            const std::size_t j = i == n ? 0 : i;
            if (points[j] == points[i - 1])
                return Error{ErrorCode::CoincidentPoints,
                             "points " + std::to_string(i - 1) + " and " + std::to_string(j) + " coincide",
                             static_cast<int>(j)};
        }
    }
    if (!increasing)
        return checkStrictlyIncreasing(s, "parameter").error();
    return s;
}

// The open-end sweep of cubicSplineDerivatives as it was before each sweep carried the divided
// difference it shares with the next row: every row built anew from its two segments (two
// divisions), then the same two-ended elimination and back substitution. The reference for
// sweepMatchesRowByRowReference.
std::vector<Point> referenceOpenSweep(std::span<const double> s, std::span<const Point> v, EndCondition end,
                                      const Point &d0, const Point &dn)
{
    const std::size_t n = v.size();
    auto h = [&](std::size_t i) { return s[i + 1] - s[i]; };
    auto delta = [&](std::size_t i) -> Point { return (v[i + 1] - v[i]) / h(i); };
    struct Row
    {
        double a, b, c;
        Point r;
    };
    auto row = [&](std::size_t i) -> Row {
        if (i == 0) {
            if (end == EndCondition::Natural)
                return {0.0, 2.0, 1.0, Point(3.0 * delta(0))};
            if (end == EndCondition::NotAKnot) {
                const double h0 = h(0), h1 = h(1);
                return {0.0, h1, h0 + h1,
                        Point(((h0 + 2.0 * (h0 + h1)) * h1 * delta(0) + h0 * h0 * delta(1)) / (h0 + h1))};
            }
            return {0.0, 1.0, 0.0, d0};
        }
        if (i == n - 1) {
            if (end == EndCondition::Natural)
                return {1.0, 2.0, 0.0, Point(3.0 * delta(n - 2))};
            if (end == EndCondition::NotAKnot) {
                const double ha = h(n - 3), hb = h(n - 2), xn = ha + hb;
                return {xn, ha, 0.0, Point((hb * hb * delta(n - 3) + (2.0 * xn + hb) * ha * delta(n - 2)) / xn)};
            }
            return {0.0, 1.0, 0.0, dn};
        }
        const double hp = s[i] - s[i - 1], hi = s[i + 1] - s[i];
        const Point dp = (v[i] - v[i - 1]) / hp, di = (v[i + 1] - v[i]) / hi;
        return {hi, 2.0 * (hp + hi), hp, Point(3.0 * (hi * dp + hp * di))};
    };
    std::vector<double> w(n);
    std::vector<Point> m(n);
    const std::size_t k = n / 2;
    double wTop = 0.0, wBottom = 0.0;
    Point gTop = Point::Zero(), gBottom = Point::Zero();
    auto step = [&](std::size_t i, bool fromTop, double &wPrev, Point &gPrev) {
        const Row q = row(i);
        const double eliminated = fromTop ? q.a : q.c, next = fromTop ? q.c : q.a;
        const double inv = 1.0 / (q.b - eliminated * wPrev);
        wPrev = next * inv;
        gPrev = (q.r - eliminated * gPrev) * inv;
        w[i] = wPrev;
        m[i] = gPrev;
    };
    for (std::size_t i = 0; i < k; ++i)
        step(i, true, wTop, gTop);
    for (std::size_t i = n - 1; i > k; --i)
        step(i, false, wBottom, gBottom);
    const Row q = row(k);
    const double wl = k > 0 ? w[k - 1] : 0.0, wr = k + 1 < n ? w[k + 1] : 0.0;
    const Point gl = k > 0 ? m[k - 1] : Point::Zero(), gr = k + 1 < n ? m[k + 1] : Point::Zero();
    m[k] = (q.r - q.a * gl - q.c * gr) / (q.b - q.a * wl - q.c * wr);
    for (std::size_t i = k; i-- > 0;)
        m[i] = m[i] - w[i] * m[i + 1];
    for (std::size_t i = k + 1; i < n; ++i)
        m[i] = m[i] - w[i] * m[i - 1];
    return m;
}

// How two parameter results differ (empty when they do not): the same error code and index, or
// the same values bit for bit.
QString differenceOf(const Result<std::vector<double>> &fast, const Result<std::vector<double>> &reference)
{
    if (fast.ok() != reference.ok())
        return fast.ok() ? QStringLiteral("an error expected") : QStringLiteral("an unexpected error");
    if (!reference.ok())
        return fast.error().code == reference.error().code && fast.error().index == reference.error().index
                   ? QString()
                   : QStringLiteral("another error");
    if (fast->size() != reference->size())
        return QStringLiteral("%1 values, %2 expected").arg(fast->size()).arg(reference->size());
    for (std::size_t i = 0; i < fast->size(); ++i)
        if (!((*fast)[i] == (*reference)[i]))
            return QStringLiteral("value %1: %2, %3 expected")
                .arg(i)
                .arg((*fast)[i], 0, 'g', 17)
                .arg((*reference)[i], 0, 'g', 17);
    return {};
}

// Second derivative with respect to the global parameter on each side of joint i (between segment
// i - 1 and i), from the Bézier pieces.
std::pair<Point, Point> secondDerivatives(const HermiteSpline &s, int joint)
{
    const auto &u = s.parameters();
    const int left = joint == 0 ? s.segmentCount() - 1 : joint - 1;
    const auto l = static_cast<std::size_t>(left), r = static_cast<std::size_t>(joint);
    const double hl = u[l + 1] - u[l], hr = u[r + 1] - u[r];
    return {s.segment(left).derivative(1.0, 2) / (hl * hl), s.segment(joint).derivative(0.0, 2) / (hr * hr)};
}

} // namespace

class TestCubicSpline final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // The spline's sweep, which also copies the points and checks the tangents as it goes, against
    // the plain sweep (cubicSplineDerivatives) on the same parameters: the same tangents bit for bit
    // and the points copied exactly, for every end condition and sizes 2…600.
    void sweepWithCopyMatchesPlainSweep()
    {
        std::mt19937_64 rng(4322);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        const EndCondition ends[] = {EndCondition::Natural, EndCondition::Clamped, EndCondition::NotAKnot,
                                     EndCondition::Periodic};
        for (int trial = 0; trial < 400; ++trial) {
            const int n = 2 + static_cast<int>(unit(rng) * 600);
            const auto pts = randomPoints(rng, n);
            const Point t0 = randomPoints(rng, 1, -5, 5)[0], t1 = randomPoints(rng, 1, -5, 5)[0];
            for (EndCondition end : ends) {
                if (end == EndCondition::Periodic && n < 3)
                    continue;
                const auto spline = cubicSpline(pts, end, Parameterization::ChordLength, t0, t1);
                QVERIFY(spline.ok());
                std::vector<Point> m(spline->tangents().size());
                QVERIFY(cubicSplineDerivatives(spline->parameters(), pts, end, t0, t1, m));
                QCOMPARE(spline->points().size(), pts.size());
                for (std::size_t i = 0; i < pts.size(); ++i)
                    QVERIFY(spline->points()[i] == pts[i]);
                for (std::size_t i = 0; i < m.size(); ++i)
                    QVERIFY2(spline->tangents()[i] == m[i], qPrintable(QStringLiteral("n %1, %2").arg(n).arg(i)));
            }
        }
    }

    // The sweep that carries each row's shared divided difference against the row-by-row reference
    // above: the same tangents bit for bit, for the open end conditions, sizes 2…700 and points from
    // 1e-6 to 1e6 across (uneven steps, so the carried and the fresh divisions would differ if they
    // were not the same expressions).
    void sweepMatchesRowByRowReference()
    {
        std::mt19937_64 rng(77031);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        const EndCondition ends[] = {EndCondition::Natural, EndCondition::Clamped, EndCondition::NotAKnot};
        for (int trial = 0; trial < 300; ++trial) {
            const int n = 2 + static_cast<int>(unit(rng) * 700);
            const double size = std::pow(10.0, -6.0 + 12.0 * unit(rng));
            const auto pts = randomPoints(rng, n, -size, size);
            const Point t0 = randomPoints(rng, 1, -5, 5)[0], t1 = randomPoints(rng, 1, -5, 5)[0];
            const auto s = splineParameters(pts, Parameterization::Centripetal, false);
            QVERIFY(s.ok());
            for (EndCondition end : ends) {
                if (end == EndCondition::NotAKnot && n <= 3)
                    continue; // the closed forms of the line and the parabola, no sweep
                std::vector<Point> m(pts.size());
                QVERIFY(cubicSplineDerivatives(*s, pts, end, t0, t1, m));
                const auto reference = referenceOpenSweep(*s, pts, end, t0, t1);
                for (std::size_t i = 0; i < m.size(); ++i)
                    QVERIFY2(m[i] == reference[i],
                             qPrintable(QStringLiteral("%1, n %2, row %3").arg(nameOf(end)).arg(n).arg(i)));
            }
        }
    }

    // From kSplineTwoThreadRows knots on, the sweep's halves run on two threads: the same tangents
    // bit for bit as the row-by-row reference just below, at and above that size, and a solution
    // that overflows in either half is still refused.
    void twoThreadSweepMatchesReference()
    {
        std::mt19937_64 rng(5511);
        const EndCondition ends[] = {EndCondition::Natural, EndCondition::Clamped, EndCondition::NotAKnot};
        const std::size_t at = kSplineTwoThreadRows;
        for (std::size_t n : {at - 1, at, at + 1, 3 * at + 7}) {
            const auto pts = randomPoints(rng, static_cast<int>(n), -1e3, 1e3);
            const auto s = splineParameters(pts, Parameterization::ChordLength, false);
            QVERIFY(s.ok());
            for (EndCondition end : ends) {
                std::vector<Point> m(n);
                QVERIFY(cubicSplineDerivatives(*s, pts, end, Point(1, 2), Point(-3, 1), m));
                const auto reference = referenceOpenSweep(*s, pts, end, Point(1, 2), Point(-3, 1));
                std::size_t differ = 0;
                for (std::size_t i = 0; i < n; ++i)
                    differ += m[i] == reference[i] ? 0 : 1;
                QVERIFY2(differ == 0,
                         qPrintable(QStringLiteral("%1, n %2: %3 rows differ").arg(nameOf(end)).arg(n).arg(differ)));
            }
        }
        for (std::size_t bad : {std::size_t(10), 2 * at + 5}) { // in the top half, in the bottom half
            const std::size_t n = 2 * at + 11;
            std::vector<Point> pts(n);
            std::vector<double> u(n);
            for (std::size_t i = 0; i < n; ++i) {
                // Within 2^200, where the spline is built without scaling (and its checks).
                pts[i] = Point(1e59 * static_cast<double>(i % 7), static_cast<double>(i % 3));
                u[i] = 0.2 * (static_cast<double>(i) - static_cast<double>(bad)); // u[bad] = 0
            }
            u[bad + 1] = 1e-290;
            const auto r = cubicSpline(u, pts, EndCondition::Natural);
            QVERIFY(!r.ok());
            QCOMPARE(r.error().code, ErrorCode::NonFiniteInput);
        }
    }

    // A solution that overflows from finite input (a step of 1e-290 in the parameter under a chord
    // of 1e59) is refused, whether the sweep checks it as it goes (open ends) or a pass after it
    // does (periodic), and so is one at the middle row and at either end.
    void overflowIsReported()
    {
        const EndCondition ends[] = {EndCondition::Natural, EndCondition::Clamped, EndCondition::NotAKnot,
                                     EndCondition::Periodic};
        for (EndCondition end : ends)
            for (std::size_t at : {0u, 2u, 3u}) {
                const std::vector<Point> pts{{0, 0}, {1e59, 0}, {2e59, 1}, {3e59, 0}, {4e59, 2}};
                std::vector<double> u(end == EndCondition::Periodic ? 6 : 5);
                for (std::size_t i = 0; i < u.size(); ++i)
                    u[i] = 0.2 * (static_cast<double>(i) - static_cast<double>(at)); // u[at] = 0
                u[at + 1] = 1e-290;
                const auto r = cubicSpline(u, pts, end, Point(1, 0), Point(1, 0));
                QVERIFY2(!r.ok(), nameOf(end));
                QCOMPARE(r.error().code, ErrorCode::NonFiniteInput);
            }
    }

    // The one-pass spline parameters against the two-pass reference above: the same sums in the same
    // order, so the same bits, and the same errors, on random walks at scales 1e-170…1e160 (which
    // take the paths with and without scaling), open and closed, every parameterization, with
    // coincident and non-finite points mixed in.
    void parametersMatchTwoPassReference()
    {
        std::mt19937_64 rng(4321);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        const double scales[] = {1e-170, 1e-6, 1.0, 1e3, 1e6, 1e160};
        const Parameterization params[] = {Parameterization::Uniform, Parameterization::ChordLength,
                                           Parameterization::Centripetal};
        int compared = 0, errors = 0;
        for (int trial = 0; trial < 3000; ++trial) {
            const double scale = scales[trial % 6];
            const int n = 2 + static_cast<int>(unit(rng) * 300);
            std::vector<Point> pts(static_cast<std::size_t>(n));
            Point p(0, 0);
            for (auto &q : pts) {
                p += scale * Point(unit(rng) - 0.3, unit(rng) - 0.5);
                q = p;
            }
            const int defect = trial % 10;
            if (defect == 7) // two coincident points
                pts[static_cast<std::size_t>(unit(rng) * (n - 1)) + 1] = pts[0];
            if (defect == 8 && n > 2) {
                const auto i = static_cast<std::size_t>(unit(rng) * (n - 1));
                pts[i + 1] = pts[i];
            }
            if (defect == 9)
                pts[static_cast<std::size_t>(unit(rng) * n)].y() = std::nan("");
            for (Parameterization param : params)
                for (bool closed : {false, true}) {
                    const auto reference = referenceSplineParameters(pts, param, closed);
                    const QString difference = differenceOf(splineParameters(pts, param, closed), reference);
                    QVERIFY2(difference.isEmpty(),
                             qPrintable(QStringLiteral("trial %1: %2").arg(trial).arg(difference)));
                    ++(reference.ok() ? compared : errors);
                }
        }
        QVERIFY(compared > 10000);
        QVERIFY(errors > 1000);
    }

    // The one-pass chord parameters (with the exponent found beside them) against splineParameters
    // with scaleExponent: the same bits, exponent and errors, on random walks at scales 1e-300…1e300,
    // open and closed, with uneven points mixed in (a coordinate or a step far below the others,
    // subnormal ones, where scaling would lose bits and the pass must fall back), coincident and
    // non-finite ones.
    void chordParametersMatchTwoPasses()
    {
        std::mt19937_64 rng(9123);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        const double scales[] = {1e-300, 1e-170, 1e-60, 1e-6, 1.0, 1e3, 1e60, 1e160, 1e300};
        int compared = 0, errors = 0;
        for (int trial = 0; trial < 4000; ++trial) {
            const double scale = scales[trial % 9];
            const int n = 2 + static_cast<int>(unit(rng) * 200);
            std::vector<Point> pts(static_cast<std::size_t>(n));
            Point p(0, 0);
            for (auto &q : pts) {
                p += scale * Point(unit(rng) - 0.3, unit(rng) - 0.5);
                q = p;
            }
            auto any = [&] { return static_cast<std::size_t>(unit(rng) * n); };
            switch ((trial / 9) % 9) {
            case 1: // one coordinate far below the rest, or subnormal
                pts[any()].x() = scale * std::ldexp(1.0, -900 - static_cast<int>(unit(rng) * 150));
                break;
            case 2: // a step far below the coordinates
                if (n > 2) {
                    const std::size_t i = any() % static_cast<std::size_t>(n - 1);
                    pts[i + 1] =
                        pts[i] +
                        Point(std::ldexp(std::abs(pts[i].x()) + scale, -40 - static_cast<int>(unit(rng) * 700)), 0);
                }
                break;
            case 3: // a subnormal step next to 0
                pts[0] = Point(0, 0);
                pts[1] = Point(4.9e-324 * (1 + static_cast<int>(unit(rng) * 1000)), 0);
                break;
            case 4:
                pts[any()] = pts[0];
                break;
            case 5:
                pts[any()].y() = std::nan("");
                break;
            case 6:
                pts[any()].x() = std::numeric_limits<double>::infinity();
                break;
            default:
                break;
            }
            for (bool closed : {false, true}) {
                int exponent = 12345;
                const auto fast = chordParameters(pts, closed, exponent);
                QCOMPARE(exponent, scaleExponent(pts));
                const auto reference = splineParameters(pts, Parameterization::ChordLength, closed, scaleExponent(pts));
                const QString difference = differenceOf(fast, reference);
                QVERIFY2(difference.isEmpty(), qPrintable(QStringLiteral("trial %1: %2").arg(trial).arg(difference)));
                ++(reference.ok() ? compared : errors);
            }
        }
        QVERIFY(compared > 4000);
        QVERIFY(errors > 2000);
    }

    void properties_data()
    {
        QTest::addColumn<EndCondition>("end");
        QTest::addColumn<Parameterization>("param");
        QTest::addColumn<int>("count");
        const EndCondition ends[] = {EndCondition::Natural, EndCondition::Clamped, EndCondition::NotAKnot,
                                     EndCondition::Periodic};
        const Parameterization params[] = {Parameterization::Uniform, Parameterization::ChordLength,
                                           Parameterization::Centripetal};
        for (EndCondition e : ends)
            for (Parameterization p : params)
                for (int n : {2, 3, 4, 5, 9, 40}) {
                    if (e == EndCondition::Periodic && n < 3)
                        continue;
                    QTest::addRow("%s/%s/%d", nameOf(e), nameOf(p), n) << e << p << n;
                }
    }

    // Interpolation at every knot, C² at the joints (jump < 1e-9 relative), the end conditions, and
    // Bézier pieces that evaluate like the spline.
    void properties()
    {
        QFETCH(EndCondition, end);
        QFETCH(Parameterization, param);
        QFETCH(int, count);
        std::mt19937_64 rng(1000 + count);
        for (int trial = 0; trial < 20; ++trial) {
            const auto pts = randomPoints(rng, count);
            const Point t0 = randomPoints(rng, 1, -5, 5)[0], t1 = randomPoints(rng, 1, -5, 5)[0];
            auto r = cubicSpline(pts, end, param, t0, t1);
            QVERIFY2(r.ok(), r.ok() ? "" : r.error().message.c_str());
            const HermiteSpline &s = *r;
            const double scale = scaleOf(pts);
            const auto &u = s.parameters();
            QCOMPARE(s.isClosed(), end == EndCondition::Periodic);
            QCOMPARE(s.segmentCount(), end == EndCondition::Periodic ? count : count - 1);
            for (int i = 0; i < count; ++i)
                QVERIFY2(near(s.eval(u[static_cast<std::size_t>(i)]), pts[static_cast<std::size_t>(i)], 1e-12 * scale),
                         qPrintable(QStringLiteral("knot %1").arg(i)));
            // C² at the interior joints (and the closing one when periodic).
            const int firstJoint = end == EndCondition::Periodic ? 0 : 1;
            for (int j = firstJoint; j < s.segmentCount(); ++j) {
                if (end != EndCondition::Periodic && j >= count - 1)
                    break;
                const auto [a, b] = secondDerivatives(s, j);
                QVERIFY2((a - b).norm() <= 1e-9 * std::max({a.norm(), b.norm(), 1.0}),
                         qPrintable(QStringLiteral("joint %1: %2 vs %3").arg(j).arg(str(a), str(b))));
            }
            if (end == EndCondition::Natural) {
                QVERIFY(s.derivative(u.front(), 2).norm() <= 1e-9 * scale);
                QVERIFY(s.derivative(u.back(), 2).norm() <= 1e-9 * scale);
            }
            if (end == EndCondition::Clamped) {
                QVERIFY(near(s.derivative(u.front()), t0, 1e-9 * (1 + t0.norm())));
                QVERIFY(near(s.derivative(u.back()), t1, 1e-9 * (1 + t1.norm())));
            }
            if (end == EndCondition::NotAKnot && count >= 4) {
                // The third derivative is continuous at the second and last-but-one knot.
                for (int j : {1, count - 2}) {
                    const auto k = static_cast<std::size_t>(j);
                    const Point a = s.derivative(0.5 * (u[k - 1] + u[k]), 3);
                    const Point b = s.derivative(0.5 * (u[k] + u[k + 1]), 3);
                    QVERIFY2((a - b).norm() <= 1e-7 * std::max({a.norm(), b.norm(), 1.0}),
                             qPrintable(QStringLiteral("knot %1: %2 vs %3").arg(j).arg(str(a), str(b))));
                }
            }
            if (end == EndCondition::Periodic)
                QVERIFY(near(s.eval(u.back()), pts.front(), 1e-12 * scale));
            // Bézier pieces, the flat control array and sorted evaluation agree with eval.
            const PiecewiseBezier pw = s.toPiecewise();
            QCOMPARE(pw.segmentCount(), s.segmentCount());
            QCOMPARE(pw.isClosed(), s.isClosed());
            const auto flat = s.bezierControlPoints();
            QCOMPARE(flat.size(), 3 * static_cast<std::size_t>(s.segmentCount()) + 1);
            std::uniform_real_distribution<double> pick(u.front(), u.back());
            std::vector<double> us(50);
            for (auto &x : us)
                x = pick(rng);
            std::sort(us.begin(), us.end());
            std::vector<Point> sorted(us.size());
            s.evalSorted(us, sorted);
            for (std::size_t k = 0; k < us.size(); ++k) {
                const Point direct = s.eval(us[k]);
                QVERIFY(near(evalPieces(pw, u, us[k]), direct, 1e-12 * scale));
                QVERIFY(near(sorted[k], direct, 1e-12 * scale));
            }
            // For uniform parameters the Bézier pieces' own report sees C² at every joint.
            if (param == Parameterization::Uniform)
                for (const auto &jc : pw.continuity(1e-8))
                    QCOMPARE(jc.level, Continuity::C2);
        }
    }

    void parametersUnnormalised()
    {
        const std::vector<Point> pts{{0, 0}, {3, 4}, {3, 4 + 9}, {3 + 16, 13}};
        auto chord = splineParameters(pts, Parameterization::ChordLength);
        QVERIFY(chord.ok());
        QCOMPARE(*chord, (std::vector<double>{0, 5, 14, 30}));
        auto centripetal = splineParameters(pts, Parameterization::Centripetal);
        QVERIFY(centripetal.ok());
        QVERIFY(near((*centripetal)[3], std::sqrt(5.0) + 3.0 + 4.0, 1e-15));
        auto uniform = splineParameters(pts, Parameterization::Uniform);
        QCOMPARE(*uniform, (std::vector<double>{0, 1, 2, 3}));
        auto closed = splineParameters(pts, Parameterization::ChordLength, true);
        QCOMPARE(closed->size(), 5u);
        QVERIFY(near(closed->back(), 30 + std::hypot(19.0, 13.0), 1e-12));
    }

    // Exact reproduction: natural splines reproduce lines; clamped (with exact slopes) and
    // not-a-knot reproduce every cubic; periodic reproduces a constant.
    void reproduction_data()
    {
        QTest::addColumn<EndCondition>("end");
        QTest::addColumn<int>("degree");
        QTest::addRow("natural/line") << EndCondition::Natural << 1;
        QTest::addRow("clamped/cubic") << EndCondition::Clamped << 3;
        QTest::addRow("not-a-knot/cubic") << EndCondition::NotAKnot << 3;
        QTest::addRow("not-a-knot/parabola, 3 points") << EndCondition::NotAKnot << 2;
    }

    void reproduction()
    {
        QFETCH(EndCondition, end);
        QFETCH(int, degree);
        std::mt19937_64 rng(7);
        auto f = [](double x) { return 0.5 - 1.5 * x + 0.25 * x * x - 0.125 * x * x * x; };
        auto df = [](double x) { return -1.5 + 0.5 * x - 0.375 * x * x; };
        auto line = [](double x) { return 2.0 - 0.75 * x; };
        auto parabola = [](double x) { return 1.0 + x - 0.5 * x * x; };
        for (int trial = 0; trial < 10; ++trial) {
            const int n = degree == 2 ? 3 : 7;
            const auto x = randomIncreasing(rng, n, -4.0);
            std::vector<double> y(x.size());
            for (std::size_t i = 0; i < x.size(); ++i)
                y[i] = degree == 1 ? line(x[i]) : degree == 2 ? parabola(x[i]) : f(x[i]);
            auto s = functionSpline(x, y, end, df(x.front()), df(x.back()));
            QVERIFY(s.ok());
            for (double t = x.front(); t <= x.back(); t += 0.05) {
                const double want = degree == 1 ? line(t) : degree == 2 ? parabola(t) : f(t);
                QVERIFY2(near(s->functionValue(t), want, 1e-11 * (1 + std::abs(want))),
                         qPrintable(QStringLiteral("x=%1: %2 vs %3").arg(t).arg(s->functionValue(t)).arg(want)));
                QVERIFY(near(s->eval(t).x(), t, 1e-12 * (1 + std::abs(t)))); // the graph: x(u) = u
            }
        }
    }

    void periodicFunction()
    {
        // Samples of sin over one period: the periodic spline is close to sin and C² across the seam.
        const int n = 25;
        std::vector<double> x(n), y(n);
        for (int i = 0; i < n; ++i) {
            x[static_cast<std::size_t>(i)] = 2 * M_PI * i / (n - 1);
            y[static_cast<std::size_t>(i)] = std::sin(x[static_cast<std::size_t>(i)]);
        }
        y.back() = y.front();
        auto s = functionSpline(x, y, EndCondition::Periodic);
        QVERIFY(s.ok());
        for (double t = 0; t <= 2 * M_PI; t += 0.01)
            QVERIFY(std::abs(s->functionValue(t) - std::sin(t)) < 2e-4);
        QVERIFY(near(s->derivative(0.0).y(), s->derivative(2 * M_PI).y(), 1e-12));
        QVERIFY(near(s->derivative(0.0, 2).y(), s->derivative(2 * M_PI, 2).y(), 1e-9));
        auto bad = functionSpline(x, x, EndCondition::Periodic); // y_0 != y_{n-1}
        QCOMPARE(bad.error().code, ErrorCode::InvalidArgument);
    }

    // The O(n) solvers against Eigen's dense LU on random diagonally dominant systems.
    void solvers_data()
    {
        QTest::addColumn<int>("n");
        QTest::addColumn<bool>("cyclic");
        for (int n : {1, 2, 3, 4, 7, 30})
            QTest::addRow("tridiagonal %d", n) << n << false;
        for (int n : {3, 4, 7, 30})
            QTest::addRow("cyclic %d", n) << n << true;
    }

    void solvers()
    {
        QFETCH(int, n);
        QFETCH(bool, cyclic);
        std::mt19937_64 rng(static_cast<unsigned>(n));
        const auto a = randomValues(rng, n, -1, 1), c = randomValues(rng, n, -1, 1);
        auto b = randomValues(rng, n, 2.5, 4);
        const auto d = randomValues(rng, n);
        Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
        for (int i = 0; i < n; ++i) {
            const auto k = static_cast<std::size_t>(i);
            m(i, i) = b[k];
            if (i > 0)
                m(i, i - 1) = a[k];
            else if (cyclic)
                m(0, n - 1) = a[0];
            if (i + 1 < n)
                m(i, i + 1) = c[k];
            else if (cyclic)
                m(n - 1, 0) = c[k];
        }
        Eigen::VectorXd rhs = Eigen::Map<const Eigen::VectorXd>(d.data(), n);
        Eigen::VectorXd want = m.partialPivLu().solve(rhs);
        std::vector<double> x = d;
        const bool ok = cyclic ? solveCyclicTridiagonal<double>(a, b, c, x) : solveTridiagonal<double>(a, b, c, x);
        QVERIFY(ok);
        for (int i = 0; i < n; ++i)
            QVERIFY(near(x[static_cast<std::size_t>(i)], want(i), 1e-12 * (1 + std::abs(want(i)))));
    }

    void badInput_data()
    {
        QTest::addColumn<std::vector<double>>("xs");
        QTest::addColumn<std::vector<double>>("ys");
        QTest::addColumn<EndCondition>("end");
        QTest::addColumn<int>("code");
        const double nan = std::nan("");
        QTest::addRow("one point") << std::vector<double>{1} << std::vector<double>{1} << EndCondition::Natural
                                   << int(ErrorCode::TooFewPoints);
        QTest::addRow("periodic, two points") << std::vector<double>{0, 1} << std::vector<double>{0, 1}
                                              << EndCondition::Periodic << int(ErrorCode::TooFewPoints);
        QTest::addRow("coincident") << std::vector<double>{0, 1, 1, 2} << std::vector<double>{0, 1, 1, 0}
                                    << EndCondition::Natural << int(ErrorCode::CoincidentPoints);
        QTest::addRow("all equal") << std::vector<double>{1, 1, 1} << std::vector<double>{2, 2, 2}
                                   << EndCondition::NotAKnot << int(ErrorCode::AllPointsEqual);
        QTest::addRow("nan") << std::vector<double>{0, nan, 2} << std::vector<double>{0, 1, 0} << EndCondition::Natural
                             << int(ErrorCode::NonFiniteInput);
        QTest::addRow("periodic, closing repeats") << std::vector<double>{0, 1, 0} << std::vector<double>{0, 1, 0}
                                                   << EndCondition::Periodic << int(ErrorCode::TooFewPoints);
    }

    // Typed errors, never NaN, for the parametric form.
    void badInput()
    {
        QFETCH(std::vector<double>, xs);
        QFETCH(std::vector<double>, ys);
        QFETCH(EndCondition, end);
        QFETCH(int, code);
        std::vector<Point> pts;
        for (std::size_t i = 0; i < xs.size(); ++i)
            pts.emplace_back(xs[i], ys[i]);
        auto r = cubicSpline(pts, end, Parameterization::ChordLength, Point(1, 0), Point(1, 0));
        QVERIFY(!r.ok());
        QCOMPARE(int(r.error().code), code);
        QVERIFY(!r.error().message.empty());
    }

    void badFunctionInput()
    {
        const std::vector<double> y{1, 2, 3};
        QCOMPARE(functionSpline(std::vector<double>{0, 2, 1}, y, EndCondition::Natural).error().code,
                 ErrorCode::InvalidArgument);
        QCOMPARE(functionSpline(std::vector<double>{0, 1, 1}, y, EndCondition::Natural).error().index, 2);
        QCOMPARE(functionSpline(std::vector<double>{0, 1}, y, EndCondition::Natural).error().code,
                 ErrorCode::InvalidArgument);
        QCOMPARE(functionSpline(std::vector<double>{0, 1, 2}, y, EndCondition::Clamped, std::nan(""), 0).error().code,
                 ErrorCode::NonFiniteInput);
        // A zero-length end tangent is valid (issue #17): the first handle lies on the first point
        // (p0 + h m0 / 3 with m0 = 0) and the end derivative is the one given.
        const std::vector<Point> pts{{0, 0}, {1, 1}, {2, 0}};
        auto r = cubicSpline(pts, EndCondition::Clamped, Parameterization::ChordLength, Point(0, 0), Point(1, 0));
        QVERIFY(r.ok());
        QCOMPARE(r->segmentControlPoints(0)[1], Point(0, 0));
        QVERIFY((r->derivative(r->endParameter()) - Point(1, 0)).norm() < 1e-12);
        QVERIFY((r->eval(r->parameters()[1]) - Point(1, 1)).norm() < 1e-12);
        // Explicit parameters that do not increase.
        auto p = cubicSpline(std::vector<double>{0, 2, 1}, pts, EndCondition::Natural);
        QCOMPARE(p.error().code, ErrorCode::InvalidArgument);
    }

    // 10⁶ points work (and a closed curve of 10⁶ points too).
    void millionPoints()
    {
        std::mt19937_64 rng(99);
        const auto pts = randomPoints(rng, 1'000'000);
        for (EndCondition e : {EndCondition::Natural, EndCondition::Periodic}) {
            auto s = cubicSpline(pts, e, Parameterization::ChordLength);
            QVERIFY(s.ok());
            QCOMPARE(s->pointCount(), 1'000'000);
            for (int i : {0, 1, 499'999, 999'999}) {
                const auto k = static_cast<std::size_t>(i);
                QVERIFY(near(s->eval(s->parameters()[k]), pts[k], 1e-9));
            }
            for (const Point &m : s->tangents())
                QVERIFY(std::isfinite(m.x()) && std::isfinite(m.y()));
        }
    }
};

QTEST_GUILESS_MAIN(TestCubicSpline)
#include "tst_cubicspline.moc"
