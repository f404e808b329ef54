// Every program the renderer builds, compiled and linked in the GLSL ES 3.00 dialect by
// Mesa's OpenGL ES context (whose `#version 300 es` compiler is strict: what it accepts is
// WebGL2's language, less the browser's own validation). After linking, each uniform location,
// sampler unit and block binding the assembler removed must be where the shaders' layouts put
// it, active exactly where the same program built for OpenGL 4.5 has it active.
//
// The families mirror the passes' program() functions (ShadowPass, ViewDepthPass,
// TransmittancePass, MomentPass, DebugPass); the main pass's variants come from MainVariant
// itself. WebGL2 cannot have depth_cube.vert (a vertex shader's gl_Layer; the six-pass
// fallback draws cubes there), named in WebGL2Lacks below; the main pass's VISIBILITY_PASS
// writes colour outputs there instead of images.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <sstream>

#include "GlesTest.h"
#include "gl/Program.h"
#include "gl/ShaderSource.h"
#include "gnomon/Error.h"
#include "render/MainVariant.h"
#include "shadow/LightRecord.h"

namespace gnomon::test {
namespace {

struct Spec {
    std::string label;
    std::vector<gl::Stage> stages;
    std::vector<std::string> defines;
};

// What a program has active, by the names the shaders' layouts gave fixed slots.
struct Active {
    std::set<std::string> uniforms, samplers, blocks;
};

Active activeIn(const gl::Program& p, const std::vector<gl::AssembledSource>& sources) {
    Active a;
    for (const gl::AssembledSource& s : sources) {
        for (const gl::FixedSlot& f : s.locations) {
            if (glGetUniformLocation(p.id(), f.name.c_str()) >= 0) a.uniforms.insert(f.name);
        }
        for (const gl::FixedSlot& f : s.samplers) {
            if (glGetUniformLocation(p.id(), f.name.c_str()) >= 0) a.samplers.insert(f.name);
        }
        for (const gl::FixedSlot& f : s.blocks) {
            if (glGetUniformBlockIndex(p.id(), f.name.c_str()) != GL_INVALID_INDEX) {
                a.blocks.insert(f.name);
            }
        }
    }
    return a;
}

// Builds `spec` in both dialects and checks the ES program's slots against the layouts.
void checkProgram(const Spec& spec) {
    SCOPED_TRACE(spec.label);
    const gl::Dialect es = gl::dialectOf(esCaps());
    std::vector<gl::AssembledSource> sources;
    for (const gl::Stage& stage : spec.stages)
        sources.push_back(gl::assembleShader(stage.file, spec.defines, es));
    // What OpenGL 4.5 has active, by the names of the ES tables (the 4.5 text has the same
    // declarations); its program is deleted while its context is current. The records'
    // uDrawBase is GLSL ES's own; the shadow rays' start table, read by gl_PrimitiveID, is
    // OpenGL 4.5's (render/DrawnTriangles.h).
    Active wanted;
    {
        useNative();
        const gl::Program native = gl::buildProgram(spec.label, spec.stages, spec.defines);
        wanted = activeIn(native, sources);
    }
    wanted.samplers.erase("uRayStarts");
    // --shadow-rays uncertain numbers its ray jobs per API (render/RayMarks.h): on OpenGL 4.5
    // the marks pass lists them where their answers will lie (uRayPyramidSize) and the second
    // draw reads the answers at their pixels (uRayAnswers); on ES the pyramid's passes number
    // them and the second draw reads the answers through it.
    if (spec.label == "shadow-ray marks") wanted.uniforms.erase("uRayPyramidSize");
    if (std::find(spec.defines.begin(), spec.defines.end(), "SHADOW_RAYS_RESOLVE") !=
        spec.defines.end()) {
        wanted.samplers.erase("uRayAnswers");
        wanted.samplers.insert("uRayPyramid");
        wanted.uniforms.insert("uRayPyramidSize");
    }
    for (const gl::AssembledSource& s : sources) {
        if (std::find(s.locations.begin(), s.locations.end(),
                      gl::FixedSlot{gl::kDrawBaseLocation, "uDrawBase"}) != s.locations.end()) {
            wanted.uniforms.insert("uDrawBase");
        }
    }
    useEs();
    gl::Program p;
    try {
        p = gl::buildProgram(spec.label, spec.stages, spec.defines);
    } catch (const Error& e) {
        ADD_FAILURE() << e.what();
        return;
    }
    EXPECT_EQ(p.api(), gl::Api::Gles3);
    const Active got = activeIn(p, sources);
    EXPECT_EQ(got.uniforms, wanted.uniforms);
    EXPECT_EQ(got.samplers, wanted.samplers);
    EXPECT_EQ(got.blocks, wanted.blocks);
    for (const gl::AssembledSource& s : sources) {
        for (const gl::FixedSlot& f : s.locations) {
            const GLint location = glGetUniformLocation(p.id(), f.name.c_str());
            if (location >= 0) {
                EXPECT_EQ(p.location(f.slot), location) << f.name;
            }
        }
        for (const gl::FixedSlot& f : s.samplers) {
            const GLint location = glGetUniformLocation(p.id(), f.name.c_str());
            if (location < 0) continue;
            GLint unit = -1;
            glGetUniformiv(p.id(), location, &unit);
            EXPECT_EQ(unit, f.slot) << f.name;
        }
        for (const gl::FixedSlot& f : s.blocks) {
            const GLuint index = glGetUniformBlockIndex(p.id(), f.name.c_str());
            if (index == GL_INVALID_INDEX) continue;
            GLint binding = -1;
            glGetActiveUniformBlockiv(p.id(), index, GL_UNIFORM_BLOCK_BINDING, &binding);
            EXPECT_EQ(binding, f.slot) << f.name;
        }
    }
    // A location no active uniform holds stays -1, which glUniform* ignores.
    for (int fixed = 0; fixed < gl::kFixedLocations; ++fixed) {
        bool named = false;
        for (const gl::AssembledSource& s : sources) {
            for (const gl::FixedSlot& f : s.locations)
                named = named || (f.slot == fixed && got.uniforms.count(f.name) > 0);
        }
        if (!named) {
            EXPECT_EQ(p.location(fixed), -1) << "location " << fixed;
        }
    }
}

const gl::Stage kDepthVert{GL_VERTEX_SHADER, "depth.vert.glsl"};
const gl::Stage kFullscreen{GL_VERTEX_SHADER, "fullscreen.vert.glsl"};

// ShadowPass::program: depth.vert with depth.frag (native depth) or depth_colour.frag (the
// packed formats), each plain, alpha-tested, or alpha-tested with blended casters' opaque parts.
TEST(GlesPrograms, ShadowPass) {
    for (const char* packing : {"", "PACK_R8", "PACK_256", "PACK_255"}) {
        const std::string frag = *packing ? "depth_colour.frag.glsl" : "depth.frag.glsl";
        for (int alpha = 0; alpha < 3; ++alpha) {
            std::vector<std::string> d;
            if (alpha > 0) d.push_back("ALPHA_TEST");
            if (alpha > 1) d.push_back("BLEND_OPAQUE_PARTS");
            if (*packing) d.push_back(packing);
            checkProgram({"shadow depth", {kDepthVert, {GL_FRAGMENT_SHADER, frag}}, d});
        }
    }
}

// ViewDepthPass::program and ::reduce; TransmittancePass::program.
TEST(GlesPrograms, ViewDepthAndTransmittancePasses) {
    const gl::Stage depthFrag{GL_FRAGMENT_SHADER, "depth.frag.glsl"};
    checkProgram({"view depth", {kDepthVert, depthFrag}, {"VIEW_CAMERA"}});
    checkProgram({"view depth alpha", {kDepthVert, depthFrag}, {"VIEW_CAMERA", "ALPHA_TEST"}});
    checkProgram({"view depth reduction",
                  {kFullscreen, {GL_FRAGMENT_SHADER, "depth_reduce.frag.glsl"}},
                  {}});
    checkProgram({"transmittance",
                  {kDepthVert, {GL_FRAGMENT_SHADER, "transmittance.frag.glsl"}},
                  {"ALPHA_TEST", "TRANSMITTANCE"}});
}

// The BVH's rays (bench/gpu_trace_bench.cpp; shadow rays in the shader later): WebGL2 too.
TEST(GlesPrograms, BvhRays) {
    checkProgram({"bvh rays", {kFullscreen, {GL_FRAGMENT_SHADER, "bvh_rays.frag.glsl"}}, {}});
}

// MomentPass::program: each moment filter's rows and columns passes, without and with a blur.
TEST(GlesPrograms, MomentPass) {
    for (const char* filter : {"MOMENTS_EVSM2", "MOMENTS_EVSM4", "MOMENTS_MSM"}) {
        for (int radius : {0, 2}) {
            for (bool rows : {true, false}) {
                std::vector<std::string> d = {filter, "MOMENT_RADIUS " + std::to_string(radius)};
                if (rows) d.push_back("ROWS");
                checkProgram(
                    {"moments", {kFullscreen, {GL_FRAGMENT_SHADER, "moments.frag.glsl"}}, d});
            }
        }
    }
}

// DebugPass: the maps view in each depth encoding, and the frusta's lines.
TEST(GlesPrograms, DebugPass) {
    for (const char* packing : {"", "PACK_R8", "PACK_256", "PACK_255"}) {
        std::vector<std::string> d;
        if (*packing) d.push_back(packing);
        checkProgram(
            {"debug maps", {kFullscreen, {GL_FRAGMENT_SHADER, "debug_maps.frag.glsl"}}, d});
    }
    checkProgram({"debug lines",
                  {{GL_VERTEX_SHADER, "debug_lines.vert.glsl"},
                   {GL_FRAGMENT_SHADER, "debug_lines.frag.glsl"}},
                  {}});
}

// The main pass's light count for the ES context, as MainPass sizes its light block.
int maxLights() {
    return std::min(256, esCaps().maxUniformBlockSize / int(sizeof(GpuLight)));
}

void checkMain(const render::MainVariant& v) {
    checkProgram({"main [" + v.label() + "]",
                  {{GL_VERTEX_SHADER, "main.vert.glsl"}, {GL_FRAGMENT_SHADER, "main.frag.glsl"}},
                  v.defines(maxLights())});
}

// The frame's inputs as MainPass::program sets them: cubes or point faces, cascades, contact
// and coloured shadows.
render::MainVariant frameVariant(const RenderOptions& o, bool pointFaces, bool material) {
    render::MainVariant v = render::variantOf(o, /*floor=*/false, /*receiverOnly=*/false);
    v.material = material;
    v.contactShadows = 1;
    v.coloured = 1;
    v.hasCubes = !pointFaces;
    v.pointFaces = pointFaces;
    v.hasCascades = 1;
    return v;
}

const ShadowFilter kFilters[] = {ShadowFilter::None,    ShadowFilter::Hw2x2, ShadowFilter::Pcf,
                                 ShadowFilter::Poisson, ShadowFilter::Pcss,  ShadowFilter::Evsm2,
                                 ShadowFilter::Evsm4,   ShadowFilter::Msm};

// Every filter with every kind of light and both shadow extras: with the receiver plane and
// cube maps, then without it and with point lights' faces as maps and the material path.
TEST(GlesPrograms, MainPassFilters) {
    for (ShadowFilter filter : kFilters) {
        for (bool plane : {true, false}) {
            RenderOptions o;
            o.shadow.filter = filter;
            o.shadow.receiverPlane = plane;
            checkMain(frameVariant(o, /*pointFaces=*/!plane, /*material=*/!plane));
        }
    }
}

// The hand-compared lookups: the packed colour formats, and --filter none on native depth
// under each --map-filter.
TEST(GlesPrograms, MainPassHandCompare) {
    for (DepthFormat format :
         {DepthFormat::R8, DepthFormat::Rgba8Packed256, DepthFormat::Rgba8Packed255}) {
        for (ShadowFilter filter : {ShadowFilter::Pcf, ShadowFilter::Hw2x2}) {
            RenderOptions o;
            o.shadow.depthFormat = format;
            o.shadow.filter = filter;
            checkMain(frameVariant(o, false, false));
        }
    }
    for (MapFilter mapFilter : {MapFilter::Nearest, MapFilter::Linear}) {
        RenderOptions o;
        o.shadow.filter = ShadowFilter::None;
        o.shadow.mapFilter = mapFilter;
        checkMain(frameVariant(o, false, false));
    }
}

// The rest of the choices: receiver-only objects, normal offset, stand-ins, the debug tint,
// dithering, the shadowed rule, outside clamp, no shadows, the floor, light kinds and falloff,
// and unrolled light loops.
TEST(GlesPrograms, MainPassChoices) {
    RenderOptions o;
    o.shadow.normalOffset = 1.0f;
    o.shadow.casterDetail = 0.5f;
    o.shadow.outside = OutsidePolicy::Clamp;
    o.shading.output = OutputEncoding::Srgb;
    o.shading.shadowedRule = ShadowedRule::Factor;
    o.debugView = DebugView::Cascades;
    checkMain(frameVariant(o, false, true));

    render::MainVariant receiverOnly = render::variantOf(RenderOptions{}, false, true);
    receiverOnly.hasCubes = receiverOnly.hasCascades = 1;
    checkMain(receiverOnly);

    RenderOptions off;
    off.shadow.enabled = false;
    off.shading.dither = false;
    checkMain(render::variantOf(off, false, false));

    render::MainVariant floor = render::variantOf(RenderOptions{}, true, false);
    floor.hasCascades = 1;
    checkMain(floor);

    render::MainVariant unrolled = frameVariant(RenderOptions{}, false, false);
    unrolled.constantFalloff = unrolled.noSpecular = 1;
    unrolled.singleMapKind = 2;  // every single map a spot's
    unrolled.unrolled = 1;
    unrolled.unshadowedCount = 1;
    unrolled.mapCount = 2;
    unrolled.cubeCount = 1;
    unrolled.cascadedCount = 1;
    checkMain(unrolled);
}

// Shadow rays in place of every kind's lookup (a soft filter's and a moment filter's too),
// with the frame's extras, for a receiver-only object and the floor; and after the maps'
// lookups where they are unsure.
TEST(GlesPrograms, MainPassShadowRays) {
    for (ShadowFilter filter : {ShadowFilter::Pcf, ShadowFilter::Pcss, ShadowFilter::Msm}) {
        for (bool faces : {false, true}) {
            RenderOptions o;
            o.shadow.filter = filter;
            o.shadow.shadowRays = ShadowRayMode::All;
            o.shadow.receiverPlane = !faces;
            checkMain(frameVariant(o, faces, faces));
        }
    }
    // Rays where the maps are unsure, with the debug view's tint; the floor's lookups too.
    for (ShadowFilter filter : {ShadowFilter::Pcf, ShadowFilter::None, ShadowFilter::Poisson}) {
        RenderOptions o;
        o.shadow.filter = filter;
        o.shadow.shadowRays = ShadowRayMode::Uncertain;
        o.debugView = DebugView::Rays;
        checkMain(frameVariant(o, true, false));
        checkMain(render::variantOf(o, true, false));
        // The first draw, which marks where rays must decide (render/RayMarks.h).
        render::MainVariant marks = frameVariant(o, false, false);
        marks.shadowRays = render::MainVariant::kRaysMarked;
        checkMain(marks);
        // The second, which reads the rays' answers; with more lights than a job holds.
        render::MainVariant resolve = frameVariant(o, false, false);
        resolve.raysResolve = 1;
        checkMain(resolve);
        resolve.rayOverflow = 1;
        checkMain(resolve);
    }
    checkProgram(
        {"shadow-ray marks", {kFullscreen, {GL_FRAGMENT_SHADER, "ray_marks.frag.glsl"}}, {}});
    checkProgram({"shadow-ray pyramid (marks)",
                  {kFullscreen, {GL_FRAGMENT_SHADER, "ray_pyramid.frag.glsl"}},
                  {"LEVEL_ONE"}});
    checkProgram({"shadow-ray pyramid (counts)",
                  {kFullscreen, {GL_FRAGMENT_SHADER, "ray_pyramid.frag.glsl"}},
                  {}});
    checkProgram(
        {"shadow rays of the marked pixels",
         {{GL_VERTEX_SHADER, "ray_trace.vert.glsl"}, {GL_FRAGMENT_SHADER, "ray_trace.frag.glsl"}},
         {"MAX_LIGHTS " + std::to_string(maxLights()), "ORDER_SLOTS 1024"}});
    RenderOptions o;
    o.shadow.shadowRays = ShadowRayMode::All;
    render::MainVariant receiverOnly = render::variantOf(o, false, true);
    receiverOnly.hasCubes = receiverOnly.hasCascades = 1;
    checkMain(receiverOnly);
    render::MainVariant floor = render::variantOf(o, true, false);
    floor.hasCascades = 1;
    checkMain(floor);
}

// The line of `file` that starts with `start` (1-based; 0: none).
int lineStarting(const std::string& file, const std::string& start) {
    std::istringstream in{std::string(gl::embeddedShader(file))};
    int n = 1;
    for (std::string line; std::getline(in, line); ++n) {
        if (line.rfind(start, 0) == 0) return n;
    }
    return 0;
}

// What WebGL2 cannot have fails where it is asked for: gl_Layer's extension; the image atomics
// of the shadow rays' list (render/RayMarks.h numbers them in a pyramid there).
TEST(GlesPrograms, WebGL2Lacks) {
    useEs();
    EXPECT_THROW(gl::buildProgram("shadow-ray list",
                                  {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                   {GL_FRAGMENT_SHADER, "ray_list.frag.glsl"}},
                                  {"AT_NEAR"}),
                 Error);
    // The casters' outlines (render/EdgeMaps.h) store with an image atomic.
    EXPECT_THROW(
        gl::buildProgram("shadow caster outlines", {{GL_VERTEX_SHADER, "edge.vert.glsl"},
                                                    {GL_FRAGMENT_SHADER, "edge.frag.glsl"}}),
        Error);
    try {
        gl::buildProgram("shadow depth cube", {{GL_VERTEX_SHADER, "depth_cube.vert.glsl"}});
        ADD_FAILURE() << "depth_cube.vert compiled in GLSL ES: build it there too";
    } catch (const Error& e) {
        const int line = lineStarting("depth_cube.vert.glsl", "#extension");
        EXPECT_NE(std::string(e.what()).find("depth_cube.vert.glsl:" + std::to_string(line)),
                  std::string::npos)
            << e.what();
    }
}

// gnomon score's visibility pass without image stores: one light a pass into colour outputs,
// the recorded light a uniform (MainPass::recordVisibilityByLight), with and without tint.
TEST(GlesPrograms, VisibilityPassByLight) {
    useEs();
    for (bool coloured : {false, true}) {
        render::MainVariant v = frameVariant(RenderOptions{}, false, true);
        v.visibilityPass = 1;
        v.coloured = coloured;
        const gl::Program p = gl::buildProgram(
            "visibility",
            {{GL_VERTEX_SHADER, "main.vert.glsl"}, {GL_FRAGMENT_SHADER, "main.frag.glsl"}},
            v.defines(maxLights()));
        EXPECT_GE(p.location(15), 0) << "uRecordLight";
        EXPECT_EQ(glGetFragDataLocation(p.id(), "fVisibility"), 1);
        EXPECT_EQ(glGetFragDataLocation(p.id(), "fTint"), coloured ? 2 : -1);
    }
}

// A driver error deep in the includes of a large variant names its file and line in ES text
// too (the dialect's lines and rewrites keep the line map).
TEST(GlesPrograms, DriverErrorNamesItsLine) {
    useEs();
    render::MainVariant v = frameVariant(RenderOptions{}, false, true);
    std::vector<std::string> d = v.defines(maxLights());
    d.push_back("uEye )");  // declared in main.frag.glsl after all its includes
    try {
        gl::buildProgram("broken", {{GL_FRAGMENT_SHADER, "main.frag.glsl"}}, d);
        ADD_FAILURE() << "the program must not compile";
    } catch (const Error& e) {
        const int line = lineStarting("main.frag.glsl", "layout(location = 5) uniform vec3 uEye");
        ASSERT_GT(line, 0);
        EXPECT_NE(std::string(e.what()).find("main.frag.glsl:" + std::to_string(line)),
                  std::string::npos)
            << e.what();
    }
}

// Every root shader is in a program above or in WebGL2Lacks: a new one needs a test here.
TEST(GlesPrograms, EveryRootShaderIsBuilt) {
    const std::set<std::string> built = {
        "depth.vert.glsl",       "depth.frag.glsl",        "depth_colour.frag.glsl",
        "fullscreen.vert.glsl",  "depth_reduce.frag.glsl", "transmittance.frag.glsl",
        "moments.frag.glsl",     "debug_maps.frag.glsl",   "debug_lines.vert.glsl",
        "debug_lines.frag.glsl", "main.vert.glsl",         "main.frag.glsl",
        "depth_cube.vert.glsl",  "bvh_rays.frag.glsl",     "ray_marks.frag.glsl",
        "ray_pyramid.frag.glsl", "ray_trace.vert.glsl",    "ray_trace.frag.glsl",
        "ray_list.frag.glsl",    "edge.vert.glsl",         "edge.frag.glsl"};
    for (const std::string& name : gl::embeddedShaderNames()) {
        if (name.ends_with(".vert.glsl") || name.ends_with(".frag.glsl")) {
            EXPECT_EQ(built.count(name), 1u) << name;
        }
    }
}

}  // namespace
}  // namespace gnomon::test
