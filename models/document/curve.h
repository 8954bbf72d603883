// One curve of a document: its kind, style, settings and defining points, and what is derived from
// them (the Bézier segments that draw it, the fit, length and continuity), kept up to date by the
// curve itself. Point edits go through here so that only what they touch is recomputed.
#pragma once

#include "geometry/bezier.h"
#include "geometry/composite.h"
#include "geometry/curveshape.h"
#include "geometry/fit.h"
#include "geometry/offset.h"
#include "geometry/parameterization.h"
#include "geometry/piecewise.h"
#include "geometry/result.h"
#include "geometry/seams.h"
#include "geometry/splines/hermite.h"
#include "io/piece.h"
#include "models/document/kindnames.h"

#include <QColor>
#include <QString>

#include <optional>
#include <utility>
#include <vector>

namespace kontur {

// The kinds of curve, their ids and their facts are the geometry's one table (geometry/curvekinds.h),
// shared with the file layer and kontur-cli; their translated names are in kindnames.h.
using geo::CurveKind;
using geo::kindId;
using geo::KindTraits;
using geo::kKindCount;
using geo::traitsOf;

// A curve's identity for as long as the document holds it: kept through moves, edits, undo and redo,
// never reused within a document. Rows change when curves come, go or move; ids do not, so whatever
// follows a curve (the selection, a teaching view, a trace result) holds its id, never its row.
// QML sees ids as ints (0: none).
enum class CurveId : int { None = 0 };

// A seam allowance's link (issue #22): the curve it is the offset of, and how. The allowance is a
// composite curve that the document computes again whenever its source changes; while linked, its
// own points do not move (the user changes the source or these settings, or detaches it).
struct SeamLink
{
    CurveId source = CurveId::None;
    geo::OffsetOptions options;
    // While a file is read: the source's index among the file's curves, until the document resolves
    // it to an id (Document::resolveSeamLinks); -1 after.
    int fileIndex = -1;

    friend bool operator==(const SeamLink &a, const SeamLink &b)
    {
        return a.source == b.source && a.options.distance == b.options.distance && a.options.side == b.options.side &&
               a.options.join == b.options.join && a.options.miterLimit == b.options.miterLimit &&
               a.options.tolerance == b.options.tolerance && a.fileIndex == b.fileIndex;
    }
};

// What a point means for its curve; the canvas draws each role differently (docs/requirements.md 1.1 req. 6).
enum class PointRole { ControlPoint, Knot, Handle, TangentEnd };

[[nodiscard]] QString pointLabel(PointRole role, int number);

// One row of the coordinates table: a defining point, or a point derived from them.
struct PointRow
{
    geo::Point position = geo::Point::Zero();
    PointRole role = PointRole::ControlPoint;
    bool editable = true;                           // false for derived points (the control points of a fitted cubic)
    int number = 0;                                 // the number in the label: P<number> or C<number>
    geo::NodeType nodeType = geo::NodeType::Smooth; // knots of a composite curve
};

// A changed point, for undo: row, position before, position after.
struct PointChange
{
    int row = 0;
    geo::Point before = geo::Point::Zero();
    geo::Point after = geo::Point::Zero();
};

// The weakest joint of a curve, and how many joints there are.
struct ContinuitySummary
{
    int joints = 0;
    geo::Continuity weakest = geo::Continuity::C2;
};

class Curve final
{
public:
    Curve() = default;
    // A curve of `kind` through or controlled by `points`. Composite curves are built from their
    // knots by the seed's rules; the others keep `points` as given.
    static Curve make(CurveKind kind, std::vector<geo::Point> points,
                      geo::Parameterization parameterization = geo::Parameterization::Uniform);
    // A composite curve from its full control vector (for undo and documents).
    static geo::Result<Curve> makeComposite(geo::CompositeCurve composite);
    // The seam allowance of `source` (geo::offsetCurve) as a composite curve, without style or link:
    // what creating an allowance and recomputing it after an edit of its source both make. A pure
    // function, safe on any thread for a source no other thread touches; `control` lets another
    // thread cancel it. The Document remembers the offsets it made (Document::allowanceOf).
    static geo::Result<Curve> makeOffset(const geo::PiecewiseBezier &source, const geo::OffsetOptions &options,
                                         geo::OffsetControl *control = nullptr);
    static geo::Result<Curve> makeOffset(const Curve &source, const geo::OffsetOptions &options,
                                         geo::OffsetControl *control = nullptr)
    {
        return makeOffset(source.toPiecewise(), options, control);
    }
    // Any other kind from its stored parts (documents): the placed points, the tangent ends of the
    // kinds with tangents (none for the others: defaults are made), the B-spline order.
    static geo::Result<Curve> restore(CurveKind kind, std::vector<geo::Point> points,
                                      std::vector<geo::Point> tangentEnds, int order,
                                      geo::Parameterization parameterization);
    [[nodiscard]] const std::vector<geo::Point> &placedPoints() const { return m_points; }
    [[nodiscard]] const std::vector<geo::Point> &tangentEnds() const { return m_tangentEnds; }

    // --- identity, style, settings ---
    // Given by the document when the curve is first inserted (Document::insertCurve); a copy keeps it,
    // which is how undo brings back the same curve.
    [[nodiscard]] CurveId id() const { return m_id; }
    [[nodiscard]] CurveKind kind() const { return m_kind; }
    // B-spline order k (2..10, at most the number of control points); 0 for other kinds.
    [[nodiscard]] int order() const { return m_kind == CurveKind::BSpline ? m_order : 0; }
    [[nodiscard]] geo::Result<geo::Ok> setOrder(int order);
    QString name;
    // The name was given by Kontur to a curve that had none when its document was opened
    // (EditController::replaceDocument), not by the user: shown, but written as no name, so that
    // opening and saving a document changes no byte of it. Renaming makes it the user's.
    bool nameGenerated = false;
    QColor color = QColor(0, 0, 0);
    bool visible = true;
    bool locked = false;
    // Set on a seam allowance; its shape follows the source (Document keeps it so).
    std::optional<SeamLink> seam;
    // Set on a closed curve that is a garment piece: its size, quantity, material, fold, grainline,
    // notches and drill holes (io/piece.h); its name is the piece's name.
    std::optional<io::PieceMarks> piece;
    [[nodiscard]] geo::Parameterization parameterization() const { return m_parameterization; }
    // Recomputes at once (seed T14). Kinds without a parameterization keep theirs unchanged.
    void setParameterization(geo::Parameterization p);
    [[nodiscard]] bool isClosed() const;
    // The fewest placed points the curve may keep: the kind's minimum, and 3 for a closed curve.
    [[nodiscard]] int minimumPoints() const;
    // Takes over another curve's name, colour, visibility and lock (a curve remade from new points);
    // not its piece's marks, which a curve split or offset from it does not have.
    void copyStyleFrom(const Curve &other);

    // --- defining points (what the user places and moves): knots or control points first, then
    // the tangent ends of the kinds with tangents (the Bézier handle each tangent gives) ---
    [[nodiscard]] int definingCount() const;
    // The points the user placed: knots or control points (a composite's knots; no tangent ends).
    [[nodiscard]] int placedCount() const
    {
        return m_kind == CurveKind::Composite ? m_composite.knotCount() : knotCount();
    }
    [[nodiscard]] geo::Point definingPoint(int i) const;
    // All defining points in order: control points, knots, or a composite's control vector.
    [[nodiscard]] std::vector<geo::Point> definingPoints() const;
    [[nodiscard]] const geo::CompositeCurve &composite() const { return m_composite; }

    // --- rows: defining points first, then derived ones ---
    [[nodiscard]] int rowCount() const;
    [[nodiscard]] PointRow row(int i) const;

    // Sets defining points exactly (undo, typed coordinates of non-composite kinds) and recomputes.
    void setPoints(const std::vector<PointChange> &changes, bool useAfter);
    // A point moved by the user, with the kind's rule (docs/requirements.md 1.4). Returns the defining points
    // that changed (for undo); errors for rows that may not move (derived points).
    [[nodiscard]] geo::Result<std::vector<PointChange>> move(int row, const geo::Point &target, geo::HandleMove mode);

    // --- structure: whole-curve edits, undone by restoring a copy ---
    [[nodiscard]] geo::Result<geo::Ok> insertPoint(int index, const geo::Point &p);
    [[nodiscard]] geo::Result<geo::Ok> removePoint(int index);
    [[nodiscard]] geo::Result<geo::Ok> setNodeType(int knot, geo::NodeType type);
    [[nodiscard]] geo::Result<geo::Ok> insertKnotOnSegment(int segment, double t);
    [[nodiscard]] geo::Result<geo::Ok> close();

    // --- derived ---
    [[nodiscard]] int segmentCount() const;
    [[nodiscard]] geo::Bezier segment(int i) const;
    // A problem that keeps the curve from being drawn (a fit on degenerate knots), if any.
    [[nodiscard]] const std::optional<geo::Error> &problem() const { return m_problem; }
    [[nodiscard]] const std::optional<geo::CubicFit> &fit() const { return m_shape.fit; }
    // Length to `accuracy` (absolute, per segment): segments are measured once and again only
    // after an edit touched them.
    [[nodiscard]] double length(double accuracy = 1e-9) const;
    [[nodiscard]] ContinuitySummary continuity() const;
    [[nodiscard]] geo::Box bounds() const; // of all rows
    // The pairs of rows joined by the light grey guide lines, for the curve's kind: the control
    // polygon (Bézier, B-spline, the Bézier segment of a cubic fit), each handle to its knot
    // (composite), each tangent end to its knot (clamped, global B-spline, Hermite). A polygon's
    // pairs come in order, each starting where the one before ended.
    [[nodiscard]] std::vector<std::pair<int, int>> guides() const;
    [[nodiscard]] geo::PiecewiseBezier toPiecewise() const;
    // A hash of all that toPiecewise() is made from (the kind, the points and tangent ends, the order,
    // the parameterization; a composite curve's control points, node types and closure): the same
    // geometry, the same hash. One pass over the rows, nothing allocated; the Document's memo of
    // offsets checks it before it builds the pieces to compare (a drag step misses at once).
    [[nodiscard]] std::size_t geometryHash() const;
    // Every row and every segment's control point is finite. A composite curve's segments are its
    // rows; the other kinds' segments are checked in place (this runs on every drag step).
    [[nodiscard]] bool isFinite() const;

    // The state a user edits, without caches: what undo must restore exactly.
    [[nodiscard]] bool sameState(const Curve &other) const;

    // --- the row layout: the one place that knows that a composite curve's rows are its control
    // vector (knot k at row 3k, its handles at 3k-1 and 3k+1) and the other kinds' rows start with
    // their placed points ---
    // The placed point a row belongs to: a composite's knot for its knot and handle rows, the point
    // itself for the other kinds' placed points; -1 for tangent ends, derived rows and rows out of range.
    [[nodiscard]] int knotOfRow(int row) const;
    // The row of placed point `knot` (-1 out of range).
    [[nodiscard]] int rowOfKnot(int knot) const;
    // Whether `row` is a placed point itself (a composite's knot, not one of its handles).
    [[nodiscard]] bool isKnotRow(int row) const { return row >= 0 && rowOfKnot(knotOfRow(row)) == row; }
    // Whether `row` is drawn and can be grabbed while `selectedRow` is this curve's selected row (-1:
    // none, or another curve is selected). Every row of the other kinds; a composite curve's knots
    // always, its handles only those of the selected row's knot and of its neighbours (Inkscape's
    // node tool), so that a traced curve of many segments stays legible.
    [[nodiscard]] bool isRowShown(int row, int selectedRow) const;

private:
    friend class Document;                    // gives ids
    void recompute();                         // everything, after a structural change
    void touchSegments(int first, int count); // marks caches of these segments stale
    void resizeCaches();
    [[nodiscard]] int knotCount() const { return static_cast<int>(m_points.size()); }
    // Default tangent ends for the kinds with tangents (geo::defaultTangentEnds).
    void initTangentEnds();

    CurveId m_id = CurveId::None;
    CurveKind m_kind = CurveKind::Bezier;
    int m_order = 4;
    std::vector<geo::Point> m_tangentEnds; // Clamped and GlobalBSpline: start, end; Hermite: one per knot
    geo::Parameterization m_parameterization = geo::Parameterization::Uniform;
    std::vector<geo::Point> m_points; // all kinds but Composite
    geo::CompositeCurve m_composite;  // Composite

    // Derived.
    geo::CurveShape m_shape; // all kinds but Composite
    std::optional<geo::Error> m_problem;
    mutable std::vector<double> m_segmentLength; // NaN: stale
    mutable double m_lengthAccuracy = 0.0;
    mutable std::vector<signed char> m_jointLevel; // -1: stale
};

// The options an allowance of `source` is computed with: `options` (the allowance's own width and
// settings) and, when the source is a piece with widths per seam, each segment's width
// (geo::segmentDistancesOf).
[[nodiscard]] geo::OffsetOptions allowanceOptions(const Curve &source, geo::OffsetOptions options);
// The same with the seams of the source's outline (geo::seamSpans) known already (Document::seamsOf).
[[nodiscard]] geo::OffsetOptions allowanceOptions(const Curve &source, geo::OffsetOptions options,
                                                  const std::vector<geo::SeamSpan> &seams);
// Whether allowanceOptions needs the source's seams: a closed piece with a width or a hem per seam.
[[nodiscard]] bool allowanceHasSeams(const Curve &source);

} // namespace kontur
