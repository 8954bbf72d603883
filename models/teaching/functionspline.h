// FunctionSplinePlot: seed 001's function splines y(x) for the teaching view (issue 9 part B): the
// inputs 'Function values', 'Interval', 'Knots' and 'Derivatives' typed in the UI language's number
// format, the 'regular (uniform) knots' choice, the spline of the chosen family (natural, clamped,
// Hermite, global B-spline), knots as dots and derivative handles whose slope to their knot is the
// derivative (dragging one changes it), and the Runge comparison: the interpolating polynomial
// through the same points on the same axes. Every change of the inputs is one step of the view's
// own undo stack (the view does not edit the document).
#pragma once

#include "geometry/result.h"
#include "geometry/splines/hermite.h"
#include "models/teaching/plotsource.h"
#include "models/text/shownmessage.h"

#include <QTimer>
#include <QUndoStack>
#include <QtQml/qqmlregistration.h>

#include <limits>
#include <vector>

namespace kontur {

class EditController;

// What the view's input says, parsed: the state one undo step restores.
struct FunctionSplineInput
{
    int method = 0;                  // FunctionSplinePlot::Method
    bool uniform = true;             // knots spread evenly over the interval
    double a = 0.0, b = 3.0;         // the interval (used when uniform)
    std::vector<double> knots;       // x_i (used when not uniform)
    std::vector<double> values;      // y_i
    std::vector<double> derivatives; // Hermite: one per knot; clamped, global B-spline: first and last
    bool runge = false;              // the values are samples of Runge's function 1/(1 + 25x²)
    int solver = 0;                  // FunctionSplinePlot::Solver (clamped spline on uniform knots)

    bool operator==(const FunctionSplineInput &) const = default;
};

// Not final: QML (Qt 6.4) derives from registered types.
class FunctionSplinePlot : public PlotSource
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(Method method READ method WRITE setMethod NOTIFY inputChanged)
    Q_PROPERTY(bool uniformKnots READ uniformKnots WRITE setUniformKnots NOTIFY inputChanged)
    Q_PROPERTY(Solver solver READ solver WRITE setSolver NOTIFY inputChanged)
    // The largest difference between the slopes of the two solvers (NaN where they do not apply).
    Q_PROPERTY(double solverDifference READ solverDifference NOTIFY plotChanged)
    Q_PROPERTY(bool showPolynomial READ showPolynomial WRITE setShowPolynomial NOTIFY showPolynomialChanged)
    // The typed fields. Setting one only stores the text; apply() reads them all.
    Q_PROPERTY(QString valuesText READ valuesText WRITE setValuesText NOTIFY textsChanged)
    Q_PROPERTY(QString intervalText READ intervalText WRITE setIntervalText NOTIFY textsChanged)
    Q_PROPERTY(QString knotsText READ knotsText WRITE setKnotsText NOTIFY textsChanged)
    Q_PROPERTY(QString derivativesText READ derivativesText WRITE setDerivativesText NOTIFY textsChanged)
    Q_PROPERTY(int derivativeCount READ derivativeCount NOTIFY inputChanged)
    // The problem with the typed input (QML: error.text; none: error.isEmpty).
    Q_PROPERTY(kontur::Message error READ error NOTIFY errorChanged)
    Q_PROPERTY(QString summary READ summary NOTIFY plotChanged)
    Q_PROPERTY(bool canUndo READ canUndo NOTIFY undoStateChanged)
    Q_PROPERTY(bool canRedo READ canRedo NOTIFY undoStateChanged)
    // There is a spline drawn (the input gave one).
    Q_PROPERTY(bool hasCurve READ hasCurve NOTIFY plotChanged)
    // The methods' names in the current language, in Method order (the view's list, the added curve's name).
    Q_PROPERTY(QStringList methodNames READ methodNames NOTIFY methodNamesChanged)

public:
    // BellSpline: seed 001's approximating B-spline P(x) = Σ c_i Bs_i(x) of cubic bells; the values are
    // its control values c_i and it takes four knots more than values.
    enum Method { Natural, Clamped, Hermite, GlobalBSpline, BellSpline };
    Q_ENUM(Method)
    // How the clamped spline's inner derivatives are solved on uniform knots (seed 001 §1.4 and §2,
    // geo::ClampedSolver): both give the same spline, which the view shows by their largest difference.
    enum Solver { Classical, Torok };
    Q_ENUM(Solver)
    // The most function values the view takes. In plotData() the dots are the knots first, then the
    // derivative handles (dragDot's index).
    static constexpr int kMaxValues = 200;

    explicit FunctionSplinePlot(QObject *parent = nullptr);

    [[nodiscard]] Method method() const { return static_cast<Method>(m_in.method); }
    void setMethod(Method method);
    [[nodiscard]] bool uniformKnots() const { return m_in.uniform; }
    void setUniformKnots(bool uniform);
    [[nodiscard]] Solver solver() const { return static_cast<Solver>(m_in.solver); }
    void setSolver(Solver solver);
    [[nodiscard]] double solverDifference() const { return m_solverDifference; }
    [[nodiscard]] bool showPolynomial() const { return m_showPolynomial; }
    void setShowPolynomial(bool show);
    [[nodiscard]] QString valuesText() const { return m_valuesText; }
    void setValuesText(const QString &text);
    [[nodiscard]] QString intervalText() const { return m_intervalText; }
    void setIntervalText(const QString &text);
    [[nodiscard]] QString knotsText() const { return m_knotsText; }
    void setKnotsText(const QString &text);
    [[nodiscard]] QString derivativesText() const { return m_derivativesText; }
    void setDerivativesText(const QString &text);
    // How many derivatives the method takes: one per knot (Hermite), 2 (clamped, global B-spline), 0.
    [[nodiscard]] int derivativeCount() const;
    // The problem with the typed input, translated when shown (empty: none).
    [[nodiscard]] Message error() const { return m_error.message(); }
    [[nodiscard]] QString summary() const;
    [[nodiscard]] bool canUndo() const { return m_undo.canUndo(); }
    [[nodiscard]] bool canRedo() const { return m_undo.canRedo(); }

    // Reads the typed fields; on success draws them (one undo step) and returns true. On an error
    // the message names the field and the number, the texts stay as typed and the curve as it was.
    Q_INVOKABLE bool apply();
    // Runge's example: n uniform samples of 1/(1 + 25x²) on [-1, 1], with the polynomial shown.
    Q_INVOKABLE void loadRungeExample(int points = 11);
    // The course's examples (docs/requirements.md 2), each one tap away and one undo step: Török's
    // (y = 3 2 −1 0,5 on [0, 3], end slopes 0, his solver: slopes −2,9 and −0,4), Example 1.23 (the
    // global B-spline through knots 2, 15/4, 5: b ≈ 0,2903 …), Example 1.30 (Hermite on 1, 2, 3:
    // P(1,5) = 3/40, P(2,5) = 47/40).
    enum Example { TorokExample, Example123, Example130 };
    Q_ENUM(Example)
    Q_INVOKABLE void loadExample(kontur::FunctionSplinePlot::Example example);
    // The typed fields whose numbers a stepper changes, one number of the list at a time (by mouse or
    // finger, without a keyboard).
    enum Field { ValuesField, IntervalField, KnotsField, DerivativesField };
    Q_ENUM(Field)
    // How many numbers `field`'s text holds (its tokens, read or not), and where the index-th stands:
    // [numberStart, numberEnd) in the text, for the view to mark it.
    Q_INVOKABLE int numberCount(kontur::FunctionSplinePlot::Field field) const;
    Q_INVOKABLE int numberStart(kontur::FunctionSplinePlot::Field field, int index) const;
    Q_INVOKABLE int numberEnd(kontur::FunctionSplinePlot::Field field, int index) const;
    // What one tap adds to the index-th number, in the UI language (empty: it is not a number): a unit
    // of its last shown decimal, at least 0,01 (kMaxStepDecimals).
    Q_INVOKABLE QString stepText(kontur::FunctionSplinePlot::Field field, int index) const;
    // One tap of − (direction -1) or + (+1): only the index-th number of the field changes, by its
    // step and written with the decimals it showed; everything else stays as typed. The input is then
    // drawn as by Draw (one undo step; a problem shows as for typed input). False: nothing to step.
    Q_INVOKABLE bool stepNumber(kontur::FunctionSplinePlot::Field field, int index, int direction);
    static constexpr int kMaxStepDecimals = 2;
    Q_INVOKABLE void undo();
    Q_INVOKABLE void redo();
    // Adds the drawn spline to `editor`'s document as one undo step there, exactly: the natural
    // spline as a function spline y(x) through the knots (editable as such), the others as their
    // composite curve of the same cubic pieces. Named after the method; answers the new curve's name
    // (empty: nothing drawn, nothing added).
    Q_INVOKABLE QString addToDocument(kontur::EditController *editor);
    [[nodiscard]] bool hasCurve() const { return m_spline.size() >= 2; }
    [[nodiscard]] QStringList methodNames() const;
    // The drawn spline's exact Bézier pieces (empty when nothing is drawn).
    [[nodiscard]] std::vector<geo::Bezier> exactPieces() const;
    // Texts again from the drawn input, in the current UI language (after a language switch).
    Q_INVOKABLE void refreshTexts();

    // Parses numbers typed in `locale`'s format, separated by spaces or semicolons (and by commas
    // when the decimal separator is a point); a number in the C format ("0.5") is accepted too.
    // On failure returns false and sets `badToken` to the first number that could not be read.
    [[nodiscard]] static bool parseNumbers(const QString &text, const QLocale &locale, std::vector<double> &out,
                                           QString *badToken = nullptr);
    [[nodiscard]] static QString formatNumbers(const std::vector<double> &values, const QLocale &locale);

    // The drawn state, for tests and the view.
    [[nodiscard]] const FunctionSplineInput &input() const { return m_in; }
    void setInput(const FunctionSplineInput &input); // as one undo step
    // The knot vector: one knot per value, or four more for the bell B-spline.
    [[nodiscard]] std::vector<double> knotX() const;
    // Where the draggable value dots are: (knot, value), or (Greville abscissa, c_i · scale_i) for bells.
    [[nodiscard]] const std::vector<double> &dotX() const { return m_x; }
    [[nodiscard]] const std::vector<double> &dotY() const { return m_dotY; }
    // The spline, its derivative at the knots and the polynomial; NaN when there is none.
    [[nodiscard]] double splineAt(double x) const;
    [[nodiscard]] double polynomialAt(double x) const;
    [[nodiscard]] std::vector<double> knotSlopes() const;

    [[nodiscard]] PlotData plotData() const override;
    void dragDot(int index, QPointF world, bool finished) override;

Q_SIGNALS:
    void inputChanged();
    void textsChanged();
    void showPolynomialChanged();
    void errorChanged();
    void undoStateChanged();
    void methodNamesChanged();

protected:
private:
    friend class FunctionSplineCommand;
    // Sets the drawn state without an undo step (undo, redo, live drags) and recomputes.
    void setState(const FunctionSplineInput &input);
    void recompute();
    [[nodiscard]] QString fieldText(Field field) const;
    // Derivatives suited to `method` from the current spline (switching keeps the curve's look).
    [[nodiscard]] std::vector<double> derivativesFor(int method) const;
    [[nodiscard]] QPointF handlePosition(int knot, double slope, const QRectF &world) const;
    [[nodiscard]] QRectF worldRect() const;
    // The spline of the input's method, in Hermite form or as a B-spline (functionspline.cpp): the
    // one place that builds it, for the plot, its values and its pieces. Every method but the bells
    // is a curve record in the function form drawn by geo::buildShape (the clamped spline by the
    // chosen solver, Török's only on evenly spaced knots, else the classical one).
    struct Built;
    [[nodiscard]] Built build() const;

    FunctionSplineInput m_in;
    bool m_showPolynomial = false;
    QString m_valuesText, m_intervalText, m_knotsText, m_derivativesText;
    ShownMessage m_error{this, [this] { Q_EMIT errorChanged(); }};
    QTimer m_languageSwitch; // announces the translated texts after a language switch
    QUndoStack m_undo;
    // During a drag: the axes stay put. Each drag has its serial, so that its steps merge into one
    // undo command.
    std::optional<QRectF> m_dragWorld;
    int m_dragSerial = 0;

    // Computed by recompute().
    std::vector<double> m_x;
    std::vector<double> m_dotY;
    std::vector<double> m_bellScale; // Bs_i = scale_i · N_i (bell B-spline only)
    QPolygonF m_spline;
    QPolygonF m_polynomial;
    QPolygonF m_function;
    std::vector<double> m_slopes;
    // Global B-spline: its control values b_0..b_{k+1} for the seed's scaled bells (Example 1.23).
    std::vector<double> m_controlValues;
    double m_maxDifference = 0.0;
    double m_solverDifference = std::numeric_limits<double>::quiet_NaN();
    bool m_torokDrawn = false; // Török's solver was chosen and could be used
    bool m_polynomialOk = false;
};

} // namespace kontur
