// gnomon::score: the renderer's per-pixel visibility against the ray-traced reference.
#include "gnomon/Score.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "gnomon/Error.h"
#include "gnomon/Renderer.h"
#include "lab/ScoreDetail.h"
#include "truth/ErrorCauses.h"
#include "truth/Metrics.h"

namespace gnomon {

namespace {
void checkScoreOptions(const RenderOptions& options, const ScoreOptions& scoreOptions) {
    if (!(scoreOptions.softSamples >= 1 && scoreOptions.softSamples <= 4096)) {
        throw Error(ErrorKind::InvalidInput, "soft-samples must be in 1..4096, got " +
                                                 std::to_string(scoreOptions.softSamples));
    }
    if (!(scoreOptions.bandTexels >= 0.0f && scoreOptions.bandTexels <= 64.0f)) {
        throw Error(ErrorKind::InvalidInput, "band must be in [0, 64] texels, got " +
                                                 std::to_string(scoreOptions.bandTexels));
    }
    if (!(scoreOptions.contactRange >= 0.0f && std::isfinite(scoreOptions.contactRange))) {
        throw Error(ErrorKind::InvalidInput, "contact-range must be a distance >= 0, got " +
                                                 std::to_string(scoreOptions.contactRange));
    }
    if (options.debugView != DebugView::None) {
        throw Error(ErrorKind::InvalidInput,
                    "score needs the scene as rendered: use --debug-view none");
    }
}
// Are there coloured shadows to score: blended casters, which with --blend-shadows coloured
// tint the light through them? Without any, the tinted light's error is no number at all.
bool colouredShadows(const Scene& scene, const RenderOptions& options) {
    if (options.shadow.blendShadows != BlendShadows::Coloured) return false;
    return std::any_of(scene.objects.begin(), scene.objects.end(), [&](const Object& o) {
        return o.castsShadows && o.material < scene.materials.size() &&
               scene.materials[o.material].alphaMode == AlphaMode::Blend;
    });
}
// The contacts' distance: the one asked for, else the contact shadows' march length.
float contactRange(const RenderOptions& options, const ScoreOptions& scoreOptions) {
    if (scoreOptions.contactRange > 0.0f) return scoreOptions.contactRange;
    return options.shadow.enabled ? options.shadow.contactLength : 0.0f;
}
// ShadowScore::traced of each light and of all: the share of the scored pairs a ray decided.
void countTraced(const truth::Reference& same, const ShadowVisibility& v, ScoreResult& r) {
    if (v.traced.size() != same.applies.size()) return;
    std::vector<long> traced(std::size_t(same.lights), 0);
    for (std::size_t c = 0; c < v.traced.size(); ++c)
        if (same.applies[c] && v.traced[c]) ++traced[c % std::size_t(same.lights)];
    long all = 0;
    for (ShadowScore& s : r.lights) {
        const long t = traced[std::size_t(s.light)];
        s.traced = s.pixels > 0 ? double(t) / double(s.pixels) : 0.0;
        all += t;
    }
    r.overall.traced = r.overall.pixels > 0 ? double(all) / double(r.overall.pixels) : 0.0;
}
}  // namespace

ScoreFrame renderForScore(Renderer& renderer, const Scene& scene, const RenderOptions& options,
                          const ScoreOptions& scoreOptions) {
    checkScoreOptions(options, scoreOptions);
    ScoreFrame frame;
    frame.render = renderer.render(scene, options, frame.visibility);
    return frame;
}

namespace detail {

truth::ReferenceOptions referenceOptions(const RenderOptions& options,
                                         const ScoreOptions& scoreOptions,
                                         truth::TracerKind tracer) {
    checkScoreOptions(options, scoreOptions);
    truth::ReferenceOptions ro;
    ro.tracer = tracer;
    ro.softSamples = options.shadow.filter == ShadowFilter::Pcss ? scoreOptions.softSamples : 0;
    ro.threads = scoreOptions.threads;
    ro.contactRange = contactRange(options, scoreOptions);
    return ro;
}

truth::Reference traceForScore(const Scene& scene, const RenderOptions& options,
                               const ScoreOptions& scoreOptions, ScoreProgress* progress,
                               double& seconds, truth::TracerKind tracer) {
    truth::ReferenceOptions ro = referenceOptions(options, scoreOptions, tracer);
    if (progress) {
        progress->rowsDone = 0;
        progress->rows = options.height;
        ro.rowsDone = &progress->rowsDone;
        ro.cancel = &progress->cancel;
    }
    const auto start = std::chrono::steady_clock::now();
    truth::Reference reference = truth::traceReference(scene, options, ro);
    seconds = secondsSince(start);
    return reference;
}

ScoreResult compareWithReference(ScoreFrame& frame, const truth::Reference& reference,
                                 const Scene& scene, const RenderOptions& options,
                                 const ScoreOptions& scoreOptions) {
    checkScoreOptions(options, scoreOptions);
    if (frame.visibility.width != options.width || frame.visibility.height != options.height ||
        reference.width != options.width || reference.height != options.height) {
        throw Error(ErrorKind::InvalidInput,
                    "score: the frame's visibility is " + std::to_string(frame.visibility.width) +
                        "x" + std::to_string(frame.visibility.height) + ", the options ask for " +
                        std::to_string(options.width) + "x" + std::to_string(options.height));
    }
    ScoreResult result;
    result.render = std::move(frame.render);
    result.softReference = options.shadow.filter == ShadowFilter::Pcss;
    result.contactRange =
        reference.nearOccluder.empty() ? 0.0f : contactRange(options, scoreOptions);
    // One aliasing band for the numbers and the map, around the reference's own edges;
    // then only the pixels where the render drew the surface the reference sees are scored.
    const ShadowVisibility& visibility = frame.visibility;
    std::vector<std::uint8_t> band = truth::aliasingBand(
        reference, visibility.texelWorld, scoreOptions.bandTexels, result.softReference);
    if (!result.softReference) {
        truth::extendBandAlongSurfaces(scene, reference, visibility.visibility,
                                       visibility.texelWorld, scoreOptions.bandTexels, band);
    }
    const truth::Reference same =
        truth::onSameSurfaces(reference, visibility.object, result.otherSurfacePixels);
    const truth::Scores scores =
        truth::scoreVisibility(scene, same, visibility.visibility, band, result.softReference);
    result.lights = scores.lights;
    result.overall = scores.overall;
    countTraced(same, visibility, result);
    result.errors =
        truth::errorMap(same, visibility.visibility, band, result.softReference, result.render);
    if (scoreOptions.explain) {
        truth::Explained explained = truth::explainErrors(
            same, visibility.visibility, visibility.texelWorld, band, result.softReference);
        result.errorCells = std::move(explained.cells);
        result.causes = explained.causes;
    }
    if (colouredShadows(scene, options)) {
        result.tint = truth::scoreTint(same, visibility.visibility, visibility.tint, band,
                                       result.softReference);
        result.tintErrors = truth::tintErrorMap(same, visibility.visibility, visibility.tint,
                                                result.softReference, result.render);
    }
    return result;
}

}  // namespace detail

ScoreResult score(Renderer& renderer, const Scene& scene, const RenderOptions& options,
                  const ScoreOptions& scoreOptions) {
    return scoreFrame(renderForScore(renderer, scene, options, scoreOptions), scene, options,
                      scoreOptions);
}

namespace {
nlohmann::json toJson(const ShadowScore& s, bool contacts) {
    nlohmann::json j = {{"light", s.light},
                        {"type", s.type},
                        {"pixels", s.pixels},
                        {"band_pixels", s.bandPixels},
                        {"misclassified", s.misclassified},
                        {"false_shadow", s.falseShadow},
                        {"leak", s.leak},
                        {"false_shadow_outside_band", s.falseShadowOutsideBand},
                        {"leak_outside_band", s.leakOutsideBand},
                        {"mean_abs_error", s.meanAbsError},
                        {"traced", s.traced}};
    if (contacts) {
        j["contact_pixels"] = s.contactPixels;
        j["contact_leak"] = s.contactLeak;
    }
    return j;
}
}  // namespace

std::string toJson(const ScoreResult& r, const std::string& scene, const RenderOptions& o) {
    nlohmann::json j;
    j["scene"] = scene;
    j["width"] = o.width;
    j["height"] = o.height;
    j["filter"] = toString(o.shadow.filter);
    j["depth_format"] = toString(o.shadow.depthFormat);
    j["soft_reference"] = r.softReference;
    j["other_surface_pixels"] = r.otherSurfacePixels;
    j["trace_seconds"] = r.traceSeconds;
    const bool contacts = r.contactRange > 0.0f;
    if (contacts) j["contact_range"] = r.contactRange;
    j["overall"] = toJson(r.overall, contacts);
    j["lights"] = nlohmann::json::array();
    for (const ShadowScore& s : r.lights)
        j["lights"].push_back(toJson(s, contacts));
    if (!r.errorCells.empty()) {
        const ErrorCauses& k = r.causes;
        j["causes_outside_band"] = {{"false_shadow_grazing", k.falseShadowGrazing},
                                    {"false_shadow_other", k.falseShadowOther},
                                    {"leak_grazing", k.leakGrazing},
                                    {"leak_contact", k.leakContact},
                                    {"leak_other", k.leakOther}};
    }
    if (!r.tintErrors.empty()) {
        j["tint"] = {{"cells", r.tint.cells},
                     {"cells_outside_band", r.tint.cellsOutsideBand},
                     {"mean_error", r.tint.meanError},
                     {"mean_error_outside_band", r.tint.meanErrorOutsideBand},
                     {"cells_both_lit", r.tint.cellsBothLit},
                     {"mean_colour_error", r.tint.meanColourError}};
    }
    return j.dump(2) + "\n";
}

std::string errorCellsCsv(const ScoreResult& r) {
    std::string out =
        "x,y,light,kind,in_band,light_cosine,occluder_distance,occluder_height_texels,texel_world,"
        "visibility\n";
    char line[256];
    for (const ErrorCell& e : r.errorCells) {
        const float height = e.occluderDistance >= 0.0f && e.texelWorld > 0.0f
                                 ? e.occluderDistance * e.lightCosine / e.texelWorld
                                 : -1.0f;
        std::snprintf(line, sizeof line, "%d,%d,%d,%s,%d,%.5f,%.6g,%.4g,%.6g,%.4f\n", e.x, e.y,
                      e.light, e.leak ? "leak" : "false-shadow", e.inBand ? 1 : 0,
                      double(e.lightCosine), double(e.occluderDistance), double(height),
                      double(e.texelWorld), double(e.visibility));
        out += line;
    }
    return out;
}

}  // namespace gnomon
