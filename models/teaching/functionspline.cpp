// FunctionSplinePlot: parsing, computing and drawing seed 001's function splines (see functionspline.h).
// Over 600 lines because the view's typed input, its five spline families and its own undo work on
// one state; the mathematics itself lives in src/geometry/splines.
#include "models/teaching/functionspline.h"

#include "geometry/composite.h"
#include "geometry/curveshape.h"
#include "geometry/splines/bspline.h"
#include "geometry/splines/globalbspline.h"
#include "geometry/splines/hermite.h"
#include "geometry/splines/polynomial.h"
#include "geometry/splines/torok.h"
#include "models/controllers/curvecommands.h"
#include "models/controllers/editcontroller.h"
#include "models/document/document.h"
#include "models/document/snapshotcommand.h"
#include "models/text/languagewatch.h"
#include "models/text/numbers.h"

#include <QCoreApplication>
#include <QLocale>
#include <QRegularExpression>
#include <QUndoCommand>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace kontur {

namespace {

const QColor kSplineColor(0x1f, 0x4e, 0x9c);
const QColor kPolynomialColor(0xc6, 0x28, 0x28);
const QColor kFunctionColor(0x80, 0x80, 0x80);
const QColor kKnotColor(0x2e, 0x9d, 0x3a);   // the seed's green knots
const QColor kHandleColor(0x70, 0x70, 0x70); // the seed's grey derivative handles
constexpr int kSamples = 400;
constexpr double kHandlePixels = 56.0; // a handle's distance from its knot on screen

double runge(double x)
{
    return 1.0 / (1.0 + 25.0 * x * x);
}

// How many derivatives a method takes for n values.
int derivativesWanted(int method, int n)
{
    switch (method) {
    case FunctionSplinePlot::Hermite:
        return n;
    case FunctionSplinePlot::Clamped:
    case FunctionSplinePlot::GlobalBSpline:
        return 2;
    default:
        return 0;
    }
}

// Knots per value count: the bell B-spline of degree 3 needs four more (docs/requirements.md 2).
int knotCount(int method, int n)
{
    return method == FunctionSplinePlot::BellSpline ? n + 4 : n;
}

QLocale uiLocale()
{
    QLocale locale; // the default, which the Language singleton sets with the UI language
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return locale;
}

} // namespace

// One change of the inputs (typed and applied, a drag, a method switch, an example); the steps of one
// drag (the same `drag` serial, 0: none) merge into one undo step.
class FunctionSplineCommand final : public SnapshotCommand<FunctionSplineInput>
{
public:
    FunctionSplineCommand(FunctionSplinePlot *plot, FunctionSplineInput before, FunctionSplineInput after, int drag = 0)
        : SnapshotCommand(std::move(before), std::move(after), 1, drag)
        , m_plot(plot)
    {
        setText(QCoreApplication::translate("FunctionSplinePlot", "Change the function spline"));
    }

private:
    void apply(const FunctionSplineInput &input) override { m_plot->setState(input); }
    FunctionSplinePlot *m_plot;
};

FunctionSplinePlot::FunctionSplinePlot(QObject *parent)
    : PlotSource(parent)
{
    // Seed 001's example input: function values 3 2 -1 0,5 on [0, 3], clamped with zero end slopes
    // (docs/requirements.md 2: the derivatives at the inner knots come out as -2.9 and -0.4).
    m_in.method = Clamped;
    m_in.values = {3.0, 2.0, -1.0, 0.5};
    m_in.derivatives = {0.0, 0.0};
    connect(&m_undo, &QUndoStack::canUndoChanged, this, &FunctionSplinePlot::undoStateChanged);
    connect(&m_undo, &QUndoStack::canRedoChanged, this, &FunctionSplinePlot::undoStateChanged);
    recompute();
    refreshTexts();
    // A language switch sends LanguageChange several times, before the UI locale is set: the fields,
    // summary and labels (plotChanged) are written again once, when the switch is done, in the new
    // number format. The error is a Message, announced again by its ShownMessage.
    m_languageSwitch.setSingleShot(true);
    connect(&m_languageSwitch, &QTimer::timeout, this, [this] {
        refreshTexts();
        Q_EMIT methodNamesChanged();
    });
    new LanguageWatch(this, [this] { m_languageSwitch.start(0); });
}

bool FunctionSplinePlot::parseNumbers(const QString &text, const QLocale &locale, std::vector<double> &out,
                                      QString *badToken)
{
    return parseNumberList(text, locale, out, badToken) == Parsed::Number;
}

QString FunctionSplinePlot::formatNumbers(const std::vector<double> &values, const QLocale &locale)
{
    QStringList parts;
    // Up to 4 decimals, trailing zeros dropped: typed numbers come back as typed; no group separators,
    // which would split a number of the list in two.
    for (double v : values)
        parts.append(fixedNumber(v, 4, locale, {.grouping = false, .trailingZeros = false}));
    return parts.join(QLatin1Char(' '));
}

void FunctionSplinePlot::refreshTexts()
{
    const QLocale locale = uiLocale();
    m_valuesText = formatNumbers(m_in.values, locale);
    m_intervalText = formatNumbers({m_in.a, m_in.b}, locale);
    m_knotsText = formatNumbers(knotX(), locale);
    m_derivativesText = formatNumbers(m_in.derivatives, locale);
    Q_EMIT textsChanged();
    Q_EMIT plotChanged(); // the labels and the summary are in the UI language too
}

void FunctionSplinePlot::setValuesText(const QString &text)
{
    if (m_valuesText == text)
        return;
    m_valuesText = text;
    Q_EMIT textsChanged();
}

void FunctionSplinePlot::setIntervalText(const QString &text)
{
    if (m_intervalText == text)
        return;
    m_intervalText = text;
    Q_EMIT textsChanged();
}

void FunctionSplinePlot::setKnotsText(const QString &text)
{
    if (m_knotsText == text)
        return;
    m_knotsText = text;
    Q_EMIT textsChanged();
}

void FunctionSplinePlot::setDerivativesText(const QString &text)
{
    if (m_derivativesText == text)
        return;
    m_derivativesText = text;
    Q_EMIT textsChanged();
}

QString FunctionSplinePlot::fieldText(Field field) const
{
    switch (field) {
    case ValuesField:
        return m_valuesText;
    case IntervalField:
        return m_intervalText;
    case KnotsField:
        return m_knotsText;
    case DerivativesField:
        return m_derivativesText;
    }
    return {};
}

int FunctionSplinePlot::numberCount(Field field) const
{
    return static_cast<int>(numberListTokens(fieldText(field), uiLocale()).size());
}

int FunctionSplinePlot::numberStart(Field field, int index) const
{
    const auto tokens = numberListTokens(fieldText(field), uiLocale());
    return index >= 0 && index < static_cast<int>(tokens.size()) ? static_cast<int>(tokens[index].start) : -1;
}

int FunctionSplinePlot::numberEnd(Field field, int index) const
{
    const auto tokens = numberListTokens(fieldText(field), uiLocale());
    return index >= 0 && index < static_cast<int>(tokens.size())
               ? static_cast<int>(tokens[index].start + tokens[index].length)
               : -1;
}

QString FunctionSplinePlot::stepText(Field field, int index) const
{
    const QLocale locale = uiLocale();
    const auto tokens = numberListTokens(fieldText(field), locale);
    if (index < 0 || index >= static_cast<int>(tokens.size()) || !tokens[index].isNumber)
        return {};
    const int decimals = std::min(tokens[index].decimals, kMaxStepDecimals);
    return fixedNumber(stepFor(tokens[index], kMaxStepDecimals), decimals, locale);
}

bool FunctionSplinePlot::stepNumber(Field field, int index, int direction)
{
    const QString stepped = stepListNumber(fieldText(field), uiLocale(), index, direction, kMaxStepDecimals);
    if (stepped.isEmpty())
        return false;
    switch (field) {
    case ValuesField:
        setValuesText(stepped);
        break;
    case IntervalField:
        setIntervalText(stepped);
        break;
    case KnotsField:
        setKnotsText(stepped);
        break;
    case DerivativesField:
        setDerivativesText(stepped);
        break;
    }
    apply();
    return true;
}

int FunctionSplinePlot::derivativeCount() const
{
    return derivativesWanted(m_in.method, static_cast<int>(m_in.values.size()));
}

bool FunctionSplinePlot::apply()
{
    const QLocale locale = uiLocale();
    FunctionSplineInput next = m_in;
    QString bad;
    std::vector<double> values;
    if (!parseNumbers(m_valuesText, locale, values, &bad)) {
        m_error.show(Message(Message::FunctionValuesNotNumbers, {bad}));
        return false;
    }
    if (values.size() < 2 || values.size() > static_cast<std::size_t>(kMaxValues)) {
        m_error.show(Message(Message::FunctionValuesCount, {kMaxValues}));
        return false;
    }
    // A field that still shows what was drawn keeps its exact values (the text is rounded).
    if (m_valuesText != formatNumbers(m_in.values, locale)) {
        next.values = values;
        next.runge = false;
    }
    const int count = static_cast<int>(next.values.size());
    if (next.uniform) {
        std::vector<double> interval;
        if (!parseNumbers(m_intervalText, locale, interval, &bad)) {
            m_error.show(Message(Message::IntervalNotNumbers, {bad}));
            return false;
        }
        if (interval.size() != 2 || !(interval[0] < interval[1])) {
            m_error.show(Message(Message::IntervalOrder));
            return false;
        }
        if (m_intervalText != formatNumbers({m_in.a, m_in.b}, locale)) {
            next.a = interval[0];
            next.b = interval[1];
        }
    } else {
        std::vector<double> knots;
        if (!parseNumbers(m_knotsText, locale, knots, &bad)) {
            m_error.show(Message(Message::KnotsNotNumbers, {bad}));
            return false;
        }
        if (static_cast<int>(knots.size()) != knotCount(next.method, count)) {
            m_error.show(Message(next.method == BellSpline ? Message::KnotsCountBells : Message::KnotsCount,
                                 {knotCount(next.method, count)}));
            return false;
        }
        for (std::size_t i = 1; i < knots.size(); ++i)
            if (!(knots[i - 1] < knots[i])) {
                m_error.show(Message(Message::KnotsOrder));
                return false;
            }
        if (m_knotsText != formatNumbers(knotX(), locale) || knots.size() != m_in.knots.size())
            next.knots = knots;
    }
    const int wanted = derivativesWanted(next.method, count);
    if (wanted > 0) {
        std::vector<double> derivatives;
        if (!parseNumbers(m_derivativesText, locale, derivatives, &bad)) {
            m_error.show(Message(Message::DerivativesNotNumbers, {bad}));
            return false;
        }
        if (static_cast<int>(derivatives.size()) != wanted) {
            if (next.method == Hermite)
                m_error.show(Message(Message::DerivativesPerKnot, {wanted}));
            else
                m_error.show(Message(Message::DerivativesTwo));
            return false;
        }
        if (m_derivativesText != formatNumbers(m_in.derivatives, locale) ||
            derivatives.size() != m_in.derivatives.size())
            next.derivatives = derivatives;
    }
    m_error.clear();
    setInput(next);
    refreshTexts();
    return true;
}

void FunctionSplinePlot::setInput(const FunctionSplineInput &input)
{
    if (input == m_in)
        return;
    m_undo.push(new FunctionSplineCommand(this, m_in, input));
}

void FunctionSplinePlot::setState(const FunctionSplineInput &input)
{
    m_in = input;
    recompute();
    if (!m_dragWorld)
        refreshTexts();
    m_error.clear();
    Q_EMIT inputChanged();
}

void FunctionSplinePlot::undo()
{
    m_undo.undo();
}

void FunctionSplinePlot::redo()
{
    m_undo.redo();
}

std::vector<double> FunctionSplinePlot::knotX() const
{
    const int n = knotCount(m_in.method, static_cast<int>(m_in.values.size()));
    if (!m_in.uniform && static_cast<int>(m_in.knots.size()) == n)
        return m_in.knots;
    std::vector<double> x(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        x[static_cast<std::size_t>(i)] = n == 1 ? m_in.a : m_in.a + (m_in.b - m_in.a) * i / (n - 1);
    return x;
}

std::vector<double> FunctionSplinePlot::derivativesFor(int method) const
{
    if (method == Hermite)
        return m_slopes;
    if (method == Natural || method == BellSpline || m_slopes.empty())
        return {};
    return {m_slopes.front(), m_slopes.back()};
}

void FunctionSplinePlot::setMethod(Method method)
{
    if (m_in.method == method)
        return;
    FunctionSplineInput next = m_in;
    next.method = method;
    next.derivatives = derivativesFor(method);
    if ((method == BellSpline) != (m_in.method == BellSpline) && !next.uniform) {
        // The number of knots changes: spread them evenly over the same range.
        const std::vector<double> x = knotX();
        next.uniform = true;
        next.a = x.front();
        next.b = x.back();
    }
    setInput(next);
}

void FunctionSplinePlot::setUniformKnots(bool uniform)
{
    if (m_in.uniform == uniform)
        return;
    FunctionSplineInput next = m_in;
    const std::vector<double> x = knotX();
    next.uniform = uniform;
    if (uniform) {
        next.a = x.front();
        next.b = x.back();
    } else {
        next.knots = x;
    }
    setInput(next);
}

void FunctionSplinePlot::setSolver(Solver solver)
{
    if (m_in.solver == solver)
        return;
    FunctionSplineInput next = m_in;
    next.solver = solver;
    setInput(next);
}

void FunctionSplinePlot::setShowPolynomial(bool show)
{
    if (m_showPolynomial == show)
        return;
    m_showPolynomial = show;
    Q_EMIT showPolynomialChanged();
    Q_EMIT plotChanged();
}

struct FunctionSplinePlot::Built
{
    std::optional<geo::HermiteSpline> hermite; // natural, clamped, Hermite
    std::optional<geo::BSpline> bspline;       // global B-spline, bells
};

FunctionSplinePlot::Built FunctionSplinePlot::build() const
{
    Built built;
    const std::vector<double> &y = m_in.values;
    if (m_in.method == BellSpline) {
        // No curve kind: its values are control values of the bells, not points of the curve.
        if (auto s = geo::bellSpline(knotX(), y, 3))
            built.bspline = std::move(s.value());
        return built;
    }
    // The other methods are curve records in the function form, built by geo::buildShape as the
    // document's curves and kontur-cli are: the derivatives are the slopes the tangent ends give.
    static constexpr geo::CurveKind kKinds[] = {geo::CurveKind::FunctionSpline, geo::CurveKind::ClampedSpline,
                                                geo::CurveKind::HermiteSpline, geo::CurveKind::GlobalBSpline};
    if (m_in.method < Natural || m_in.method > GlobalBSpline || m_x.size() != y.size())
        return built;
    geo::CurveParts parts;
    parts.kind = kKinds[m_in.method];
    parts.function = true;
    for (std::size_t i = 0; i < y.size(); ++i)
        parts.points.emplace_back(m_x[i], y[i]);
    if (geo::hasEndTangents(parts.kind) || geo::hasKnotTangents(parts.kind)) {
        const std::size_t wanted = geo::hasEndTangents(parts.kind) ? 2 : y.size();
        if (m_in.derivatives.size() != wanted || y.size() < 2)
            return built;
        std::vector<geo::Point> tangents;
        for (double d : m_in.derivatives)
            tangents.emplace_back(1.0, d);
        parts.tangentEnds = geo::endsFromTangents(parts, m_x, tangents);
    }
    if (m_in.method == Clamped && m_in.solver == Torok)
        parts.solver = geo::ClampedSolver::Torok;
    auto shape = geo::buildShape(parts);
    if (!shape && parts.solver == geo::ClampedSolver::Torok) {
        // Török's solver only on evenly spaced knots; elsewhere the classical one draws it.
        parts.solver = geo::ClampedSolver::Classical;
        shape = geo::buildShape(parts);
    }
    if (shape) {
        built.hermite = std::move(shape->hermite);
        built.bspline = std::move(shape->bspline);
    }
    return built;
}

QStringList FunctionSplinePlot::methodNames() const
{
    // Kept in the view's translation context, where they were first translated.
    static const char *const names[] = {QT_TRANSLATE_NOOP("FunctionSplineView", "Natural spline"),
                                        QT_TRANSLATE_NOOP("FunctionSplineView", "Clamped spline (C-spline)"),
                                        QT_TRANSLATE_NOOP("FunctionSplineView", "Hermite spline (H-spline)"),
                                        QT_TRANSLATE_NOOP("FunctionSplineView", "Global B-spline"),
                                        QT_TRANSLATE_NOOP("FunctionSplineView", "B-spline of bell functions")};
    QStringList out;
    for (const char *name : names)
        out << QCoreApplication::translate("FunctionSplineView", name);
    return out;
}

std::vector<geo::Bezier> FunctionSplinePlot::exactPieces() const
{
    if (!hasCurve())
        return {};
    const Built built = build();
    if (built.hermite)
        return built.hermite->toPiecewise().segments();
    if (built.bspline)
        return built.bspline->toPiecewise().segments();
    return {};
}

QString FunctionSplinePlot::addToDocument(EditController *editor)
{
    if (!editor)
        return {};
    const std::vector<geo::Bezier> pieces = exactPieces();
    if (pieces.empty())
        return {};
    Curve curve;
    if (m_in.method == Natural) {
        std::vector<geo::Point> knots;
        for (std::size_t i = 0; i < m_x.size() && i < m_in.values.size(); ++i)
            knots.emplace_back(m_x[i], m_in.values[i]);
        curve = Curve::make(CurveKind::FunctionSpline, std::move(knots));
    } else {
        auto composite = geo::compositeFromPieces(pieces, false);
        if (!composite)
            return {};
        curve = *Curve::makeComposite(std::move(composite).value());
    }
    if (!curve.isFinite())
        return {};
    curve.name = methodNames().value(m_in.method) + QStringLiteral(" y(x)");
    const QString name = curve.name;
    editor->commands()->appendCurve(std::move(curve), tr("Add the function spline to the document"));
    return name;
}

void FunctionSplinePlot::loadRungeExample(int points)
{
    points = std::clamp(points, 3, geo::kMaxPolynomialPoints);
    FunctionSplineInput next;
    next.method = Natural;
    next.uniform = true;
    next.a = -1.0;
    next.b = 1.0;
    next.runge = true;
    for (int i = 0; i < points; ++i)
        next.values.push_back(runge(-1.0 + 2.0 * i / (points - 1)));
    setShowPolynomial(true);
    setInput(next);
}

void FunctionSplinePlot::loadExample(Example example)
{
    FunctionSplineInput next;
    switch (example) {
    case TorokExample:
        next.method = Clamped;
        next.values = {3.0, 2.0, -1.0, 0.5};
        next.derivatives = {0.0, 0.0};
        next.solver = Torok;
        break;
    case Example123:
        next.method = GlobalBSpline;
        next.uniform = false;
        next.knots = {2.0, 3.75, 5.0};
        next.values = {-0.5, 1.1, 0.75};
        next.derivatives = {-2.0, 0.8};
        break;
    case Example130:
        next.method = Hermite;
        next.a = 1.0;
        next.b = 3.0;
        next.values = {-0.1, 1.0, 1.1};
        next.derivatives = {-2.0, 1.0, 0.0};
        break;
    }
    setShowPolynomial(false);
    m_error.clear();
    setInput(next);
    refreshTexts();
}

void FunctionSplinePlot::recompute()
{
    m_x = knotX();
    m_dotY = m_in.values;
    m_bellScale.clear();
    m_spline.clear();
    m_polynomial.clear();
    m_function.clear();
    m_slopes.clear();
    m_controlValues.clear();
    m_maxDifference = 0.0;
    m_polynomialOk = false;
    m_solverDifference = std::numeric_limits<double>::quiet_NaN();
    m_torokDrawn = false;
    const std::vector<double> &y = m_in.values;
    if (m_in.method == BellSpline) {
        // Seed 001's B-spline of bells: P(x) = Σ c_i Bs_i(x) over [v_3, v_{K-4}] (docs/requirements.md 2). Each c_i is
        // shown at its Greville abscissa, scaled like its bell, so the dots lie near the curve.
        const std::vector<double> v = knotX();
        const Built built = build();
        const std::optional<geo::BSpline> &spline = built.bspline;
        m_x.clear();
        m_dotY.clear();
        if (!spline) {
            Q_EMIT plotChanged();
            return;
        }
        for (std::size_t i = 0; i < y.size(); ++i) {
            m_bellScale.push_back(geo::bellScale(v, static_cast<int>(i), 3));
            m_x.push_back((v[i + 1] + v[i + 2] + v[i + 3]) / 3.0);
            m_dotY.push_back(y[i] * m_bellScale.back());
        }
        const double x0 = v[3];
        const double x1 = v[v.size() - 4];
        for (int s = 0; s <= kSamples; ++s) {
            const geo::Point p = spline->eval(x0 + (x1 - x0) * s / kSamples);
            m_spline.append(QPointF(p.x(), p.y()));
        }
        // The values at the knots inside: P(v_{i+3}) = c_i + 4c_{i+1} + c_{i+2} on unit knots.
        for (std::size_t j = 3; j + 3 < v.size(); ++j)
            m_slopes.push_back(spline->eval(v[j]).y());
        Q_EMIT plotChanged();
        return;
    }
    if (m_x.size() < 2 || m_x.size() != y.size())
        return;
    const double x0 = m_x.front();
    const double x1 = m_x.back();
    std::vector<double> xs(kSamples + 1);
    for (int s = 0; s <= kSamples; ++s)
        xs[static_cast<std::size_t>(s)] = x0 + (x1 - x0) * s / kSamples;

    // The spline: a Hermite-form function for three families, a B-spline for the global one.
    const Built built = build();
    const std::optional<geo::HermiteSpline> &hermite = built.hermite;
    const std::optional<geo::BSpline> &bspline = built.bspline;
    const std::vector<double> &d = m_in.derivatives;
    if (m_in.method == Clamped && d.size() == 2) {
        // Both solvers on evenly spaced knots, to show that they agree.
        const double h = (m_x.back() - m_x.front()) / static_cast<double>(m_x.size() - 1);
        auto classical = geo::uniformClampedSlopes(y, h, d[0], d[1], geo::ClampedSolver::Classical);
        auto torok = geo::uniformClampedSpline(m_x, y, d[0], d[1], geo::ClampedSolver::Torok);
        if (classical && torok) {
            m_solverDifference = 0.0;
            const std::vector<geo::Point> &t = torok->tangents();
            for (std::size_t i = 0; i < t.size() && i < classical->size(); ++i)
                m_solverDifference = std::max(m_solverDifference, std::abs(t[i].y() / t[i].x() - (*classical)[i]));
            m_torokDrawn = m_in.solver == Torok;
        }
    }
    if (hermite) {
        std::vector<geo::Point> out(xs.size());
        hermite->evalSorted(xs, out);
        for (const geo::Point &p : out)
            m_spline.append(QPointF(p.x(), p.y()));
        for (const geo::Point &t : hermite->tangents())
            m_slopes.push_back(t.x() != 0.0 ? t.y() / t.x() : 0.0);
    } else if (bspline) {
        for (double x : xs) {
            const geo::Point p = bspline->eval(x);
            m_spline.append(QPointF(p.x(), p.y()));
        }
        for (double x : m_x) {
            const geo::Point t = bspline->derivative(x);
            m_slopes.push_back(t.x() != 0.0 ? t.y() / t.x() : 0.0);
        }
        // The control values b as the seed writes them (for its scaled bells), so that a class can
        // compare them with Example 1.23's b ≈ (0.29, −0.22, 0.14, −0.03, 0.27).
        if (m_in.method == GlobalBSpline && d.size() == 2)
            if (auto g = geo::globalBSplineFunction(m_x, y, d[0], d[1]))
                m_controlValues = std::move(g->coefficients);
    }

    if (auto p = geo::functionPolynomial(m_x, y)) {
        m_polynomialOk = true;
        for (std::size_t s = 0; s < xs.size(); ++s) {
            const double v = p->eval(xs[s]).y();
            m_polynomial.append(QPointF(xs[s], v));
            if (s < static_cast<std::size_t>(m_spline.size()))
                m_maxDifference = std::max(m_maxDifference, std::abs(v - m_spline[static_cast<qsizetype>(s)].y()));
        }
    }
    if (m_in.runge)
        for (double x : xs)
            m_function.append(QPointF(x, runge(x)));
    Q_EMIT plotChanged();
}

double FunctionSplinePlot::splineAt(double x) const
{
    if (m_spline.size() < 2)
        return std::numeric_limits<double>::quiet_NaN();
    // Linear between the dense samples is not exact: evaluate again.
    const Built built = build();
    if (built.hermite)
        return built.hermite->functionValue(x);
    if (built.bspline)
        return built.bspline->eval(x).y();
    return std::numeric_limits<double>::quiet_NaN();
}

double FunctionSplinePlot::polynomialAt(double x) const
{
    if (auto p = geo::functionPolynomial(m_x, m_in.values))
        return p->eval(x).y();
    return std::numeric_limits<double>::quiet_NaN();
}

std::vector<double> FunctionSplinePlot::knotSlopes() const
{
    return m_slopes;
}

QString FunctionSplinePlot::summary() const
{
    const QLocale locale = uiLocale();
    const QString list = formatNumbers(m_slopes, locale).replace(QLatin1Char(' '), QStringLiteral("; "));
    QString text = m_in.method == BellSpline ? tr("Values P at the inner knots: %1").arg(list)
                                             : tr("Slopes y′ at the knots: %1").arg(list);
    if (m_in.method == GlobalBSpline && !m_controlValues.empty())
        //: b are the global B-spline's control values, as the course writes them (one per bell Bs).
        text += QLatin1Char('\n') + tr("Control values b: %1")
                                        .arg(formatNumbers(m_controlValues, locale)
                                                 .replace(QLatin1Char(' '), QStringLiteral("; ")));
    if (m_in.method == Clamped) {
        if (m_in.solver == Torok && !m_torokDrawn)
            text +=
                QLatin1Char('\n') + tr("Török's procedure needs evenly spaced knots: the classical system is drawn.");
        else if (std::isfinite(m_solverDifference) && m_solverDifference < 1e-15)
            // A class reads "4,4e-16" as a number of its own: below 10⁻¹⁵ the difference is rounding.
            text += QLatin1Char('\n') + tr("Török's half-size system and the classical system agree: their slopes "
                                           "differ by less than 10⁻¹⁵ (rounding).");
        else if (std::isfinite(m_solverDifference))
            text += QLatin1Char('\n') + tr("Török's half-size system and the classical system agree: their slopes "
                                           "differ by at most %1.")
                                            .arg(significantNumber(m_solverDifference, 2, locale));
    }
    if (m_in.method == Hermite && m_x.size() >= 2) {
        // The values between the knots, as the course prints them for its Example 1.30.
        QStringList middles;
        for (std::size_t i = 0; i + 1 < m_x.size(); ++i) {
            const double x = (m_x[i] + m_x[i + 1]) / 2;
            //: One value of the spline: P(1,5) = 0,075 (%1 is x, %2 the value).
            middles << tr("P(%1) = %2").arg(significantNumber(x, 6, locale), significantNumber(splineAt(x), 6, locale));
        }
        //: The spline's values halfway between the knots, e.g. "P(1,5) = 0,075; P(2,5) = 1,175".
        text += QLatin1Char('\n') + tr("Between the knots: %1").arg(middles.join(QStringLiteral("; ")));
    }
    if (m_showPolynomial && m_in.method != BellSpline) { // the bells' values are not interpolated
        if (m_polynomialOk)
            text += QLatin1Char('\n') + tr("Polynomial of degree %1: it differs from the spline by up to %2.")
                                            .arg(static_cast<int>(m_x.size()) - 1)
                                            .arg(significantNumber(m_maxDifference, 3, locale));
        else
            text += QLatin1Char('\n') +
                    tr("The polynomial is drawn for at most %n point(s).", nullptr, geo::kMaxPolynomialPoints);
    }
    return text;
}

QRectF FunctionSplinePlot::worldRect() const
{
    if (m_dragWorld)
        return *m_dragWorld;
    if (m_x.size() < 2)
        return QRectF(0, -1, 1, 2);
    const double x0 = std::min(m_x.front(), m_spline.isEmpty() ? m_x.front() : m_spline.first().x());
    const double x1 = std::max(m_x.back(), m_spline.isEmpty() ? m_x.back() : m_spline.last().x());
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    auto include = [&](double v) {
        if (std::isfinite(v)) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    };
    for (double v : m_dotY)
        include(v);
    for (const QPointF &p : m_spline)
        include(p.y());
    for (const QPointF &p : m_function)
        include(p.y());
    // The polynomial may swing far out (that is Runge's point), but not so far that the spline
    // becomes a flat line: at most four times the data's height beyond it.
    const double span = std::max(hi - lo, 1e-9);
    if (m_showPolynomial)
        for (const QPointF &p : m_polynomial)
            include(std::clamp(p.y(), lo - 4 * span, hi + 4 * span));
    if (hi - lo < 1e-9) {
        lo -= 1.0;
        hi += 1.0;
    }
    const double padX = (x1 - x0) * 0.06;
    const double padY = (hi - lo) * 0.12;
    return QRectF(x0 - padX, lo - padY, x1 - x0 + 2 * padX, hi - lo + 2 * padY);
}

QPointF FunctionSplinePlot::handlePosition(int knot, double slope, const QRectF &world) const
{
    const QSizeF area = plotArea();
    const double sx = area.width() / world.width(); // pixels per unit
    const double sy = area.height() / world.height();
    const double f = kHandlePixels / std::hypot(sx, sy * slope);
    const double side = knot == static_cast<int>(m_x.size()) - 1 ? -1.0 : 1.0;
    const auto i = static_cast<std::size_t>(knot);
    return {m_x[i] + side * f, m_in.values[i] + side * f * slope};
}

PlotData FunctionSplinePlot::plotData() const
{
    PlotData data;
    data.world = worldRect();
    data.xLabel = QStringLiteral("x");
    data.yLabel = QStringLiteral("y");
    if (!m_function.isEmpty()) {
        PlotSeries f;
        f.points = m_function;
        f.color = kFunctionColor;
        f.width = 1.5;
        f.dashed = true;
        f.label = QStringLiteral("1/(1+25x²)");
        data.series.push_back(f);
    }
    if (m_showPolynomial && m_polynomialOk) {
        PlotSeries p;
        p.points = m_polynomial;
        p.color = kPolynomialColor;
        p.width = 2.0;
        //: Legend label (noun): the interpolating polynomial drawn beside the spline.
        p.label = tr("polynomial");
        data.series.push_back(p);
    }
    PlotSeries s;
    s.points = m_spline;
    s.color = kSplineColor;
    s.width = 2.5;
    //: Legend label (noun): the spline.
    s.label = tr("spline");
    data.series.push_back(s);

    for (std::size_t i = 0; i < m_x.size(); ++i) {
        PlotDot knot;
        knot.position = QPointF(m_x[i], m_dotY[i]);
        knot.color = kKnotColor;
        knot.radius = 5.0;
        knot.draggable = true;
        data.dots.push_back(knot);
    }
    // Derivative handles for the derivatives that are input.
    std::vector<int> knotsWithHandle;
    if (m_in.method == Hermite && m_in.derivatives.size() == m_x.size())
        for (std::size_t i = 0; i < m_x.size(); ++i)
            knotsWithHandle.push_back(static_cast<int>(i));
    else if ((m_in.method == Clamped || m_in.method == GlobalBSpline) && m_in.derivatives.size() == 2)
        knotsWithHandle = {0, static_cast<int>(m_x.size()) - 1};
    for (std::size_t h = 0; h < knotsWithHandle.size(); ++h) {
        const int k = knotsWithHandle[h];
        PlotDot handle;
        handle.position = handlePosition(k, m_in.derivatives[h], data.world);
        handle.anchor = QPointF(m_x[static_cast<std::size_t>(k)], m_in.values[static_cast<std::size_t>(k)]);
        handle.color = kHandleColor;
        handle.shape = PlotDot::Square;
        handle.radius = 4.5;
        handle.draggable = true;
        data.dots.push_back(handle);
    }
    return data;
}

void FunctionSplinePlot::dragDot(int index, QPointF world, bool finished)
{
    const int n = static_cast<int>(m_x.size());
    if (index < 0 || n < 2)
        return;
    if (!m_dragWorld) { // a new drag
        m_dragWorld = worldRect();
        ++m_dragSerial;
    }
    FunctionSplineInput next = m_in;
    if (index < n) {
        // A knot moves up and down: its x comes from the interval or the knots field. A bell's
        // control value is the dot's height over its scale.
        const auto i = static_cast<std::size_t>(index);
        next.values[i] = m_in.method == BellSpline && i < m_bellScale.size() && m_bellScale[i] != 0.0
                             ? world.y() / m_bellScale[i]
                             : world.y();
        next.runge = false;
    } else if (const int h = index - n; h < static_cast<int>(next.derivatives.size())) {
        const int k = next.method == Hermite ? h : (h == 0 ? 0 : n - 1);
        const auto ki = static_cast<std::size_t>(k);
        const double dx = world.x() - m_x[ki];
        // The handle's slope to its knot is the derivative; straight above the knot it has none.
        if (std::abs(dx) > 1e-9 * std::max(1.0, m_dragWorld->width()))
            next.derivatives[static_cast<std::size_t>(h)] = (world.y() - m_in.values[ki]) / dx;
    }
    if (finished)
        m_dragWorld.reset(); // the axes fit the curve again, and the fields show it (setState)
    // Every step is a command whose redo() applies it; the stack merges the drag's steps.
    if (!(next == m_in))
        m_undo.push(new FunctionSplineCommand(this, m_in, next, m_dragSerial));
    else if (finished)
        refreshTexts();
}

} // namespace kontur
