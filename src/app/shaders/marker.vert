#version 440
// Point markers: one quad per disc or ring, in item pixels.

layout(location = 0) in vec2 position; // item pixels
layout(location = 1) in vec2 offset;   // from the marker's centre, pixels
layout(location = 2) in vec2 shape;    // radius, ring width (0: a filled disc)
layout(location = 3) in vec4 color;    // premultiplied

layout(location = 0) out vec2 vOffset;
layout(location = 1) out vec2 vShape;
layout(location = 2) out vec4 vColor;

layout(std140, binding = 0) uniform buf {
    mat4 qt_Matrix;
    float qt_Opacity;
};

out gl_PerVertex { vec4 gl_Position; };

void main()
{
    vOffset = offset;
    vShape = shape;
    vColor = color * qt_Opacity;
    gl_Position = qt_Matrix * vec4(position, 0.0, 1.0);
}
