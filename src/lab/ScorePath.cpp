// gnomon::scorePath: every frame of a camera or light path scored against its reference, and
// the flicker between successive frames (truth/Flicker.h).
#include <algorithm>

#include <nlohmann/json.hpp>

#include "gnomon/Error.h"
#include "gnomon/Score.h"
#include "lab/ScoreDetail.h"
#include "truth/Flicker.h"

namespace gnomon {

namespace {

void summarise(PathScoreResult& r) {
    double flicker = 0.0, misclassified = 0.0;
    r.maxFlicker = 0.0;
    for (std::size_t i = 0; i < r.frames.size(); ++i) {
        misclassified += r.frames[i].overall.misclassified;
        if (i == 0) continue;
        flicker += r.frames[i].flicker;
        r.maxFlicker = std::max(r.maxFlicker, r.frames[i].flicker);
    }
    r.meanMisclassified = r.frames.empty() ? 0.0 : misclassified / double(r.frames.size());
    r.meanFlicker = r.frames.size() > 1 ? flicker / double(r.frames.size() - 1) : 0.0;
}

// The previous frame, kept for the flicker of the next.
struct Previous {
    truth::Reference reference;
    std::vector<float> visibility;
    Camera camera;
    std::vector<glm::vec3> lightDirections;
    bool valid = false;
};

bool sameCamera(const Camera& a, const Camera& b) {
    return a.eye == b.eye && a.centre == b.centre && a.up == b.up &&
           a.fovyDegrees == b.fovyDegrees && a.near == b.near && a.far == b.far &&
           a.projection == b.projection;
}

std::vector<glm::vec3> directions(const Scene& s) {
    std::vector<glm::vec3> d;
    for (const Light& l : s.lights)
        d.push_back(l.direction);
    return d;
}

// The flicker between `previous` and the frame `scene` now holds (rendered as `visibility`
// against `reference`): the previous frame's view drawn again with this frame's maps and
// lights, compared with what that view showed then.
truth::FlickerCount flickerSince(const Previous& previous, Renderer& renderer, Scene& scene,
                                 const RenderOptions& options, const ScoreOptions& scoreOptions,
                                 const std::vector<float>& visibility,
                                 const truth::Reference& reference, ScoreProgress* progress,
                                 bool soft) {
    if (sameCamera(previous.camera, scene.camera)) {
        return truth::countFlicker(previous.reference, previous.visibility, reference, visibility,
                                   soft);
    }
    const Camera now = scene.camera;
    scene.camera = previous.camera;
    ShadowVisibility cross;
    renderer.render(scene, options, cross, now);
    truth::Reference traced;
    const bool lightsMoved = directions(scene) != previous.lightDirections;
    if (lightsMoved) {
        double seconds = 0.0;
        traced = detail::traceForScore(scene, options, scoreOptions, progress, seconds);
    }
    scene.camera = now;
    return truth::countFlicker(previous.reference, previous.visibility,
                               lightsMoved ? traced : previous.reference, cross.visibility, soft);
}

}  // namespace

PathScoreResult scorePath(Renderer& renderer, Scene& scene, const RenderOptions& options,
                          const ScenePath& path, const ScoreOptions& scoreOptions,
                          bool keepErrorMaps, ScoreProgress* progress,
                          const std::function<void(const PathScoreResult&)>& onFrame) {
    const detail::RestoreView restore(scene);
    // The frames follow one another as a viewer's would: stabilised maps hold still while
    // they cover the view (Renderer::setFollowing).
    struct Following {
        Renderer& r;
        explicit Following(Renderer& renderer) : r(renderer) { r.setFollowing(true); }
        ~Following() { r.setFollowing(false); }
        Following(const Following&) = delete;
        Following& operator=(const Following&) = delete;
    } following(renderer);
    PathScoreResult out;
    out.path = path.name;
    out.framesAsked = path.frames();
    out.softReference = options.shadow.filter == ShadowFilter::Pcss;
    Previous previous;
    for (int i = 0; i < path.frames(); ++i) {
        applyPathFrame(path, i, scene);
        PathFrameScore f;
        try {
            ScoreFrame frame = renderForScore(renderer, scene, options, scoreOptions);
            double seconds = 0.0;
            truth::Reference reference =
                detail::traceForScore(scene, options, scoreOptions, progress, seconds);
            out.traceSeconds += seconds;
            ScoreResult scored =
                detail::compareWithReference(frame, reference, scene, options, scoreOptions);
            f.overall = scored.overall;
            if (previous.valid) {
                const truth::FlickerCount c = flickerSince(
                    previous, renderer, scene, options, scoreOptions, frame.visibility.visibility,
                    reference, progress, out.softReference);
                f.compared = c.compared;
                f.flickered = c.flickered;
                f.flicker = c.fraction();
                for (std::size_t p = 0; keepErrorMaps && p < c.map.size(); ++p) {
                    if (!c.map[p]) continue;
                    std::uint8_t* px =
                        &scored.errors.pixels[p * std::size_t(scored.errors.channels)];
                    px[0] = 255, px[1] = 220, px[2] = 0;  // yellow: flicker
                }
            }
            if (keepErrorMaps) f.errors = std::move(scored.errors);
            previous.reference = std::move(reference);
            previous.visibility = std::move(frame.visibility.visibility);
        } catch (const Error&) {
            if (!(progress && progress->cancel)) throw;
            out.interrupted = true;
            break;
        }
        previous.camera = scene.camera;
        previous.lightDirections = directions(scene);
        previous.valid = true;
        out.frames.push_back(std::move(f));
        summarise(out);
        if (onFrame) onFrame(out);
        if (progress && progress->cancel) {
            out.interrupted = i + 1 < path.frames();
            break;
        }
    }
    return out;
}

std::string toJson(const PathScoreResult& r, const std::string& scene, const RenderOptions& o) {
    nlohmann::json j;
    j["scene"] = scene;
    j["path"] = r.path;
    j["width"] = o.width;
    j["height"] = o.height;
    j["filter"] = toString(o.shadow.filter);
    j["stabilise"] = o.shadow.stabilise;
    j["soft_reference"] = r.softReference;
    j["frames_asked"] = r.framesAsked;
    j["frames_scored"] = r.frames.size();
    j["interrupted"] = r.interrupted;
    j["trace_seconds"] = r.traceSeconds;
    j["mean_flicker"] = r.meanFlicker;
    j["max_flicker"] = r.maxFlicker;
    j["mean_misclassified"] = r.meanMisclassified;
    j["frames"] = nlohmann::json::array();
    for (const PathFrameScore& f : r.frames) {
        j["frames"].push_back({{"misclassified", f.overall.misclassified},
                               {"false_shadow", f.overall.falseShadow},
                               {"leak", f.overall.leak},
                               {"compared", f.compared},
                               {"flickered", f.flickered},
                               {"flicker", f.flicker}});
    }
    return j.dump(2) + "\n";
}

}  // namespace gnomon
