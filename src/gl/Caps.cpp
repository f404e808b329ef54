#include "gl/Caps.h"

#include <cstring>
#include <set>
#include <string>

#include "gl/Gl.h"

namespace gnomon::gl {
namespace {

int integer(GLenum name) {
    GLint value = 0;
    glGetIntegerv(name, &value);
    return int(value);
}

// The context's extensions by name ("GL_EXT_depth_clamp"; a browser's WebGL extensions
// have the same "GL_" names in Emscripten).
std::set<std::string> extensions() {
    std::set<std::string> out;
    for (int i = 0, n = integer(GL_NUM_EXTENSIONS); i < n; ++i) {
        const GLubyte* name = glGetStringi(GL_EXTENSIONS, GLuint(i));
        if (name) out.insert(reinterpret_cast<const char*>(name));
    }
    return out;
}

bool isEs() {
    const GLubyte* version = glGetString(GL_VERSION);
    return version && std::strncmp(reinterpret_cast<const char*>(version), "OpenGL ES", 9) == 0;
}

const Caps kGl45{};
thread_local const Caps* tActive = nullptr;

}  // namespace

Caps queryCaps() {
    Caps c;
    const std::set<std::string> all = extensions();
    auto has = [&](const char* name) { return all.count(name) > 0; };
    c.api = isEs() ? Api::Gles3 : Api::Gl45;
    c.maxUniformBlockSize = integer(GL_MAX_UNIFORM_BLOCK_SIZE);
    c.maxTextureSize = integer(GL_MAX_TEXTURE_SIZE);
    c.maxArrayLayers = integer(GL_MAX_ARRAY_TEXTURE_LAYERS);
    c.debugLabels = has("GL_KHR_debug");
    if (c.api == Api::Gl45) {
        c.maxTextureBufferSize = integer(GL_MAX_TEXTURE_BUFFER_SIZE);
        c.layeredFromVertex = has("GL_ARB_shader_viewport_layer_array");
        c.pipelineStatistics = has("GL_ARB_pipeline_statistics_query");
        return c;
    }
    // WebGL2's set: what ES 3.1/3.2 add beyond 3.0 is not used, so that Mesa's ES context
    // runs exactly the browser's path.
    c.directStateAccess = c.cubeMapArrays = c.textureBuffers = c.textureViews = false;
    c.textureGather = c.imageStore = c.drawIndirect = c.clearTexture = false;
    c.textureReadback = c.srgbWriteControl = c.norm16 = c.seamlessCubes = false;
    c.maxTextureBufferSize = 0;
    c.depthClamp = has("GL_EXT_depth_clamp");
    c.multiDraw = has("GL_ANGLE_multi_draw") || has("GL_WEBGL_multi_draw");
    c.floatTargets = has("GL_EXT_color_buffer_float");
    c.floatLinear = has("GL_OES_texture_float_linear");
    return c;
}

std::string currentGlInfo() {
    auto str = [](GLenum e) {
        const GLubyte* s = glGetString(e);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    return str(GL_VENDOR) + " / " + str(GL_RENDERER) + " / " + str(GL_VERSION);
}

const Caps& activeCaps() {
    return tActive ? *tActive : kGl45;
}

void activate(const Caps* caps) {
    tActive = caps;
}

}  // namespace gnomon::gl
