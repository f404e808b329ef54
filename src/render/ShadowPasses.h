// The frame's shadow passes, after planning (shadow::FramePlan): the depth maps the plan marks
// for redrawing (ShadowPass), their moments for the moment filters (MomentPass) and coloured
// shadows' transmittance maps (TransmittancePass), with the frame's counts of them and the
// textures the main pass reads.
#pragma once

#include "gnomon/Options.h"
#include "gnomon/Renderer.h"
#include "render/GpuScene.h"
#include "render/MainPass.h"
#include "render/MomentPass.h"
#include "render/ShadowPass.h"
#include "render/TransmittancePass.h"
#include "shadow/FramePlan.h"

namespace gnomon::render {

class PassClock;

class ShadowPasses {
public:
    // Draws the passes `plan` and `options` ask for this frame, counts them into `stats` and
    // points `in`'s maps at what the main pass reads (null where a kind is absent). With
    // `clock`, each pass is timed into stats.passes.
    void draw(const GpuScene& scene, const shadow::FramePlan& plan, const RenderOptions& options,
              PassClock* clock, FrameStats& stats, MainPassInputs& in);
    // The depth maps: the plan's input for what it may keep, the debug views' and read-backs'
    // source.
    ShadowPass& depth() { return mDepth; }
    const ShadowPass& depth() const { return mDepth; }

private:
    ShadowPass mDepth;
    MomentPass mMoments;               // filterable maps' moments (evsm2, evsm4, msm)
    TransmittancePass mTransmittance;  // coloured shadows' transmittance maps
};

}  // namespace gnomon::render
