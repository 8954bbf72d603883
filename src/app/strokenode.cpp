// Stroke nodes: a triangle strip of two vertices per polyline point, extruded in the vertex
// shader by half the stroke width in pixels along the join's miter.
#include "app/strokenode.h"

#include "app/displaylist.h"

#include <QSGMaterialShader>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <tuple>
#include <utility>

namespace kontur {

namespace {

struct StrokeVertex
{
    float xHigh, yHigh;                // world position: the float nearest to it
    float xLow, yLow;                  // and the float nearest to the rest
    float mx, my;                      // miter: unit normal of the join divided by the cosine of half the turn
    float across;                      // signed distance of this side's outer edge from the centre line, pixels
    std::array<unsigned char, 4> rgba; // premultiplied colour, times the weight of a line thinner than a pixel
};
static_assert(sizeof(StrokeVertex) == 32);

const QSGGeometry::AttributeSet &strokeAttributes()
{
    // The position is deliberately not declared a PositionAttribute: the renderer would read
    // world units as item pixels for its overlap tests. Without one it treats the node as
    // overlapping everything, which keeps the drawing order exact.
    static const QSGGeometry::Attribute attributes[] = {
        QSGGeometry::Attribute::createWithAttributeType(0, 4, QSGGeometry::FloatType, QSGGeometry::UnknownAttribute),
        QSGGeometry::Attribute::createWithAttributeType(1, 2, QSGGeometry::FloatType, QSGGeometry::UnknownAttribute),
        QSGGeometry::Attribute::createWithAttributeType(2, 1, QSGGeometry::FloatType, QSGGeometry::UnknownAttribute),
        QSGGeometry::Attribute::createWithAttributeType(3, 4, QSGGeometry::UnsignedByteType,
                                                        QSGGeometry::ColorAttribute),
    };
    static const QSGGeometry::AttributeSet set = {4, sizeof(StrokeVertex), attributes};
    return set;
}

// A double as the sum of two floats.
std::pair<float, float> split(double value)
{
    const auto high = static_cast<float>(value);
    return {high, static_cast<float>(value - static_cast<double>(high))};
}

class StrokeShader final : public QSGMaterialShader
{
public:
    StrokeShader()
    {
        setShaderFileName(VertexStage, QStringLiteral(":/kontur/shaders/stroke.vert.qsb"));
        setShaderFileName(FragmentStage, QStringLiteral(":/kontur/shaders/stroke.frag.qsb"));
    }

    bool updateUniformData(RenderState &state, QSGMaterial *newMaterial, QSGMaterial *) override
    {
        // The layout of `buf` in stroke.vert (std140).
        struct Uniforms
        {
            float matrix[16];
            float center[4]; // high x, y; low x, y
            float middle[2]; // the item's centre in pixels
            float zoom;
            float opacity;
        };
        static_assert(sizeof(Uniforms) == 96);
        const auto *material = static_cast<const StrokeMaterial *>(newMaterial);
        const StrokeView &view = *material->view;
        Uniforms u{};
        const QMatrix4x4 m = state.combinedMatrix();
        std::memcpy(u.matrix, m.constData(), sizeof(u.matrix));
        std::tie(u.center[0], u.center[2]) = split(view.center.x());
        std::tie(u.center[1], u.center[3]) = split(view.center.y());
        u.middle[0] = static_cast<float>(view.size.width() / 2.0);
        u.middle[1] = static_cast<float>(view.size.height() / 2.0);
        u.zoom = static_cast<float>(view.zoom);
        u.opacity = state.opacity();
        QByteArray *buffer = state.uniformData();
        Q_ASSERT(buffer->size() >= static_cast<qsizetype>(sizeof(Uniforms)));
        std::memcpy(buffer->data(), &u, sizeof(Uniforms));
        return true;
    }
};

// Appends one polyline's strip (two vertices per point, closed ones back to their start).
void appendStrip(const StrokePath &path, std::vector<geo::Point> &pts, std::vector<StrokeVertex> &out)
{
    pts.clear();
    for (const geo::Point &p : *path.world)
        if (pts.empty() || p != pts.back())
            pts.push_back(p);
    if (path.closed && pts.size() > 2 && pts.back() == pts.front())
        pts.pop_back();
    const std::size_t n = pts.size();
    if (n < 2)
        return;
    // Lines thinner than a pixel keep their weight through a fainter colour; the outer edge is
    // half a pixel of anti-aliasing fringe beyond half the width.
    const float outer = std::max(path.width, 1.0F) / 2.0F + 0.5F;
    const std::array<unsigned char, 4> rgba = premultipliedRgba(path.color, std::min(path.width, 1.0F));
    const auto normal = [](const geo::Point &from, const geo::Point &to) -> geo::Point {
        const geo::Point d = to - from;
        const double length = d.norm();
        return length > 0.0 ? geo::Point(-d.y() / length, d.x() / length) : geo::Point(0, 0);
    };
    const bool join = !out.empty(); // a degenerate triangle pair from the previous strip
    if (join)
        out.push_back(out.back());
    const std::size_t points = path.closed ? n + 1 : n;
    for (std::size_t k = 0; k < points; ++k) {
        const std::size_t i = k % n;
        const bool hasPrev = i > 0 || path.closed;
        const bool hasNext = i + 1 < n || path.closed;
        const geo::Point nIn = hasPrev ? normal(pts[(i + n - 1) % n], pts[i]) : geo::Point(0, 0);
        const geo::Point nOut = hasNext ? normal(pts[i], pts[(i + 1) % n]) : geo::Point(0, 0);
        geo::Point m = nIn + nOut;
        double length = m.norm();
        if (length < 1e-9) { // a reversal: fall back to one side's normal
            m = hasNext ? nOut : nIn;
            length = 1.0;
        }
        m /= length;
        // Miter: stretch the offset so the edges stay parallel to both segments, limited to 2×.
        const geo::Point &ref = hasNext ? nOut : nIn;
        m /= std::max(m.dot(ref), 0.5);
        const auto [xHigh, xLow] = split(pts[i].x());
        const auto [yHigh, yLow] = split(pts[i].y());
        const auto mx = static_cast<float>(m.x());
        const auto my = static_cast<float>(m.y());
        for (const float side : {-outer, outer}) {
            const StrokeVertex v{xHigh, yHigh, xLow, yLow, mx, my, side, rgba};
            out.push_back(v);
            if (join && k == 0 && side < 0.0F)
                out.push_back(v);
        }
    }
}

} // namespace

void flattenWithin(const geo::Bezier &curve, double tolerance, std::vector<geo::Point> &out)
{
    const auto degree = static_cast<int>(curve.controlPoints().size()) - 1;
    const double share = degree >= 2 ? 1.0 - std::pow(0.5, degree - 1) : 1.0;
    geo::flatten(curve, tolerance / share, out);
}

StrokeMaterial::StrokeMaterial(const StrokeView *view)
    : view(view)
{
    setFlag(Blending, true);
    // The vertex shader needs the node's own matrix: never merge (and pre-transform) stroke nodes.
    setFlag(RequiresFullMatrix, true);
}

QSGMaterialType *StrokeMaterial::type() const
{
    static QSGMaterialType type;
    return &type;
}

QSGMaterialShader *StrokeMaterial::createShader(QSGRendererInterface::RenderMode) const
{
    return new StrokeShader;
}

StrokeNode::StrokeNode(const StrokeView *view)
    : m_material(view)
    , m_geometry(strokeAttributes(), 0)
{
    m_geometry.setDrawingMode(QSGGeometry::DrawTriangleStrip);
    setGeometry(&m_geometry);
    setMaterial(&m_material);
}

void StrokeNode::setPaths(const std::vector<StrokePath> &paths)
{
    std::vector<StrokeVertex> vertices;
    std::size_t estimate = 0;
    for (const StrokePath &path : paths)
        estimate += path.world ? 2 * path.world->size() + 6 : 0;
    vertices.reserve(estimate);
    std::vector<geo::Point> pts;
    for (const StrokePath &path : paths)
        if (path.world)
            appendStrip(path, pts, vertices);
    m_geometry.allocate(static_cast<int>(vertices.size()));
    if (!vertices.empty())
        std::memcpy(m_geometry.vertexData(), vertices.data(), vertices.size() * sizeof(StrokeVertex));
    markDirty(DirtyGeometry);
}

} // namespace kontur
