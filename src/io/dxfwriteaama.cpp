// DXF export (see dxf.h): garment pieces as ASTM D6673 (AAMA DXF) exchanges them. The pieces of a
// document (closed curves cut along their allowances, with the open curves inside them), each a
// block on the standard's numbered layers with its marks (notches, fold, grain line, drill holes)
// and its annotations, inserted once at the origin. The writer's insides: dxfwrite_p.h.
#include "io/dxf.h"

#include "io/drawnwrite.h"
#include "io/dxfwrite_p.h"
#include "io/seam.h"
#include "io/shapes.h"

#include <QSet>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace kontur::io::dxfwrite {

namespace {

// A TEXT entity (AcDbText) at p, `height` high, on the writer's layer.
void writeText(Writer &w, const geo::Point &p, double height, const QByteArray &text)
{
    w.entity("TEXT", "AcDbText");
    w.point(10, p);
    w.number(40, height);
    w.pair(1, text);
    w.pair(100, "AcDbText");
}

// A POINT entity at p on the writer's layer; `angle` (degrees) when it is not 0.
void writePoint(Writer &w, const geo::Point &p, double angle = 0.0)
{
    w.entity("POINT", "AcDbPoint");
    ++w.entities;
    ++w.points;
    w.point(10, p);
    if (angle != 0.0)
        w.number(50, angle);
}

// The degrees counter-clockwise from the x axis of a direction, in [0, 360).
double degreesOf(const geo::Point &d)
{
    double a = std::atan2(d.y(), d.x()) * 180.0 / std::numbers::pi;
    if (a < 0)
        a += 360.0;
    return a >= 360.0 ? 0.0 : a;
}

// A piece's marks on the standard's layers (the block's entities; see AamaPiece).
void writeMarks(Writer &e, const AamaPiece &piece, double scale)
{
    const PieceMarks &m = *piece.marks;
    const geo::PiecewiseBezier &own = piece.sew.isEmpty() ? piece.cut : piece.sew;
    // Layer 4: each notch where it meets the cut line (carried across from the seam along its own
    // direction), its direction
    // as the point's angle; its kind on D6673's layer (80 T, 81 castle, 82 check, 83 U, 84 V; slit: none).
    for (const Notch &n : m.notches) {
        const CurvePlace place = placeAtLength(own, n.position);
        const geo::Point direction = notchDirection(own, place, n.angle);
        geo::Point at = place.point;
        if (!piece.sew.isEmpty())
            at = meetAlong(piece.cut, place.point, direction).value_or(piece.cut.nearest(place.point).point);
        const double angle = degreesOf(direction);
        e.layer = "4";
        writePoint(e, at * scale, angle);
        if (n.kind != NotchKind::Slit) {
            e.layer = n.kind == NotchKind::Castle ? "81" : "84";
            writePoint(e, at * scale, angle);
        }
    }
    if (m.fold) {
        e.layer = "6";
        writeLines(e, {m.fold->a * scale, m.fold->b * scale}, false);
    }
    if (m.grainline) {
        e.layer = "7";
        writeLines(e, {m.grainline->a * scale, m.grainline->b * scale}, false);
    }
    e.layer = "13";
    for (const geo::Point &p : m.drillHoles)
        writePoint(e, p * scale);
}

// Block names: the piece's name as a layer name is made (AutoCAD's refused characters as "_"),
// unique regardless of case; "Piece N" for a piece without one. Their handles from `next` on, three
// each; `next` ends after them.
std::vector<BlockHandles> pieceBlocks(std::span<const AamaPiece> pieces, const CodePage &page, unsigned &next)
{
    std::vector<BlockHandles> blocks;
    QSet<QString> taken;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        QString base = layerNameOf(pieces[i].name);
        if (base.isEmpty() || base.startsWith(QLatin1Char('*')))
            base = QStringLiteral("Piece %1").arg(i + 1);
        QString name = base;
        for (int n = 2; taken.contains(name.toCaseFolded()); ++n)
            name = base.left(240) + QStringLiteral(" (%1)").arg(n);
        taken.insert(name.toCaseFolded());
        blocks.push_back({dxfText(name, page), next, next + 1, next + 2});
        next += 3;
    }
    return blocks;
}

// Layer 1: the annotations the standard names, in the middle of the piece.
void writeAnnotations(Writer &e, const AamaPiece &piece, const BlockHandles &b, const CodePage &page, double scale)
{
    e.layer = "1";
    const geo::Box box = piece.cut.boundingBox();
    const double height = std::max(box.sizes().y() * scale / 40, 1e-6);
    geo::Point at = box.center() * scale - geo::Point(box.sizes().x() * scale / 4, 0);
    const auto text = [&](const QByteArray &line) {
        writeText(e, at, height, line);
        at.y() -= 1.5 * height;
    };
    text("Piece Name: " + dxfText(piece.name.isEmpty() ? QString::fromUtf8(b.name) : piece.name, page));
    if (piece.marks && !piece.marks->size.isEmpty())
        text("Size: " + dxfText(piece.marks->size, page));
    text("Quantity: " + QByteArray::number(piece.marks ? piece.marks->quantity : 1));
    if (piece.marks && !piece.marks->material.isEmpty())
        text("Material: " + dxfText(piece.marks->material, page));
    if (piece.marks && piece.marks->fold)
        text("Annotation: On fold");
}

// A piece's block: BLOCK, its lines and marks on the standard's layers, its annotations, ENDBLK.
void writePieceBlock(Writer &e, const AamaPiece &piece, const BlockHandles &b, const CodePage &page,
                     const DxfExportOptions &options, double scale, double tolerance)
{
    e.blockBegin(b.name, b.begin, b.record, "1");
    e.owner = b.record;
    e.rgb = -1;
    // Layer 1: the cut line (the allowance's outline, else the piece's own curve).
    e.layer = "1";
    for (const auto &run : runsOf(piece.cut, scale))
        writeRun(e, run, piece.cut.isClosed(), options, tolerance);
    // Layer 14: the sew line, where an allowance lies around it.
    if (!piece.sew.isEmpty()) {
        e.layer = "14";
        for (const auto &run : runsOf(piece.sew, scale))
            writeRun(e, run, piece.sew.isClosed(), options, tolerance);
    }
    // Layer 8: the internal lines.
    e.layer = "8";
    for (const geo::PiecewiseBezier &line : piece.internal)
        for (const auto &run : runsOf(line, scale))
            writeRun(e, run, line.isClosed(), options, tolerance);
    // Layers 4, 6, 7 and 13: the piece's own marks; no grain line where the piece has none.
    if (piece.marks)
        writeMarks(e, piece, scale);
    writeAnnotations(e, piece, b, page, scale);
    e.blockEnd(b.end, b.record, "1");
}

// ASTM D6673 (AAMA DXF): each piece a block on the standard's numbered layers, inserted once at the
// origin (its block's base point), so the pieces lie where they were drawn.
QByteArray buildAama(std::span<const AamaPiece> pieces, const DxfExportOptions &options, qint64 &entities,
                     qint64 &points)
{
    const auto [insunits, scale] = fileUnits(options.units);
    const double tolerance = (options.tolerance > 0 ? options.tolerance : defaultDxfTolerance(options.units)) * scale;
    geo::Box extents; // in the file's units
    for (const AamaPiece &piece : pieces)
        if (!piece.cut.isEmpty()) {
            const geo::Box b = piece.cut.boundingBox();
            extents.extend(b.min() * scale);
            extents.extend(b.max() * scale);
        }
    // The layers of the standard that Kontur writes, with the colours garment CAD shows them in.
    std::vector<Layer> layers{
        {QStringLiteral("1"), 7, "1"},   {QStringLiteral("4"), 1, "4"},   {QStringLiteral("6"), 6, "6"},
        {QStringLiteral("7"), 5, "7"},   {QStringLiteral("8"), 4, "8"},   {QStringLiteral("13"), 2, "13"},
        {QStringLiteral("14"), 3, "14"}, {QStringLiteral("81"), 1, "81"}, {QStringLiteral("84"), 1, "84"}};
    std::vector<QString> names;
    for (const AamaPiece &piece : pieces) {
        names.push_back(piece.name);
        if (piece.marks) {
            names.push_back(piece.marks->size);
            names.push_back(piece.marks->material);
        }
    }
    const CodePage &page = codePageFor(names);
    unsigned next = FirstFree + static_cast<unsigned>(layers.size());
    const std::vector<BlockHandles> blocks = pieceBlocks(pieces, page, next);
    Writer e;
    e.handle = next;
    for (std::size_t i = 0; i < pieces.size(); ++i)
        writePieceBlock(e, pieces[i], blocks[i], page, options, scale, tolerance);
    QByteArray blockText = std::move(e.out);
    e.out.clear();
    e.owner = ModelSpaceRecord;
    e.pair(0, "SECTION");
    e.pair(2, "ENTITIES");
    e.layer = "1";
    for (const BlockHandles &b : blocks) {
        e.entity("INSERT", "AcDbBlockReference");
        e.pair(2, b.name);
        e.point(10, geo::Point(0, 0));
    }
    e.pair(0, "ENDSEC");

    return writeDrawing("Written by Kontur: ASTM D6673 (AAMA) pieces, one block each", e, page, insunits, extents,
                        layers, blocks, blockText, entities, points);
}

} // namespace

} // namespace kontur::io::dxfwrite

namespace kontur::io {

Result<std::vector<AamaPiece>> aamaPieces(const std::vector<CurveRecord> &records)
{
    const int n = static_cast<int>(records.size());
    std::vector<std::optional<geo::PiecewiseBezier>> shapes(records.size());
    std::vector<int> sourceOf(records.size(), -1);
    for (int i = 0; i < n; ++i) {
        const CurveRecord &r = records[static_cast<std::size_t>(i)];
        if (!r.visible)
            continue;
        auto shape = curveShape(r);
        if (!shape) {
            Error e = shape.error();
            e.path = QStringLiteral("curves[%1]").arg(i);
            return e;
        }
        shapes[static_cast<std::size_t>(i)] = std::move(shape).value();
        if (const auto seam = seamFromSettings(r.settings, n))
            sourceOf[static_cast<std::size_t>(i)] = seam->source;
    }
    std::vector<AamaPiece> pieces;
    std::vector<int> pieceOf(records.size(), -1);
    for (int i = 0; i < n; ++i) {
        const auto &shape = shapes[static_cast<std::size_t>(i)];
        if (!shape || sourceOf[static_cast<std::size_t>(i)] >= 0 || !shape->isClosed() || shape->isEmpty())
            continue;
        AamaPiece piece;
        piece.name = records[static_cast<std::size_t>(i)].name;
        piece.cut = *shape;
        piece.marks = pieceFromSettings(records[static_cast<std::size_t>(i)].settings);
        for (int k = 0; k < n; ++k)
            if (sourceOf[static_cast<std::size_t>(k)] == i && shapes[static_cast<std::size_t>(k)] &&
                !shapes[static_cast<std::size_t>(k)]->isEmpty()) {
                piece.sew = *shape;
                piece.cut = *shapes[static_cast<std::size_t>(k)];
                break;
            }
        pieceOf[static_cast<std::size_t>(i)] = static_cast<int>(pieces.size());
        pieces.push_back(std::move(piece));
    }
    for (int i = 0; i < n; ++i) {
        const auto &shape = shapes[static_cast<std::size_t>(i)];
        if (!shape || shape->isClosed() || shape->isEmpty() || sourceOf[static_cast<std::size_t>(i)] >= 0)
            continue;
        const geo::Box box = shape->boundingBox();
        for (AamaPiece &piece : pieces)
            if (piece.cut.boundingBox().contains(box)) {
                piece.internal.push_back(*shape);
                break;
            }
    }
    return pieces;
}

std::vector<QString> piecesWithoutGrainline(std::span<const AamaPiece> pieces)
{
    std::vector<QString> names;
    for (const AamaPiece &piece : pieces)
        if (!piece.marks || !piece.marks->grainline)
            names.push_back(piece.name);
    return names;
}

QByteArray exportAamaDxf(std::span<const AamaPiece> pieces, const DxfExportOptions &options)
{
    qint64 entities = 0, points = 0;
    return dxfwrite::buildAama(pieces, options, entities, points);
}

Result<Ok> writeAamaDxf(const QString &path, std::span<const AamaPiece> pieces, const DxfExportOptions &options,
                        const Limits &limits)
{
    for (const AamaPiece &piece : pieces)
        for (const geo::PiecewiseBezier *c : {&piece.cut, &piece.sew})
            for (const geo::Bezier &b : c->segments())
                for (const geo::Point &p : b.controlPoints())
                    if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
                        return NonFiniteWatch::error(path, QStringLiteral("the drawing"));
    qint64 entities = 0, points = 0;
    const NonFiniteWatch watch;
    const QByteArray bytes = dxfwrite::buildAama(pieces, options, entities, points);
    return writeDrawing(path, bytes, watch.seen(), {entities, "entities"}, {points, "points"}, limits);
}

} // namespace kontur::io
