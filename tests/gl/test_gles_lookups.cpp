// GLSL ES's stand-ins for what WebGL2 lacks read what OpenGL 4.5's hardware reads: on the
// OpenGL 4.5 context, a shader reads the same texels through the 4.5 lookup and through the ES
// code of cube_access.glsl and texel_gather.glsl (GNOMON_GLES defined), and every pixel must
// agree exactly. Directions and coordinates keep clear of texel edges, where either side's
// rounding may pick the neighbour.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "GlesTest.h"
#include "gl/Objects.h"
#include "gl/ShaderSource.h"

namespace gnomon::test {
namespace {

GLuint compile(GLenum type, const std::string& text) {
    const GLuint shader = glCreateShader(type);
    const char* source = text.c_str();
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    char log[4096] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    EXPECT_EQ(ok, GL_TRUE) << log;
    return shader;
}

// Draws `fragment` (after the ES stand-ins) over a width x height RGBA32F target and returns
// its pixels, four floats each, rows from the bottom.
std::vector<float> drawFullscreen(const std::string& fragment, int width, int height) {
    const std::string header = "#version 450 core\n#define GNOMON_GLES 1\n";
    const GLuint vs =
        compile(GL_VERTEX_SHADER, std::string(gl::embeddedShader("fullscreen.vert.glsl")));
    const GLuint fs = compile(GL_FRAGMENT_SHADER,
                              header + std::string(gl::embeddedShader("cube_access.glsl")) +
                                  std::string(gl::embeddedShader("texel_gather.glsl")) + fragment);
    gl::Program program(glCreateProgram());
    glAttachShader(program.id(), vs);
    glAttachShader(program.id(), fs);
    glLinkProgram(program.id());
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint linked = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &linked);
    EXPECT_EQ(linked, GL_TRUE);
    gl::Texture target = gl::Texture::plain2D("lookups", GL_RGBA32F, width, height);
    gl::Framebuffer fb("lookups");
    glNamedFramebufferTexture(fb.id(), GL_COLOR_ATTACHMENT0, target.id(), 0);
    fb.checkComplete();
    gl::VertexArray empty("lookups");
    glBindFramebuffer(GL_FRAMEBUFFER, fb.id());
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(program.id());
    glBindVertexArray(empty.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    std::vector<float> pixels(std::size_t(4 * width * height));
    glGetTextureImage(target.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(float)),
                      pixels.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return pixels;
}

constexpr int kFace = 8;   // texels along a cube face's side
constexpr int kCubes = 2;  // cubes in the array

// Texel (s, t) of face f of cube c holds a number of its own.
float cubeTexel(int c, int f, int s, int t) {
    return float(1000 * c + 100 * f + kFace * t + s);
}

// A cube-map array and a 2D array holding the same texels, layer 6 cube + face each, read
// NEAREST: each pixel looks up one direction through hardware (x) and cubeLayerCoord (y).
TEST(GlesLookups, CubeLayersReadWhatCubeMapsRead) {
    useNative();
    std::vector<float> texels;
    for (int layer = 0; layer < 6 * kCubes; ++layer) {
        for (int t = 0; t < kFace; ++t) {
            for (int s = 0; s < kFace; ++s)
                texels.push_back(cubeTexel(layer / 6, layer % 6, s, t));
        }
    }
    gl::Texture cubes = gl::Texture::cubeArray("cube texels", GL_R32F, kFace, kCubes);
    gl::Texture layers = gl::Texture::array2D("cube layers", GL_R32F, kFace, kFace, 6 * kCubes);
    for (const gl::Texture* t : {&cubes, &layers}) {
        glTextureSubImage3D(t->id(), 0, 0, 0, 0, kFace, kFace, 6 * kCubes, GL_RED, GL_FLOAT,
                            texels.data());
    }
    gl::Sampler nearest = gl::Sampler::clamped("nearest", GL_NEAREST);
    glBindTextureUnit(0, cubes.id());
    glBindTextureUnit(1, layers.id());
    glBindSampler(0, nearest.id());
    glBindSampler(1, nearest.id());
    // Pixel (x, y): face x / 2N, texel s = x % 2N / 2, cube y / 2N, texel t = y % 2N / 2, and
    // two points in each texel along each axis; the direction through that point of the face
    // by GL's cube map table (OpenGL 4.5, table 8.19), scaled.
    const std::string fragment = R"(
layout(binding = 0) uniform samplerCubeArray uCubes;
layout(binding = 1) uniform sampler2DArray uLayers;
layout(location = 0) out vec4 result;
const int N = )" + std::to_string(kFace) +
                                 R"(;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int face = p.x / (2 * N), cube = p.y / (2 * N);
    vec2 st = (vec2(p % (2 * N) / 2) + 0.25 + 0.5 * vec2(p % 2)) / float(N);
    vec2 c = 2.0 * st - 1.0;  // sc, tc
    vec3 d = face == 0 ? vec3(1.0, -c.y, -c.x) : face == 1 ? vec3(-1.0, -c.y, c.x)
           : face == 2 ? vec3(c.x, 1.0, c.y)   : face == 3 ? vec3(c.x, -1.0, -c.y)
           : face == 4 ? vec3(c.x, -c.y, 1.0)  : vec3(-c.x, -c.y, -1.0);
    d *= 3.7;
    result = vec4(texture(uCubes, vec4(d, cube)).r, CUBE_READ(uLayers, d, float(cube)).r, 0, 1);
}
)";
    const int width = 6 * 2 * kFace, height = kCubes * 2 * kFace;
    const std::vector<float> pixels = drawFullscreen(fragment, width, height);
    int wrong = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float* p = &pixels[std::size_t(4 * (y * width + x))];
            const int face = x / (2 * kFace), cube = y / (2 * kFace);
            const float want = cubeTexel(cube, face, x % (2 * kFace) / 2, y % (2 * kFace) / 2);
            // The hardware reads the texel the table says (so the face images are laid out as
            // the layers are), and the ES code reads the same.
            if (p[0] != want || p[1] != want) {
                if (++wrong <= 5) {
                    ADD_FAILURE() << "cube " << cube << " face " << face << " pixel " << x << ","
                                  << y << ": wanted " << want << ", cube map " << p[0]
                                  << ", layers " << p[1];
                }
            }
        }
    }
    EXPECT_EQ(wrong, 0);
}

// textureGather against the four fetches: of a 2D texture at texel corners (depth_reduce), of
// a layer at texel corners (map_filters) and at bilinear read points, red and alpha
// (transmittance_lookup), up to and past the edges, where both clamp.
TEST(GlesLookups, FetchedGathersMatchGathers) {
    useNative();
    constexpr int kSize = 8, kLayers = 2;
    std::vector<float> texels;
    for (int i = 0; i < kSize * kSize * kLayers; ++i) {
        for (int c = 0; c < 4; ++c)
            texels.push_back(float(i) + 0.25f * float(c));
    }
    gl::Texture layers = gl::Texture::array2D("gathered", GL_RGBA32F, kSize, kSize, kLayers);
    glTextureSubImage3D(layers.id(), 0, 0, 0, 0, kSize, kSize, kLayers, GL_RGBA, GL_FLOAT,
                        texels.data());
    gl::Texture plain = gl::Texture::plain2D("gathered 2D", GL_RGBA32F, kSize, kSize);
    glTextureSubImage2D(plain.id(), 0, 0, 0, kSize, kSize, GL_RGBA, GL_FLOAT, texels.data());
    gl::Sampler nearest = gl::Sampler::clamped("nearest", GL_NEAREST);
    glBindTextureUnit(0, layers.id());
    glBindTextureUnit(1, plain.id());
    glBindSampler(0, nearest.id());
    glBindSampler(1, nearest.id());
    // Pixel (x, y) of layer l: texel corner (i, j) = (x - 1, y - 1) % (N + 1) ... from -1 to
    // N - 1, and a bilinear read point inside the 2x2 from there (a fifth and four fifths of a
    // texel past its centre).
    const std::string fragment = R"(
layout(binding = 0) uniform sampler2DArray uLayers;
layout(binding = 1) uniform sampler2D uPlain;
layout(location = 0) out vec4 result;
const int N = )" + std::to_string(kSize) +
                                 R"(;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 ij = p % (N + 1) - 1;
    float layer = float(p.x / (N + 1));
    vec2 texel = vec2(1.0 / float(N));
    vec2 uv = (vec2(ij) + 0.5 + (p.y / (N + 1) == 0 ? 0.2 : 0.8)) * texel;
    vec3 at = vec3(uv, layer), corner = vec3((vec2(ij) + 1.0) * texel, layer);
    vec4 red = textureGather(uLayers, at, 0) - GATHER_LAYER_AT(uLayers, uv, layer, 0);
    vec4 alpha = textureGather(uLayers, at, 3) - GATHER_LAYER_AT(uLayers, uv, layer, 3);
    vec4 corners = textureGather(uLayers, corner) - GATHER_LAYER(uLayers, vec2(ij), texel.x, layer);
    vec2 plainCorner = vec2(ij.x + 1, ij.y + 1) * texel;
    vec4 plain = textureGather(uPlain, plainCorner) - GATHER_2D(uPlain, ij.x, ij.y, texel);
    vec4 one = vec4(1.0);
    result = vec4(dot(abs(red), one), dot(abs(alpha), one), dot(abs(corners), one),
                  dot(abs(plain), one));
}
)";
    const int width = kLayers * (kSize + 1), height = 2 * (kSize + 1);
    const std::vector<float> pixels = drawFullscreen(fragment, width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float* p = &pixels[std::size_t(4 * (y * width + x))];
            EXPECT_TRUE(p[0] == 0.0f && p[1] == 0.0f && p[2] == 0.0f && p[3] == 0.0f)
                << "pixel " << x << "," << y << ": differences " << p[0] << " " << p[1] << " "
                << p[2] << " " << p[3];
        }
    }
}

}  // namespace
}  // namespace gnomon::test
