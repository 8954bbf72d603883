#version 440
// Coverage falls from full to none over the outermost pixel of the stroke.

layout(location = 0) in float vAcross;
layout(location = 1) in float vOuter;
layout(location = 2) in vec4 vColor;
layout(location = 0) out vec4 fragColor;

void main()
{
    fragColor = vColor * clamp(vOuter - abs(vAcross), 0.0, 1.0);
}
