#version 450 core
// Main pass: carries each surface point in world space, where it is lit and its shadows
// looked up, and to clip space for the rasteriser. (Lighting in view space too would cost
// two more interpolated vectors and a rotation per light.)
#include "scene_data.glsl"
// RAYS_FROM_DRAWN: shadow rays on OpenGL 4.5 start on the triangle drawn
// (render/DrawnTriangles.h, shadow_rays.glsl's rayStartBegin); uncertain's first draw writes it
// into the pixel's ray job (shadow_rays.glsl's rayJobSurface).
#if defined(SHADOW_RAYS) && !defined(GNOMON_GLES)
#define RAYS_FROM_DRAWN
#endif

layout(location = 0) in vec3 msPosition;
layout(location = 1) in vec3 msNormal;
layout(location = 2) in vec3 vertexColour;
#ifdef MATERIAL_PATH
layout(location = 3) in vec2 msUv;
#endif

// The visibility pass redraws the main pass's surfaces with an equal-depth test, and the
// main pass itself may start from the view depth pass's depth: all compute the very same
// positions (view_clip.glsl).
#include "view_clip.glsl"

out VertexOut {
    vec3 wsPosition;
    vec3 wsNormal;
    vec3 colour;
    flat vec4 material;  // specular, shininess, unlit, double-sided (ObjectData.material)
    flat float receives;
#ifdef MATERIAL_PATH
    vec2 uv;
    flat vec3 alpha;  // alpha factor, alpha mode (0 opaque, 1 mask, 2 blend), cutoff
#endif
#if defined(VISIBILITY_PASS) || defined(SHADOW_RAYS)
    flat float object;  // the scene object's index: recorded beside the lights' visibility, and
                        // the one a shadow ray's start looks for (shadow_rays.glsl)
#endif
#ifdef RAYS_FROM_DRAWN
    flat int firstTriangle;  // the draw's first triangle's number (render/DrawnTriangles.h)
#endif
#ifdef STAND_IN_LIFT
    flat float standInError;  // world units (shadow_lookup.glsl)
#endif
} vOut;

void main() {
    ObjectData o = objectAt(OBJECT_INDEX);
    vec4 wsPosition, vsPosition;  // vsPosition: unused here, the depth pass's chain
    gl_Position = viewClip(o, msPosition, wsPosition, vsPosition);
    vec3 wsNormal = normalize(mat3(o.worldFromModelNormal) * msNormal);
    vOut.wsPosition = wsPosition.xyz;
    vOut.wsNormal = wsNormal;
    vOut.colour = vertexColour * o.baseColour.rgb;
    // Per-object values travel as flat varyings: cheaper than a storage read per fragment.
    vOut.material = o.material;
    vOut.receives = o.flags.x;
#ifdef MATERIAL_PATH
    vOut.uv = materialUv(o, msUv);
    vOut.alpha = vec3(o.baseColour.a, o.flags.y, o.flags.z);
#endif
#if defined(VISIBILITY_PASS) || defined(SHADOW_RAYS)
    vOut.object = float(OBJECT_INDEX);
#endif
#ifdef RAYS_FROM_DRAWN
    vOut.firstTriangle = int(aFirstTriangle);
#endif
#ifdef STAND_IN_LIFT
    // The object's stand-in error, model units to world units (at most: its largest scale).
    mat3 m = mat3(o.worldFromModel);
    vOut.standInError = o.flags.w * max(length(m[0]), max(length(m[1]), length(m[2])));
#endif
}
