#include "render/DebugPass.h"

#include <algorithm>

#include "gl/Program.h"

namespace gnomon::render {

namespace {
const char* packDefine(DepthFormat f) {
    switch (f) {
        case DepthFormat::R8:
            return "PACK_R8";
        case DepthFormat::Rgba8Packed256:
            return "PACK_256";
        case DepthFormat::Rgba8Packed255:
            return "PACK_255";
        default:
            return nullptr;
    }
}

// Distinct colours for up to eight lights, then repeating.
glm::vec3 lightColour(int light) {
    static const glm::vec3 kColours[8] = {
        {1.0f, 0.9f, 0.2f},  {0.2f, 0.9f, 1.0f}, {1.0f, 0.4f, 0.9f}, {0.4f, 1.0f, 0.4f},
        {1.0f, 0.55f, 0.2f}, {0.6f, 0.6f, 1.0f}, {1.0f, 0.3f, 0.3f}, {0.9f, 0.9f, 0.9f}};
    return kColours[light % 8];
}
}  // namespace

const gl::Program& DebugPass::mapsProgram(DepthFormat format) {
    auto it = mMapsPrograms.find(format);
    if (it == mMapsPrograms.end()) {
        std::vector<std::string> defines;
        if (const char* d = packDefine(format)) defines.push_back(d);
        it = mMapsPrograms
                 .emplace(format, gl::buildProgram(std::string("debug maps ") + toString(format),
                                                   {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                                    {GL_FRAGMENT_SHADER, "debug_maps.frag.glsl"}},
                                                   defines))
                 .first;
    }
    return it->second;
}

bool DebugPass::drawMaps(const ShadowPass& maps, const std::vector<ShadowedLight>& shadowed,
                         int light, int width, int height) {
    // This light's maps: one, its cascades, or its cube's six faces.
    float panels[24];  // per panel: layer, share of the layer the map covers, its origin
    int count = 0;
    bool cube = false;
    for (const ShadowedLight& sl : shadowed) {
        if (sl.light != light || count >= 6) continue;
        cube = sl.frame.kind == shadow::FrameKind::Cube;
        if (cube) {
            for (int face = 0; face < 6; ++face) {
                const float share = float(sl.mapSize) / float(maps.cubes().width());
                const float panel[4] = {float(6 * sl.layer + face), share, 0.0f, 0.0f};
                std::copy(panel, panel + 4, panels + 4 * face);
            }
            count = 6;
            break;
        }
        const float size = float(maps.mapArraySize());
        const float panel[4] = {float(sl.layer), float(sl.mapSize) / size,
                                float(sl.origin.x) / size, float(sl.origin.y) / size};
        std::copy(panel, panel + 4, panels + 4 * count);
        ++count;
    }
    if (count == 0) return false;
    const int columns = cube ? 3 : count, rows = cube ? 2 : 1;
    const float panel = std::min(float(width) / float(columns), float(height) / float(rows));
    const float x0 = 0.5f * (float(width) - panel * float(columns));
    const float y0 = 0.5f * (float(height) - panel * float(rows));

    const gl::Texture* texture = &maps.maps();
    DepthFormat format = maps.mapFormat();
    if (cube) {
        texture = &maps.cubes();  // already a 2D array where there are no cube-map arrays
        if (maps.cubes().target() != GL_TEXTURE_2D_ARRAY) {
            if (!mCubeView || mCubeViewSource != maps.cubes().id() ||
                mCubeView.layers() != maps.cubes().layers()) {
                mCubeView = gl::Texture::layersView("point shadow cubes as layers", maps.cubes());
                mCubeViewSource = maps.cubes().id();
            }
            texture = &mCubeView;
        }
        format = DepthFormat::Depth32F;  // cubes are always native depth
    }
    if (!mRawSampler) mRawSampler = gl::Sampler::storedDepth("debug maps sampler");
    if (!mEmpty) mEmpty = gl::VertexArray("fullscreen (no attributes)");
    gl::use(mapsProgram(format));
    gl::uniform(0, glm::ivec2(columns, rows));
    gl::uniform(1, glm::vec3(x0, y0, panel));
    gl::uniform(2, count);
    gl::uniform(3, std::span<const float>(panels, std::size_t(4 * count)), 4);
    gl::bindTexture(0, *texture);
    glBindSampler(0, mRawSampler.id());
    glDisable(GL_DEPTH_TEST);
    glBindVertexArray(mEmpty.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindSampler(0, 0);
    glEnable(GL_DEPTH_TEST);
    return true;
}

void DebugPass::drawFrusta(const std::vector<ShadowedLight>& shadowed,
                           const glm::mat4& clipFromWorld) {
    mLineData.clear();
    auto box = [&](const std::array<glm::vec3, 8>& c, const glm::vec3& colour) {
        // Corners numbered by x, y, z bits: edges join those differing in one bit.
        for (int i = 0; i < 8; ++i) {
            for (int bit = 1; bit < 8; bit <<= 1) {
                if (i & bit) continue;
                mLineData.insert(mLineData.end(),
                                 {c[size_t(i)], colour, c[size_t(i | bit)], colour});
            }
        }
    };
    for (const ShadowedLight& sl : shadowed) {
        const glm::vec3 colour = lightColour(sl.light) * (sl.cascade > 0 ? 0.7f : 1.0f);
        std::array<glm::vec3, 8> corners;
        if (sl.frame.kind == shadow::FrameKind::Cube) {
            // The six faces' frusta together: a cube of half-size `far` around the light.
            const glm::vec3 eye = glm::vec3(glm::inverse(sl.frame.lightFromWorld)[3]);
            for (int i = 0; i < 8; ++i) {
                corners[size_t(i)] =
                    eye + sl.frame.far * glm::vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
            }
        } else {
            const glm::mat4 worldFromClip = glm::inverse(sl.frame.clipFromWorld());
            for (int i = 0; i < 8; ++i) {
                const glm::vec4 p =
                    worldFromClip * glm::vec4(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1, 1.0f);
                corners[size_t(i)] = glm::vec3(p) / p.w;
            }
        }
        box(corners, colour);
    }
    if (mLineData.empty()) return;
    const std::size_t bytes = mLineData.size() * sizeof(glm::vec3);
    if (!mLineBuffer || mLineBuffer.size() < bytes) {
        mLineBuffer = gl::Buffer("debug lines", bytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
        mLines = gl::VertexArray("debug lines");
        mLines.vertexBuffer(0, mLineBuffer, 0, 2 * sizeof(glm::vec3));
        for (int a = 0; a < 2; ++a)
            mLines.attribute(a, 0, 3, GL_FLOAT, std::size_t(a) * sizeof(glm::vec3));
    }
    mLineBuffer.update(0, bytes, mLineData.data());
    if (!mLinesProgram) {
        mLinesProgram =
            gl::buildProgram("debug lines", {{GL_VERTEX_SHADER, "debug_lines.vert.glsl"},
                                             {GL_FRAGMENT_SHADER, "debug_lines.frag.glsl"}});
    }
    gl::use(mLinesProgram);
    gl::uniform(0, clipFromWorld);
    glDisable(GL_DEPTH_TEST);  // volumes show through the scene
    glBindVertexArray(mLines.id());
    glDrawArrays(GL_LINES, 0, GLsizei(mLineData.size() / 2));
    glEnable(GL_DEPTH_TEST);
}

}  // namespace gnomon::render
