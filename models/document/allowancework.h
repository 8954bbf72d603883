// What the Document keeps to compute seam allowances (issue #45): the offsets it made last, looked
// up instead of computed again (an undo, a redo, a result a worker thread made), and the one worker
// thread that computes an allowance while its source is being dragged. Both belong to one Document
// and are used from its thread only; the worker's job is the only thing another thread touches.
#pragma once

#include "geometry/offset.h"
#include "geometry/piecewise.h"
#include "models/document/curve.h"

#include <QObject>

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

class QThread;

namespace kontur {

// Whether two sets of offset options give the same offset (every field compared exactly).
[[nodiscard]] bool sameOffsetOptions(const geo::OffsetOptions &a, const geo::OffsetOptions &b);
// Whether two sources are the same pieces, bit for bit.
[[nodiscard]] bool samePieces(const geo::PiecewiseBezier &a, const geo::PiecewiseBezier &b);

// The offsets made last, newest first, by their source's pieces and their options (compared exactly,
// so that a lookup answers what computing would). Kept: kSize, enough for an allowance before and
// after a drag or a change of its settings, for a few allowances, and for an allowance of an allowance.
// Each entry also keeps its source curve's Curve::geometryHash(): a source whose hash no entry has is
// not remembered, and is answered without building its pieces (holds()).
class OffsetMemo final
{
public:
    static constexpr std::size_t kSize = 8;
    // Whether an offset of a source with this Curve::geometryHash() may be remembered.
    [[nodiscard]] bool holds(std::size_t sourceHash) const;
    // The offset of `source` (whose curve's hash is `sourceHash`) with `options` when it is remembered
    // (it becomes the newest), else null.
    [[nodiscard]] const Curve *find(std::size_t sourceHash, const geo::PiecewiseBezier &source,
                                    const geo::OffsetOptions &options);
    void store(std::size_t sourceHash, geo::PiecewiseBezier source, const geo::OffsetOptions &options,
               Curve offset);

private:
    struct Entry
    {
        std::size_t sourceHash = 0;
        geo::PiecewiseBezier source;
        geo::OffsetOptions options;
        Curve offset;
    };
    std::vector<Entry> m_entries;
};

// One allowance computed off the Document's thread: the source's pieces and the options as they
// were when it started (copies: the document changes meanwhile), and the result. The worker reads
// `source`, `options` and `control` and writes only `result`; the Document reads `result` after the
// worker's thread has finished.
struct AllowanceJob
{
    CurveId allowance = CurveId::None;
    int ticket = 0; // which request for this allowance the job answers (Document's bookkeeping)
    CurveId sourceId = CurveId::None;
    std::size_t sourceHash = 0; // the source curve's Curve::geometryHash(), for the memo
    geo::PiecewiseBezier source;
    geo::OffsetOptions options;
    geo::OffsetControl control;
    std::optional<geo::Result<Curve>> result;
};

// Runs one AllowanceJob at a time on a thread of its own (QThread::create, as the seam allowance
// dialog does); `done` is called on the owner's thread when it has finished.
class AllowanceWorker final
{
public:
    AllowanceWorker();
    // Cancels the job and waits for its thread.
    ~AllowanceWorker();
    Q_DISABLE_COPY_MOVE(AllowanceWorker)

    [[nodiscard]] bool busy() const { return m_job != nullptr; }
    // The job being computed (null when none).
    [[nodiscard]] const AllowanceJob *job() const { return m_job.get(); }
    // Starts `job`; `done` runs on `context`'s thread once it has finished (queued). Not while busy.
    void start(std::shared_ptr<AllowanceJob> job, QObject *context, std::function<void()> done);
    // The finished job, and the worker idle again; null while the job still runs (or there is none).
    [[nodiscard]] std::shared_ptr<AllowanceJob> takeFinished();
    // Asks the running job to stop (geo::OffsetControl); it ends with ErrorCode::Cancelled soon after.
    void cancel();
    // Waits until the running job has finished (its result is then taken with takeFinished()).
    void wait();

private:
    std::shared_ptr<AllowanceJob> m_job;
    std::unique_ptr<QThread> m_thread;
};

} // namespace kontur
