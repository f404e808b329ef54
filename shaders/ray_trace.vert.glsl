#version 450 core
// The shadow rays' pass covers as many rows of answers (ray_pyramid.glsl's rayAnswerTexel: in
// blocks of 4x4, P texels wide) as the marked pixels fill: their count read from the
// pyramid's top, so no fragment runs past them.
#include "ray_pyramid.glsl"
layout(location = 1) uniform int uResultRows;  // rows of answers the texture holds

void main() {
    int rows = 4 * ((rayJobCount() + 4 * uRayPyramidSize.x - 1) >> (uRayPyramidSize.y + 2));
    float top = -1.0 + 2.0 * float(rows) / float(uResultRows);
    gl_Position = vec4(float(gl_VertexID & 1) * 2.0 - 1.0, (gl_VertexID & 2) != 0 ? top : -1.0,
                      0.0, 1.0);
}
