#include "render/ShadowPasses.h"

namespace gnomon::render {

namespace {
// --shadow-rays all: a ray answers every lookup, and the main pass reads no depth map and no
// moments (under coloured shadows a lookup gives the transmittance's tint alone:
// shadow_lookup.glsl, cube_lookup.glsl).
bool raysOnly(const ShadowOptions& so) {
    return tracesShadowRays(so) && so.shadowRays == ShadowRayMode::All;
}
}  // namespace

void ShadowPasses::draw(const GpuScene& scene, const shadow::FramePlan& plan,
                        const RenderOptions& options, PassClock* clock, FrameStats& stats,
                        MainPassInputs& in) {
    const ShadowOptions& so = options.shadow;
    const std::vector<ShadowedLight>& shadowed = plan.shadowed();
    const bool rays = raysOnly(so);
    const bool tinted = so.enabled && scene.hasTintingCasters(so) && !shadowed.empty();
    // What reads the depth maps: the lookups, coloured shadows' transmittance pass (its depth
    // test) and the shadow-map debug view.
    const bool mapsRead = !rays || tinted || options.debugView == DebugView::ShadowMap;
    // Left out, the maps keep what they hold and the keys they were drawn under, so a later
    // frame keeps those that still serve it and redraws the rest.
    mLeftOut = !mapsRead && !shadowed.empty();
    mLeftOutOptions = so;
    if (mapsRead) {
        const ShadowPassStats passStats = mDepth.render(scene, plan, so, clock, &stats.passes);
        stats.shadowPasses = passStats.rendered;
        stats.shadowTriangles = passStats.triangles;
        stats.castersCulled = passStats.culled;
        stats.shadowMaps = int(shadowed.size());
        for (const ShadowedLight& sl : shadowed)
            stats.shadowMapsWaiting += sl.waiting ? 1 : 0;
    }
    stats.shadowMapBytes = shadowed.empty() ? 0 : mDepth.bytes();
    const bool moments = isMomentFilter(so.filter) && so.enabled && !rays;
    if (moments && mDepth.mapArraySize() > 0) {
        stats.momentPasses =
            mMoments.update(mDepth, shadowed, mDepth.drawn(), so, clock, &stats.passes);
        stats.shadowMapBytes += mMoments.bytes();
    } else if (!moments) {
        // Made again for every map when next read: none is left behind maps drawn without it.
        mMoments.release();
    }
    if (tinted) {
        stats.transmittancePasses = mTransmittance.update(scene, mDepth, shadowed, mDepth.drawn(),
                                                          so, clock, &stats.passes);
        stats.shadowMapBytes += mTransmittance.bytes();
    } else {
        mTransmittance.release();
    }

    bool any2D = false, anyCube = false;
    for (const ShadowedLight& sl : shadowed)
        (sl.frame.kind == shadow::FrameKind::Cube ? anyCube : any2D) = true;
    in.hasCubes = anyCube;
    // Only maps made this frame (an array left from another format must not be bound), and
    // only where the lookups read them.
    in.shadowMaps = any2D && !rays ? &mDepth.maps() : nullptr;
    in.shadowCubes = anyCube && !rays ? &mDepth.cubes() : nullptr;
    in.edgeMaps = any2D && !rays ? mDepth.edgeMaps() : nullptr;
    in.shadowMoments = any2D && moments ? &mMoments.moments() : nullptr;
    in.transmittance = tinted ? &mTransmittance : nullptr;
}

const ShadowPass& ShadowPasses::shownDepth(const GpuScene& scene, const shadow::FramePlan& plan) {
    // The plan chose what to redraw against what the arrays still hold: the maps it marks.
    if (mLeftOut) mDepth.render(scene, plan, mLeftOutOptions);
    mLeftOut = false;
    return mDepth;
}

}  // namespace gnomon::render
