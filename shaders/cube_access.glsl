// Point lights' cubes as the lookups read them: CUBE_COMPARE(cubes, d, cube, reference)
// compares `reference` with the depth stored in direction `d` of cube `cube` (a sampler of type
// CUBE_SHADOW_MAPS); CUBE_READ(cubes, d, cube) reads the texel there (type CUBE_MAPS).
// OpenGL 4.5: cube-map arrays, one cube per light. GLSL ES 3.00 (WebGL2) has none: a cube is
// six layers of a 2D array, layer 6 cube + face, the faces in GL's order (+X -X +Y -Y +Z -Z)
// and each stored as a cube map's face is; a direction is read in the face of its major axis
// at the coordinates of GL's cube map table (OpenGL 4.5, table 8.19). Filtering stops at the
// face's edge, where a cube map's crosses it; taps off the face read the face they reach.
// A call of these macros stays on one line: after a macro call that spans lines, Mesa's error
// messages number every line too low by the lines it spans.
#ifdef GNOMON_GLES
#define CUBE_MAPS sampler2DArray
#define CUBE_SHADOW_MAPS sampler2DArrayShadow
#define CUBE_COMPARE(cubes, d, cube, ref) texture(cubes, vec4(cubeLayerCoord(d, cube), ref))
#define CUBE_READ(cubes, d, cube) texture(cubes, cubeLayerCoord(d, cube))

// The face's (s, t) and the layer of direction `d` in cube `cube`; the major axis ties as
// shadow_lookup.glsl's faceVisibility breaks them.
vec3 cubeLayerCoord(vec3 d, float cube) {
    vec3 a = abs(d);
    float face, major;
    vec2 st;
    if (a.x >= a.y && a.x >= a.z) {  // +-X: s = -+z, t = -y
        face = d.x < 0.0 ? 1.0 : 0.0;
        major = a.x;
        st = vec2(d.x < 0.0 ? d.z : -d.z, -d.y);
    } else if (a.y >= a.z) {  // +-Y: s = x, t = +-z
        face = d.y < 0.0 ? 3.0 : 2.0;
        major = a.y;
        st = vec2(d.x, d.y < 0.0 ? -d.z : d.z);
    } else {  // +-Z: s = +-x, t = -y
        face = d.z < 0.0 ? 5.0 : 4.0;
        major = a.z;
        st = vec2(d.z < 0.0 ? -d.x : d.x, -d.y);
    }
    return vec3(0.5 * st / major + 0.5, 6.0 * cube + face);
}
#else
#define CUBE_MAPS samplerCubeArray
#define CUBE_SHADOW_MAPS samplerCubeArrayShadow
#define CUBE_COMPARE(cubes, d, cube, reference) texture(cubes, vec4(d, cube), reference)
#define CUBE_READ(cubes, d, cube) texture(cubes, vec4(d, cube))
#endif
