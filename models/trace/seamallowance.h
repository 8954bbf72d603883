// SeamAllowance: the seam allowance of the selected curve (issue #22, Trace menu "Seam allowance…").
// It makes a linked offset curve (Curve::seam, kept up to date by the Document), changes an existing
// allowance's settings, or detaches it into a free curve: one undo step each. QML shows the settings
// of the selected allowance (or the last used ones, 1 cm at first, in the document's units) and
// passes typed texts, parsed here in the UI language's number format. The offset runs on a worker
// thread (a long curve at a fine tolerance takes seconds) and its result is pushed as one undo
// command on the GUI thread; the dialog shows `progress` and Cancel once a job has run ~300 ms.
#pragma once

#include "models/controllers/editcontroller.h"
#include "models/text/shownmessage.h"

#include <QObject>
#include <QPointer>
#include <QTimer>
#include <QVariant>
#include <QtQml/qqmlregistration.h>

#include <memory>

class QThread;

namespace kontur {

// Not final: QML (Qt 6.4) derives from registered types.
class SeamAllowance : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(kontur::EditController *editor READ editor WRITE setEditor NOTIFY editorChanged)
    // A curve with segments is selected.
    Q_PROPERTY(bool available READ available NOTIFY stateChanged)
    // The selected curve is a linked seam allowance (its settings are shown and changed).
    Q_PROPERTY(bool isAllowance READ isAllowance NOTIFY stateChanged)
    // The curve the sides refer to (the allowance's source, or the selected curve) is closed: the
    // sides read Outside / Inside, else Left / Right.
    Q_PROPERTY(bool closed READ closed NOTIFY stateChanged)
    Q_PROPERTY(QString units READ units NOTIFY stateChanged)
    // The settings shown: the selected allowance's, else the ones used last (defaults at first).
    Q_PROPERTY(QString distanceText READ distanceText NOTIFY stateChanged)
    Q_PROPERTY(QString miterLimitText READ miterLimitText NOTIFY stateChanged)
    Q_PROPERTY(int side READ side NOTIFY stateChanged)
    Q_PROPERTY(int join READ join NOTIFY stateChanged)
    // Why the last Add or Apply was refused (empty after a success or a new selection): the dialog
    // shows `refusal.text` next to its fields, where the message line may be covered.
    Q_PROPERTY(kontur::Message refusal READ refusal NOTIFY refusalChanged)
    // An Add or Apply is being computed (on a worker thread); another is refused meanwhile.
    Q_PROPERTY(bool busy READ busy NOTIFY busyChanged)
    // The job has run for kShowProgressMs: the dialog shows the progress and Cancel (short jobs,
    // most of them, finish before and show nothing).
    Q_PROPERTY(bool progressShown READ progressShown NOTIFY busyChanged)
    // 0..1, the offset's own estimate (by stage), updated every 100 ms while busy.
    Q_PROPERTY(double progress READ progress NOTIFY progressChanged)

public:
    // The QML values of side and join: geo::OffsetSide and geo::OffsetJoin in their order.
    enum Side { Outside, Inside, Left, Right };
    Q_ENUM(Side)
    enum Join { Miter, Bevel, Round };
    Q_ENUM(Join)

    static constexpr int kShowProgressMs = 300;

    explicit SeamAllowance(QObject *parent = nullptr);
    // Cancels a running job and waits for its thread (a few milliseconds: the offset looks at the
    // flag after every few evaluations), so quitting mid-job leaves no thread behind.
    ~SeamAllowance() override;
    Q_DISABLE_COPY_MOVE(SeamAllowance)

    [[nodiscard]] EditController *editor() const { return m_editor; }
    void setEditor(EditController *editor);
    [[nodiscard]] bool available() const;
    [[nodiscard]] bool isAllowance() const;
    [[nodiscard]] bool closed() const;
    [[nodiscard]] QString units() const;
    [[nodiscard]] QString distanceText() const;
    [[nodiscard]] QString miterLimitText() const;
    [[nodiscard]] int side() const;
    [[nodiscard]] int join() const;
    [[nodiscard]] Message refusal() const { return m_refusal.message(); }
    [[nodiscard]] bool busy() const { return m_job != nullptr; }
    [[nodiscard]] bool progressShown() const { return m_progressShown; }
    [[nodiscard]] double progress() const { return m_progress; }

    // Starts computing the allowance of the selected curve; when it is done it is added (and
    // selected) as one undo step and finished(true) follows. False at once for message 10 (a distance
    // that is not a positive number) or while another job runs; a refusal when no allowance fits
    // comes with finished(false).
    Q_INVOKABLE bool create(const QVariant &distance, int side, int join, const QVariant &miterLimit);
    // Starts changing the selected allowance's settings, likewise; one undo step when done (none, and
    // finished(true) at once, when nothing changes).
    Q_INVOKABLE bool apply(const QVariant &distance, int side, int join, const QVariant &miterLimit);
    // The selected allowance becomes a free composite curve (its shape stays); one undo step.
    Q_INVOKABLE bool detach();
    // Stops the running job: the document and the undo stack stay exactly as they were.
    Q_INVOKABLE void cancel();

Q_SIGNALS:
    void editorChanged();
    void stateChanged();
    void refusalChanged();
    void busyChanged();
    void progressChanged();
    // A job started by create() or apply() ended: `done` when its undo step was pushed (or nothing
    // needed changing), false when it was refused, cancelled or outdated.
    void finished(bool done);

private:
    struct Job;
    // Runs `job` on a worker thread; finish() takes its result on this thread.
    void start(std::shared_ptr<Job> job);
    void finish();
    // Applies a finished job's result as one undo step; false when it was cancelled, refused or is
    // stale (its curve changed meanwhile).
    bool land(Job &job);
    // Cancels the running job and waits for its thread.
    void stopWorker();

    [[nodiscard]] const Curve *selected() const;
    [[nodiscard]] geo::OffsetOptions shown() const;
    // Typed settings on top of `base`; false (with a message) when a number is not valid.
    [[nodiscard]] bool read(const QVariant &distance, int side, int join, const QVariant &miterLimit,
                            geo::OffsetOptions &out);
    // Shows why an offset was refused (the message line and `refusal`), or clears it (None).
    void refuse(Message message);

    QPointer<EditController> m_editor;
    std::optional<geo::OffsetOptions> m_last; // the settings used last, in m_lastUnits
    QString m_lastUnits;
    ShownMessage m_refusal{this, [this] { Q_EMIT refusalChanged(); }};
    CurveId m_refusalCurve = CurveId::None; // the curve selected when m_refusal was set
    std::shared_ptr<Job> m_job;             // the running job, shared with its worker thread
    std::unique_ptr<QThread> m_thread;
    QTimer m_poll;     // reads the job's progress every 100 ms
    QTimer m_showLate; // shows the progress after kShowProgressMs
    bool m_progressShown = false;
    double m_progress = 0.0;
};

} // namespace kontur
