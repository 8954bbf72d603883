// A piece's seam allowance per seam, set by touch (see seamwidths.h).
#include "models/controllers/seamwidths.h"

#include "geometry/seams.h"
#include "io/seam.h"
#include "models/controllers/editcontroller.h"
#include "models/document/commands.h"
#include "models/document/selection.h"
#include "text/numbertext.h"

#include <algorithm>
#include <cmath>

namespace kontur {

SeamWidths::SeamWidths(QObject *parent)
    : QObject(parent)
{
}

void SeamWidths::setEditor(EditController *editor)
{
    if (m_editor == editor)
        return;
    if (m_editor) {
        disconnect(m_editor->selection(), nullptr, this, nullptr);
        disconnect(m_editor->document(), nullptr, this, nullptr);
    }
    m_editor = editor;
    if (m_editor) {
        const auto changed = [this] {
            // Another curve selected, or the piece's outline changed its seams: no seam is chosen.
            const Curve *p = piece();
            if (m_seam >= 0 && (!p || p->id() != m_piece || m_seam >= seamCount()))
                m_seam = -1;
            Q_EMIT stateChanged();
        };
        connect(m_editor->selection(), &Selection::curveChanged, this, changed);
        connect(m_editor->document(), &Document::curveChanged, this, changed);
        connect(m_editor->document(), &Document::curveCountChanged, this, changed);
        connect(m_editor->document(), &Document::unitsChanged, this, changed);
        connect(m_editor->document(), &Document::allowanceFailed, this, [this](int row) {
            const Curve *a = allowance();
            if (a && a->id() == m_editor->document()->idAt(row))
                m_message.show(Message::SeamWidthDoesNotFit);
        });
    }
    m_seam = -1;
    Q_EMIT editorChanged();
    Q_EMIT stateChanged();
}

const Curve *SeamWidths::piece() const
{
    const Curve *c = m_editor ? m_editor->selection()->curve() : nullptr;
    return c && c->piece && c->isClosed() ? c : nullptr;
}

const Curve *SeamWidths::allowance() const
{
    const Curve *p = piece();
    if (!p)
        return nullptr;
    for (const Curve &c : m_editor->document()->curves())
        if (c.seam && c.seam->source == p->id())
            return &c;
    return nullptr;
}

int SeamWidths::seamCount() const
{
    const Curve *p = piece();
    return p ? static_cast<int>(m_editor->document()->seamsOf(*p).size()) : 0;
}

std::optional<double> SeamWidths::width() const
{
    const Curve *p = piece();
    const Curve *a = allowance();
    if (!p || !a || m_seam < 0)
        return std::nullopt;
    const auto &widths = p->piece->seamWidths;
    if (static_cast<std::size_t>(m_seam) < widths.size() && widths[static_cast<std::size_t>(m_seam)])
        return widths[static_cast<std::size_t>(m_seam)];
    return a->seam->options.distance;
}

bool SeamWidths::ownWidth() const
{
    const Curve *p = piece();
    return p && m_seam >= 0 && static_cast<std::size_t>(m_seam) < p->piece->seamWidths.size() &&
           p->piece->seamWidths[static_cast<std::size_t>(m_seam)].has_value();
}

bool SeamWidths::hem() const
{
    const Curve *p = piece();
    return p && m_seam >= 0 && std::binary_search(p->piece->hems.begin(), p->piece->hems.end(), m_seam);
}

QString SeamWidths::widthText() const
{
    const auto w = width();
    return w ? exactNumber(*w) : QString();
}

QString SeamWidths::units() const
{
    return m_editor ? m_editor->document()->units() : QString();
}

double SeamWidths::step() const
{
    return 0.5 * io::defaultSeamOptions(units()).distance;
}

QString SeamWidths::stepText() const
{
    return exactNumber(step());
}

std::optional<geo::PiecewiseBezier> SeamWidths::seamShape() const
{
    const Curve *p = piece();
    if (!p || m_seam < 0)
        return std::nullopt;
    const std::vector<geo::SeamSpan> seams = m_editor->document()->seamsOf(*p);
    if (static_cast<std::size_t>(m_seam) >= seams.size())
        return std::nullopt;
    const geo::SeamSpan &s = seams[static_cast<std::size_t>(m_seam)];
    std::vector<geo::Bezier> segments;
    for (int i = 0; i < s.count; ++i)
        segments.push_back(p->segment((s.first + i) % p->segmentCount()));
    return geo::PiecewiseBezier(std::move(segments));
}

bool SeamWidths::selectSeamAt(double x, double y, double radius)
{
    const Curve *p = piece();
    if (!p) {
        m_message.show(Message::SelectPiece);
        return false;
    }
    const geo::PiecewiseBezier outline = p->toPiecewise();
    const geo::PiecewiseNearest near = outline.nearest(geo::Point(x, y));
    if (!(near.distance <= radius))
        return false;
    const std::vector<geo::SeamSpan> seams = m_editor->document()->seamsOf(*p);
    return selectSeam(geo::seamOfSegment(seams, outline.segmentCount(), near.segment));
}

bool SeamWidths::selectSeam(int seam)
{
    const Curve *p = piece();
    if (!p || seam < 0 || seam >= seamCount())
        return false;
    m_piece = p->id();
    m_seam = seam;
    m_message.show(allowance() ? Message::None : Message::NoAllowanceYet);
    Q_EMIT stateChanged();
    return true;
}

bool SeamWidths::stepWidth(int direction)
{
    const auto w = width();
    if (!w) {
        m_message.show(!piece()       ? Message::SelectPiece
                       : !allowance() ? Message::NoAllowanceYet
                                      : Message::NoSeamChosen);
        return false;
    }
    // Tapped repeatedly: the allowance follows on the worker, as for a drag (no trial offset here).
    return change(std::max(0.0, *w + (direction > 0 ? step() : -step())), AllowancesFollow::Later);
}

bool SeamWidths::setWidthText(const QString &text)
{
    double w = 0.0;
    if (parseNumber(QVariant(text.trimmed()), w) != Parsed::Number || !(w >= 0)) {
        m_message.show(Message::BadSeamWidth);
        return false;
    }
    return setWidth(w);
}

bool SeamWidths::setWidth(double width)
{
    if (!(std::isfinite(width) && width >= 0)) {
        m_message.show(Message::BadSeamWidth);
        return false;
    }
    return change(width);
}

bool SeamWidths::resetWidth()
{
    return change(std::nullopt);
}

bool SeamWidths::editable(const Curve *&p, const Curve *&a)
{
    p = piece();
    a = allowance();
    if (!p || !a || m_seam < 0) {
        m_message.show(!p ? Message::SelectPiece : !a ? Message::NoAllowanceYet : Message::NoSeamChosen);
        return false;
    }
    if (p->locked) {
        m_editor->showMessage(Message::CurveLocked, {p->name});
        return false;
    }
    return true;
}

bool SeamWidths::setHem(bool hem)
{
    const Curve *p = nullptr, *a = nullptr;
    if (!editable(p, a))
        return false;
    io::PieceMarks marks = *p->piece;
    auto &hems = marks.hems;
    const auto at = std::lower_bound(hems.begin(), hems.end(), m_seam);
    const bool is = at != hems.end() && *at == m_seam;
    if (is == hem)
        return true;
    if (hem)
        hems.insert(at, m_seam);
    else
        hems.erase(at);
    return push(*p, *a, std::move(marks), tr("Set a hem's corners"));
}

bool SeamWidths::change(std::optional<double> width, AllowancesFollow follow)
{
    const Curve *p = nullptr, *a = nullptr;
    if (!editable(p, a))
        return false;
    io::PieceMarks marks = *p->piece;
    auto &widths = marks.seamWidths;
    if (widths.size() <= static_cast<std::size_t>(m_seam))
        widths.resize(static_cast<std::size_t>(m_seam) + 1);
    widths[static_cast<std::size_t>(m_seam)] = width;
    while (!widths.empty() && !widths.back())
        widths.pop_back();
    return push(*p, *a, std::move(marks), tr("Set a seam's allowance"), follow);
}

bool SeamWidths::push(const Curve &piece, const Curve &allowance, io::PieceMarks marks, const QString &text,
                      AllowancesFollow follow)
{
    if (marks == *piece.piece)
        return true;
    // The allowance of the new marks, made now: refused here rather than left unchanged silently.
    // A step's is made on the worker; when it cannot be made, the allowance keeps its last shape
    // and the message says so when the worker has found out (Document::allowanceFailed).
    if (follow == AllowancesFollow::AtOnce) {
        Curve trial = piece;
        trial.piece = marks;
        if (!m_editor->document()->allowanceOf(trial, allowance.seam->options).ok()) { // remembered for the push
            m_message.show(Message::SeamWidthDoesNotFit);
            return false;
        }
    }
    m_message.clear();
    m_editor->push(new PieceCommand(m_editor->document(), piece.id(), piece.piece, std::move(marks), text, 0, follow));
    return true;
}

} // namespace kontur
