// The plain records the file formats read and write: one curve, the background picture, the whole
// document. They are data only (Qt Core and geometry points); the models convert them to and from
// their own types, so src/io never depends on models/. validateCurve() is the one place that says
// what a well-formed curve record is, shared by every format.
#pragma once

#include "geometry/bezier.h"
#include "io/error.h"

#include <QJsonObject>
#include <QString>

#include <array>

#include <optional>
#include <vector>

namespace kontur::io {

struct CurveRecord
{
    // "bezier", "interpolating", "least-squares", "composite"; the spline kinds join the table in
    // records.cpp. The set is open: an unknown kind is an error of the reader that meets it.
    QString kind;
    QString name;
    QString color = QStringLiteral("#000000"); // "#rrggbb", lower case when written
    bool visible = true;
    bool locked = false;
    // "uniform" | "chord" | "centripetal" for kinds that use one; empty for the others.
    QString parameterization;
    // The defining points: control points (bezier), knots (interpolating, least-squares, splines),
    // or a composite curve's control vector: 3n - 2 points open, 3n closed (the repeated first knot
    // of CompositeCurve::controlPoints() is NOT stored).
    std::vector<geo::Point> points;
    // Composite curves: one per knot, "smooth" | "symmetric" | "corner". Empty for other kinds.
    std::vector<QString> nodeTypes;
    bool closed = false;
    // Kind-specific settings (degree, order, end conditions, tangents, tension…), stored as given.
    QJsonObject settings;

    friend bool operator==(const CurveRecord &, const CurveRecord &) = default;
};

struct BackgroundRecord
{
    // The picture. In memory an absolute path (or whatever the caller gives); in a saved document
    // relative to the document's folder, resolved again on open.
    QString file;
    bool visible = true;
    double opacity = 1.0;                          // 0..1
    double originX = 0.0, originY = 0.0;           // where the picture's top-left lies in the world
    double scale = 1.0;                            // world units per image pixel, > 0
    double rotation = 0.0;                         // degrees
    bool calibrated = false;                       // two image points a known distance apart:
    double ax = 0.0, ay = 0.0, bx = 0.0, by = 0.0; // the points, in image pixels
    double distance = 0.0;                         // their distance in the document's units
    bool locked = false;                           // placement and calibration locked (issue 10)
    // Perspective calibration (issue #22): the picture's four corners of a known rectangle, in image
    // pixels, ordered top-left, top-right, bottom-right, bottom-left as seen in the picture; the
    // rectangle's size in the document's units and where its top-left corner lies in the world. While
    // set it places the picture instead of origin/scale/rotation, which are kept for when it is cleared.
    bool perspective = false;
    std::array<double, 8> corners{}; // x0, y0, x1, y1, x2, y2, x3, y3
    double rectWidth = 0.0, rectHeight = 0.0;
    double rectX = 0.0, rectY = 0.0;

    friend bool operator==(const BackgroundRecord &, const BackgroundRecord &) = default;
};

struct DocumentData
{
    QString units = QStringLiteral("px"); // "px", "mm", "cm", "in", "pt"
    std::vector<CurveRecord> curves;
    std::optional<BackgroundRecord> background;

    friend bool operator==(const DocumentData &, const DocumentData &) = default;
};

// What the files check of a kind, made from the kinds' table (geometry/curvekinds.h) in records.cpp.
struct KindInfo
{
    const char *id;            // as written in files
    int minPoints;             // fewest defining points (composite: knots)
    int maxPoints;             // most defining points; 0: no limit besides Limits::maxPoints
    bool usesParameterization; // interpolating and least-squares
    bool definedByKnots;       // the points are knots (else control points / a control vector)
    bool closable;             // may be closed (composite; periodic splines later)
};
// nullptr for an unknown kind.
[[nodiscard]] const KindInfo *kindInfo(const QString &kind);
[[nodiscard]] std::vector<QString> knownKinds();
[[nodiscard]] bool isParameterizationName(const QString &name); // uniform, chord, centripetal
[[nodiscard]] bool isNodeTypeName(const QString &name);         // smooth, symmetric, corner
[[nodiscard]] bool isColorName(const QString &color);           // #rrggbb
[[nodiscard]] bool isUnitName(const QString &units);            // px, mm, cm, in, pt
// Millimetres per unit of length: mm 1, cm 10, in 25.4, pt 25.4/72. A px has no physical size: 0,
// or with `cssPixels` the CSS reference pixel, 1/96 in (what printing and the seam allowance's
// default assume). 0 for anything else. The one table of the units' sizes.
inline constexpr double kCssPixelsPerInch = 96.0;
[[nodiscard]] double millimetresPerUnit(const QString &units, bool cssPixels = false);

// Knots of a composite curve stored as `pointCount` points: 0 if the count fits no curve.
[[nodiscard]] int compositeKnotCount(std::size_t pointCount, bool closed);

// Where validateCurve found a problem, relative to the record; the reader adds the file position.
struct CurveProblem
{
    enum Field { Kind, Parameterization, Points, Point, NodeTypes, NodeType, Color, Closed };
    Field field = Kind;
    int index = -1;      // the point or node type, when the problem is one of them
    int coordinate = -1; // 0 = x, 1 = y for a non-finite coordinate
    ErrorCode code = ErrorCode::InvalidValue;
    QString message;
};

// Checks a record against its kind: a known kind, its parameterization, its point count, finite
// coordinates, node types (composite), the colour. Returns nothing when the record is well formed.
[[nodiscard]] std::optional<CurveProblem> validateCurve(const CurveRecord &curve);

} // namespace kontur::io
