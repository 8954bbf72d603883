// The Document's seam allowances: computed again when their source changes, on this thread outside a
// live edit and on the worker during one: a drag, or a step edit (an arrow-key nudge, a seam width's
// step, and their undo and redo), a live edit that ends with its one edit (see document.h, "seam
// allowances").
#include "models/document/document.h"

#include <algorithm>
#include <utility>

namespace kontur {

namespace {

constexpr int kMaxAllowanceDepth = 8;

} // namespace

Document::~Document()
{
    m_worker.cancel();
    m_worker.wait();
}

bool Document::recomputeAllowance(int row, int depth)
{
    Curve &allowance = m_curves[static_cast<std::size_t>(row)];
    const bool settled = allowancesSettled();
    dropStale(allowance.m_id); // computed now: a job of it is superseded
    const Curve *source = find(allowance.seam->source);
    if (!source || source == &allowance) {
        announceSettled(settled);
        return true; // the source is deleted (an undo may bring it back): the allowance keeps its shape
    }
    auto made = allowanceOf(*source, allowance.seam->options);
    announceSettled(settled);
    if (!made.ok())
        return false; // e.g. wider inside than the curve: the last shape stays
    setAllowanceShape(row, std::move(made).value(), depth, false);
    return true;
}

void Document::recomputeAllowancesOf(CurveId source, int depth, bool later)
{
    if (depth > kMaxAllowanceDepth)
        return;
    for (int row = 0; row < curveCount(); ++row) {
        const Curve &c = m_curves[static_cast<std::size_t>(row)];
        if (!c.seam || c.seam->source != source || c.m_id == source)
            continue;
        if (later)
            followLater(row, depth);
        else
            recomputeAllowance(row, depth);
    }
}

void Document::refreshAllowance(int row)
{
    if (!following()) {
        recomputeAllowance(row);
        return;
    }
    followLater(row, 0);
}

void Document::followLater(int row, int depth)
{
    const Curve &allowance = m_curves[static_cast<std::size_t>(row)];
    if (const Curve *known = knownOffset(allowance)) {
        const bool settled = allowancesSettled();
        Curve shape = *known; // a copy: the memo's order changes while the shape lands
        dropStale(allowance.m_id);
        setAllowanceShape(row, std::move(shape), depth, true);
        announceSettled(settled);
    } else {
        markStale(row, depth);
    }
}

void Document::setAllowanceShape(int row, Curve made, int depth, bool later)
{
    Curve &allowance = m_curves[static_cast<std::size_t>(row)];
    made.copyStyleFrom(allowance);
    made.seam = allowance.seam;
    made.m_id = allowance.m_id;
    if (made.sameState(allowance))
        return;
    allowance = std::move(made);
    Q_EMIT curveChanged(row);
    Q_EMIT changed();
    recomputeAllowancesOf(allowance.m_id, depth + 1, later);
}

geo::Result<Curve> Document::allowanceOf(const Curve &source, const geo::OffsetOptions &options)
{
    const std::size_t hash = source.geometryHash();
    geo::PiecewiseBezier pieces = source.toPiecewise();
    const geo::OffsetOptions full = allowanceOptionsOf(source, options);
    if (const Curve *known = m_offsets.find(hash, pieces, full))
        return *known;
    auto made = Curve::makeOffset(pieces, full);
    if (made.ok())
        m_offsets.store(hash, std::move(pieces), full, made.value());
    return made;
}

void Document::rememberOffset(const Curve &source, const geo::OffsetOptions &options, Curve offset)
{
    m_offsets.store(source.geometryHash(), source.toPiecewise(), allowanceOptionsOf(source, options), std::move(offset));
}

std::vector<geo::SeamSpan> Document::seamsOf(const Curve &curve) const
{
    if (find(curve.m_id) != &curve)
        return geo::seamSpans(curve.toPiecewise()); // no curve of the document: a trial copy
    const int id = static_cast<int>(curve.m_id);
    if (const auto known = m_seams.constFind(id); known != m_seams.cend())
        return *known;
    return *m_seams.insert(id, geo::seamSpans(curve.toPiecewise()));
}

geo::OffsetOptions Document::allowanceOptionsOf(const Curve &source, const geo::OffsetOptions &options) const
{
    return allowanceOptions(source, options,
                            allowanceHasSeams(source) ? seamsOf(source) : std::vector<geo::SeamSpan>{});
}

void Document::forgetSeams(int row)
{
    if (row >= 0 && row < curveCount())
        m_seams.remove(static_cast<int>(m_curves[static_cast<std::size_t>(row)].m_id));
}

// --- during a live edit: stale allowances and the worker ----------------------------------------

void Document::beginLiveEdit(EditKey)
{
    m_live = true;
}

void Document::endLiveEdit(EditKey)
{
    if (!m_live)
        return;
    m_live = false;
    if (m_steps == 0)
        followLatest();
}

void Document::endStepEdit(EditKey)
{
    if (m_steps == 0)
        return;
    if (--m_steps == 0 && !m_live)
        followLatest();
}

void Document::followLatest()
{
    const bool settled = allowancesSettled();
    // The latest state's offsets that are known land at once (a drag back to where it began, an undo).
    for (std::size_t i = 0; i < m_stale.size();) {
        const Stale stale = m_stale[i];
        const int row = indexOf(stale.allowance);
        const Curve *known = row >= 0 ? knownOffset(m_curves[static_cast<std::size_t>(row)]) : nullptr;
        if (!known) {
            ++i;
            continue;
        }
        const Curve shape = *known;
        dropStale(stale.allowance); // and its job, if it runs
        setAllowanceShape(row, shape, stale.depth, true);
        i = 0; // the landing may have marked others stale
    }
    // A job of a state the edit has left is of no use any more: the latest state goes next.
    if (const AllowanceJob *job = m_worker.job(); job && !jobCurrent(*job))
        m_worker.cancel();
    startAllowanceJob();
    announceSettled(settled);
}

void Document::markStale(int row, int depth)
{
    const CurveId id = m_curves[static_cast<std::size_t>(row)].m_id;
    if (std::any_of(m_stale.begin(), m_stale.end(), [&](const Stale &s) { return s.allowance == id; }))
        return; // already waiting: its next job reads the source as it is then
    const bool settled = allowancesSettled();
    m_stale.push_back({id, ++m_lastTicket, depth});
    startAllowanceJob();
    announceSettled(settled);
}

void Document::dropStale(CurveId allowance)
{
    const auto it =
        std::find_if(m_stale.begin(), m_stale.end(), [&](const Stale &s) { return s.allowance == allowance; });
    if (it == m_stale.end())
        return;
    m_stale.erase(it);
    if (const AllowanceJob *job = m_worker.job(); job && job->allowance == allowance)
        m_worker.cancel(); // its result would be dropped
}

const Curve *Document::knownOffset(const Curve &allowance)
{
    const Curve *source = allowance.seam ? find(allowance.seam->source) : nullptr;
    if (!source || source == &allowance)
        return nullptr;
    const std::size_t hash = source->geometryHash();
    if (!m_offsets.holds(hash))
        return nullptr; // a drag step's usual answer, found without building the pieces and the seams
    return m_offsets.find(hash, source->toPiecewise(), allowanceOptionsOf(*source, allowance.seam->options));
}

bool Document::jobCurrent(const AllowanceJob &job) const
{
    const Curve *allowance = find(job.allowance);
    const Curve *source = allowance && allowance->seam ? find(allowance->seam->source) : nullptr;
    return source && source->m_id == job.sourceId &&
           sameOffsetOptions(allowanceOptionsOf(*source, allowance->seam->options), job.options) &&
           samePieces(source->toPiecewise(), job.source);
}

void Document::startAllowanceJob()
{
    while (!m_worker.busy() && !m_stale.empty()) {
        // An allowance whose source is itself stale waits for it (an allowance of an allowance),
        // unless every one waits (a cycle of links).
        const auto isStale = [&](CurveId id) {
            return std::any_of(m_stale.begin(), m_stale.end(), [&](const Stale &s) { return s.allowance == id; });
        };
        auto next = std::find_if(m_stale.begin(), m_stale.end(), [&](const Stale &s) {
            const Curve *c = find(s.allowance);
            return !c || !c->seam || !isStale(c->seam->source);
        });
        if (next == m_stale.end())
            next = m_stale.begin();
        const Curve *allowance = find(next->allowance);
        const Curve *source = allowance && allowance->seam ? find(allowance->seam->source) : nullptr;
        if (!source || source == allowance) {
            m_stale.erase(next); // nothing to follow: it keeps its shape, as on this thread
            continue;
        }
        auto job = std::make_shared<AllowanceJob>();
        job->allowance = next->allowance;
        job->ticket = next->ticket;
        job->sourceId = source->m_id;
        job->sourceHash = source->geometryHash();
        job->source = source->toPiecewise();
        job->options = allowanceOptionsOf(*source, allowance->seam->options);
        m_worker.start(std::move(job), this, [this] { landAllowanceJob(); });
    }
}

void Document::landAllowanceJob(bool startNext)
{
    const bool settled = allowancesSettled();
    const std::shared_ptr<AllowanceJob> job = m_worker.takeFinished();
    const auto stale = job ? std::find_if(m_stale.begin(), m_stale.end(),
                                          [&](const Stale &s) { return s.allowance == job->allowance; })
                           : m_stale.end();
    // Dropped when a synchronous recomputation (or a removal) answered the request meanwhile.
    const int row = job ? indexOf(job->allowance) : -1;
    if (row < 0 || !curve(row).seam) {
        if (stale != m_stale.end())
            m_stale.erase(stale); // gone, or no allowance any more
    } else if (job->result && stale != m_stale.end() && stale->ticket == job->ticket) {
        const int depth = stale->depth;
        const bool current = jobCurrent(*job);
        const Curve &allowance = curve(row);
        const Curve *source = find(allowance.seam->source);
        // Of the same settings, a result of a state the drag has since left is still the nearer shape.
        const bool follows =
            current || (source && source->m_id == job->sourceId &&
                        sameOffsetOptions(allowanceOptionsOf(*source, allowance.seam->options), job->options));
        if (job->result->ok()) {
            if (current) {
                m_stale.erase(stale);
                m_offsets.store(job->sourceHash, std::move(job->source), job->options, job->result->value());
            }
            if (follows)
                setAllowanceShape(row, std::move(*job->result).value(), depth, true);
        } else if (current && job->result->error().code != geo::ErrorCode::Cancelled) {
            m_stale.erase(stale); // no allowance for this state: the last shape stays, as on this thread
            Q_EMIT allowanceFailed(row);
        }
    }
    if (startNext)
        startAllowanceJob();
    announceSettled(settled);
}

void Document::settleAllowances()
{
    const bool settled = allowancesSettled();
    // A job of the current state is waited for (its landing may start one for an allowance of the
    // allowance, waited for in turn); any other is cancelled.
    while (const AllowanceJob *job = m_worker.job()) {
        if (!jobCurrent(*job))
            m_worker.cancel();
        m_worker.wait();
        landAllowanceJob(false);
    }
    // What is left stale (cancelled, or not started) is computed here.
    while (!m_stale.empty()) {
        const Stale stale = m_stale.front();
        m_stale.erase(m_stale.begin());
        if (const int row = indexOf(stale.allowance); row >= 0 && !recomputeAllowance(row, stale.depth))
            Q_EMIT allowanceFailed(row);
    }
    announceSettled(settled);
}

void Document::announceSettled(bool before)
{
    if (allowancesSettled() != before)
        Q_EMIT allowancesSettledChanged();
}

} // namespace kontur
