// The document: the ordered curves the user works on, the background image state and the units.
// Every change goes through these few mutators, called by undo commands, and is announced with
// fine-grained signals so that the models notify only the rows and roles that changed.
#pragma once

#include "models/curve.h"

#include <QObject>
#include <QPointF>
#include <QtQml/qqmlregistration.h>

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

    friend bool operator==(const Background &, const Background &) = default;
};

// Where the curve at `index` stands after the curve at `from` moved to `to` (Document::moveCurve):
// the moved one goes to `to`, those between close up behind it.
[[nodiscard]] constexpr int indexAfterMove(int index, int from, int to)
{
    if (index == from)
        return to;
    if (from < index && index <= to)
        return index - 1;
    if (to <= index && index < from)
        return index + 1;
    return index;
}

// Not final: QML (Qt 6.4) derives from registered types.
class Document : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("The document belongs to an EditController.")
    Q_PROPERTY(int curveCount READ curveCount NOTIFY curveCountChanged)
    Q_PROPERTY(QString units READ units NOTIFY unitsChanged)

public:
    explicit Document(QObject *parent = nullptr);
    Q_DISABLE_COPY_MOVE(Document)

    [[nodiscard]] int curveCount() const { return static_cast<int>(m_curves.size()); }
    [[nodiscard]] const Curve &curve(int index) const { return m_curves.at(static_cast<std::size_t>(index)); }
    [[nodiscard]] const std::vector<Curve> &curves() const { return m_curves; }
    [[nodiscard]] bool isValidRow(int curve, int row) const;
    [[nodiscard]] const Background &background() const { return m_background; }
    [[nodiscard]] QString units() const { return m_units; }

    // --- mutators (the undo commands call these) ---
    void insertCurve(int index, Curve curve);
    Curve takeCurve(int index);
    void moveCurve(int from, int to);
    // Replaces a whole curve (structure, settings, style); rows are inserted or removed at the end.
    void replaceCurve(int index, Curve curve);
    void setPoints(int curve, const std::vector<PointChange> &changes, bool useAfter);
    // A user's move with the kind's rule; the changes are returned for undo. A move whose result
    // would not be finite (a target near the largest double carrying handles past it) changes
    // nothing and answers NonFiniteInput.
    [[nodiscard]] geo::Result<std::vector<PointChange>> movePoint(int curve, int row, const geo::Point &target,
                                                                  geo::HandleMove mode);
    void setBackground(const Background &background);
    void setUnits(const QString &units);

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
    // Anything visible changed: the canvas repaints on this.
    void changed();

private:
    void announceRows(int curve, const std::vector<PointChange> &changes);

    std::vector<Curve> m_curves;
    Background m_background;
    QString m_units = QStringLiteral("px");
};

} // namespace kontur
