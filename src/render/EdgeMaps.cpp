#include "render/EdgeMaps.h"

#include <span>
#include <string>

#include "gl/Caps.h"
#include "gl/Program.h"
#include "gl/State.h"
#include "gnomon/Error.h"

namespace gnomon::render {

bool EdgeMaps::supported() {
    return gl::activeCaps().api == gl::Api::Gl45;
}

bool EdgeMaps::wanted(const ShadowOptions& options) {
    return options.shadowRays == ShadowRayMode::Uncertain && tracesShadowRays(options) &&
           options.casterOutlines && supported();
}

void EdgeMaps::sync(const Scene& scene, const GpuScene& gpu, double seconds) {
    mLines.sync(scene, gpu.geometryHash());
    if (mRevision == gpu.revision()) return;
    mObjects.clear();
    for (const Object& o : scene.objects)
        mObjects.push_back({o.mesh, o.worldFromModelAt(seconds)});
    mDrawnFor.assign(mObjects.size(), 0);
    mDraws = 0;
    mRevision = gpu.revision();
}

void EdgeMaps::allocate(int size, int layers) {
    if (mEdges && mEdges.width() == size && mEdges.layers() == layers) return;
    release();
    mEdges = gl::Texture::array2D("shadow maps' caster outlines", GL_R32UI, size, size, layers);
    if (!mEdges.allocated()) {
        const long long bytes = 4ll * size * size * layers;
        release();
        throw Error(ErrorKind::Gl, "--shadow-rays uncertain: the casters' outline maps need " +
                                       std::to_string(bytes >> 20) +
                                       " MiB, which the OpenGL driver refused; lower --map-size, "
                                       "leave them out (--caster-outlines off) or trace every "
                                       "lookup (--shadow-rays all)");
    }
    mEdges.setParameter(GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    mEdges.setParameter(GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    mTarget = gl::Framebuffer("caster outlines");
    mTarget.emptyOfSize(size, size);
    // Per layer, a framebuffer to clear a map's square through, as the maps' own are cleared.
    for (int layer = 0; layer < layers; ++layer) {
        gl::Framebuffer fb("caster outlines layer " + std::to_string(layer));
        fb.attachLayer(GL_COLOR_ATTACHMENT0, mEdges, layer);
        fb.drawColour0();
        fb.checkComplete();
        mClears.push_back(std::move(fb));
    }
}

void EdgeMaps::release() {
    mClears.clear();
    mTarget = gl::Framebuffer();
    mEdges = gl::Texture();
}

std::size_t EdgeMaps::bytes() const {
    if (!mEdges) return mLines.bytes();
    const std::size_t side = std::size_t(mEdges.width());
    return mLines.bytes() + side * side * 4 * std::size_t(mEdges.layers());
}

void EdgeMaps::draw(const GpuScene& scene, const shadow::FramePlan& plan,
                    const shadow::ShadowedLight& light, const glm::mat4& clipFromWorld) {
    if (!mProgram) {
        mProgram = gl::buildProgram(
            "shadow caster outlines",
            {{GL_VERTEX_SHADER, "edge.vert.glsl"}, {GL_FRAGMENT_SHADER, "edge.frag.glsl"}});
    }
    gl::Framebuffer& clear = mClears[std::size_t(light.layer)];
    glBindFramebuffer(GL_FRAMEBUFFER, clear.id());
    // The map's square, or its whole layer when it fills it (llvmpipe draws a scissored
    // clear as a square, and merely marks a whole one).
    const bool whole = light.mapSize == mEdges.width();
    if (!whole) {
        glEnable(GL_SCISSOR_TEST);
        glScissor(light.origin.x, light.origin.y, light.mapSize, light.mapSize);
    }
    clear.clearUnsignedZero(0);
    if (!whole) glDisable(GL_SCISSOR_TEST);
    gl::imageStoresRead();  // the clear before the stores
    glBindFramebuffer(GL_FRAMEBUFFER, mTarget.id());
    glDisable(GL_CULL_FACE);
    gl::bindImage(2, mEdges, GL_R32UI, GL_READ_WRITE);

    // Where the light is: its camera's eye, or for an orthographic map the way towards it.
    const glm::mat4 worldFromLight = glm::inverse(light.frame.lightFromWorld);
    const glm::vec4 toLight = light.frame.orthographic
                                  ? glm::vec4(glm::vec3(worldFromLight[2]), 0.0f)
                                  : glm::vec4(glm::vec3(worldFromLight[3]), 1.0f);
    gl::use(mProgram);
    gl::uniform(9, glm::vec4(light.origin.x, light.origin.y, light.mapSize, light.mapSize));
    gl::uniform(12, light.layer);
    mLines.bind();
    ++mDraws;
    const std::span<const std::uint32_t> casters(plan.casters().data() + light.firstCaster,
                                                 light.casterCount);
    for (std::uint32_t index : casters) {
        const std::uint32_t object = scene.items()[index].object;
        if (object >= mObjects.size() || mDrawnFor[object] == mDraws) continue;
        mDrawnFor[object] = mDraws;
        const ObjectLines& o = mObjects[object];
        gl::uniform(1, clipFromWorld * o.worldFromModel);
        gl::uniform(10, glm::inverse(o.worldFromModel) * toLight);
        mLines.draw(o.mesh);
    }
    gl::imageStoresDone();
    gl::unbindImage(2, GL_R32UI);
}

}  // namespace gnomon::render
