// BasisPlot: the basis functions behind the selected curve, sampled for the plot under the canvas
// (issue 9 part B): Bernstein polynomials B_{i,n} of a Bézier curve (seed 004), B-spline bases
// N_{i,k} with their knot vector (seed 003 KG-205), seed 001's scaled "bell" functions Bs and the
// Hermite bases Hs, Hds (docs/requirements.md 2) — on one segment, or on the selected spline's own segments, a
// value basis Hs_k and a derivative basis Hds_k per knot, non-zero on the segments beside it. The basis of the selected
// control point is highlighted, and a marker at the parameter t shows every basis value there (they sum to 1 for
// Bernstein and B-spline).
#pragma once

#include "models/controllers/editcontroller.h"
#include "models/teaching/plotsource.h"

#include <QPointer>
#include <QtQml/qqmlregistration.h>

#include <vector>

namespace kontur {

// Not final: QML (Qt 6.4) derives from registered types.
class BasisPlot : public PlotSource
{
    Q_OBJECT
    QML_ELEMENT
    // The selected curve of this controller chooses the family (Auto) and the highlighted function.
    Q_PROPERTY(kontur::EditController *editor READ editor WRITE setEditor NOTIFY editorChanged)
    Q_PROPERTY(Family family READ family WRITE setFamily NOTIFY settingsChanged)
    Q_PROPERTY(Family shownFamily READ shownFamily NOTIFY plotChanged)
    // Bernstein degree n when no Bézier curve is selected (1..30).
    Q_PROPERTY(int degree READ degree WRITE setDegree NOTIFY settingsChanged)
    // B-spline order k (2..10) and number of basis functions (control points) when no B-spline is selected.
    Q_PROPERTY(int order READ order WRITE setOrder NOTIFY settingsChanged)
    Q_PROPERTY(int count READ count WRITE setCount NOTIFY settingsChanged)
    // The parameter as a fraction 0..1 of the plotted domain (t itself for Bernstein and Hermite).
    Q_PROPERTY(double parameter READ parameter WRITE setParameter NOTIFY parameterChanged)
    Q_PROPERTY(int functionCount READ functionCount NOTIFY plotChanged)
    Q_PROPERTY(int highlighted READ highlighted NOTIFY plotChanged)
    Q_PROPERTY(QString title READ title NOTIFY plotChanged)
    Q_PROPERTY(QString knotText READ knotText NOTIFY plotChanged)
    Q_PROPERTY(QString valuesText READ valuesText NOTIFY plotChanged)

public:
    enum Family { Auto, Bernstein, BSpline, Bell, Hermite };
    Q_ENUM(Family)

    // More basis functions than this are not drawn (a B-spline of a million points).
    static constexpr int kMaxFunctions = 120;
    // The plot draws Hermite's derivative bases Hds this many times taller (labelled "4·Hds…"): at their
    // true size they stay within 4/27 of the axis, about 11 px of the panel's plot.
    static constexpr double kHermiteSlopeScale = 4.0;

    explicit BasisPlot(QObject *parent = nullptr);

    [[nodiscard]] EditController *editor() const { return m_editor; }
    void setEditor(EditController *editor);
    [[nodiscard]] Family family() const { return m_family; }
    void setFamily(Family family);
    [[nodiscard]] Family shownFamily() const { return m_shown; }
    [[nodiscard]] int degree() const { return m_degree; }
    void setDegree(int degree);
    [[nodiscard]] int order() const { return m_order; }
    void setOrder(int order);
    [[nodiscard]] int count() const { return m_count; }
    void setCount(int count);
    [[nodiscard]] double parameter() const { return m_parameter; }
    void setParameter(double parameter);

    // Draws again (after a language switch: the tick labels and values follow the number format).
    void refresh() { Q_EMIT plotChanged(); }

    [[nodiscard]] int functionCount() const { return m_functionCount; }
    [[nodiscard]] int highlighted() const { return m_highlighted; }
    [[nodiscard]] QString title() const;
    [[nodiscard]] QString knotText() const;
    [[nodiscard]] QString valuesText() const;

    // The domain [lo, hi] of the plotted basis, the knot vector (B-spline and bells) and the value
    // of basis function i at x (for tests and the marker).
    [[nodiscard]] double domainStart() const { return m_lo; }
    [[nodiscard]] double domainEnd() const { return m_hi; }
    [[nodiscard]] const std::vector<double> &knots() const { return m_knots; }
    [[nodiscard]] double value(int i, double x) const;
    [[nodiscard]] double markerX() const { return m_lo + m_parameter * (m_hi - m_lo); }

    [[nodiscard]] PlotData plotData() const override;
    void dragMarker(double x) override;
    void hoverSeries(int id) override;

Q_SIGNALS:
    void editorChanged();
    void settingsChanged();
    void parameterChanged();

private:
    void rebuild();
    [[nodiscard]] int highlightFromSelection() const;
    [[nodiscard]] QString functionLabel(int i) const;

    QPointer<EditController> m_editor;
    Family m_family = Auto;
    Family m_shown = Bernstein;
    int m_degree = 3;
    int m_order = 4;
    int m_count = 8;
    double m_parameter = 0.5;
    int m_hovered = -1;

    // What rebuild() found.
    int m_functionCount = 0;
    int m_shownDegree = 3; // Bernstein degree, or the B-spline/bell degree
    int m_highlighted = -1;
    bool m_tooMany = false;
    int m_requestedCount = 0; // the functions the basis has (also when too many to draw)
    double m_lo = 0.0;
    double m_hi = 1.0;
    std::vector<double> m_knots;
    // Hermite bases on the selected curve's own segments: its joints at 0, 1, …, m (the de Casteljau
    // view's parameter u = t·m); empty for the bases of one segment.
    int m_hermiteSegments = 0;
    std::vector<QPolygonF> m_samples;
};

} // namespace kontur
