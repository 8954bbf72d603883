// SnapshotCommand: the undo command of a change that is best stored as the whole state before and
// after (a curve's settings, the background picture, a teaching view's inputs). redo() applies the
// state after, undo() the state before (as in Qt's undoframework example); the steps of one drag,
// which share a serial that is not 0, merge into the first, which keeps its "before", and a drag that
// ends where it began leaves no undo step. A command only says how a state is applied.
#pragma once

#include <QUndoCommand>

#include <concepts>
#include <utility>

namespace kontur {

template <class State, class Base = QUndoCommand> class SnapshotCommand : public Base
{
public:
    // `mergeId`: the QUndoCommand::id() the steps of a drag share (one per kind of command); `serial`:
    // the drag's serial, 0 for a change that merges with nothing. `baseArgs` go to Base.
    template <class... BaseArgs>
    SnapshotCommand(State before, State after, int mergeId, int serial, BaseArgs &&...baseArgs)
        : Base(std::forward<BaseArgs>(baseArgs)...)
        , m_before(std::move(before))
        , m_after(std::move(after))
        , m_mergeId(mergeId)
        , m_serial(serial)
    {
    }

    void redo() override { apply(m_after); }
    void undo() override { apply(m_before); }
    [[nodiscard]] int id() const override { return m_serial != 0 ? m_mergeId : -1; }
    bool mergeWith(const QUndoCommand *other) override
    {
        const auto *next = dynamic_cast<const SnapshotCommand *>(other);
        if (!next || next->m_serial != m_serial)
            return false;
        m_after = next->m_after;
        if constexpr (std::equality_comparable<State>)
            this->setObsolete(m_after == m_before);
        return true;
    }

protected:
    virtual void apply(const State &state) = 0;

private:
    State m_before;
    State m_after;
    int m_mergeId;
    int m_serial;
};

} // namespace kontur
