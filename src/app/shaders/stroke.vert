#version 440
// Anti-aliased strokes of a fixed width in pixels, whatever the zoom. The vertices are the
// polylines' points in world units (y up), each twice: once per side, with the offset direction
// of the join (miter). The view (zoom and centre) is a uniform, so pan and zoom change no vertex.
// World positions and the centre come as a float plus the float rest of the double: their
// difference, taken part by part, keeps double precision even far from the origin at high zoom.

layout(location = 0) in vec4 position; // world: high x, y; low x, y
layout(location = 1) in vec2 miter;    // world direction of the offset; length 1/cos of half the turn
layout(location = 2) in float across;  // signed distance of this side's outer edge, pixels
layout(location = 3) in vec4 color;    // premultiplied

layout(location = 0) out float vAcross; // signed distance from the centre line, pixels
layout(location = 1) out float vOuter;  // half the width plus half a pixel of fringe
layout(location = 2) out vec4 vColor;

layout(std140, binding = 0) uniform buf {
    mat4 qt_Matrix;   // item pixels to clip space
    vec4 center;      // the world point at the item's centre: high x, y; low x, y
    vec2 middle;      // the item's centre in pixels
    float zoom;       // pixels per world unit
    float qt_Opacity;
};

out gl_PerVertex { vec4 gl_Position; };

void main()
{
    vec2 d = (position.xy - center.xy) + (position.zw - center.zw);
    vec2 screen = middle + vec2(d.x, -d.y) * zoom + vec2(miter.x, -miter.y) * across;
    vAcross = across;
    vOuter = abs(across);
    vColor = color * qt_Opacity;
    gl_Position = qt_Matrix * vec4(screen, 0.0, 1.0);
}
