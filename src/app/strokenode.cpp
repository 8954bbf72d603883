// Stroke nodes: a triangle strip of two vertices per polyline point, extruded in the vertex
// shader by half the stroke width in pixels along the join's miter.
#include "app/strokenode.h"

#include <QSGMaterialShader>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace kontur {

namespace {

struct StrokeVertex
{
    float x, y;   // world, relative to the material's origin
    float mx, my; // miter: unit normal of the join divided by the cosine of half the turn
    float side;   // -1 or +1
};

const QSGGeometry::AttributeSet &strokeAttributes()
{
    // The position is deliberately not declared a PositionAttribute: the renderer would read
    // world units as item pixels for its overlap tests. Without one it treats the node as
    // overlapping everything, which keeps the drawing order exact.
    static const QSGGeometry::Attribute attributes[] = {
        QSGGeometry::Attribute::createWithAttributeType(0, 2, QSGGeometry::FloatType, QSGGeometry::UnknownAttribute),
        QSGGeometry::Attribute::createWithAttributeType(1, 2, QSGGeometry::FloatType, QSGGeometry::UnknownAttribute),
        QSGGeometry::Attribute::createWithAttributeType(2, 1, QSGGeometry::FloatType, QSGGeometry::UnknownAttribute),
    };
    static const QSGGeometry::AttributeSet set = {3, sizeof(StrokeVertex), attributes};
    return set;
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
            float color[4];
            float origin[2];
            float zoom;
            float outer;
            float weight;
            float opacity;
        };
        static_assert(sizeof(Uniforms) == 104);
        const auto *material = static_cast<const StrokeMaterial *>(newMaterial);
        const StrokeView &view = *material->view;
        Uniforms u{};
        const QMatrix4x4 m = state.combinedMatrix();
        std::memcpy(u.matrix, m.constData(), sizeof(u.matrix));
        const QColor &c = material->color;
        const auto alpha = static_cast<float>(c.alphaF());
        u.color[0] = static_cast<float>(c.redF()) * alpha;
        u.color[1] = static_cast<float>(c.greenF()) * alpha;
        u.color[2] = static_cast<float>(c.blueF()) * alpha;
        u.color[3] = alpha;
        // The origin's place on screen, in double precision: the vertices stay small numbers.
        u.origin[0] = static_cast<float>(view.size.width() / 2.0 + (material->origin.x() - view.center.x()) * view.zoom);
        u.origin[1] = static_cast<float>(view.size.height() / 2.0 - (material->origin.y() - view.center.y()) * view.zoom);
        u.zoom = static_cast<float>(view.zoom);
        // Lines thinner than a pixel keep their weight through a fainter colour.
        u.outer = std::max(material->width, 1.0F) / 2.0F + 0.5F;
        u.weight = std::min(material->width, 1.0F);
        u.opacity = state.opacity();
        QByteArray *buffer = state.uniformData();
        Q_ASSERT(buffer->size() >= static_cast<qsizetype>(sizeof(Uniforms)));
        std::memcpy(buffer->data(), &u, sizeof(Uniforms));
        return true;
    }
};

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

void StrokeNode::setPolyline(const std::vector<geo::Point> &world, bool closed)
{
    std::vector<geo::Point> pts;
    pts.reserve(world.size() + 1);
    for (const geo::Point &p : world)
        if (pts.empty() || p != pts.back())
            pts.push_back(p);
    if (closed && pts.size() > 2 && pts.back() == pts.front())
        pts.pop_back();
    const std::size_t n = pts.size();
    if (n < 2) {
        m_geometry.allocate(0);
        markDirty(DirtyGeometry);
        return;
    }
    const geo::Point origin = pts.front();
    if (m_material.origin != QPointF(origin.x(), origin.y())) {
        m_material.origin = QPointF(origin.x(), origin.y());
        markDirty(DirtyMaterial);
    }
    const auto normal = [](const geo::Point &from, const geo::Point &to) -> geo::Point {
        const geo::Point d = to - from;
        const double length = d.norm();
        return length > 0.0 ? geo::Point(-d.y() / length, d.x() / length) : geo::Point(0, 0);
    };
    const std::size_t points = closed ? n + 1 : n;
    m_geometry.allocate(static_cast<int>(2 * points));
    auto *v = static_cast<StrokeVertex *>(m_geometry.vertexData());
    for (std::size_t k = 0; k < points; ++k) {
        const std::size_t i = k % n;
        const bool hasPrev = i > 0 || closed;
        const bool hasNext = i + 1 < n || closed;
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
        const auto x = static_cast<float>(pts[i].x() - origin.x());
        const auto y = static_cast<float>(pts[i].y() - origin.y());
        const auto mx = static_cast<float>(m.x());
        const auto my = static_cast<float>(m.y());
        *v++ = {x, y, mx, my, -1.0F};
        *v++ = {x, y, mx, my, 1.0F};
    }
    markDirty(DirtyGeometry);
}

void StrokeNode::setStyle(const QColor &color, float width)
{
    if (color == m_material.color && width == m_material.width)
        return;
    m_material.color = color;
    m_material.width = width;
    markDirty(DirtyMaterial);
}

} // namespace kontur
