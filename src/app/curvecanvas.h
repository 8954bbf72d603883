// CurveCanvas: the drawing surface. It owns the view (zoom and pan, world y up), turns the
// gestures QML forwards into world coordinates for the EditController, and draws the document
// through the scene graph. On both backends the curves other than the selected one are kept in a
// cached layer with a margin around the view: shown moved and scaled while a gesture goes on,
// drawn sharp again once the view settles, and untouched while the selected curve is edited.
// GPU backends: the layer is a child item rendered into a texture (Qt Quick's item layer), its
// curves in stroke nodes of 64 curves each whose vertices stay in world units (the view is a
// shader uniform), re-flattened only when a curve changes or the zoom leaves the band its
// flattening was made for; a second child item draws the selected curve and the points over it.
// Software backend: a QPainter render node with a cached layer picture.
// The parts: ViewState (viewstate.h), FlatCache (flatcache.h), the scene builder's display lists
// (scenebuilder.h), PainterNode (painternode.h) and the GPU nodes (canvasnodes.h).
#pragma once

#include "app/displaylist.h"
#include "app/flatcache.h"
#include "app/scenebuilder.h"
#include "app/strokenode.h"
#include "app/viewstate.h"
#include "models/controllers/editcontroller.h"
#include "models/controllers/picturesource.h"
#include "models/document/document.h"

#include <QColor>
#include <QImage>
#include <QPointer>
#include <QQuickItem>
#include <QTimer>

#include <cstdint>
#include <memory>
#include <optional>

namespace kontur {

class CanvasPart;

// Not final: QML (Qt 6.4) derives from registered types.
class CurveCanvas : public QQuickItem, public PictureSource
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(kontur::EditController *controller READ controller WRITE setController NOTIFY controllerChanged)
    Q_PROPERTY(double zoom READ zoom NOTIFY viewChanged)
    Q_PROPERTY(QPointF center READ center NOTIFY viewChanged)
    Q_PROPERTY(double minimumZoom READ minimumZoom CONSTANT)
    Q_PROPERTY(double maximumZoom READ maximumZoom CONSTANT)
    Q_PROPERTY(bool panning READ isPanning NOTIFY panningChanged)
    Q_PROPERTY(double hitRadius READ hitRadius WRITE setHitRadius NOTIFY styleChanged)
    Q_PROPERTY(QColor curveColor MEMBER m_curveColor NOTIFY styleChanged)
    Q_PROPERTY(QColor polygonColor MEMBER m_polygonColor NOTIFY styleChanged)
    Q_PROPERTY(QColor controlPointColor MEMBER m_controlPointColor NOTIFY styleChanged)
    Q_PROPERTY(QColor accentColor MEMBER m_accentColor NOTIFY styleChanged)
    Q_PROPERTY(QColor tangentColor MEMBER m_tangentColor NOTIFY styleChanged)
    Q_PROPERTY(double curveWidth MEMBER m_curveWidth NOTIFY styleChanged)
    Q_PROPERTY(double pointRadius MEMBER m_pointRadius NOTIFY styleChanged)
    Q_PROPERTY(QString graphicsApi READ graphicsApi NOTIFY graphicsApiChanged)
    Q_PROPERTY(bool showGrid MEMBER m_showGrid NOTIFY styleChanged)
    Q_PROPERTY(QColor gridColor MEMBER m_gridColor NOTIFY styleChanged)
    Q_PROPERTY(QColor axisColor MEMBER m_axisColor NOTIFY styleChanged)
    // GPU backends: the curves other than the selected one are kept in a texture (true, the
    // default) or drawn directly every frame: false for a grab at another scale (PNG export),
    // which would otherwise enlarge the texture's pixels.
    Q_PROPERTY(bool layered READ isLayered WRITE setLayered NOTIFY layeredChanged)
    // How the curves other than the selected one are kept: "texture" (GPU), "picture" (a painted
    // picture, where OpenGL rasterizes on the processor), "painter" (Qt Quick's software backend).
    Q_PROPERTY(QString layerKind READ layerKind NOTIFY layerKindChanged)
    // The world distance between grid lines at the current zoom (1, 2 or 5 times a power of ten).
    Q_PROPERTY(double gridStep READ gridStep NOTIFY viewChanged)

public:
    explicit CurveCanvas(QQuickItem *parent = nullptr);
    Q_DISABLE_COPY_MOVE(CurveCanvas)

    [[nodiscard]] EditController *controller() const { return m_controller; }
    void setController(EditController *controller);

    [[nodiscard]] double zoom() const { return m_zoom; }
    [[nodiscard]] QPointF center() const { return m_center; }
    // Wide enough that Fit shows a document from 1e-130 to 1e130 units whole (a CAD export in
    // micrometres, an SVG in large user units), narrow enough that a touch target's radius in world
    // units (22 px / zoom) still squares without overflow or underflow in hit testing.
    [[nodiscard]] static double minimumZoom() { return 1e-140; }
    [[nodiscard]] static double maximumZoom() { return 1e140; }
    [[nodiscard]] bool isPanning() const { return m_panning; }
    [[nodiscard]] double gridStep() const;
    [[nodiscard]] static double gridStepAt(double zoom) { return kontur::gridStepAt(zoom); }
    [[nodiscard]] QString graphicsApi() const;
    [[nodiscard]] bool isLayered() const { return m_layered; }
    [[nodiscard]] QString layerKind() const;
    void setLayered(bool layered);
    // Radius of a point's touch target in item pixels, whatever the zoom (>= 22: 44 px targets).
    [[nodiscard]] double hitRadius() const { return m_hitRadius; }
    void setHitRadius(double radius);

    // World (y up, docs/requirements.md 2 transform) ↔ item coordinates (y down).
    Q_INVOKABLE QPointF toWorld(QPointF screen) const;
    Q_INVOKABLE QPointF toScreen(QPointF world) const;
    // The background picture as read (null when none or unreadable), for the perspective magnifier.
    [[nodiscard]] const QImage &backgroundImage() const { return m_backgroundImage; }
    // The touch target's radius in world units at the current zoom.
    Q_INVOKABLE double hitRadiusWorld() const { return m_hitRadius / m_zoom; }

    // View changes. Zooming keeps the world point under `anchor` (item coordinates) in place.
    Q_INVOKABLE void zoomBy(double factor, QPointF anchor);
    Q_INVOKABLE void zoomIn();
    Q_INVOKABLE void zoomOut();
    Q_INVOKABLE void panBy(QPointF delta);
    Q_INVOKABLE void resetView();
    // Puts the view back where it was (after a temporary fit, e.g. for a picture).
    Q_INVOKABLE void restoreView(double zoom, QPointF center) { setView(zoom, center); }
    // The world was mapped by p ↦ scale · R(radians) p (a calibration, or its undo): the view
    // follows, so that what was on the screen stays there (TraceController::worldMapped).
    Q_INVOKABLE void followWorldMapping(double scale, double radians);
    Q_INVOKABLE void fitToView();
    // As fitToView, with the world rectangle `extra` in view too (a teaching view's compared curves);
    // a null rectangle adds nothing.
    Q_INVOKABLE void fitToViewWith(const QRectF &extra);
    // A picture of the canvas (PNG export, PictureSource): every curve drawn at the picture's scale,
    // not from the layer; with `wholeDocument` the view fits all curves until the grab is done.
    [[nodiscard]] QSizeF pictureSize() const override { return size(); }
    // How many curves were flattened since the canvas was made (tests and benchmarks).
    [[nodiscard]] std::uint64_t flattenings() const { return m_flat.flattenings(); }
    [[nodiscard]] bool makePicture(QSize size, bool wholeDocument, std::function<void(const QImage &)> done) override;
    void beginPicture(bool wholeDocument);
    void endPicture();

    // Gestures forwarded by QML's pointer handlers, in item coordinates.
    Q_INVOKABLE void tapAt(QPointF position);
    // `constrained`: the right button or Shift, the seed's constrained handle move.
    Q_INVOKABLE void dragStarted(QPointF pressPosition, bool constrained = false);
    Q_INVOKABLE void dragMoved(QPointF position);
    Q_INVOKABLE void dragEnded();
    Q_INVOKABLE void hoverAt(QPointF position);
    Q_INVOKABLE void hoverEnded();
    Q_INVOKABLE void pinchStarted(QPointF centroid);
    Q_INVOKABLE void pinchUpdated(double scale, QPointF centroid);
    Q_INVOKABLE void pinchEnded();
    Q_INVOKABLE void wheelAt(QPointF position, double angleDeltaY);

Q_SIGNALS:
    void controllerChanged();
    void viewChanged();
    void panningChanged();
    void styleChanged();
    void graphicsApiChanged();
    void layeredChanged();
    void layerKindChanged();

protected:
    QSGNode *updatePaintNode(QSGNode *oldNode, UpdatePaintNodeData *data) override;
    void geometryChange(const QRectF &newGeometry, const QRectF &oldGeometry) override;
    void itemChange(ItemChange change, const ItemChangeData &value) override;

private:
    friend class CanvasPart;

    // `gesture`: a continuous change (pinch, wheel, pan); on large drawings the cached layer is
    // shown transformed until the view settles. Other changes are drawn sharp at once.
    void setView(double zoom, QPointF center, bool gesture = false);
    // Bézier segments in the document; up to kSharpGestureSegments, gestures draw every frame sharp.
    [[nodiscard]] std::size_t segmentTotal() const;
    static constexpr std::size_t kSharpGestureSegments = 2000;
    // update() of the canvas and of the parts drawn over it.
    void repaint();
    // GPU backends: the nodes of the layer (curves other than the selected one, at the layer's
    // view) and of the live part (the selected curve, the placement preview and the points).
    QSGNode *updateLayerNode(QSGNode *oldNode);
    QSGNode *updateLiveNode(QSGNode *oldNode);
    // The world the layer shows (at the layer's view, with its margin), and a little more.
    [[nodiscard]] QRectF layerWorld() const;
    // The layer shows the current view from now on (drawn anew).
    void freezeLayerView();
    // Moves and scales the layer item so that the view it was drawn for matches the current one.
    void placeLayer();
    // Turns Qt Quick's item layer of the layer part on or off as the backend and `layered` ask.
    void applyLayered();
    // Whether the window draws through Qt Quick's software backend.
    [[nodiscard]] bool isSoftware() const;
    // A curve as drawn at `zoom`: re-flattened if it meets `area` (world) and its flattening is
    // out of date or of another zoom band, counted in `reflattened`.
    ShownCurve shownCurve(std::size_t curve, QColor color, float strokeWidth, double zoom, const QRectF &area,
                          std::size_t *reflattened);
    // The selected curve at the current view (nothing when none is selected).
    ShownCurve shownSelected();
    [[nodiscard]] StrokePath strokePath(std::size_t curve, const ShownCurve &shown) const;
    // Moves the view so that `world` shows at item position `screen`.
    void keepAt(QPointF world, QPointF screen, bool gesture = true);
    // m_lists for this frame's sync (the scene builder's), built by whichever node update needs
    // it first.
    const ScreenLists &screenLists(bool software);
    // The current view, and the style as the scene builder takes it.
    [[nodiscard]] ViewState view() const { return {m_zoom, m_center, size()}; }
    [[nodiscard]] SceneStyle sceneStyle() const;
    [[nodiscard]] const Curve &curveAt(std::size_t curve) const { return m_controller->document()->curves()[curve]; }
    // The curve's world flattening brought up to the zoom band of `zoom` over the world rectangle
    // `area`; true when it was redone.
    bool ensureFlat(std::size_t curve, double zoom, const QRectF &area)
    {
        return m_flat.ensure(curve, curveAt(curve), zoom, area);
    }
    // Whether the curve's control points' hull meets the world rectangle.
    bool curveMeets(std::size_t curve, const QRectF &worldRect)
    {
        return m_flat.meets(curve, curveAt(curve), worldRect);
    }
    // The visible curves with points, other than `except`, that meet the world rectangle, in order.
    std::vector<std::size_t> curvesMeeting(const QRectF &worldRect, int except);
    // Flattens those of them that are stale at `zoom`, in parallel; returns how many.
    std::size_t flattenMeeting(const QRectF &worldRect, double zoom, int except);
    [[nodiscard]] QRectF visibleWorld(double margin) const { return view().visibleWorld(margin); }
    void layerChanged() { ++m_layerVersion; }
    // Reads the document's background picture when its file changed.
    void reloadBackground();

    QPointer<EditController> m_controller;
    double m_zoom = 1.0;
    QPointF m_center;            // world point at the item's centre
    double m_windowHeight = 0.0; // the window's height at the last geometry change

    // Gesture state.
    bool m_panning = false;
    bool m_draggingPoint = false;
    QPointF m_anchorWorld; // the world point held under the finger while panning or pinching
    double m_pinchStartZoom = 1.0;

    // Style, set from the QML Theme (until then the scene builder's defaults).
    double m_hitRadius = 22.0; // 44 px touch targets
    QColor m_curveColor = SceneStyle{}.curve;
    QColor m_polygonColor = SceneStyle{}.polygon;
    QColor m_controlPointColor = SceneStyle{}.controlPoint;
    QColor m_accentColor = SceneStyle{}.accent;
    QColor m_tangentColor = SceneStyle{}.tangent;
    bool m_showGrid = SceneStyle{}.showGrid;
    QColor m_gridColor = SceneStyle{}.grid;
    QColor m_axisColor = SceneStyle{}.axis;
    double m_curveWidth = SceneStyle{}.curveWidth;
    double m_pointRadius = SceneStyle{}.pointRadius;

    ScreenLists m_lists;             // reused between frames
    std::uint64_t m_syncSerial = 0;  // counts the window's syncs (render thread, GUI blocked)
    std::uint64_t m_listsSerial = 0; // the sync m_lists was built in
    // GPU backends: the child items drawn over the canvas, and the view the layer shows.
    CanvasPart *m_layerPart = nullptr;
    CanvasPart *m_livePart = nullptr;
    double m_layerZoom = 1.0;
    QPointF m_layerCenter;
    double m_layerMargin = 0.0; // pixels around the view that the layer covers too
    bool m_gpu = false;         // drawn by a GPU backend (the parts' nodes), not the software one
    bool m_layered = true;      // GPU: the layer part goes through a texture
    QPointer<QObject> m_layer;  // the layer part's QQuickItemLayer
    // GPU backends whose rasterizer is software (Mesa's llvmpipe): the layer is a picture painted
    // with QPainter and shown as a texture in the rasterizer's own pixel order, with the grid in
    // it, so that nearly every tile of the canvas is a plain copy there (its fast linear path);
    // drawn strokes and a texture Qt renders to (RGBA) take the general shading path per pixel.
    // Decided on the render thread at the first frame; KONTUR_CANVAS_LAYER=picture or texture
    // chooses (tests run both).
    bool m_imageLayer = false;
    bool m_rasterizerKnown = false;
    [[nodiscard]] bool imageLayerActive() const { return m_gpu && m_layered && m_imageLayer; }
    QSGNode *updateLayerImage(QSGNode *root);
    FlatCache m_flat; // curves flattened in world units for a band of zooms
    void invalidateFlat(int curve);
    // Software layer: bumped whenever something drawn in it changed (not for view changes).
    std::uint64_t m_layerVersion = 0;
    int m_layerExcluded = -2; // the curve kept out of the layer when it was last described
    bool m_viewSettled = true;
    QTimer m_settleTimer;
    QString m_backgroundFile;
    QImage m_backgroundImage;
    bool m_backgroundDirty = false;
    // The drawing and view to go back to after a picture.
    struct PictureState
    {
        bool layered;
        bool wholeDocument;
        double zoom;
        QPointF center;
    };
    std::optional<PictureState> m_picture;
};

} // namespace kontur
