// MarkerNode: point markers (filled discs and rings) as one quad each, drawn by MarkerMaterial's
// shaders, which compute the anti-aliased circle's coverage per pixel. Tessellated circles cost
// dozens of tiny triangles per marker, which a software rasterizer pays for dearly.
#pragma once

#include "app/displaylist.h"

#include <QSGGeometryNode>
#include <QSGMaterial>

#include <vector>

namespace kontur {

class MarkerMaterial final : public QSGMaterial
{
public:
    MarkerMaterial();
    [[nodiscard]] QSGMaterialType *type() const override;
    [[nodiscard]] QSGMaterialShader *createShader(QSGRendererInterface::RenderMode renderMode) const override;
};

class MarkerNode final : public QSGGeometryNode
{
public:
    MarkerNode();

    // Replaces the markers (item pixels), drawn in order: discs, then rings.
    void setMarkers(const std::vector<Disc> &discs, const std::vector<Ring> &rings);
    [[nodiscard]] int markerCount() const { return geometry()->vertexCount() / 4; }

private:
    MarkerMaterial m_material;
    QSGGeometry m_geometry;
};

} // namespace kontur
