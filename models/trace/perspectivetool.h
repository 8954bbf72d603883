// PerspectiveTool: the background calibrated by the four corners of a known rectangle seen in
// perspective (models/perspective.h). Four taps mark the corners; calibratePerspective() makes the
// homography that places the picture rectified and in real units (one undo step); a corner (a mark
// being placed, or one of the calibration) can be dragged to refine it. The corners come in as
// picture points (calibratePerspectiveImage), so that corners found in the picture can take the
// finger's place.
#pragma once

#include "models/trace/tracecontext.h"

#include <QObject>
#include <QPointF>
#include <QtQml/qqmlregistration.h>

#include <array>
#include <vector>

namespace kontur {

class PerspectiveTool final : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("A tracing tool belongs to a TraceController.")
    Q_PROPERTY(bool calibrated READ calibrated NOTIFY calibratedChanged)
    Q_PROPERTY(int marks READ marks NOTIFY marksChanged)
    // The orientation the four marks suggest (Auto): wider than high in the picture.
    Q_PROPERTY(bool landscape READ landscape NOTIFY marksChanged)
    // A corner is being dragged; where it is (world), for the magnifier.
    Q_PROPERTY(bool cornerDragging READ cornerDragging NOTIFY marksChanged)
    Q_PROPERTY(QPointF cornerDragPoint READ cornerDragPoint NOTIFY marksChanged)
    // The calibration's estimated error in mm at the photo's far corners (one sigma of the edge fits,
    // with how far the corners in use lie from where the sheet's edges meet); -1 when not known (no
    // perspective, no unit of length, or no sheet's edges near the corners).
    Q_PROPERTY(double calibrationError READ calibrationError NOTIFY calibratedChanged)

public:
    // The known rectangles (rectangleSize()).
    enum Rectangle {
        A4,      // 210 × 297 mm
        A3,      // 297 × 420 mm
        Letter,  // 8.5 × 11 in
        Mat1cm,  // a cutting mat's grid square
        Mat10cm, // ten squares of a metric mat
        Mat1in,  // an imperial mat's square
        Mat6in,  // six of them
        CustomRectangle,
    };
    Q_ENUM(Rectangle)
    enum Orientation {
        AutoOrientation, // from the marked quadrilateral: its longer sides are the rectangle's
        Portrait,
        Landscape,
    };
    Q_ENUM(Orientation)

    explicit PerspectiveTool(TraceContext *context, QObject *parent = nullptr);
    Q_DISABLE_COPY_MOVE(PerspectiveTool)

    [[nodiscard]] bool calibrated() const;
    [[nodiscard]] int marks() const { return static_cast<int>(m_marks.size()); }
    [[nodiscard]] const std::vector<geo::Point> &markPoints() const { return m_marks; } // world
    // What the tool shows as corners (world): the marks being placed, else the corners of the
    // current calibration's rectangle.
    [[nodiscard]] std::vector<geo::Point> handles() const;
    [[nodiscard]] bool landscape() const;
    // A rectangle's sides (short, long) in `unit` (mm, cm or in); false for CustomRectangle.
    [[nodiscard]] static bool rectangleSize(Rectangle rectangle, const QString &unit, double &shortSide,
                                            double &longSide);
    // The unit a preset rectangle is measured in when the document has no real unit yet.
    [[nodiscard]] static QString rectangleUnit(Rectangle rectangle);

    Q_INVOKABLE void tap(QPointF world);
    // Finds the sheet in the picture (vision::findSheet, in colour) and puts the four marks on its
    // corners, to a fraction of a photo pixel; the rectangle is then chosen and applied as for tapped
    // marks. A rectangle of other proportions than `rectangle`'s (a Rectangle; for CustomRectangle the
    // sides as typed) is not taken for it. False (marks unchanged, with a message saying why and to tap
    // the corners) when there is no picture or no such sheet in it.
    Q_INVOKABLE bool findSheet(int rectangle = A4, const QString &widthText = {}, const QString &heightText = {});
    [[nodiscard]] double calibrationError() const;
    // Above this the calibration is reported as imprecise (mm).
    static constexpr double errorWarningMm = 0.5;
    Q_INVOKABLE void clear();
    // Applies the calibration to the four marks: `rectangle` a Rectangle, `orientation` an
    // Orientation; for CustomRectangle the sides as typed (the UI language's format) in `unit` (mm,
    // cm, in). One undo step; false with a message on bad input.
    Q_INVOKABLE bool calibratePerspective(int rectangle, int orientation, const QString &widthText,
                                          const QString &heightText, const QString &unit);
    // The same with the picture points given (image pixels, any order) and the rectangle's sides
    // (width × height as given; `orientation` may swap them), for tests and files.
    bool calibratePerspectiveImage(const std::array<QPointF, 4> &image, double width, double height,
                                   const QString &unit, Orientation orientation);
    // Back to the placement before the calibration (kept, in the current units).
    Q_INVOKABLE void clearPerspective();
    // A press at `world`: true when it takes a corner within `radius`; the corner then follows
    // dragCornerTo, and endCornerDrag moves it there (a calibration's corner: one undo step per drag).
    Q_INVOKABLE bool beginCornerDrag(QPointF world, double radius);
    Q_INVOKABLE void dragCornerTo(QPointF world);
    Q_INVOKABLE void endCornerDrag();
    Q_INVOKABLE void cancelCornerDrag();
    [[nodiscard]] bool cornerDragging() const { return m_drag >= 0; }
    [[nodiscard]] QPointF cornerDragPoint() const { return m_dragPoint; }

Q_SIGNALS:
    void calibratedChanged();
    void marksChanged();
    void overlayChanged();

private:
    TraceContext *m_context;
    std::vector<geo::Point> m_marks; // the corners being marked (world)
    int m_drag = -1;                 // which handle is being dragged
    QPointF m_dragPoint;             // where (world)
    double m_dragRadius = 0.0;       // the finger's reach (world): how far a dropped corner snaps
    // calibrationError() for the background it was computed for.
    mutable Background m_errorFor;
    mutable QString m_errorUnits;
    mutable double m_error = -1.0;

    // The picture point the finger dropped a corner at, moved to the corner of two edges near it
    // (a message when there is none).
    [[nodiscard]] QPointF snapped(QPointF image);
    // Says so when the calibration's error exceeds errorWarningMm.
    void warnIfImprecise();
};

} // namespace kontur
