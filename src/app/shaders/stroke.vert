#version 440
// Anti-aliased strokes of a fixed width in pixels, whatever the zoom. The vertices are the
// polyline's points in world units (y up), relative to the node's origin, each twice: once per
// side, with the offset direction of the join (miter). The view (zoom and the origin's place on
// screen) is a uniform, so pan and zoom change no vertex.

layout(location = 0) in vec2 position; // world, relative to the node's origin
layout(location = 1) in vec2 miter;    // world direction of the offset; length 1/cos of half the turn
layout(location = 2) in float side;    // -1 or +1

layout(location = 0) out float across; // signed distance from the centre line in pixels

layout(std140, binding = 0) uniform buf {
    mat4 qt_Matrix;  // item pixels to clip space
    vec4 color;      // premultiplied
    vec2 origin;     // the node's origin in item pixels
    float zoom;      // pixels per world unit
    float outer;     // half the stroke width plus half a pixel of anti-aliasing fringe
    float weight;    // coverage of strokes thinner than a pixel
    float qt_Opacity;
};

out gl_PerVertex { vec4 gl_Position; };

void main()
{
    vec2 screen = origin + vec2(position.x, -position.y) * zoom + vec2(miter.x, -miter.y) * (side * outer);
    across = side * outer;
    gl_Position = qt_Matrix * vec4(screen, 0.0, 1.0);
}
