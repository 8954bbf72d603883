// BasisPlot: sampling and highlighting of the basis functions (see basisplot.h).
#include "models/teaching/basisplot.h"

#include "geometry/bernstein.h"
#include "geometry/splines/bspline.h"
#include "models/controllers/editcontroller.h"
#include "models/document/curve.h"
#include "models/document/document.h"
#include "models/text/languagewatch.h"
#include "models/text/numbers.h"

#include <QCoreApplication>
#include <QLocale>

#include <algorithm>
#include <array>
#include <cmath>

namespace kontur {

namespace {

// Distinct hues for neighbouring functions; the highlighted one is drawn in the accent colour.
const std::array<QColor, 8> kPalette{QColor(0x1b, 0x9e, 0x77), QColor(0xd9, 0x5f, 0x02), QColor(0x75, 0x70, 0xb3),
                                     QColor(0xe7, 0x29, 0x8a), QColor(0x66, 0xa6, 0x1e), QColor(0xa6, 0x76, 0x1d),
                                     QColor(0x1f, 0x78, 0xb4), QColor(0x66, 0x66, 0x66)};
const QColor kHighlight(0xc6, 0x28, 0x28);
const QColor kMarker(0x1f, 0x6f, 0xd1);

// Hermite bases on [0, 1] in seed 001's form (docs/requirements.md 2, with the corrected Hs):
// Hs_{0,1} = (1 + 2x)(x - 1)², Hds_{0,1} = (x - 1)² x, Hs_{1,0} = (3 - 2x) x², Hds_{1,0} = x² (x - 1).
double hermiteBasis(int i, double x)
{
    switch (i) {
    case 0:
        return (1 + 2 * x) * (x - 1) * (x - 1);
    case 1:
        return (x - 1) * (x - 1) * x;
    case 2:
        return (3 - 2 * x) * x * x;
    case 3:
        return x * x * (x - 1);
    default:
        return 0.0;
    }
}

} // namespace

BasisPlot::BasisPlot(QObject *parent)
    : PlotSource(parent)
{
    rebuild();
    // The title, the knot and value texts and the tick labels follow the language and its numbers.
    new LanguageWatch(this, [this] { refresh(); });
}

void BasisPlot::setEditor(EditController *editor)
{
    if (m_editor == editor)
        return;
    if (m_editor) {
        disconnect(m_editor, nullptr, this, nullptr);
        disconnect(m_editor->document(), nullptr, this, nullptr);
    }
    m_editor = editor;
    if (m_editor) {
        connect(m_editor->selection(), &Selection::changed, this, &BasisPlot::rebuild);
        // Structure and settings (order, point count), not every drag: the basis does not depend on positions.
        connect(m_editor->document(), &Document::curveChanged, this, &BasisPlot::rebuild);
        connect(m_editor->document(), &Document::curveCountChanged, this, &BasisPlot::rebuild);
    }
    rebuild();
    Q_EMIT editorChanged();
}

void BasisPlot::setFamily(Family family)
{
    if (m_family == family)
        return;
    m_family = family;
    m_hovered = -1;
    rebuild();
    Q_EMIT settingsChanged();
}

void BasisPlot::setDegree(int degree)
{
    degree = std::clamp(degree, 1, 30);
    if (m_degree == degree)
        return;
    m_degree = degree;
    rebuild();
    Q_EMIT settingsChanged();
}

void BasisPlot::setOrder(int order)
{
    order = std::clamp(order, geo::kMinBSplineOrder, geo::kMaxBSplineOrder);
    if (m_order == order)
        return;
    m_order = order;
    rebuild();
    Q_EMIT settingsChanged();
}

void BasisPlot::setCount(int count)
{
    count = std::clamp(count, 2, 30);
    if (m_count == count)
        return;
    m_count = count;
    rebuild();
    Q_EMIT settingsChanged();
}

void BasisPlot::setParameter(double parameter)
{
    if (!std::isfinite(parameter))
        return;
    parameter = std::clamp(parameter, 0.0, 1.0);
    if (m_parameter == parameter)
        return;
    m_parameter = parameter;
    Q_EMIT parameterChanged();
    Q_EMIT plotChanged();
}

void BasisPlot::dragMarker(double x)
{
    if (m_hi > m_lo)
        setParameter((x - m_lo) / (m_hi - m_lo));
}

void BasisPlot::hoverSeries(int index)
{
    if (index >= m_functionCount)
        index = -1;
    if (m_hovered == index)
        return;
    m_hovered = index;
    m_highlighted = m_hovered >= 0 ? m_hovered : highlightFromSelection();
    Q_EMIT plotChanged();
}

double BasisPlot::value(int i, double x) const
{
    if (i < 0 || i >= m_functionCount)
        return 0.0;
    switch (m_shown) {
    case Bernstein:
        return geo::binomial(m_shownDegree, i) * std::pow(x, i) * std::pow(1 - x, m_shownDegree - i);
    case BSpline:
        return geo::basisFunction(m_knots, i, m_shownDegree + 1, x);
    case Bell:
        return geo::basisFunction(m_knots, i, m_shownDegree + 1, x) * geo::bellScale(m_knots, i, m_shownDegree);
    case Hermite:
        if (m_hermiteSegments > 0) {
            // Knot k = i / 2 at x = k: its value basis (i even) or its derivative basis (i odd) on the
            // segment before it (rising half) and after it (falling half), in each segment's own u.
            const int k = i / 2;
            const bool derivative = i % 2 == 1;
            if (k > 0 && x >= k - 1 && x <= k)
                return hermiteBasis(derivative ? 3 : 2, x - (k - 1));
            if (k < m_hermiteSegments && x >= k && x <= k + 1)
                return hermiteBasis(derivative ? 1 : 0, x - k);
            return 0.0;
        }
        return hermiteBasis(i, x);
    case Auto:
        break;
    }
    return 0.0;
}

int BasisPlot::highlightFromSelection() const
{
    const Curve *selected = m_editor ? m_editor->selection()->curve() : nullptr;
    const int row = m_editor ? m_editor->selection()->point() : -1;
    if (!selected || row < 0)
        return -1;
    const Curve &curve = *selected;
    if (row >= curve.rowCount())
        return -1;
    switch (m_shown) {
    case Bernstein:
        if (curve.kind() == CurveKind::Bezier)
            return row <= m_shownDegree ? row : -1;
        if (curve.kind() == CurveKind::Composite)
            return row % 3; // c_{3i} is B_0 of segment i (and B_3 of the one before)
        return -1;
    case BSpline:
        return curve.kind() == CurveKind::BSpline && row < m_functionCount ? row : -1;
    case Hermite: {
        // A knot weights Hs (its value), a tangent end Hds (its derivative): on one segment the ones it
        // starts, on the curve's segments its own knot's.
        const PointRow r = curve.row(row);
        if (m_hermiteSegments > 0 && (r.role == PointRole::Knot || r.role == PointRole::TangentEnd))
            return std::min(2 * r.number + (r.role == PointRole::TangentEnd ? 1 : 0), m_functionCount - 1);
        return r.role == PointRole::TangentEnd ? 1 : 0;
    }
    case Bell:
    case Auto:
        break;
    }
    return -1;
}

void BasisPlot::rebuild()
{
    // Which family and size: the selected curve's when Auto, else the settings.
    Family shown = m_family;
    int hermiteSegments = 0;
    int bernsteinDegree = m_degree;
    int order = m_order;
    int count = m_count;
    if (m_family == Auto) {
        shown = Bernstein;
        if (const Curve *selected = m_editor ? m_editor->selection()->curve() : nullptr) {
            const Curve &curve = *selected;
            if (curve.kind() == CurveKind::Bezier) {
                bernsteinDegree = curve.placedCount() - 1;
            } else if (curve.kind() == CurveKind::BSpline) {
                shown = BSpline;
                order = curve.order();
                count = curve.placedCount();
            } else if (traitsOf(curve.kind()).hermiteForm) {
                shown = Hermite;
                hermiteSegments = curve.segmentCount();
            } else {
                bernsteinDegree = 3; // composite, fitted cubics: cubic Bézier segments
            }
        }
    }

    m_shown = shown;
    m_hermiteSegments = hermiteSegments;
    m_knots.clear();
    m_samples.clear();
    m_tooMany = false;
    switch (shown) {
    case Bernstein:
        m_shownDegree = std::max(1, bernsteinDegree);
        m_functionCount = m_shownDegree + 1;
        m_lo = 0.0;
        m_hi = 1.0;
        break;
    case Hermite:
        m_shownDegree = 3;
        m_functionCount = hermiteSegments > 0 ? 2 * (hermiteSegments + 1) : 4;
        m_lo = 0.0;
        m_hi = std::max(1, hermiteSegments);
        if (m_functionCount > kMaxFunctions) {
            m_tooMany = true;
            m_requestedCount = m_functionCount;
            m_functionCount = 0;
            hermiteSegments = 0;
        }
        break;
    case BSpline:
    case Bell:
    case Auto: {
        m_shownDegree = order - 1;
        m_functionCount = count;
        auto knots = shown == BSpline ? geo::openUniformKnots(count, order) : geo::uniformKnots(count, order);
        if (count > kMaxFunctions || !knots) {
            m_tooMany = count > kMaxFunctions;
            m_requestedCount = count;
            m_functionCount = 0;
            m_lo = 0.0;
            m_hi = 1.0;
        } else {
            m_knots = std::move(knots.value());
            m_lo = m_knots.front();
            m_hi = m_knots.back();
        }
        break;
    }
    }

    // Samples: 160 over [0, 1] for the polynomials; 24 per knot span over each B-spline's support.
    m_samples.resize(static_cast<std::size_t>(m_functionCount));
    for (int i = 0; i < m_functionCount; ++i) {
        QPolygonF &poly = m_samples[static_cast<std::size_t>(i)];
        if (m_hermiteSegments > 0) {
            // Over the segments beside its knot, 40 samples each.
            const int k = i / 2;
            const int first = std::max(0, k - 1);
            const int last = std::min(m_hermiteSegments, k + 1);
            constexpr int kPerSegment = 40;
            for (int s = 0; s <= kPerSegment * (last - first); ++s) {
                const double x = first + static_cast<double>(s) / kPerSegment;
                poly.append(QPointF(x, value(i, x)));
            }
            continue;
        }
        if (m_knots.empty()) {
            constexpr int kSamples = 160;
            for (int s = 0; s <= kSamples; ++s) {
                const double x = static_cast<double>(s) / kSamples;
                poly.append(QPointF(x, value(i, x)));
            }
            continue;
        }
        const int k = m_shownDegree + 1;
        for (int span = i; span < i + k; ++span) {
            const double a = m_knots[static_cast<std::size_t>(span)];
            const double b = m_knots[static_cast<std::size_t>(span + 1)];
            if (b <= a)
                continue;
            constexpr int kPerSpan = 24;
            for (int s = poly.isEmpty() ? 0 : 1; s <= kPerSpan; ++s) {
                // The right end of a span belongs to the next one (half-open intervals): take it from
                // inside so a function that jumps there (repeated knots) is drawn up to its limit.
                const double x = s == kPerSpan && span + 1 < static_cast<int>(m_knots.size()) - 1
                                     ? b - 1e-12 * std::max(1.0, std::abs(b))
                                     : a + (b - a) * s / kPerSpan;
                poly.append(QPointF(x, value(i, x)));
            }
        }
    }
    m_highlighted = m_hovered >= 0 && m_hovered < m_functionCount ? m_hovered : highlightFromSelection();
    Q_EMIT plotChanged();
}

QString BasisPlot::functionLabel(int i) const
{
    switch (m_shown) {
    case Bernstein:
        return QStringLiteral("B%1,%2").arg(i).arg(m_shownDegree);
    case BSpline:
        return QStringLiteral("N%1,%2").arg(i).arg(m_shownDegree + 1);
    case Bell:
        return QStringLiteral("Bs%1").arg(i);
    case Hermite: {
        if (m_hermiteSegments > 0)
            return (i % 2 == 0 ? QStringLiteral("Hs%1") : QStringLiteral("Hds%1")).arg(i / 2);
        static const std::array<const char *, 4> names{"Hs(0,1)", "Hds(0,1)", "Hs(1,0)", "Hds(1,0)"};
        return QString::fromLatin1(names[static_cast<std::size_t>(std::clamp(i, 0, 3))]);
    }
    case Auto:
        break;
    }
    return {};
}

QString BasisPlot::title() const
{
    if (m_tooMany)
        return QCoreApplication::translate("BasisPlot", "Too many basis functions to draw (%n).", nullptr,
                                           m_requestedCount);
    switch (m_shown) {
    case Bernstein:
        return QCoreApplication::translate("BasisPlot", "Bernstein polynomials of degree %1").arg(m_shownDegree);
    case BSpline:
        return QCoreApplication::translate("BasisPlot", "B-spline basis functions N(i,k), order k = %1")
            .arg(m_shownDegree + 1);
    case Bell:
        //: Title: the bell-shaped B-spline basis functions Bs (one bell per knot) of degree %1 (a number).
        return QCoreApplication::translate("BasisPlot", "Bell functions Bs of degree %1").arg(m_shownDegree);
    case Hermite:
        if (m_hermiteSegments > 0)
            return QCoreApplication::translate("BasisPlot", "Hermite basis functions on the curve's %n segment(s)",
                                               nullptr, m_hermiteSegments);
        return QCoreApplication::translate("BasisPlot", "Hermite basis functions on one segment");
    case Auto:
        break;
    }
    return {};
}

QString BasisPlot::knotText() const
{
    if (m_knots.empty())
        return {};
    const QLocale locale;
    QStringList parts;
    parts.reserve(static_cast<qsizetype>(m_knots.size()));
    for (double t : m_knots)
        parts.append(significantNumber(t, 6, locale));
    return QCoreApplication::translate("BasisPlot", "Knot vector: %1").arg(parts.join(QLatin1Char(' ')));
}

QString BasisPlot::valuesText() const
{
    if (m_functionCount == 0)
        return {};
    const QLocale locale;
    const double x = markerX();
    QStringList parts;
    double sum = 0.0;
    for (int i = 0; i < m_functionCount; ++i) {
        const double v = value(i, x);
        sum += v;
        if (i < 12)
            parts.append(QStringLiteral("%1 = %2").arg(functionLabel(i), fixedNumber(v, 3, locale)));
    }
    if (m_functionCount > 12)
        parts.append(QStringLiteral("…"));
    QString text = QStringLiteral("t = %1: ").arg(fixedNumber(x, 3, locale)) + parts.join(QStringLiteral("; "));
    if (m_shown == Bernstein || m_shown == BSpline)
        text += QCoreApplication::translate("BasisPlot", " (sum %1)").arg(fixedNumber(sum, 3, locale));
    return text;
}

PlotData BasisPlot::plotData() const
{
    PlotData data;
    double top = 1.0;
    for (const QPolygonF &poly : m_samples)
        for (const QPointF &p : poly)
            top = std::max(top, p.y());
    // The derivative bases Hds stay within 4/27 of the axis (11 px of a 100 px plot): drawn
    // kHermiteSlopeScale times taller, and labelled so ("4·Hds(0,1)"); the values read out are theirs.
    const auto scaleOf = [this](int i) { return m_shown == Hermite && i % 2 == 1 ? kHermiteSlopeScale : 1.0; };
    double bottom = 0.0;
    if (m_shown == Hermite)
        bottom = -0.15 * kHermiteSlopeScale; // the derivative bases dip below zero (to -4/27, scaled)
    data.world = QRectF(m_lo, bottom, m_hi - m_lo, (top - bottom) * 1.08);
    for (int i = 0; i < m_functionCount; ++i) {
        PlotSeries s;
        s.points = m_samples[static_cast<std::size_t>(i)];
        for (QPointF &p : s.points)
            p.setY(p.y() * scaleOf(i));
        const bool lit = i == m_highlighted;
        s.color = lit ? kHighlight : kPalette[static_cast<std::size_t>(i) % kPalette.size()];
        if (m_highlighted >= 0 && !lit)
            s.color.setAlphaF(0.45f);
        s.width = lit ? 3.5 : 1.6;
        s.label = m_functionCount <= 16 || lit ? functionLabel(i) : QString();
        if (!s.label.isEmpty() && scaleOf(i) != 1.0)
            s.label = QStringLiteral("%1·%2").arg(scaleOf(i)).arg(s.label);
        s.id = i;
        data.series.push_back(std::move(s));
    }
    // The highlighted function is drawn last, over the others.
    if (m_highlighted >= 0 && m_highlighted < static_cast<int>(data.series.size()))
        std::rotate(data.series.begin() + m_highlighted, data.series.begin() + m_highlighted + 1, data.series.end());
    const double x = markerX();
    data.marker = x;
    for (int i = 0; i < m_functionCount; ++i) {
        PlotDot dot;
        dot.position = QPointF(x, value(i, x) * scaleOf(i));
        dot.color = i == m_highlighted ? kHighlight : kMarker;
        dot.radius = 3.5;
        data.dots.push_back(dot);
    }
    data.xMarks = m_knots;
    for (int k = 0; m_hermiteSegments > 0 && k <= m_hermiteSegments; ++k)
        data.xMarks.push_back(k); // the curve's knots
    data.xLabel = QStringLiteral("t");
    return data;
}

} // namespace kontur
