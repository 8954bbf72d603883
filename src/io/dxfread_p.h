// The DXF reader's insides (see dxf.h), shared by its stages and by nothing else: the pairs and
// sections (dxf.cpp), the entity kinds as Bézier pieces (dxfentities.cpp), blocks, INSERTs and ASTM
// D6673 pieces (dxfblocks.cpp) and hatch boundaries (dxfhatch.cpp). A file is pairs of lines, a group
// code (an integer) and its value (Autodesk's "DXF Reference", AutoCAD 2000, AC1015).
#pragma once

#include "io/dxf.h"
#include "io/fileio.h"

#include <QHash>

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace kontur::io::dxfread {

struct Group
{
    int code = 0;
    std::string_view value; // trimmed
    int line = 0;           // the line of the group code
};

// An entity as read: its first group ("0" and the type), the groups up to the next entity, and for a
// POLYLINE its VERTEX entities (as numbers: a polyline may have millions).
struct Vertex
{
    double x = 0, y = 0, bulge = 0;
    long long flags = 0;
    int line = 0;
};

struct RawEntity
{
    Group start;
    std::vector<Group> groups;
    std::vector<Vertex> vertices;
};

// A BLOCK: its base point (the point an INSERT puts at its insertion point) and its entities.
struct Block
{
    geo::Point base = geo::Point::Zero();
    std::vector<RawEntity> entities;
};

// Where an entity lies in the drawing: x ↦ m·x + t (the INSERTs it is inside of, composed), the layer
// that its entities on the layer "0" take (DXF's rule for block content) and the nesting depth.
struct Placement
{
    Eigen::Matrix2d m = Eigen::Matrix2d::Identity();
    geo::Point t = geo::Point::Zero();
    std::string_view layer;
    QString color; // the INSERT's colour, for its content's colour "by block" (62 = 0)
    QString piece; // the ASTM D6673 (AAMA) piece the block is, empty when it is none
    int depth = 0;
};

// Blocks inside blocks deeper than this are a loop (a block that inserts itself) or a hostile file.
inline constexpr int kMaxBlockDepth = 32;

// Text as a DXF file holds it: UTF-8 (AutoCAD 2007 on) or in the drawing's code page (`codec`, from
// $DWGCODEPAGE, before), with AutoCAD's escape \U+XXXX (four hex digits) for a character outside it.
[[nodiscard]] QString dxfText(std::string_view value, const QByteArray &codec);
// A group's value as an integer; 0 when it is none.
[[nodiscard]] long long integerOf(const Group &g);
// The value of the first group with `code` as an integer; 0 when there is none or it is no integer.
[[nodiscard]] long long integerOf(const std::vector<Group> &groups, int code);

// The control points a polyline's arcs add to its vertices (none for a polyline of lines).
[[nodiscard]] qint64 interiorPoints(const std::vector<geo::Bezier> &segments);
// Vertices with bulges as segments: lines, or arcs where the bulge is not 0. Stops once the arcs'
// control points pass `budget` (the points the file may still have), so that a hostile file of many
// huge arcs is refused before it fills the memory; the caller's count then refuses it.
[[nodiscard]] std::vector<geo::Bezier> polylineSegments(const std::vector<geo::Point> &pts,
                                                        const std::vector<double> &bulges, bool closed,
                                                        double tolerance, qint64 budget);
// The Bézier pieces of a B-spline of degree p with knots U and control points P (dxfentities.cpp).
[[nodiscard]] std::vector<geo::Bezier> bezierPieces(const std::vector<double> &U, const std::vector<geo::Point> &P,
                                                    int p);

class Reader final
{
public:
    Reader(std::string_view text, const QString &file, const DxfImportOptions &options)
        : m_lines(text)
        , m_file(file)
        , m_options(options)
    {
    }

    Result<DxfImport> read();

private:
    Error error(ErrorCode code, int line, const QString &message) const
    {
        Error e;
        e.code = code;
        e.file = m_file;
        e.line = line;
        e.message = message;
        return e;
    }

    // ---- the pairs and sections (dxf.cpp)
    // The next pair, or false at the end of the text (an error when it ends after a group code).
    std::optional<Error> next(Group &g, bool &end);
    std::optional<Error> readHeader(DxfImport &out, double &scale);
    // The entities of a section up to its ENDSEC, each handed to `take` (a POLYLINE with its vertices).
    std::optional<Error> readSection(const char *section,
                                     const std::function<std::optional<Error>(RawEntity &&)> &take);
    std::optional<Error> readBlocks();
    std::optional<Error> readTables();
    // One entity: its groups up to the next "0".
    std::optional<Error> entityGroups(std::vector<Group> &groups, Group &following, bool &end);
    std::optional<Error> number(const Group &g, double &v) const;
    // The number of the first group with `code`, else `fallback`.
    std::optional<Error> number(const std::vector<Group> &groups, int code, double fallback, double &v) const;
    std::optional<Error> countPoints(qint64 n, int line);
    void skip(DxfImport &out, DxfSkipped what) { ++out.skipped[static_cast<std::size_t>(what)]; }
    // The colour an entity is drawn in: its true colour (420), its ACI (62: 1–255; 0 by block), else
    // its layer's; black when none is given.
    QString colorOf(const std::vector<Group> &groups, std::string_view layer, const Placement &place) const;

    // ---- entities as Bézier pieces (dxfentities.cpp)
    std::optional<Error> addEntity(const Group &start, const std::vector<Group> &groups, const Placement &place,
                                   DxfImport &out);
    // `mirrored`: the entity is seen from below (extrusion 0,0,-1), its object x axis the other way.
    std::optional<Error> addLine(const Group &start, const std::vector<Group> &groups, const Placement &place,
                                 DxfImport &out);
    std::optional<Error> addLwPolyline(const Group &start, const std::vector<Group> &groups, bool mirrored,
                                       const Placement &place, DxfImport &out);
    std::optional<Error> addArc(const Group &start, const std::vector<Group> &groups, bool mirrored,
                                const Placement &place, DxfImport &out);
    std::optional<Error> addEllipse(const Group &start, const std::vector<Group> &groups, bool mirrored,
                                    const Placement &place, DxfImport &out);
    // The cubics of an ARC, CIRCLE or ELLIPSE as a curve (`full`: a whole turn, closed), counted.
    std::optional<Error> addArcs(const Group &start, const std::vector<Group> &groups, std::vector<geo::Bezier> arcs,
                                 bool full, const Placement &place, DxfImport &out);
    std::optional<Error> addSpline(const Group &start, const std::vector<Group> &groups, const Placement &place,
                                   DxfImport &out);
    std::optional<Error> polyline(const RawEntity &entity, const Placement &place, DxfImport &out);
    std::optional<Error> addCurve(DxfImport &out, const Group &start, const std::vector<Group> &groups,
                                  geo::PiecewiseBezier curve, const Placement &place);

    // ---- blocks, INSERTs and ASTM D6673 pieces (dxfblocks.cpp)
    std::optional<Error> process(const RawEntity &entity, const Placement &place, DxfImport &out);
    std::optional<Error> insert(const RawEntity &entity, const Placement &place, DxfImport &out);
    // A POINT or TEXT of an ASTM D6673 piece's block: a notch, a drill hole or the piece's text.
    std::optional<Error> aamaMark(const RawEntity &entity, const Placement &place, DxfImport &out);
    // The piece's name when `block` is an ASTM D6673 piece (its cut line on layer 1 and its "Piece
    // Name:" text or a grain line on layer 7), else empty.
    QString aamaPiece(std::string_view name, const Block &block);

    // ---- hatch boundaries (dxfhatch.cpp)
    struct HatchCursor;
    using Pieces = std::vector<geo::Bezier>;
    std::optional<Error> hatch(const RawEntity &entity, const Placement &place, DxfImport &out);
    std::optional<Error> hatchPolylinePath(HatchCursor &c, int line, std::vector<Pieces> &edges);
    std::optional<Error> hatchEdgePath(HatchCursor &c, int line, std::vector<Pieces> &edges);
    std::optional<Error> hatchArcEdge(HatchCursor &c, long long edge, Pieces &pieces);
    std::optional<Error> hatchSplineEdge(HatchCursor &c, int line, Pieces &pieces);
    std::optional<Error> addHatchLoops(const RawEntity &entity, std::vector<Pieces> &loops, bool mirrored,
                                       const Placement &place, DxfImport &out);

    LineSplitter m_lines;
    QString m_file;
    DxfImportOptions m_options;
    double m_scale = 1.0; // file units to the imported units
    QByteArray m_codec;   // the code page of the file's text (for QStringDecoder), empty for UTF-8
    qint64 m_points = 0;
    std::optional<Group> m_pending; // a pair read ahead
    std::map<std::string, Block, std::less<>> m_blocks;
    bool m_blocksRead = false;
    std::vector<RawEntity> m_deferred;     // INSERTs met before the BLOCKS section
    qint64 m_instances = 0;                // block instances exploded so far
    QHash<QString, QString> m_layerColors; // the LAYER table's colours, by case-folded layer name
    std::map<std::string, QString, std::less<>> m_pieces;
};

} // namespace kontur::io::dxfread
