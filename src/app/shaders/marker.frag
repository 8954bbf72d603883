#version 440
// Coverage of a disc (radius r) or a ring (outline of width w centred on radius r), falling from
// full to none over one pixel at each edge, as the tessellated strokes do.

layout(location = 0) in vec2 vOffset;
layout(location = 1) in vec2 vShape;
layout(location = 2) in vec4 vColor;
layout(location = 0) out vec4 fragColor;

layout(std140, binding = 0) uniform buf {
    mat4 qt_Matrix;
    float qt_Opacity;
};

void main()
{
    float d = length(vOffset);
    float coverage;
    if (vShape.y > 0.0) {
        // Rings thinner than a pixel keep their weight through a fainter colour.
        float halfWidth = max(vShape.y, 1.0) * 0.5;
        coverage = clamp(halfWidth + 0.5 - abs(d - vShape.x), 0.0, 1.0) * min(vShape.y, 1.0);
    } else {
        coverage = clamp(vShape.x + 0.5 - d, 0.0, 1.0);
    }
    fragColor = vColor * coverage;
}
