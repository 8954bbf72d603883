// The seam allowance of the selected curve (see seamallowance.h).
#include "models/trace/seamallowance.h"

#include "io/seam.h"
#include "models/controllers/curvecommands.h"
#include "models/document/commands.h"
#include "models/document/selection.h"
#include "models/text/numbers.h"

#include <QCoreApplication>
#include <QThread>

#include <cmath>
#include <optional>

namespace kontur {

namespace {

// The message for an offset the geometry refused.
Message refusalOf(const geo::Error &error)
{
    switch (error.code) {
    case geo::ErrorCode::OutOfProportion:
        return {Message::SeamAllowanceTooWide, {static_cast<qlonglong>(geo::kOffsetMaxRatio)}};
    case geo::ErrorCode::WorkBudget:
    case geo::ErrorCode::NonFiniteInput:
        return {Message::SeamAllowanceTooFine, {}};
    default:
        return {Message::SeamAllowanceFailed, {}};
    }
}

} // namespace

// One Add or Apply: what it started from, and the result the worker leaves. The worker reads only
// `source`, `options` and `control` and writes only `result`; this thread reads `result` after the
// worker's thread has finished.
struct SeamAllowance::Job
{
    bool create = true;
    QPointer<EditController> editor;
    CurveId sourceId = CurveId::None;
    Curve source; // a copy: the document may change while the worker runs
    Curve before; // apply: the allowance as it was
    geo::OffsetOptions options;
    geo::OffsetControl control;
    std::optional<geo::Result<Curve>> result;
};

SeamAllowance::SeamAllowance(QObject *parent)
    : QObject(parent)
{
    // Each change repaints the dialog, and with it the canvas: a tenth of a second keeps the bar
    // moving without spending the GUI thread on frames of a large document.
    m_poll.setInterval(100);
    connect(&m_poll, &QTimer::timeout, this, [this] {
        if (!m_job)
            return;
        const double p = m_job->control.progress.load(std::memory_order_relaxed);
        if (std::abs(p - m_progress) >= 0.01) {
            m_progress = p;
            Q_EMIT progressChanged();
        }
    });
    m_showLate.setSingleShot(true);
    m_showLate.setInterval(kShowProgressMs);
    connect(&m_showLate, &QTimer::timeout, this, [this] {
        m_progressShown = m_job != nullptr;
        Q_EMIT busyChanged();
    });
    // Quitting mid-job: stop the worker now; the destructor then waits only for it to notice.
    if (QCoreApplication *app = QCoreApplication::instance())
        connect(app, &QCoreApplication::aboutToQuit, this, &SeamAllowance::cancel);
    connect(this, &SeamAllowance::stateChanged, this, [this] {
        // A new selection starts without the refusal of another curve's settings.
        if (m_refusalCurve != (m_editor ? m_editor->selection()->curveId() : CurveId::None))
            refuse({});
    });
}

SeamAllowance::~SeamAllowance()
{
    stopWorker();
}

void SeamAllowance::stopWorker()
{
    if (!m_job)
        return;
    m_job->control.cancel();
    m_thread->wait();
    m_thread.reset();
    m_job.reset();
    m_poll.stop();
    m_showLate.stop();
    m_progressShown = false;
}

void SeamAllowance::cancel()
{
    if (m_job)
        m_job->control.cancel();
}

void SeamAllowance::start(std::shared_ptr<Job> job)
{
    job->editor = m_editor;
    m_job = job;
    m_thread.reset(QThread::create([job] {
        job->result.emplace(Curve::makeOffset(job->source, allowanceOptions(job->source, job->options), &job->control));
    }));
    // Emitted on the worker thread: queued to this one, where the result is applied.
    connect(m_thread.get(), &QThread::finished, this, &SeamAllowance::finish);
    m_progress = 0.0;
    m_progressShown = false;
    m_poll.start();
    m_showLate.start();
    m_thread->start();
    Q_EMIT busyChanged();
    Q_EMIT progressChanged();
}

void SeamAllowance::finish()
{
    if (!m_job || !m_thread || !m_thread->isFinished())
        return;
    m_thread->wait();
    m_thread.reset();
    const std::shared_ptr<Job> job = std::move(m_job);
    m_poll.stop();
    m_showLate.stop();
    m_progressShown = false;
    Q_EMIT busyChanged();
    Q_EMIT finished(land(*job));
}

bool SeamAllowance::land(Job &job)
{
    if (!m_editor || job.editor != m_editor || !job.result)
        return false;
    if (job.control.cancelled.load()) {
        m_editor->showMessage(Message::SeamAllowanceCancelled);
        return false;
    }
    if (!job.result->ok()) {
        refuse(refusalOf(job.result->error()));
        return false;
    }
    // The offset is of the source as it was: an edit, a deletion or an undo meanwhile makes it stale.
    Document *document = m_editor->document();
    const Curve *source = document->find(job.sourceId);
    const Curve *before = job.create ? nullptr : document->find(job.before.id());
    if (!source || !source->sameState(job.source) || (!job.create && (!before || !before->sameState(job.before)))) {
        m_editor->showMessage(Message::SeamAllowanceOutdated);
        return false;
    }
    Curve made = std::move(*job.result).value();
    // Remembered by the document, so that adding or changing the allowance computes nothing again.
    document->rememberOffset(job.source, job.options, made);
    m_last = job.options;
    m_lastUnits = units();
    m_editor->clearMessage();
    refuse({});
    if (job.create) {
        //: Name of a new seam allowance: %1 is the name of its curve.
        made.name = QCoreApplication::translate("kontur", "%1 seam allowance").arg(source->name);
        made.color = source->color;
        made.seam = SeamLink{source->id(), job.options};
        const QString sourceName = source->name; // the append may move the document's curves
        m_editor->commands()->appendCurve(std::move(made), QCoreApplication::translate("kontur", "Add seam allowance"));
        m_editor->showMessage(Message::SeamAllowanceAdded, {sourceName, job.options.distance, units()});
        return true;
    }
    // The new shape goes into the command, so its redo() needs no offset of its own.
    made.copyStyleFrom(*before);
    made.seam = before->seam;
    made.seam->options = job.options;
    m_editor->push(new ReplaceCurveCommand(document, before->id(), *before, std::move(made),
                                           QCoreApplication::translate("kontur", "Change seam allowance")));
    return true;
}

void SeamAllowance::refuse(Message message)
{
    if (!message.isEmpty())
        m_editor->showMessage(message.id, message.args);
    m_refusalCurve = m_editor ? m_editor->selection()->curveId() : CurveId::None;
    m_refusal.show(std::move(message));
}

void SeamAllowance::setEditor(EditController *editor)
{
    if (m_editor == editor)
        return;
    if (busy()) { // a job of another document's curve
        stopWorker();
        Q_EMIT busyChanged();
    }
    if (m_editor) {
        disconnect(m_editor->selection(), nullptr, this, nullptr);
        disconnect(m_editor->document(), nullptr, this, nullptr);
    }
    m_editor = editor;
    if (m_editor) {
        connect(m_editor->selection(), &Selection::curveChanged, this, &SeamAllowance::stateChanged);
        connect(m_editor->document(), &Document::changed, this, &SeamAllowance::stateChanged);
        connect(m_editor->document(), &Document::unitsChanged, this, &SeamAllowance::stateChanged);
    }
    Q_EMIT editorChanged();
    Q_EMIT stateChanged();
}

const Curve *SeamAllowance::selected() const
{
    return m_editor ? m_editor->document()->find(m_editor->selection()->curveId()) : nullptr;
}

bool SeamAllowance::available() const
{
    const Curve *c = selected();
    return c && c->segmentCount() > 0;
}

bool SeamAllowance::isAllowance() const
{
    const Curve *c = selected();
    return c && c->seam.has_value();
}

bool SeamAllowance::closed() const
{
    const Curve *c = selected();
    if (c && c->seam)
        if (const Curve *source = m_editor->document()->find(c->seam->source))
            return source->isClosed();
    return c && c->isClosed();
}

QString SeamAllowance::units() const
{
    return m_editor ? m_editor->document()->units() : QStringLiteral("px");
}

geo::OffsetOptions SeamAllowance::shown() const
{
    if (const Curve *c = selected(); c && c->seam)
        return c->seam->options;
    if (m_last && m_lastUnits == units())
        return *m_last;
    return io::defaultSeamOptions(units());
}

QString SeamAllowance::distanceText() const
{
    return exactNumber(shown().distance);
}
QString SeamAllowance::miterLimitText() const
{
    return exactNumber(shown().miterLimit);
}
int SeamAllowance::side() const
{
    return static_cast<int>(shown().side);
}
int SeamAllowance::join() const
{
    return static_cast<int>(shown().join);
}

bool SeamAllowance::read(const QVariant &distance, int side, int join, const QVariant &miterLimit,
                         geo::OffsetOptions &out)
{
    double d = 0.0, limit = 0.0;
    if (parseNumber(distance, d) != Parsed::Number || !(d > 0) || parseNumber(miterLimit, limit) != Parsed::Number ||
        limit < 0 || side < Outside || side > Right || join < Miter || join > Round) {
        m_editor->showMessage(Message::FillAllValues);
        return false;
    }
    out.distance = d;
    out.miterLimit = limit;
    out.side = static_cast<geo::OffsetSide>(side);
    out.join = static_cast<geo::OffsetJoin>(join);
    return true;
}

bool SeamAllowance::create(const QVariant &distance, int side, int join, const QVariant &miterLimit)
{
    const Curve *source = selected();
    if (!source || source->segmentCount() == 0)
        return false;
    if (busy()) {
        m_editor->showMessage(Message::SeamAllowanceBusy);
        return false;
    }
    auto job = std::make_shared<Job>();
    job->options = io::defaultSeamOptions(units()); // the tolerance: 0.05 mm
    if (!read(distance, side, join, miterLimit, job->options))
        return false;
    job->create = true;
    job->sourceId = source->id();
    job->source = *source;
    start(std::move(job));
    return true;
}

bool SeamAllowance::apply(const QVariant &distance, int side, int join, const QVariant &miterLimit)
{
    const Curve *before = selected();
    if (!before || !before->seam)
        return false;
    if (busy()) {
        m_editor->showMessage(Message::SeamAllowanceBusy);
        return false;
    }
    if (before->locked) {
        m_editor->showMessage(Message::CurveLocked, {before->name});
        return false;
    }
    geo::OffsetOptions options = before->seam->options;
    if (!read(distance, side, join, miterLimit, options))
        return false;
    Curve after = *before;
    after.seam->options = options;
    const Curve *source = m_editor->document()->find(before->seam->source);
    if (after.sameState(*before) || !source) {
        // Nothing to compute: the same settings, or a source that is deleted (the allowance keeps its
        // shape until an undo brings the source back).
        refuse({});
        m_last = options;
        m_lastUnits = units();
        if (!after.sameState(*before)) {
            m_editor->clearMessage();
            m_editor->push(new ReplaceCurveCommand(m_editor->document(), before->id(), *before, std::move(after),
                                                   QCoreApplication::translate("kontur", "Change seam allowance")));
        }
        Q_EMIT finished(true);
        return true;
    }
    auto job = std::make_shared<Job>();
    job->create = false;
    job->options = options;
    job->sourceId = source->id();
    job->source = *source;
    job->before = *before;
    start(std::move(job));
    return true;
}

bool SeamAllowance::detach()
{
    const Curve *before = selected();
    if (!before || !before->seam)
        return false;
    if (busy()) {
        m_editor->showMessage(Message::SeamAllowanceBusy);
        return false;
    }
    Curve after = *before;
    after.seam.reset();
    m_editor->push(new ReplaceCurveCommand(m_editor->document(), before->id(), *before, std::move(after),
                                           QCoreApplication::translate("kontur", "Detach seam allowance")));
    return true;
}

} // namespace kontur
