// TraceController: tracing a garment pattern (issue #10). The tools of the "Trace" group — freehand
// strokes fitted with a composite curve, calibration of the background to real units by two points or
// by the four corners of a known rectangle in perspective (issue #22, traceperspective.cpp), a straight
// measure, the length of a seam between two knots, and the deviation of one curve from another —
// with snapping to knots, the grid and the calibration marks. QML forwards taps and strokes in
// world coordinates; every document change goes through the EditController's undo stack.
#pragma once

#include "geometry/measure.h"
#include "models/document.h"
#include "models/editcontroller.h"

#include <QObject>
#include <QPointF>
#include <QPointer>
#include <QTimer>
#include <QTransform>
#include <QtQml/qqmlregistration.h>

#include <array>
#include <vector>

namespace kontur {

// Not final: QML (Qt 6.4) derives from registered types.
class TraceController : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(kontur::EditController *editor READ editor WRITE setEditor NOTIFY editorChanged)
    Q_PROPERTY(Tool tool READ tool WRITE setTool NOTIFY toolChanged)
    Q_PROPERTY(double tolerance READ tolerance WRITE setTolerance NOTIFY toleranceChanged)
    // The world length of one screen pixel at the view's zoom (0: not known), kept by the canvas.
    Q_PROPERTY(double pixelSize READ pixelSize WRITE setPixelSize NOTIFY effectiveToleranceChanged)
    // The tolerance a stroke drawn now is fitted with: the user's, or the input's own precision at
    // this zoom (inputPrecision screen pixels) where that is coarser.
    Q_PROPERTY(double effectiveTolerance READ effectiveTolerance NOTIFY effectiveToleranceChanged)
    Q_PROPERTY(bool snapping READ snapping WRITE setSnapping NOTIFY snappingChanged)
    Q_PROPERTY(double gridStep MEMBER m_gridStep NOTIFY gridStepChanged)
    Q_PROPERTY(QString units READ units NOTIFY unitsChanged)
    Q_PROPERTY(bool drawing READ isDrawing NOTIFY strokeChanged)
    Q_PROPERTY(int calibrationPoints READ calibrationPoints NOTIFY calibrationChanged)
    Q_PROPERTY(double calibrationImageDistance READ calibrationImageDistance NOTIFY calibrationChanged)
    Q_PROPERTY(bool backgroundLocked READ backgroundLocked WRITE setBackgroundLocked NOTIFY backgroundChanged)
    Q_PROPERTY(bool backgroundCalibrated READ backgroundCalibrated NOTIFY backgroundChanged)
    // Perspective calibration (issue #22; models/traceperspective.cpp).
    Q_PROPERTY(bool backgroundPerspective READ backgroundPerspective NOTIFY backgroundChanged)
    Q_PROPERTY(int perspectiveMarks READ perspectiveMarks NOTIFY perspectiveChanged)
    // The orientation the four marks suggest (Auto): wider than high in the picture.
    Q_PROPERTY(bool perspectiveLandscape READ perspectiveLandscape NOTIFY perspectiveChanged)
    // A corner is being dragged; where it is (world), for the magnifier.
    Q_PROPERTY(bool cornerDragging READ cornerDragging NOTIFY perspectiveChanged)
    Q_PROPERTY(QPointF cornerDragPoint READ cornerDragPoint NOTIFY perspectiveChanged)
    Q_PROPERTY(int measurePoints READ measurePoints NOTIFY resultChanged)
    Q_PROPERTY(double measureDistance READ measureDistance NOTIFY resultChanged)
    Q_PROPERTY(double seamLength READ seamLength NOTIFY resultChanged)
    Q_PROPERTY(int seamKnots READ seamKnots NOTIFY resultChanged)
    Q_PROPERTY(bool hasDeviation READ hasDeviation NOTIFY resultChanged)
    Q_PROPERTY(int deviationCurves READ deviationCurves NOTIFY resultChanged)
    Q_PROPERTY(double deviationMaximum READ deviationMaximum NOTIFY resultChanged)
    Q_PROPERTY(double deviationMean READ deviationMean NOTIFY resultChanged)
    Q_PROPERTY(int lastSegmentCount READ lastSegmentCount NOTIFY resultChanged)
    // The last refusal or problem, in the current language (empty: none).
    Q_PROPERTY(QString message READ message NOTIFY messageChanged)
    // What to do next with the current tool, in the current language.
    Q_PROPERTY(QString hint READ hint NOTIFY hintChanged)
    // The results as the UI writes them: in the UI language's number format with the decimals of the
    // document's unit and the unit itself (units.h); the picture distance in pixels, one decimal.
    Q_PROPERTY(QString measureText READ measureText NOTIFY textsChanged)
    Q_PROPERTY(QString seamText READ seamText NOTIFY textsChanged)
    Q_PROPERTY(QString deviationMaximumText READ deviationMaximumText NOTIFY textsChanged)
    Q_PROPERTY(QString deviationMeanText READ deviationMeanText NOTIFY textsChanged)
    Q_PROPERTY(QString calibrationImageText READ calibrationImageText NOTIFY textsChanged)
    // Where the current tool's result is written on the canvas (world), and whether there is one.
    Q_PROPERTY(QPointF labelAnchor READ labelAnchor NOTIFY resultChanged)
    Q_PROPERTY(bool hasLabel READ hasLabel NOTIFY resultChanged)

public:
    enum class Tool {
        None,           // the canvas edits as usual
        Freehand,       // a one-finger / stylus / mouse drag draws a stroke that becomes a composite curve
        Calibrate,      // two taps on the picture, then the real distance between them
        Measure,        // two taps: the straight distance
        Seam,           // two knots of one curve: the length along it between them
        Deviation,      // two curves: the largest and mean distance between them
        MoveBackground, // a drag moves the background picture; one undo step per drag
        Perspective,    // four taps on the corners of a known rectangle; a drag refines a corner
    };
    Q_ENUM(Tool)
    // The known rectangles of the perspective calibration (rectangleSize()).
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
    enum Align {
        NoAlign,
        Horizontal, // the marked line becomes horizontal (the picture rotates)
        Vertical,
    };
    Q_ENUM(Align)

    explicit TraceController(QObject *parent = nullptr);
    Q_DISABLE_COPY_MOVE(TraceController)

    [[nodiscard]] EditController *editor() const { return m_editor; }
    void setEditor(EditController *editor);
    [[nodiscard]] Tool tool() const { return m_tool; }
    void setTool(Tool tool);
    [[nodiscard]] double tolerance() const { return m_tolerance; }
    void setTolerance(double tolerance);
    [[nodiscard]] bool snapping() const { return m_snapping; }
    void setSnapping(bool on);
    [[nodiscard]] QString units() const;
    [[nodiscard]] double pixelSize() const { return m_pixelSize; }
    void setPixelSize(double size);
    // A pointer moves in steps of about a screen pixel: a tolerance below ~1.5 of them makes the fit
    // follow those steps (a smooth stroke along three cubics became 35 segments at 256 %).
    static constexpr double inputPrecision = 1.5;
    [[nodiscard]] double effectiveTolerance() const;
    // A sensible fitting tolerance in `units` (about half a millimetre; one pixel).
    [[nodiscard]] static double defaultTolerance(const QString &units);
    // The tolerance as the user types it, in the UI language's number format; false (and a message)
    // when it is not a positive number.
    Q_INVOKABLE bool setToleranceText(const QString &text);

    // --- snapping: the knot, calibration mark or grid crossing within `radius` of `world` ---
    [[nodiscard]] Q_INVOKABLE QPointF snap(QPointF world, double radius) const;

    // --- freehand ---
    [[nodiscard]] bool isDrawing() const { return m_drawing; }
    [[nodiscard]] const std::vector<geo::Point> &stroke() const { return m_stroke; }
    Q_INVOKABLE void beginStroke(QPointF world, double snapRadius);
    Q_INVOKABLE void extendStroke(QPointF world);
    // Fits the stroke and adds the composite curve (one undo step); false for a stroke too short.
    Q_INVOKABLE bool endStroke(double snapRadius);
    Q_INVOKABLE void cancelStroke();
    // The fit itself, for tests and the command line: a composite curve within `tolerance`.
    [[nodiscard]] static geo::Result<Curve> curveFromStroke(const std::vector<geo::Point> &stroke, double tolerance);

    // --- taps of the two-point tools, in world coordinates ---
    Q_INVOKABLE void tap(QPointF world, double hitRadius);
    // Drops the points and results of the current tool.
    Q_INVOKABLE void clear();

    // --- calibration ---
    [[nodiscard]] int calibrationPoints() const { return static_cast<int>(m_calibration.size()); }
    [[nodiscard]] const std::vector<geo::Point> &calibrationMarks() const { return m_calibration; } // world
    // The marked distance in picture pixels (0 until two points are marked).
    [[nodiscard]] double calibrationImageDistance() const;
    // Applies the calibration: `distanceText` in the UI language's format, `unit` one of mm, cm, in,
    // `align` an Align value. The world is scaled (and turned) so that the marked picture points lie
    // `distance` apart in the new units, and the curves with it so that they stay on the picture; the
    // document then works in `unit`. One undo step. False with a message on bad input.
    Q_INVOKABLE bool calibrate(const QString &distanceText, const QString &unit, int align);
    // The same with the picture points given (image pixels), for tests and files.
    bool calibrateImagePoints(QPointF imageA, QPointF imageB, double distance, const QString &unit, Align align);
    [[nodiscard]] bool backgroundLocked() const;
    void setBackgroundLocked(bool locked);
    [[nodiscard]] bool backgroundCalibrated() const;

    // --- perspective calibration (models/traceperspective.cpp) ---
    [[nodiscard]] bool backgroundPerspective() const;
    [[nodiscard]] int perspectiveMarks() const { return static_cast<int>(m_perspective.size()); }
    [[nodiscard]] const std::vector<geo::Point> &perspectiveMarkPoints() const { return m_perspective; } // world
    // What the perspective tool shows as corners (world): the marks being placed, else the corners of
    // the current calibration's rectangle.
    [[nodiscard]] std::vector<geo::Point> perspectiveHandles() const;
    [[nodiscard]] bool perspectiveLandscape() const;
    // A rectangle's sides (short, long) in `unit` (mm, cm or in); false for CustomRectangle.
    [[nodiscard]] static bool rectangleSize(Rectangle rectangle, const QString &unit, double &shortSide,
                                            double &longSide);
    // The unit a preset rectangle is measured in when the document has no real unit yet.
    [[nodiscard]] static QString rectangleUnit(Rectangle rectangle);
    // Applies the perspective calibration to the four marks: `rectangle` a Rectangle, `orientation` an
    // Orientation; for CustomRectangle the sides as typed (the UI language's format) in `unit` (mm, cm,
    // in). One undo step; false with a message on bad input.
    Q_INVOKABLE bool calibratePerspective(int rectangle, int orientation, const QString &widthText,
                                          const QString &heightText, const QString &unit);
    // The same with the picture points given (image pixels, any order) and the rectangle's sides
    // (width × height as given; `orientation` may swap them), for tests and files.
    bool calibratePerspectiveImage(const std::array<QPointF, 4> &image, double width, double height,
                                   const QString &unit, Orientation orientation);
    // Back to the placement before the perspective calibration (kept, in the current units). One undo step.
    Q_INVOKABLE void clearPerspective();
    // A press of the perspective tool at `world`: true when it takes a corner (a mark being placed or a
    // corner of the calibration) within `radius`; the corner then follows dragCornerTo, and
    // endCornerDrag moves it there (a calibration's corner: one undo step per drag).
    Q_INVOKABLE bool beginCornerDrag(QPointF world, double radius);
    Q_INVOKABLE void dragCornerTo(QPointF world);
    Q_INVOKABLE void endCornerDrag();
    Q_INVOKABLE void cancelCornerDrag();
    [[nodiscard]] bool cornerDragging() const { return m_cornerDrag >= 0; }
    [[nodiscard]] QPointF cornerDragPoint() const { return m_cornerDragPoint; }

    // --- measure, seam, deviation ---
    [[nodiscard]] int measurePoints() const { return static_cast<int>(m_measure.size()); }
    [[nodiscard]] const std::vector<geo::Point> &measureMarks() const { return m_measure; }
    [[nodiscard]] double measureDistance() const;
    [[nodiscard]] int seamKnots() const { return static_cast<int>(m_seamKnots.size()); }
    [[nodiscard]] double seamLength() const { return m_seamLength; }
    // The seam as Bézier segments (world), for drawing it.
    [[nodiscard]] std::vector<geo::Bezier> seamSegments() const;
    [[nodiscard]] std::vector<geo::Point> seamMarks() const;
    // The length along `curve` from knot `a` to knot `b` (placed points of composite and spline
    // kinds) to `accuracy`; sets the seam result. False with a message when the kind has no knots.
    Q_INVOKABLE bool measureSeam(int curve, int knotA, int knotB); // curve: an id
    [[nodiscard]] bool hasDeviation() const { return m_hasDeviation; }
    [[nodiscard]] int deviationCurves() const { return static_cast<int>(m_deviationPick.size()); }
    [[nodiscard]] const geo::Deviation &deviation() const { return m_deviation; }
    [[nodiscard]] double deviationMaximum() const { return m_hasDeviation ? m_deviation.maximum : 0.0; }
    [[nodiscard]] double deviationMean() const { return m_hasDeviation ? m_deviation.mean : 0.0; }
    // Compares two curves of the document; sets the deviation result.
    Q_INVOKABLE bool compareCurves(int a, int b); // curve ids
    [[nodiscard]] int lastSegmentCount() const { return m_lastSegments; }

    // The background's position: a drag shifts the picture (world units) and is one undo step.
    // Refused, with a message, without a picture or while the background is locked.
    Q_INVOKABLE bool beginBackgroundMove();
    Q_INVOKABLE void moveBackgroundBy(QPointF worldDelta);
    Q_INVOKABLE void endBackgroundMove();

    // The accuracy of every length shown (absolute, document units).
    static constexpr double kLengthAccuracy = 1e-6;

    [[nodiscard]] QString message() const;
    [[nodiscard]] QPointF labelAnchor() const;
    [[nodiscard]] bool hasLabel() const;
    [[nodiscard]] QString hint() const;
    [[nodiscard]] QString measureText() const;
    [[nodiscard]] QString seamText() const;
    [[nodiscard]] QString deviationMaximumText() const;
    [[nodiscard]] QString deviationMeanText() const;
    [[nodiscard]] QString calibrationImageText() const;

Q_SIGNALS:
    void editorChanged();
    void toolChanged();
    void toleranceChanged();
    void effectiveToleranceChanged();
    void snappingChanged();
    void gridStepChanged();
    void unitsChanged();
    void strokeChanged();
    void calibrationChanged();
    void backgroundChanged();
    void perspectiveChanged();
    void resultChanged();
    void messageChanged();
    void hintChanged();
    void textsChanged();
    // Anything drawn over the canvas changed.
    void overlayChanged();
    // A calibration mapped the world by p ↦ scale · R(radians) p: the view may follow, so that the
    // picture stays where it was on the screen.
    void worldMapped(double scale, double radians);

protected:
private:
    // The messages, kept as ids and translated when shown (message()).
    enum class Note {
        None,
        ToleranceNotPositive,
        StrokeTooShort,
        StrokeNotFitted,
        NoPicture,
        TapKnot,
        TapCurve,
        TapOtherCurve,
        NoKnots,
        NotComparable,
        NoMarks,
        DistanceNotPositive,
        LockedCalibrate,
        LockedMove,
        UnknownUnit,
        SamePoints,
        CurveNotTurnable, // the curve's name
        NotConvex,
        NoCorners,
        SidesNotPositive,
        PerspectiveSet,
        CornerNotConvex,
    };
    // Pushes a calibration: the world mapped by p ↦ scale · R(radians) p (the curves with it), the
    // background and the units changed; one undo step named `text`. False (with a message) when a
    // curve cannot be mapped.
    bool pushCalibration(const QString &text, const Background &before, const Background &after, const QString &unit,
                         double scale, double radians);
    void setMessage(Note note, const QString &arg = {});
    void onDocumentChanged();
    [[nodiscard]] Document *document() const { return m_editor ? m_editor->document() : nullptr; }

    QPointer<EditController> m_editor;
    Tool m_tool = Tool::None;
    bool m_moving = false;   // a background drag is in progress
    int m_moveSerial = 0;    // which drag: its steps merge into one undo command
    QTimer m_languageSwitch; // announces the translated texts after a language switch
    double m_tolerance = 1.0;
    double m_pixelSize = 0.0;
    double m_strokeTolerance = 1.0; // effectiveTolerance() when the stroke began
    bool m_snapping = false;
    double m_gridStep = 0.0;
    QString m_lastUnits;
    bool m_drawing = false;
    std::vector<geo::Point> m_stroke;
    std::vector<geo::Point> m_calibration;
    std::vector<geo::Point> m_measure;
    std::vector<geo::Point> m_perspective; // the corners being marked (world)
    int m_cornerDrag = -1;                 // which handle is being dragged
    QPointF m_cornerDragPoint;             // where (world)
    CurveId m_seamCurve = CurveId::None;
    std::vector<int> m_seamKnots;
    double m_seamLength = -1.0;
    std::vector<CurveId> m_deviationPick;
    geo::Deviation m_deviation;
    bool m_hasDeviation = false;
    int m_lastSegments = 0;
    Note m_note = Note::None;
    QString m_noteArg;
};

} // namespace kontur
