// DXF import (see dxf.h): blocks and what is made of them. An entity is drawn where the INSERTs it is
// inside of place it (nested, scaled, rotated, MINSERT arrays), and a block that is an ASTM D6673
// (AAMA) piece gives its curves the piece's name and its POINTs and TEXT the piece's notches, drill
// holes, size, quantity, material and fold. The reader's insides: dxfread_p.h.
#include "io/dxf.h"

#include "io/dxfread_p.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

namespace kontur::io::dxfread {

std::optional<Error> Reader::process(const RawEntity &entity, const Placement &place, DxfImport &out)
{
    const std::string_view type = entity.start.value;
    if (type == "INSERT")
        return insert(entity, place, out);
    if (type == "POLYLINE")
        return polyline(entity, place, out);
    if (type == "HATCH")
        return hatch(entity, place, out);
    if (type == "SEQEND" || type == "VERTEX" || type == "VIEWPORT")
        return std::nullopt; // the end of an INSERT's attributes; a paper space view: nothing to draw
    if (!place.piece.isEmpty() && (type == "POINT" || type == "TEXT" || type == "MTEXT"))
        return aamaMark(entity, place, out);
    return addEntity(entity.start, entity.groups, place, out);
}

std::optional<Error> Reader::aamaMark(const RawEntity &entity, const Placement &place, DxfImport &out)
{
    std::string_view layer = "0", text;
    double x = 0, y = 0, angle = 0;
    for (const Group &g : entity.groups) {
        double *v = g.code == 10 ? &x : g.code == 20 ? &y : g.code == 50 ? &angle : nullptr;
        if (v) {
            if (auto e = number(g, *v))
                return e;
        } else if (g.code == 8) {
            layer = g.value;
        } else if (g.code == 1) {
            text = g.value;
        }
    }
    if (layer == "0" && !place.layer.empty())
        layer = place.layer;
    auto found = std::find_if(out.pieces.begin(), out.pieces.end(),
                              [&](const DxfAamaPiece &p) { return p.name == place.piece; });
    if (found == out.pieces.end()) {
        out.pieces.push_back({});
        out.pieces.back().name = place.piece;
        found = out.pieces.end() - 1;
    }
    DxfAamaPiece &piece = *found;
    if (entity.start.value != "POINT") {
        // The standard's annotations ("Key: value"); the piece's name was read with its block.
        const QString t = dxfText(text, m_codec).trimmed();
        const auto value = [&](const char *key) {
            return t.startsWith(QLatin1String(key), Qt::CaseInsensitive)
                       ? std::optional<QString>(t.mid(static_cast<qsizetype>(std::strlen(key))).trimmed())
                       : std::nullopt;
        };
        if (value("Piece Name:")) {
            // read with the block (Reader::aamaPiece)
        } else if (const auto size = value("Size:")) {
            piece.size = *size;
        } else if (const auto material = value("Material:")) {
            piece.material = *material;
        } else if (const auto quantity = value("Quantity:")) {
            bool ok = false;
            const int n = quantity->toInt(&ok);
            if (ok && n >= 1)
                piece.quantity = n;
        } else if (const auto note = value("Annotation:");
                   note && note->compare(QLatin1String("On fold"), Qt::CaseInsensitive) == 0) {
            piece.onFold = true;
        } else {
            skip(out, DxfSkipped::Text);
        }
        return std::nullopt;
    }
    bool isNumber = false;
    const int aama = QString::fromLatin1(layer.data(), static_cast<qsizetype>(layer.size())).toInt(&isNumber);
    if (!isNumber || (aama != 4 && aama != 13 && (aama < 80 || aama > 84))) {
        skip(out, DxfSkipped::Other);
        return std::nullopt;
    }
    const bool placed = place.depth > 0;
    const geo::Point p = (placed ? geo::Point(place.m * geo::Point(x, y) + place.t) : geo::Point(x, y)) * m_scale;
    const double a = angle * std::numbers::pi / 180.0;
    const geo::Point d =
        placed ? geo::Point(place.m * geo::Point(std::cos(a), std::sin(a))) : geo::Point(std::cos(a), std::sin(a));
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
        return error(ErrorCode::NumberOutOfRange, entity.start.line,
                     QStringLiteral("POINT: a point lies beyond the range of numbers"));
    piece.points.push_back({p, std::atan2(d.y(), d.x()) * 180.0 / std::numbers::pi, aama});
    return std::nullopt;
}

// An INSERT draws its block's entities moved by the insertion transform of the DXF Reference: the block's
// base point to the origin, scaled by (41, 42), rotated by 50 (degrees), moved to the insertion point
// (10, 20); a MINSERT repeats it in 70 columns and 71 rows spaced 44 and 45 along the rotated axes.
std::optional<Error> Reader::insert(const RawEntity &entity, const Placement &place, DxfImport &out)
{
    std::string_view blockName, layer = "0";
    double x = 0, y = 0, sx = 1, sy = 1, rotation = 0, dx = 0, dy = 0, ex = 0, ey = 0, ez = 1;
    long long columns = 1, rows = 1;
    for (const Group &g : entity.groups) {
        double *v = nullptr;
        switch (g.code) {
        case 2:
            blockName = g.value;
            break;
        case 8:
            layer = g.value;
            break;
        case 10:
            v = &x;
            break;
        case 20:
            v = &y;
            break;
        case 41:
            v = &sx;
            break;
        case 42:
            v = &sy;
            break;
        case 50:
            v = &rotation;
            break;
        case 44:
            v = &dx;
            break;
        case 45:
            v = &dy;
            break;
        case 210:
            v = &ex;
            break;
        case 220:
            v = &ey;
            break;
        case 230:
            v = &ez;
            break;
        case 70:
            columns = integerOf(g);
            break;
        case 71:
            rows = integerOf(g);
            break;
        default:
            break;
        }
        if (v)
            if (auto e = number(g, *v))
                return e;
    }
    const auto block = m_blocks.find(blockName);
    if (block == m_blocks.end() || place.depth >= kMaxBlockDepth) {
        skip(out, DxfSkipped::Other);
        return std::nullopt;
    }
    if (std::abs(ex) > 1e-12 || std::abs(ey) > 1e-12 || std::abs(std::abs(ez) - 1.0) > 1e-12) {
        skip(out, DxfSkipped::Solid3D);
        return std::nullopt;
    }
    if (sx == 0.0 || sy == 0.0)
        return std::nullopt; // flattened to a line or a point
    columns = std::max(1LL, columns);
    rows = std::max(1LL, rows);
    const double a = rotation * std::numbers::pi / 180.0;
    Eigen::Matrix2d r;
    r << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
    Eigen::Matrix2d scale = Eigen::Matrix2d::Zero();
    scale(0, 0) = sx;
    scale(1, 1) = sy;
    // Seen from below (extrusion 0,0,-1) the INSERT's own x axis points the other way.
    Eigen::Matrix2d flip = Eigen::Matrix2d::Identity();
    if (ez < 0)
        flip(0, 0) = -1;
    const Block &b = block->second;
    const QString piece = aamaPiece(blockName, b);
    const QString insertColor =
        colorOf(entity.groups, layer == "0" && !place.layer.empty() ? place.layer : layer, place);
    for (long long row = 0; row < rows; ++row)
        for (long long column = 0; column < columns; ++column) {
            if (++m_instances > m_options.limits.maxCurves)
                return error(ErrorCode::TooManyCurves, entity.start.line,
                             QStringLiteral("INSERT: more than %1 block instances, the most Kontur reads from one file")
                                 .arg(m_options.limits.maxCurves));
            const geo::Point at = geo::Point(x, y) + r * geo::Point(column * dx, row * dy);
            Placement inner;
            inner.m = place.m * flip * r * scale;
            inner.t = place.m * (flip * (at - r * scale * b.base)) + place.t;
            inner.layer = layer == "0" ? place.layer : layer;
            inner.color = insertColor;
            inner.piece = piece;
            inner.depth = place.depth + 1;
            for (const RawEntity &child : b.entities)
                if (auto e = process(child, inner, out))
                    return e;
        }
    return std::nullopt;
}

QString Reader::aamaPiece(std::string_view name, const Block &block)
{
    if (const auto found = m_pieces.find(name); found != m_pieces.end())
        return found->second;
    bool cut = false, grain = false;
    QString title;
    for (const RawEntity &e : block.entities) {
        std::string_view layer = "0", text;
        for (const Group &g : e.groups) {
            if (g.code == 8)
                layer = g.value;
            else if (g.code == 1)
                text = g.value;
        }
        const bool isText = e.start.value == "TEXT" || e.start.value == "MTEXT";
        cut = cut || (layer == "1" && !isText);
        grain = grain || layer == "7";
        if (isText && title.isEmpty()) {
            const QString t = dxfText(text, m_codec).trimmed();
            if (t.startsWith(QLatin1String("Piece Name:"), Qt::CaseInsensitive))
                title = t.mid(11).trimmed();
        }
    }
    QString piece;
    if (cut && (grain || !title.isEmpty()))
        piece = title.isEmpty() ? dxfText(name, m_codec) : title;
    m_pieces.emplace(std::string(name), piece);
    return piece;
}

} // namespace kontur::io::dxfread
