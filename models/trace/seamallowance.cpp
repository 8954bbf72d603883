// The seam allowance of the selected curve (see seamallowance.h).
#include "models/trace/seamallowance.h"

#include "io/seam.h"
#include "models/controllers/curvecommands.h"
#include "models/document/commands.h"
#include "models/document/selection.h"
#include "models/text/languagewatch.h"
#include "models/text/numbers.h"

#include <QCoreApplication>

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

SeamAllowance::SeamAllowance(QObject *parent)
    : QObject(parent)
{
    new LanguageWatch(this, [this] { Q_EMIT refusalChanged(); });
    connect(this, &SeamAllowance::stateChanged, this, [this] {
        // A new selection starts without the refusal of another curve's settings.
        if (m_refusalCurve != (m_editor ? m_editor->selection()->curveId() : CurveId::None))
            refuse({});
    });
}

void SeamAllowance::refuse(Message message)
{
    if (!message.isEmpty())
        m_editor->showMessage(message.id, message.args);
    m_refusalCurve = m_editor ? m_editor->selection()->curveId() : CurveId::None;
    if (message == m_refusal)
        return;
    m_refusal = std::move(message);
    Q_EMIT refusalChanged();
}

void SeamAllowance::setEditor(EditController *editor)
{
    if (m_editor == editor)
        return;
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
    geo::OffsetOptions options = io::defaultSeamOptions(units()); // the tolerance: 0.05 mm
    if (!read(distance, side, join, miterLimit, options))
        return false;
    auto made = Curve::makeOffset(*source, options);
    if (!made.ok()) {
        refuse(refusalOf(made.error()));
        return false;
    }
    Curve allowance = std::move(made).value();
    //: Name of a new seam allowance: %1 is the name of its curve.
    allowance.name = QCoreApplication::translate("kontur", "%1 seam allowance").arg(source->name);
    allowance.color = source->color;
    allowance.seam = SeamLink{source->id(), options};
    m_last = options;
    m_lastUnits = units();
    m_editor->clearMessage();
    refuse({});
    m_editor->commands()->appendCurve(std::move(allowance),
                                      QCoreApplication::translate("kontur", "Add seam allowance"));
    return true;
}

bool SeamAllowance::apply(const QVariant &distance, int side, int join, const QVariant &miterLimit)
{
    const Curve *before = selected();
    if (!before || !before->seam)
        return false;
    if (before->locked) {
        m_editor->showMessage(Message::CurveLocked, {before->name});
        return false;
    }
    geo::OffsetOptions options = before->seam->options;
    if (!read(distance, side, join, miterLimit, options))
        return false;
    if (const Curve *source = m_editor->document()->find(before->seam->source))
        if (const auto offset = geo::offsetCurve(source->toPiecewise(), options); !offset.ok()) {
            refuse(refusalOf(offset.error()));
            return false;
        }
    refuse({});
    Curve after = *before;
    after.seam->options = options;
    m_last = options;
    m_lastUnits = units();
    if (after.sameState(*before))
        return true;
    m_editor->clearMessage();
    m_editor->push(new ReplaceCurveCommand(m_editor->document(), before->id(), *before, std::move(after),
                                           QCoreApplication::translate("kontur", "Change seam allowance")));
    return true;
}

bool SeamAllowance::detach()
{
    const Curve *before = selected();
    if (!before || !before->seam)
        return false;
    Curve after = *before;
    after.seam.reset();
    m_editor->push(new ReplaceCurveCommand(m_editor->document(), before->id(), *before, std::move(after),
                                           QCoreApplication::translate("kontur", "Detach seam allowance")));
    return true;
}

} // namespace kontur
