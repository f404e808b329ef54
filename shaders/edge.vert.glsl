#version 450 core
// The casters' outlines for the edge maps (render/EdgeMaps.h, render/CasterEdges.h). A mesh's
// edge is drawn where, seen from the light, its two triangles' far corners lie on the same side
// of the plane through the edge and the light (a contour: the surface turns away from the
// light there, whatever the triangles' winding), or where it borders one triangle only.
// Elsewhere both ends go outside the clip volume. Both ends decide alike: they judge the same
// points in the same order.
layout(location = 0) in vec3 msPosition;
layout(location = 1) in vec3 msOther;
layout(location = 2) in vec3 msCornerA;
layout(location = 3) in vec4 msCornerB;  // w 0: no second triangle
layout(location = 1) uniform mat4 uClipFromModel;  // the light camera's, for this object
// The light in the model's space: its position (w 1), or the way towards it (w 0) for an
// orthographic map. The sides of a plane are kept by any invertible affine transform.
layout(location = 10) uniform vec4 uToLight;
out vec4 vEdgeClip;  // interpolated with perspective: the line's point, in clip space

// Is q before p (x, then y, then z)?
bool before(vec3 q, vec3 p) {
    return q.x != p.x ? q.x < p.x : q.y != p.y ? q.y < p.y : q.z < p.z;
}

void main() {
    // The same two ends in the same order at both vertices.
    bool swap = before(msOther, msPosition);
    vec3 lo = swap ? msOther : msPosition, hi = swap ? msPosition : msOther;
    vec3 toLight = uToLight.xyz - lo * uToLight.w;
    vec3 across = cross(hi - lo, toLight);
    float sideA = dot(across, msCornerA - lo), sideB = dot(across, msCornerB.xyz - lo);
    bool contour = msCornerB.w == 0.0 || sideA * sideB >= 0.0;
    gl_Position = contour ? uClipFromModel * vec4(msPosition, 1.0) : vec4(2.0, 2.0, 2.0, 1.0);
    vEdgeClip = gl_Position;
}
