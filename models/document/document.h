// The document: the ordered curves the user works on, the background image state and the units.
// Every change goes through these few mutators, called by undo commands, and is announced with
// fine-grained signals so that the models notify only the rows and roles that changed.
#pragma once

#include "geometry/projective.h"
#include "models/document/allowancework.h"
#include "models/document/curve.h"

#include <QHash>
#include <QObject>
#include <QPointF>

#include <QtQml/qqmlregistration.h>
#include <array>
#include <optional>

namespace kontur {

// The background picture under the curves (seed 000's "Upload background", seed 004's picture):
// where it lies in the world, and its calibration to real units for pattern tracing.
struct Background
{
    QString file; // absolute path; empty: none
    bool visible = true;
    double opacity = 1.0;
    QPointF origin;        // world position of the image's top-left corner
    double scale = 1.0;    // world units per image pixel
    double rotation = 0.0; // degrees, counter-clockwise
    // Calibration: two image points a known distance apart.
    bool calibrated = false;
    QPointF calibrationA, calibrationB; // image pixels
    double calibrationDistance = 0.0;   // in `Document::units`
    bool locked = false;                // no calibration or placement change while locked (issue #10)
    // Perspective calibration (issue #22, models/perspective.h): while `perspective` is set the picture
    // is placed by the homography that takes `corners` (image pixels; top-left, top-right, bottom-right,
    // bottom-left as seen in the picture) to the rectangle rectWidth × rectHeight (document units)
    // whose top-left corner lies at `rectOrigin` (world); origin/scale/rotation are kept for clearing.
    bool perspective = false;
    std::array<QPointF, 4> corners{};
    double rectWidth = 0.0, rectHeight = 0.0;
    QPointF rectOrigin;

    // The one picture → world mapping (image pixels, y down → world, y up): the perspective
    // calibration's homography while it holds, otherwise the placement by origin, scale and rotation.
    // The canvas, the painters and the tracing tools all map the picture through it.
    [[nodiscard]] geo::Projective2D imageToWorld() const;
    [[nodiscard]] geo::Projective2D worldToImage() const;
    // Whether the picture is placed by a (non-degenerate) perspective calibration.
    [[nodiscard]] bool placedInPerspective() const;
    // The perspective calibration's homography, while `perspective` is set and it exists.
    [[nodiscard]] std::optional<geo::Projective2D> perspectiveMap() const;
    // The homography that takes the ordered picture corners (top-left, top-right, bottom-right,
    // bottom-left) to the rectangle width × height whose top-left corner lies at `topLeft` in the world
    // (y up: the picture's bottom corners lie at topLeft.y - height). Nothing when it does not exist
    // (a degenerate quadrilateral or rectangle, or a corner on the line the homography takes to infinity).
    [[nodiscard]] static std::optional<geo::Projective2D> homography(const std::array<QPointF, 4> &ordered,
                                                                     double width, double height, QPointF topLeft);
    [[nodiscard]] geo::Point toWorld(QPointF image) const
    {
        return imageToWorld().map(geo::Point(image.x(), image.y()));
    }
    [[nodiscard]] QPointF toImage(const geo::Point &world) const;

    friend bool operator==(const Background &, const Background &) = default;
};

class DocumentCommand;

// Not final: QML (Qt 6.4) derives from registered types.
class Document : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("The document belongs to an EditController.")
    Q_PROPERTY(int curveCount READ curveCount NOTIFY curveCountChanged)
    Q_PROPERTY(QString units READ units NOTIFY unitsChanged)
    // Every linked seam allowance is the offset of its source as it is now, and no worker computes
    // one (false while a drag's allowances follow it, and until the last of them has landed).
    Q_PROPERTY(bool allowancesSettled READ allowancesSettled NOTIFY allowancesSettledChanged)

public:
    explicit Document(QObject *parent = nullptr);
    // Stops the allowance worker (cancelled, and waited for: a few milliseconds).
    ~Document() override;
    Q_DISABLE_COPY_MOVE(Document)

    [[nodiscard]] int curveCount() const { return static_cast<int>(m_curves.size()); }
    [[nodiscard]] const Curve &curve(int index) const { return m_curves.at(static_cast<std::size_t>(index)); }
    [[nodiscard]] const std::vector<Curve> &curves() const { return m_curves; }
    // --- curves by identity ---
    // The row of the curve with `id`, or -1 when the document has none (deleted, never there).
    [[nodiscard]] int indexOf(CurveId id) const;
    [[nodiscard]] const Curve *find(CurveId id) const;
    [[nodiscard]] bool contains(CurveId id) const { return indexOf(id) >= 0; }
    [[nodiscard]] CurveId idAt(int index) const
    {
        return index >= 0 && index < curveCount() ? curve(index).id() : CurveId::None;
    }

    // Only undo commands change the document (the passkey idiom): a change made anywhere else could
    // not be undone, and a drag that changed the document before its command existed is how undo went
    // wrong before. Loading a file replaces everything through `EditController::replaceDocument`,
    // which starts a new history.
    class EditKey
    {
        friend class DocumentCommand;
        friend class EditController;
        EditKey() = default;
    };
    [[nodiscard]] const Background &background() const { return m_background; }
    [[nodiscard]] QString units() const { return m_units; }

    // --- mutators (the undo commands call these) ---
    // Inserts at `index`; a curve without an id, or with one the document already holds (a pasted
    // copy), gets a new one. Answers the curve's id.
    CurveId insertCurve(EditKey, int index, Curve curve);
    Curve takeCurve(EditKey, int index);
    void moveCurve(EditKey, int from, int to);
    // Replaces a whole curve (structure, settings, style), keeping its id; rows are inserted or
    // removed at the end.
    void replaceCurve(EditKey, int index, Curve curve);
    void setPoints(EditKey, int curve, const std::vector<PointChange> &changes, bool useAfter);
    // A piece's marks (none: the curve is no piece); the shape is untouched.
    void setPiece(EditKey, int curve, const std::optional<io::PieceMarks> &piece);
    // A user's move with the kind's rule; the changes are returned for undo. A move whose result
    // would not be finite (a target near the largest double carrying handles past it) changes
    // nothing and answers NonFiniteInput.
    [[nodiscard]] geo::Result<std::vector<PointChange>> movePoint(EditKey, int curve, int row, const geo::Point &target,
                                                                  geo::HandleMove mode);
    // After curves read from a file were inserted from row `first` on: their seam allowances' links
    // (file indices, relative to `first`) become ids; a link to no curve, or to itself, is dropped.
    // Returns the rows of the allowances whose settings gave no shape (they keep the saved one).
    [[nodiscard]] std::vector<int> resolveSeamLinks(EditKey, int first);
    void setBackground(EditKey, const Background &background);
    void setUnits(EditKey, const QString &units);

    // --- seam allowances (issue #22; computed off this thread during a drag, issue #45) ---
    // Outside a live edit, an edit of a curve computes its allowances again at once, on this thread
    // (a lookup when the offset was made before). During a live edit (a drag, from its start to its
    // release) an allowance whose source changes is not computed here: it keeps its shape and is
    // marked stale, and one worker thread computes it for the source as it is when the job starts;
    // each result lands (is shown) when done, and the next job takes the state the drag has reached
    // by then. When the live edit ends, a job of a state the drag has left is cancelled
    // (geo::OffsetControl) and the final state is computed; `allowancesSettled` turns true when it
    // has landed (at once when that offset is remembered). A synchronous recomputation (an undo, a
    // typed number) supersedes a stale allowance's job: its result is dropped.
    void beginLiveEdit(EditKey);
    void endLiveEdit(EditKey);
    // A step edit: one edit (a mutator call) whose allowances follow on the worker, as in a live edit
    // that ends with the edit: an arrow-key nudge, a seam width's − / + step and their undo and redo,
    // repeated fast (a held key auto-repeats). Each step's end cancels a job of a state it has left
    // and the worker takes the latest state, so that successive steps coalesce. Within a live edit
    // (a key pressed during a drag) the drag's release ends it.
    void beginStepEdit(EditKey) { ++m_steps; }
    void endStepEdit(EditKey);
    [[nodiscard]] bool allowancesSettled() const { return m_stale.empty() && !m_worker.busy(); }
    // Makes every stale allowance exact now, on this thread: waits for the worker's job when it is
    // of the current state, else computes (what is written or printed must be exact).
    void settleAllowances();
    // The allowance of `source` with `options` (allowanceOptions), as the document computes it:
    // remembered, so that an edit that then makes this allowance looks it up. For a trial before an
    // edit (SeamWidths), on this thread.
    [[nodiscard]] geo::Result<Curve> allowanceOf(const Curve &source, const geo::OffsetOptions &options);
    // An offset of `source` with `options` made elsewhere (the seam allowance dialog's worker, with
    // Curve::makeOffset), remembered so that the edit that adds it computes nothing again.
    void rememberOffset(const Curve &source, const geo::OffsetOptions &options, Curve offset);
    // The seams of `curve`'s outline (geo::seamSpans, a look at every joint of the outline). Those of
    // a curve of this document are found once and kept until that curve changes (its curveChanged,
    // rowsChanged, curveInserted or curveAboutToBeRemoved forgets them): a seam width's step asks for
    // them several times (the seam bar, the allowance's options, the worker's job, issue #45). Those
    // of any other curve (a trial copy) are found anew.
    [[nodiscard]] std::vector<geo::SeamSpan> seamsOf(const Curve &curve) const;
    // allowanceOptions(source, options), with the seams of seamsOf.
    [[nodiscard]] geo::OffsetOptions allowanceOptionsOf(const Curve &source, const geo::OffsetOptions &options) const;

Q_SIGNALS:
    void curveAboutToBeInserted(int index);
    void curveInserted(int index);
    void curveAboutToBeRemoved(int index);
    void curveRemoved(int index);
    void curveAboutToBeMoved(int from, int to);
    void curveMoved(int from, int to);
    // Rows first..last of `curve` changed position; the row count may have changed too.
    void rowsChanged(int curve, int first, int last);
    // Anything about the curve may have changed (settings, style, structure).
    void curveChanged(int curve);
    void curveCountChanged();
    void backgroundChanged();
    void unitsChanged();
    void allowancesSettledChanged();
    // The allowance at row `curve` could not be made for its source as it is now, found out by the
    // worker or by settleAllowances (e.g. wider inside than the piece): it keeps its last shape.
    void allowanceFailed(int curve);
    // Anything visible changed: the canvas repaints on this.
    void changed();

private:
    void announceRows(int curve, const std::vector<PointChange> &changes);
    // Seam allowances (issue #22): the allowance at `row` computed again from its source (kept as it
    // was while the source is absent or its offset fails), and every allowance of `source`, in turn
    // theirs (to a depth of 8: an allowance of an allowance is allowed); `later`: marked stale for
    // the worker instead (documentallowances.cpp). False when the offset fails (the allowance keeps
    // its shape).
    bool recomputeAllowance(int row, int depth = 0);
    void recomputeAllowancesOf(CurveId source, int depth = 0, bool later = false);
    // The edit mutators' calls: later while a live edit lasts (a lookup when the offset is known).
    void allowancesFollow(CurveId source) { recomputeAllowancesOf(source, 0, following()); }
    // Whether edits mark allowances stale for the worker now (a live edit or a step edit).
    [[nodiscard]] bool following() const { return m_live || m_steps > 0; }
    // The end of a live or step edit: remembered offsets land, a job of a state left is cancelled,
    // and the worker takes the state reached.
    void followLatest();
    void refreshAllowance(int row);
    // The allowance at `row` takes the shape `made` (its style, link and id kept), then its own
    // allowances follow, `later` or now.
    void setAllowanceShape(int row, Curve made, int depth, bool later);
    // The allowance at `row` follows its source later: its remembered offset lands at once, else it
    // is marked stale for the worker.
    void followLater(int row, int depth);
    void markStale(int row, int depth);
    void dropStale(CurveId allowance);
    // The stale allowance's offset when the memo knows it for its source as it is now.
    [[nodiscard]] const Curve *knownOffset(const Curve &allowance);
    // Whether the worker's job is of the allowance's source and settings as they are now.
    [[nodiscard]] bool jobCurrent(const AllowanceJob &job) const;
    void startAllowanceJob();
    // The worker's finished job: its result lands when it still answers a stale allowance; then the
    // next job starts unless `startNext` is false.
    void landAllowanceJob(bool startNext = true);
    void announceSettled(bool before);
    // The seams kept for the curve at `row` are of no use any more (seamsOf).
    void forgetSeams(int row);

    // A stale allowance: its id, which request it is (a synchronous recomputation ends it), and how
    // deep in a chain of allowances it lies.
    struct Stale
    {
        CurveId allowance;
        int ticket;
        int depth;
    };
    std::vector<Stale> m_stale;
    int m_lastTicket = 0;
    bool m_live = false;
    int m_steps = 0; // step edits begun and not ended (nested)
    OffsetMemo m_offsets;
    AllowanceWorker m_worker;

    std::vector<Curve> m_curves;
    // id -> row, rebuilt on the first lookup after curves came, went or moved (a file of 10^5
    // curves inserts each: rebuilding on every insertion would be quadratic).
    mutable QHash<int, int> m_rowOfId;
    mutable bool m_rowsStale = false;
    mutable int m_lastRow = 0;                              // the row indexOf answered last
    mutable QHash<int, std::vector<geo::SeamSpan>> m_seams; // curve id -> its seams (seamsOf)
    int m_lastId = 0;
    Background m_background;
    QString m_units = QStringLiteral("px");
};

} // namespace kontur
