// Filterable shadow maps (ShadowFilter::Evsm2, Evsm4, Msm): after the shadow pass, the
// moments of each 2D map it drew go into an RGBA32F array laid out as the depth maps are
// (same layers, same squares), which the main pass reads with one bilinear lookup; with a
// blur, box-blurred in two passes (rows into a scratch texture, then columns). Point lights' cubes
// have no moments: their lookups keep the default 3x3 PCF.
#pragma once
#include <map>
#include <vector>

#include "gl/Objects.h"
#include "gnomon/Options.h"
#include "render/ShadowPass.h"

namespace gnomon::render {

class PassClock;

class MomentPass {
public:
    // Makes the moments of the 2D maps among `lights` that the shadow pass drew this frame
    // (`drawn`: their indices into `lights`), or of every 2D map when the moments array is
    // new or the moment settings changed. With `clock`, each map is timed into `timings`.
    // Returns the passes drawn (per map: one, or two with a blur).
    int update(const ShadowPass& pass, const std::vector<ShadowedLight>& lights,
               const std::vector<int>& drawn, const ShadowOptions& options, PassClock* clock,
               std::vector<PassTiming>* timings);
    // Frees the moments (the filter no longer reads them).
    void release();
    const gl::Texture& moments() const { return mMoments; }
    std::size_t bytes() const;

private:
    void allocate(int size, int layers);
    void allocateRows(int size);
    // One map's moments, blurred by `radius`: the passes drawn (1 without a blur, else 2).
    int blur(const ShadowPass& pass, const ShadowedLight& light, int radius);
    // The pass for `filter`, rows or columns, with `radius` built in (a variant per radius
    // used: 0 to the option's 16).
    const gl::Program& program(ShadowFilter filter, bool rows, int radius);

    gl::Texture mMoments, mRows;
    std::vector<gl::Framebuffer> mLayerTargets;  // one per layer of mMoments
    gl::Framebuffer mRowTarget;
    gl::Sampler mStored;  // the depth maps as stored: NEAREST, no comparison
    gl::VertexArray mEmpty;
    std::map<int, gl::Program> mPrograms;  // by (filter x rows or columns) x 64 + radius
    ShadowFilter mFilter = ShadowFilter::Pcf;
    int mRadius = -1;
};

}  // namespace gnomon::render
