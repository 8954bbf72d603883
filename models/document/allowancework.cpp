// The Document's memo of offsets and its allowance worker (see allowancework.h).
#include "models/document/allowancework.h"

#include <QThread>

#include <algorithm>
#include <utility>

namespace kontur {

bool sameOffsetOptions(const geo::OffsetOptions &a, const geo::OffsetOptions &b)
{
    return a.distance == b.distance && a.side == b.side && a.join == b.join && a.miterLimit == b.miterLimit &&
           a.tolerance == b.tolerance && a.segmentDistances == b.segmentDistances && a.hems == b.hems;
}

bool samePieces(const geo::PiecewiseBezier &a, const geo::PiecewiseBezier &b)
{
    if (a.isClosed() != b.isClosed() || a.segmentCount() != b.segmentCount())
        return false;
    for (int i = 0; i < a.segmentCount(); ++i)
        if (a.segments()[static_cast<std::size_t>(i)].controlPoints() !=
            b.segments()[static_cast<std::size_t>(i)].controlPoints())
            return false;
    return true;
}

bool OffsetMemo::holds(std::size_t sourceHash) const
{
    return std::any_of(m_entries.begin(), m_entries.end(), [&](const Entry &e) { return e.sourceHash == sourceHash; });
}

const Curve *OffsetMemo::find(std::size_t sourceHash, const geo::PiecewiseBezier &source,
                              const geo::OffsetOptions &options)
{
    for (auto it = m_entries.begin(); it != m_entries.end(); ++it)
        if (it->sourceHash == sourceHash && sameOffsetOptions(it->options, options) && samePieces(it->source, source)) {
            std::rotate(m_entries.begin(), it, it + 1);
            return &m_entries.front().offset;
        }
    return nullptr;
}

void OffsetMemo::store(std::size_t sourceHash, geo::PiecewiseBezier source, const geo::OffsetOptions &options,
                       Curve offset)
{
    if (find(sourceHash, source, options))
        return; // already the newest
    m_entries.insert(m_entries.begin(), Entry{sourceHash, std::move(source), options, std::move(offset)});
    if (m_entries.size() > kSize)
        m_entries.pop_back();
}

AllowanceWorker::AllowanceWorker() = default;

AllowanceWorker::~AllowanceWorker()
{
    cancel();
    wait();
}

void AllowanceWorker::start(std::shared_ptr<AllowanceJob> job, QObject *context, std::function<void()> done)
{
    Q_ASSERT(!busy());
    m_job = std::move(job);
    m_thread.reset(QThread::create(
        [job = m_job] { job->result.emplace(Curve::makeOffset(job->source, job->options, &job->control)); }));
    // Emitted on the worker thread: queued to the context's thread.
    QObject::connect(m_thread.get(), &QThread::finished, context, std::move(done), Qt::QueuedConnection);
    m_thread->start();
}

std::shared_ptr<AllowanceJob> AllowanceWorker::takeFinished()
{
    // A finished signal can arrive after its job was taken (wait() and takeFinished() went first).
    if (!m_job || !m_thread->isFinished())
        return nullptr;
    m_thread->wait();
    m_thread.reset();
    return std::exchange(m_job, nullptr);
}

void AllowanceWorker::cancel()
{
    if (m_job)
        m_job->control.cancel();
}

void AllowanceWorker::wait()
{
    if (m_thread)
        m_thread->wait();
}

} // namespace kontur
