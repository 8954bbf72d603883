// Marker nodes: four vertices per marker, each carrying the marker's centre-relative position,
// so that the fragment shader knows the distance from the centre.
#include "app/markernode.h"

#include <QSGMaterialShader>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

namespace kontur {

namespace {

struct MarkerVertex
{
    float x, y;                        // item pixels
    float dx, dy;                      // from the marker's centre, pixels
    float radius, ring;                // ring: the outline's width, 0 for a filled disc
    std::array<unsigned char, 4> rgba; // premultiplied colour
};
static_assert(sizeof(MarkerVertex) == 28);

const QSGGeometry::AttributeSet &markerAttributes()
{
    static const QSGGeometry::Attribute attributes[] = {
        QSGGeometry::Attribute::createWithAttributeType(0, 2, QSGGeometry::FloatType, QSGGeometry::PositionAttribute),
        QSGGeometry::Attribute::createWithAttributeType(1, 2, QSGGeometry::FloatType, QSGGeometry::UnknownAttribute),
        QSGGeometry::Attribute::createWithAttributeType(2, 2, QSGGeometry::FloatType, QSGGeometry::UnknownAttribute),
        QSGGeometry::Attribute::createWithAttributeType(3, 4, QSGGeometry::UnsignedByteType,
                                                        QSGGeometry::ColorAttribute),
    };
    static const QSGGeometry::AttributeSet set = {4, sizeof(MarkerVertex), attributes};
    return set;
}

class MarkerShader final : public QSGMaterialShader
{
public:
    MarkerShader()
    {
        setShaderFileName(VertexStage, QStringLiteral(":/kontur/shaders/marker.vert.qsb"));
        setShaderFileName(FragmentStage, QStringLiteral(":/kontur/shaders/marker.frag.qsb"));
    }

    bool updateUniformData(RenderState &state, QSGMaterial *, QSGMaterial *) override
    {
        QByteArray *buffer = state.uniformData();
        Q_ASSERT(buffer->size() >= 68);
        bool changed = false;
        if (state.isMatrixDirty()) {
            const QMatrix4x4 m = state.combinedMatrix();
            std::memcpy(buffer->data(), m.constData(), 64);
            changed = true;
        }
        if (state.isOpacityDirty()) {
            const float opacity = state.opacity();
            std::memcpy(buffer->data() + 64, &opacity, 4);
            changed = true;
        }
        return changed;
    }
};

void appendQuad(std::vector<MarkerVertex> &out, QPointF center, float radius, float ring, const QColor &color)
{
    const std::array<unsigned char, 4> rgba = premultipliedRgba(color);
    // Half a pixel of fringe beyond the outer edge, plus a little for rounding.
    const float extent = radius + std::max(ring, 1.0F) / 2.0F + 1.0F;
    const auto cx = static_cast<float>(center.x());
    const auto cy = static_cast<float>(center.y());
    for (const auto &[sx, sy] : {std::pair{-1.0F, -1.0F}, {1.0F, -1.0F}, {-1.0F, 1.0F}, {1.0F, 1.0F}}) {
        out.push_back({cx + sx * extent, cy + sy * extent, sx * extent, sy * extent, radius, ring, rgba});
    }
}

} // namespace

MarkerMaterial::MarkerMaterial()
{
    setFlag(Blending, true);
}

QSGMaterialType *MarkerMaterial::type() const
{
    static QSGMaterialType type;
    return &type;
}

QSGMaterialShader *MarkerMaterial::createShader(QSGRendererInterface::RenderMode) const
{
    return new MarkerShader;
}

MarkerNode::MarkerNode()
    : m_geometry(markerAttributes(), 0, 0, QSGGeometry::UnsignedIntType)
{
    m_geometry.setDrawingMode(QSGGeometry::DrawTriangles);
    setGeometry(&m_geometry);
    setMaterial(&m_material);
}

void MarkerNode::setMarkers(const std::vector<Disc> &discs, const std::vector<Ring> &rings)
{
    std::vector<MarkerVertex> vertices;
    vertices.reserve(4 * (discs.size() + rings.size()));
    for (const Disc &disc : discs)
        appendQuad(vertices, disc.center, disc.radius, 0.0F, disc.color);
    for (const Ring &ring : rings)
        appendQuad(vertices, ring.center, ring.radius, std::max(ring.width, 1e-3F), ring.color);
    const auto quads = static_cast<int>(vertices.size() / 4);
    m_geometry.allocate(4 * quads, 6 * quads);
    std::memcpy(m_geometry.vertexData(), vertices.data(), vertices.size() * sizeof(MarkerVertex));
    auto *index = m_geometry.indexDataAsUInt();
    for (int q = 0; q < quads; ++q) {
        const auto base = static_cast<quint32>(4 * q);
        for (quint32 i : {0U, 1U, 2U, 2U, 1U, 3U})
            *index++ = base + i;
    }
    markDirty(DirtyGeometry);
}

} // namespace kontur
