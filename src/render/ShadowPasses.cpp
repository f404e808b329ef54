#include "render/ShadowPasses.h"

namespace gnomon::render {

void ShadowPasses::draw(const GpuScene& scene, const shadow::FramePlan& plan,
                        const RenderOptions& options, PassClock* clock, FrameStats& stats,
                        MainPassInputs& in) {
    const ShadowOptions& so = options.shadow;
    const std::vector<ShadowedLight>& shadowed = plan.shadowed();
    const ShadowPassStats passStats = mDepth.render(scene, plan, so, clock, &stats.passes);
    stats.shadowPasses = passStats.rendered;
    stats.shadowTriangles = passStats.triangles;
    stats.castersCulled = passStats.culled;
    stats.shadowMaps = int(shadowed.size());
    stats.shadowMapBytes = shadowed.empty() ? 0 : mDepth.bytes();
    const bool moments = isMomentFilter(so.filter) && so.enabled;
    if (moments && mDepth.mapArraySize() > 0) {
        stats.momentPasses =
            mMoments.update(mDepth, shadowed, mDepth.drawn(), so, clock, &stats.passes);
        stats.shadowMapBytes += mMoments.bytes();
    } else if (!moments) {
        mMoments.release();
    }
    const bool tinted = so.enabled && scene.hasTintingCasters(so) && !shadowed.empty();
    if (tinted) {
        stats.transmittancePasses = mTransmittance.update(scene, mDepth, shadowed, mDepth.drawn(),
                                                          so, clock, &stats.passes);
        stats.shadowMapBytes += mTransmittance.bytes();
    } else {
        mTransmittance.release();
    }

    // Only maps made this frame: an array left from another format must not be bound.
    bool any2D = false, anyCube = false;
    for (const ShadowedLight& sl : shadowed)
        (sl.frame.kind == shadow::FrameKind::Cube ? anyCube : any2D) = true;
    in.shadowMaps = any2D ? &mDepth.maps() : nullptr;
    in.shadowCubes = anyCube ? &mDepth.cubes() : nullptr;
    in.shadowMoments = any2D && moments ? &mMoments.moments() : nullptr;
    in.transmittance = tinted ? &mTransmittance : nullptr;
}

}  // namespace gnomon::render
