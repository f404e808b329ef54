// The frame's shadow passes, after planning (shadow::FramePlan): the depth maps the plan marks
// for redrawing (ShadowPass), their moments for the moment filters (MomentPass) and coloured
// shadows' transmittance maps (TransmittancePass), with the frame's counts of them and the
// textures the main pass reads. Under --shadow-rays all a ray answers every lookup: no map is
// drawn but for coloured shadows' tints (the transmittance pass tests against the depth maps)
// and --debug-view shadow-map; panels and read-backs draw the left-out maps when they ask.
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
    // The depth maps: the plan's input for what it may keep.
    ShadowPass& depth() { return mDepth; }
    const ShadowPass& depth() const { return mDepth; }
    // The depth maps of the last draw(), for what shows them (panels, read-backs): those that
    // frame left out are drawn now, from the same `scene` and `plan`.
    const ShadowPass& shownDepth(const GpuScene& scene, const shadow::FramePlan& plan);

private:
    // The maps the last draw() left out, and its options to draw them with (shownDepth()).
    bool mLeftOut = false;
    ShadowOptions mLeftOutOptions;
    ShadowPass mDepth;
    MomentPass mMoments;               // filterable maps' moments (evsm2, evsm4, msm)
    TransmittancePass mTransmittance;  // coloured shadows' transmittance maps
};

}  // namespace gnomon::render
