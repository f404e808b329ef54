#version 450 core
// Shadow pass: scene casters seen from the light camera; only depth is written.
// VIEW_CAMERA: the view depth pass instead (render/ViewDepthPass.h), seen from the view.
// ALPHA_TEST: also the texture coordinates and alpha rule of masked and blended casters;
// TRANSMITTANCE: and their colour (render/TransmittancePass.h).
#include "scene_data.glsl"

layout(location = 0) in vec3 msPosition;
#ifdef VIEW_CAMERA
// The view depth pass: the view camera's positions exactly as the main pass computes them.
#include "view_clip.glsl"
#else
layout(location = 1) uniform mat4 uClipFromWorld;  // the light camera
#endif

#ifdef ALPHA_TEST
#include "alpha_test_vertex.glsl"
#endif
#ifdef TRANSMITTANCE
// The transmittance pass (coloured shadows): the caster's colour as the main pass has it.
layout(location = 2) in vec3 vertexColour;
out vec3 vColour;
#endif

void main() {
    ObjectData o = objectAt(OBJECT_INDEX);
#ifdef VIEW_CAMERA
    vec4 ws, vs;
    gl_Position = viewClip(o, msPosition, ws, vs);
#else
    gl_Position = uClipFromWorld * (o.worldFromModel * vec4(msPosition, 1.0));
#endif
#ifdef ALPHA_TEST
    passAlphaRule(o);
#endif
#ifdef TRANSMITTANCE
    vColour = vertexColour * o.baseColour.rgb;
#endif
}
