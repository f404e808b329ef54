// What the current OpenGL context can do, read once when a renderer opens it: the seam
// between the two targets gnomon draws on. OpenGL 4.5 core (native) has every feature below;
// OpenGL ES 3.0 as WebGL2 exposes it (the browser, and Mesa's ES context in the tests) lacks
// most, and the wrappers in src/gl and the passes choose their path from these flags instead
// of from #ifdefs. An ES 3.1/3.2 context is treated as WebGL2: only what WebGL2 offers counts.
#pragma once

#include <string>

namespace gnomon::gl {

enum class Api { Gl45, Gles3 };

struct Caps {
    Api api = Api::Gl45;
    // Features of OpenGL 4.5 core that ES 3.0 lacks.
    bool directStateAccess = true;  // glCreate*/glNamed*: objects edited without binding
    bool cubeMapArrays = true;      // else cubes are 2D arrays of 6 layers per cube
    bool textureBuffers = true;     // samplerBuffer; else 2D data textures
    bool textureViews = true;
    bool textureGather = true;
    bool imageStore = true;        // image stores in fragment shaders (gnomon score)
    bool drawIndirect = true;      // multi-draw indirect with base vertex and base instance
    bool clearTexture = true;      // glClearTexImage
    bool textureReadback = true;   // glGetTextureImage
    bool srgbWriteControl = true;  // GL_FRAMEBUFFER_SRGB
    bool norm16 = true;            // RGBA16 colour targets
    bool seamlessCubes = true;     // GL_TEXTURE_CUBE_MAP_SEAMLESS is a switch (ES: always on)
    // Extensions, on either API.
    bool layeredFromVertex = false;   // gl_Layer written by a vertex shader
    bool pipelineStatistics = false;  // fragment shader invocations per pass
    bool debugLabels = false;         // KHR_debug object labels and messages
    bool depthClamp = true;           // GL_DEPTH_CLAMP (ES: EXT_depth_clamp)
    bool multiDraw = false;           // ES: ANGLE/WEBGL multi_draw with gl_DrawID
    bool floatTargets = true;         // render to 32F colour (ES: EXT_color_buffer_float)
    bool floatLinear = true;          // filter 32F textures (ES: OES_texture_float_linear)
    // Limits.
    int maxUniformBlockSize = 16384;
    int maxTextureSize = 2048;
    int maxArrayLayers = 256;
    int maxTextureBufferSize = 65536;  // texels; 0 without texture buffers
};

// The capabilities of the context current on this thread.
Caps queryCaps();
// "vendor / renderer / version" of the current context.
std::string currentGlInfo();

// The capabilities the src/gl wrappers follow on this thread: those given to the last
// activate() here, or OpenGL 4.5's when none was (nothing to ask, tests' own contexts).
const Caps& activeCaps();
// A renderer activates its context's capabilities whenever it makes the context current;
// `caps` must outlive the activation (nullptr: back to OpenGL 4.5's).
void activate(const Caps* caps);

// One context's capabilities, read when made (the context current) and activated on this
// thread until destroyed or another is activated; a renderer holds one beside its context.
class ContextCaps {
public:
    ContextCaps() : mCaps(queryCaps()) { gl::activate(&mCaps); }
    ~ContextCaps() {
        if (&activeCaps() == &mCaps) gl::activate(nullptr);
    }
    ContextCaps(const ContextCaps&) = delete;
    ContextCaps& operator=(const ContextCaps&) = delete;
    const Caps& get() const { return mCaps; }
    void activate() const { gl::activate(&mCaps); }

private:
    Caps mCaps;
};

}  // namespace gnomon::gl
