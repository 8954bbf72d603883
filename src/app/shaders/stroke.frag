#version 440
// Coverage falls from full to none over the outermost pixel of the stroke.

layout(location = 0) in float across;
layout(location = 0) out vec4 fragColor;

layout(std140, binding = 0) uniform buf {
    mat4 qt_Matrix;
    vec4 color;
    vec2 origin;
    float zoom;
    float outer;
    float weight;
    float qt_Opacity;
};

void main()
{
    float coverage = clamp(outer - abs(across), 0.0, 1.0) * weight;
    fragColor = color * (coverage * qt_Opacity);
}
