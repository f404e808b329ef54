#version 450 core
// A caster's outline in its light's map (render/EdgeMaps.h): at each texel the line crosses,
// the point of the line the rasteriser interpolated there, its depth and its offset from the
// texel's centre, kept where it is the nearest line yet (the largest 1 - depth: an atomic
// maximum). shadow_lookup.glsl's edgeAbovePlane compares it with the receiver's plane at that
// very point.
in vec4 vEdgeClip;
layout(location = 9) uniform vec4 uViewport;  // the map's square: x, y, width, height
layout(location = 12) uniform int uLayer;
layout(r32ui, binding = 2) uniform coherent uimage2DArray uEdges;

void main() {
    vec2 window = uViewport.xy + (vEdgeClip.xy / vEdgeClip.w * 0.5 + 0.5) * uViewport.zw;
    uvec2 offset = uvec2(clamp(round((window - gl_FragCoord.xy) * 8.0) + 8.0, 0.0, 15.0));
    uint nearness = uint(ceil(clamp(1.0 - gl_FragCoord.z, 0.0, 1.0) * 16777215.0));
    imageAtomicMax(uEdges, ivec3(ivec2(gl_FragCoord.xy), uLayer),
                   (nearness << 8) | (offset.x << 4) | offset.y);
}
