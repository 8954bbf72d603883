// SVG path data parser (see svgpath.h).
#include "io/svgpath.h"

#include "io/fileio.h"

#include <cmath>
#include <numbers>

namespace kontur::io {

namespace {

bool isWsp(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f';
}

class Scanner final
{
public:
    explicit Scanner(std::string_view d)
        : m_d(d)
    {
    }

    void skipWsp()
    {
        while (m_pos < m_d.size() && isWsp(m_d[m_pos]))
            ++m_pos;
    }
    // Blanks, at most one comma, blanks (the comma-wsp of the grammar).
    void skipCommaWsp()
    {
        skipWsp();
        if (m_pos < m_d.size() && m_d[m_pos] == ',') {
            ++m_pos;
            skipWsp();
        }
    }
    [[nodiscard]] bool atEnd() const { return m_pos >= m_d.size(); }
    [[nodiscard]] char peek() const { return atEnd() ? '\0' : m_d[m_pos]; }
    [[nodiscard]] std::size_t pos() const { return m_pos; }
    void advance() { ++m_pos; }
    // True when a number starts here (the start of an implicit repetition of the last command).
    [[nodiscard]] bool numberAhead() const
    {
        const char c = peek();
        return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.';
    }

    // number ::= sign? (digits ('.' digits?)? | '.' digits) exponent?; the longest match, so
    // ".5.5" is two numbers and "-1-2" too.
    bool number(double &out)
    {
        const std::size_t start = m_pos;
        const std::size_t length = numberLength(m_d.substr(start));
        if (length == 0)
            return false;
        const std::size_t i = start + length;
        if (parseDouble(m_d.substr(start, i - start), out) != NumberStatus::Ok)
            return false;
        m_pos = i;
        return true;
    }
    // An arc flag: a single '0' or '1', which need no separator after it.
    bool flag(bool &out)
    {
        if (peek() != '0' && peek() != '1')
            return false;
        out = peek() == '1';
        ++m_pos;
        return true;
    }

private:
    std::string_view m_d;
    std::size_t m_pos = 0;
};

Error pathError(std::size_t at, const QString &message, ErrorCode code = ErrorCode::PathSyntax)
{
    Error e;
    e.code = code;
    e.column = static_cast<int>(at) + 1;
    e.message = message;
    return e;
}

// sin⁶(θ/4)/cos²(θ/4) · 4/27: the radial error bound of the cubic through an arc of angle θ with
// handles of length 4/3 tan(θ/4) on the unit circle (Goldapp 1991).
double arcErrorBound(double theta)
{
    const double s = std::sin(std::abs(theta) / 4.0), c = std::cos(std::abs(theta) / 4.0);
    return 4.0 / 27.0 * std::pow(s, 6) / (c * c);
}

} // namespace

std::vector<geo::Bezier> arcToCubics(const geo::Point &center, double rx, double ry, double phi, double theta1,
                                     double dtheta, double tolerance)
{
    const double r = std::max(rx, ry);
    if (!std::isfinite(r) || !std::isfinite(dtheta) || !std::isfinite(theta1) || !std::isfinite(phi) ||
        !center.allFinite())
        return {};
    int n = std::max(1, static_cast<int>(std::ceil(std::abs(dtheta) / (std::numbers::pi / 2) - 1e-12)));
    if (!(tolerance > 0.0))
        tolerance = 1e-6;
    while (n < 4096 && r * arcErrorBound(dtheta / n) > tolerance)
        n *= 2;
    const double step = dtheta / n;
    const double k = 4.0 / 3.0 * std::tan(step / 4.0);
    const double cp = std::cos(phi), sp = std::sin(phi);
    // Point and derivative direction on the ellipse at angle t (SVG's parameterisation, F.6.3).
    const auto at = [&](double t) {
        const double x = rx * std::cos(t), y = ry * std::sin(t);
        return geo::Point(center.x() + cp * x - sp * y, center.y() + sp * x + cp * y);
    };
    const auto tangent = [&](double t) {
        const double x = -rx * std::sin(t), y = ry * std::cos(t);
        return geo::Point(cp * x - sp * y, sp * x + cp * y);
    };
    std::vector<geo::Bezier> out;
    out.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        const double a = theta1 + i * step, b = theta1 + (i + 1) * step;
        const geo::Point p0 = at(a), p3 = at(b);
        out.emplace_back(std::vector<geo::Point>{p0, p0 + k * tangent(a), p3 - k * tangent(b), p3});
    }
    return out;
}

Result<std::vector<geo::PiecewiseBezier>> parseSvgPathData(std::string_view d, const SvgPathOptions &options)
{
    std::vector<geo::PiecewiseBezier> out;
    std::vector<geo::Bezier> segments;
    qint64 total = 0;
    geo::Point cur = geo::Point::Zero(), start = geo::Point::Zero();
    geo::Point lastCubic = cur, lastQuad = cur; // second control point of the last C/S, control point of the last Q/T
    bool hasCubic = false, hasQuad = false, open = false;

    const auto flush = [&](bool closed) {
        if (!segments.empty())
            out.emplace_back(std::move(segments), closed);
        segments.clear();
    };
    const auto add = [&](std::vector<geo::Point> pts, std::size_t at) -> std::optional<Error> {
        if (++total > options.maxSegments)
            return pathError(at, QStringLiteral("more than %1 segments in one path").arg(options.maxSegments),
                             ErrorCode::TooManyPoints);
        segments.emplace_back(std::move(pts));
        return std::nullopt;
    };

    Scanner s(d);
    s.skipWsp();
    char command = 0;
    while (true) {
        s.skipWsp();
        if (s.atEnd())
            break;
        const std::size_t cmdAt = s.pos();
        const char c = s.peek();
        if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z')) {
            command = c;
            s.advance();
            s.skipWsp();
        } else if (command == 0) {
            return pathError(cmdAt, QStringLiteral("path data must start with a moveto (M or m)"));
        } else if (command == 'z' || command == 'Z' || !s.numberAhead()) {
            return pathError(cmdAt, QStringLiteral("expected a path command"));
        }
        // Else: an implicit repetition of the previous command (after M/m it is L/l).
        if (std::string_view("MmZzLlHhVvCcSsQqTtAa").find(command) == std::string_view::npos)
            return pathError(cmdAt, QStringLiteral("unknown path command '%1'").arg(QLatin1Char(command)));
        if (!open && command != 'M' && command != 'm')
            return pathError(cmdAt, QStringLiteral("path data must start with a moveto (M or m)"));

        const bool rel = command >= 'a' && command <= 'z';
        const geo::Point base = rel ? cur : geo::Point::Zero();
        double v[7] = {};
        const auto numbers = [&](int n) -> std::optional<Error> {
            for (int i = 0; i < n; ++i) {
                if (i > 0)
                    s.skipCommaWsp();
                if (!s.number(v[i]))
                    return pathError(s.pos(), QStringLiteral("expected a number for '%1'").arg(QLatin1Char(command)));
            }
            return std::nullopt;
        };
        const auto endArgs = [&] { s.skipCommaWsp(); };
        bool keepCubic = false, keepQuad = false;

        switch (command) {
        case 'M':
        case 'm': {
            if (auto e = numbers(2))
                return *e;
            flush(false);
            cur = base + geo::Point(v[0], v[1]);
            start = cur;
            open = true;
            command = rel ? 'l' : 'L'; // implicit repetitions are linetos
            break;
        }
        case 'Z':
        case 'z': {
            if (cur != start)
                if (auto e = add({cur, start}, cmdAt))
                    return *e;
            cur = start;
            flush(true);
            // A command after Z starts a new subpath at the same point.
            break;
        }
        case 'L':
        case 'l': {
            if (auto e = numbers(2))
                return *e;
            const geo::Point p = base + geo::Point(v[0], v[1]);
            if (auto e = add({cur, p}, cmdAt))
                return *e;
            cur = p;
            break;
        }
        case 'H':
        case 'h':
        case 'V':
        case 'v': {
            if (auto e = numbers(1))
                return *e;
            geo::Point p = cur;
            if (command == 'H' || command == 'h')
                p.x() = (rel ? cur.x() : 0.0) + v[0];
            else
                p.y() = (rel ? cur.y() : 0.0) + v[0];
            if (auto e = add({cur, p}, cmdAt))
                return *e;
            cur = p;
            break;
        }
        case 'C':
        case 'c':
        case 'S':
        case 's': {
            const bool smooth = command == 'S' || command == 's';
            if (auto e = numbers(smooth ? 4 : 6))
                return *e;
            geo::Point c1, c2, p;
            if (smooth) {
                c1 = hasCubic ? geo::Point(2 * cur - lastCubic) : cur;
                c2 = base + geo::Point(v[0], v[1]);
                p = base + geo::Point(v[2], v[3]);
            } else {
                c1 = base + geo::Point(v[0], v[1]);
                c2 = base + geo::Point(v[2], v[3]);
                p = base + geo::Point(v[4], v[5]);
            }
            if (auto e = add({cur, c1, c2, p}, cmdAt))
                return *e;
            lastCubic = c2;
            keepCubic = true;
            cur = p;
            break;
        }
        case 'Q':
        case 'q':
        case 'T':
        case 't': {
            const bool smooth = command == 'T' || command == 't';
            if (auto e = numbers(smooth ? 2 : 4))
                return *e;
            geo::Point c1, p;
            if (smooth) {
                c1 = hasQuad ? geo::Point(2 * cur - lastQuad) : cur;
                p = base + geo::Point(v[0], v[1]);
            } else {
                c1 = base + geo::Point(v[0], v[1]);
                p = base + geo::Point(v[2], v[3]);
            }
            if (auto e = add({cur, c1, p}, cmdAt))
                return *e;
            lastQuad = c1;
            keepQuad = true;
            cur = p;
            break;
        }
        case 'A':
        case 'a': {
            // rx ry phi large-arc sweep x y; the flags may follow each other without separators.
            if (auto e = numbers(3))
                return *e;
            bool large = false, sweep = false;
            s.skipCommaWsp();
            if (!s.flag(large))
                return pathError(s.pos(), QStringLiteral("expected an arc flag (0 or 1)"));
            s.skipCommaWsp();
            if (!s.flag(sweep))
                return pathError(s.pos(), QStringLiteral("expected an arc flag (0 or 1)"));
            s.skipCommaWsp();
            double xy[2];
            for (int i = 0; i < 2; ++i) {
                if (i > 0)
                    s.skipCommaWsp();
                if (!s.number(xy[i]))
                    return pathError(s.pos(), QStringLiteral("expected a number for '%1'").arg(QLatin1Char(command)));
            }
            const geo::Point p = base + geo::Point(xy[0], xy[1]);
            double rx = std::abs(v[0]), ry = std::abs(v[1]);
            const double phi = v[2] * std::numbers::pi / 180.0;
            if (p == cur)
                break; // SVG F.6.2: an arc to the current point is omitted
            if (rx == 0.0 || ry == 0.0) {
                if (auto e = add({cur, p}, cmdAt)) // F.6.2: a straight line
                    return *e;
                cur = p;
                break;
            }
            // Endpoint to center parameterisation, SVG 1.1 F.6.5, with out-of-range radii scaled up (F.6.6).
            const double cp = std::cos(phi), sp = std::sin(phi);
            const double dx = (cur.x() - p.x()) / 2, dy = (cur.y() - p.y()) / 2;
            const double x1 = cp * dx + sp * dy, y1 = -sp * dx + cp * dy;
            const double lambda = (x1 * x1) / (rx * rx) + (y1 * y1) / (ry * ry);
            if (lambda > 1) {
                rx *= std::sqrt(lambda);
                ry *= std::sqrt(lambda);
            }
            const double num = rx * rx * ry * ry - rx * rx * y1 * y1 - ry * ry * x1 * x1;
            const double den = rx * rx * y1 * y1 + ry * ry * x1 * x1;
            double coef = den > 0 ? std::sqrt(std::max(0.0, num / den)) : 0.0;
            if (large == sweep)
                coef = -coef;
            const double cx1 = coef * rx * y1 / ry, cy1 = -coef * ry * x1 / rx;
            const geo::Point center(cp * cx1 - sp * cy1 + (cur.x() + p.x()) / 2,
                                    sp * cx1 + cp * cy1 + (cur.y() + p.y()) / 2);
            const auto angle = [](double ux, double uy, double vx, double vy) {
                return std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
            };
            const double theta1 = angle(1, 0, (x1 - cx1) / rx, (y1 - cy1) / ry);
            double dtheta = angle((x1 - cx1) / rx, (y1 - cy1) / ry, (-x1 - cx1) / rx, (-y1 - cy1) / ry);
            // Radii so large that their squares overflow leave nothing finite to draw (found by fuzzing).
            if (!std::isfinite(rx) || !std::isfinite(ry) || !center.allFinite() || !std::isfinite(theta1) ||
                !std::isfinite(dtheta))
                return pathError(cmdAt, QStringLiteral("the arc's radii are too large to compute"));
            if (!sweep && dtheta > 0)
                dtheta -= 2 * std::numbers::pi;
            else if (sweep && dtheta < 0)
                dtheta += 2 * std::numbers::pi;
            std::vector<geo::Bezier> arcs = arcToCubics(center, rx, ry, phi, theta1, dtheta, options.arcTolerance);
            // The computed ends differ from the given ones by rounding: use the exact ones.
            for (std::size_t i = 0; i < arcs.size(); ++i) {
                std::vector<geo::Point> cps = arcs[i].controlPoints();
                if (i == 0)
                    cps.front() = cur;
                if (i + 1 == arcs.size())
                    cps.back() = p;
                if (auto e = add(std::move(cps), cmdAt))
                    return *e;
            }
            cur = p;
            break;
        }
        default:
            return pathError(cmdAt, QStringLiteral("unknown path command '%1'").arg(QLatin1Char(command)));
        }
        hasCubic = keepCubic;
        hasQuad = keepQuad;
        endArgs();
        if (command == 'Z' || command == 'z') {
            // Z takes no numbers: something that is not a command after it is an error.
            s.skipWsp();
            if (!s.atEnd() && s.numberAhead())
                return pathError(s.pos(), QStringLiteral("closepath (Z) takes no numbers"));
        }
    }
    flush(false);
    return out;
}

} // namespace kontur::io
