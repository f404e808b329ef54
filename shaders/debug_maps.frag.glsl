#version 450 core
// --debug-view shadow-map: one light's maps as grey panels (stored depth, darker = nearer,
// as --shadow-maps writes them): one panel per map, cascades side by side, a cube's six
// faces as two rows (+X -X +Y / -Y +Z -Z). Panels are square, centred in the viewport.
// PACK_*: the maps hold encoded depth in RGBA8 (decoded as the main pass does).
#include "depth_packing.glsl"

layout(binding = 0) uniform sampler2DArray uMaps;  // NEAREST, no comparison
layout(location = 0) uniform ivec2 uGrid;          // columns, rows
layout(location = 1) uniform vec3 uRect;           // lower-left corner (pixels), panel size
layout(location = 2) uniform int uPanels;
layout(location = 3) uniform vec4 uPanel[6];  // layer, share of the layer the map covers,
                                              // the map's origin in the layer (uv)

layout(location = 0) out vec4 fragColour;

void main() {
    vec2 p = (gl_FragCoord.xy - uRect.xy) / uRect.z;
    ivec2 cell = ivec2(floor(p));
    int panel = (uGrid.y - 1 - cell.y) * uGrid.x + cell.x;  // first row at the top
    if (any(lessThan(cell, ivec2(0))) || any(greaterThanEqual(cell, uGrid)) || panel >= uPanels) {
        fragColour = vec4(0.1, 0.1, 0.15, 1.0);
        return;
    }
    vec2 uv = uPanel[panel].zw + fract(p) * uPanel[panel].y;
    float depth = unpackDepth(texture(uMaps, vec3(uv, uPanel[panel].x)));
    fragColour = vec4(vec3(clamp(depth, 0.0, 1.0)), 1.0);
}
