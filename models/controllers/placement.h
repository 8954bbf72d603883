// Placement: building a new curve point by point (the seed's "New curve": taps place its points) or
// from typed coordinates (the seed's "w/ Keyboard"). Holds the settings for new curves, the points
// placed so far and the preview; a finished curve is added with one undo command.
#pragma once

#include "geometry/bezier.h"
#include "models/document/curve.h"

#include <QObject>
#include <QPointF>
#include <QVariantList>
#include <QtQml/qqmlregistration.h>

#include <vector>

namespace kontur {

class EditController;

// Not final: QML (Qt 6.4) derives from registered types.
class Placement : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("Placement belongs to an EditController.")
    // A CurveKind value.
    Q_PROPERTY(int kind READ kind WRITE setKind NOTIFY settingsChanged)
    // The degree of a new Bézier curve (its points are degree + 1).
    Q_PROPERTY(int degree READ degree WRITE setDegree NOTIFY settingsChanged)
    // A Parameterization value for the kinds that use one.
    Q_PROPERTY(int parameterization READ parameterization WRITE setParameterization NOTIFY settingsChanged)
    Q_PROPERTY(int pendingCount READ pendingCount NOTIFY pendingChanged)
    Q_PROPERTY(int requiredPoints READ requiredPoints NOTIFY settingsChanged)
    Q_PROPERTY(bool openEnded READ openEnded NOTIFY settingsChanged)
    // The kinds a user can create, for menus: [{kind, name, icon, usesParameterization}], names in
    // the UI language (announced again after a language switch), icons as named in qml/icons.
    Q_PROPERTY(QVariantList kinds READ kinds NOTIFY kindsChanged)

public:
    explicit Placement(EditController *editor);
    Q_DISABLE_COPY_MOVE(Placement)

    [[nodiscard]] int kind() const { return static_cast<int>(m_kind); }
    void setKind(int kind);
    [[nodiscard]] int degree() const { return m_degree; }
    void setDegree(int degree);
    [[nodiscard]] int parameterization() const { return static_cast<int>(m_parameterization); }
    void setParameterization(int parameterization);
    [[nodiscard]] QVariantList kinds() const;

    [[nodiscard]] const std::vector<geo::Point> &pendingPoints() const { return m_pending; }
    [[nodiscard]] int pendingCount() const { return static_cast<int>(m_pending.size()); }
    // Points that finish the placement by themselves; 0 for open-ended kinds (they need "Done").
    [[nodiscard]] int requiredPoints() const;
    [[nodiscard]] bool openEnded() const { return requiredPoints() == 0; }
    // The segments to preview while placing (the seed shows composite segments from the 3rd knot),
    // all finite.
    [[nodiscard]] std::vector<geo::Bezier> pendingSegments() const;
    [[nodiscard]] bool hasHover() const { return m_hasHover; }
    [[nodiscard]] geo::Point hoverPoint() const { return m_hover; }

    // Places the next point (message 8 beyond the kind's most points); finishes by itself when the
    // kind's count is reached.
    void place(const geo::Point &point);
    // "Done": finishes an open-ended placement (or a Bézier curve of fewer points).
    Q_INVOKABLE bool finish();
    Q_INVOKABLE void cancel();
    Q_INVOKABLE void removeLast();
    Q_INVOKABLE void hover(QPointF world);
    Q_INVOKABLE void clearHover();
    // A new curve of `kind` from typed coordinates: `rows` lists [x, y] texts in the UI language's
    // number format (or with a decimal point). One undo step; the new curve is selected.
    Q_INVOKABLE bool createFromCoordinates(int kind, const QVariantList &rows);

    // Announces the kinds' names again (a language switch).
    void retranslate() { Q_EMIT kindsChanged(); }

Q_SIGNALS:
    void settingsChanged();
    void pendingChanged();
    void hoverChanged();
    void kindsChanged();

private:
    // pendingSegments before the check that they are finite.
    [[nodiscard]] std::vector<geo::Bezier> previewSegments() const;
    // Adds a made curve (one undo step) and selects it; messages for a curve that cannot be.
    bool add(Curve curve);

    EditController *m_editor;
    CurveKind m_kind = CurveKind::Bezier;
    int m_degree = 3;
    geo::Parameterization m_parameterization = geo::Parameterization::Uniform;
    std::vector<geo::Point> m_pending;
    geo::Point m_hover = geo::Point::Zero();
    bool m_hasHover = false;
};

} // namespace kontur
