// Coloured shadows (--blend-shadows coloured): beside each light's depth map, a transmittance
// map of the same layout (a layer or square per 2D map, six faces per cube) that holds, per
// texel, the product of the transmittance of the blended casters in front of the opaque
// depth, and the depth of the nearest of them. The blended casters are drawn after the
// shadow pass with that map's depth as a read-only depth test and multiplicative blending, so
// their order does not matter (the approach of Wicked Engine's "Easy transparent shadow maps",
// Turánszki 2018); the depth, kept by a MIN blend in alpha, lets receivers in front of the
// glass stay untinted. RGBA16: colour and depth in 16 bits each.
#pragma once

#include <vector>

#include "gl/Objects.h"
#include "gnomon/Options.h"
#include "render/ShadowPass.h"

namespace gnomon::render {

class PassClock;

class TransmittancePass {
public:
    // Draws the blended casters into the transmittance of every map the shadow pass drew this
    // frame (`drawn`: indices into `lights`), or of every map when the arrays are new.
    // With `clock`, each map is timed into `timings`. Returns the maps drawn.
    int update(const GpuScene& scene, const ShadowPass& pass,
               const std::vector<ShadowedLight>& lights, const std::vector<int>& drawn,
               const ShadowOptions& options, PassClock* clock, std::vector<PassTiming>* timings);
    // Frees the maps (nothing reads them).
    void release();
    const gl::Texture& maps() const { return mMaps; }
    const gl::Texture& cubes() const { return mCubes; }
    std::size_t bytes() const;

private:
    void allocate(const ShadowPass& pass);
    void drawLight(const GpuScene& scene, const ShadowedLight& light, const ShadowOptions& options);
    // The blended casters inside `light`'s volume, into mVisible.
    void collect(const GpuScene& scene, const ShadowedLight& light, const ShadowOptions& options);
    const gl::Program& program();

    gl::Texture mMaps, mCubes;
    std::vector<gl::Framebuffer> mLayerTargets;  // per 2D layer: colour + the maps' depth
    std::vector<gl::Framebuffer> mFaceTargets;   // per cube face
    gl::Program mProgram;
    std::vector<std::uint32_t> mVisible;  // reused every frame
    int mGeneration = -1;                 // the shadow pass's arrays the targets were made for
};

}  // namespace gnomon::render
