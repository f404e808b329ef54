// A view written as the page's address (PageRequest.h): what it was loaded from, then only
// what the user changed since, in the spellings parseAddress reads, so a link reproduces it.
#include <limits>

#include "PageEdits.h"
#include "PageRequest.h"
#include "gnomon/Error.h"
#include "gnomon/OptionSchema.h"

namespace gnomon::web {
namespace {

// The address as it is written: "#" then key=value pairs joined by '&'.
class Address {
public:
    explicit Address(const std::string& scene) : mText("#scene=" + encodedValue(scene)) {}
    void add(const std::string& key, const std::string& value) {
        mText += "&" + key + "=" + encodedValue(value);
    }
    void addFlag(const std::string& key) { mText += "&" + key; }
    const std::string& text() const { return mText; }

private:
    std::string mText;
};

std::string vec3Text(const glm::vec3& v) {
    return numberText(v.x) + "," + numberText(v.y) + "," + numberText(v.z);
}

// The camera's keys, the sun and ambient: the CLI's keys first, as the load applies them. A
// key is written when its value moved since loading or when `base` gave it (the load applied
// it: left out, it would be lost).
void addSceneKeys(Address& out, const PageRequest& base, const Scene& loaded, const Scene& edited) {
    const auto gave = [&](const char* key) { return base.edits.count(key) > 0; };
    const Camera& was = loaded.camera;
    const Camera& now = edited.camera;
    const bool placed = now.eye != was.eye || now.centre != was.centre || gave("camera-eye") ||
                        gave("camera-target");
    if (placed) {
        out.add("camera-eye", vec3Text(now.eye));
        out.add("camera-target", vec3Text(now.centre));
    }
    if (now.fovyDegrees != was.fovyDegrees || gave("camera-fov"))
        out.add("camera-fov", numberText(now.fovyDegrees));
    // As given: the view edits the light it made through light0.
    if (gave("sun")) out.add("sun", base.edits.at("sun"));
    // What the load gives without the page's own keys: the loaded camera and ambient, but a
    // camera placed by eye and target gets its planes fitted to the scene (placeCameraAndSun).
    Scene reload;
    reload.camera = was;
    reload.ambient = loaded.ambient;
    if (placed) {
        Camera fitted = now;
        fitted.near = fitted.far = std::numeric_limits<float>::quiet_NaN();  // unless fitted
        fitCameraDepth(loaded, fitted);
        reload.camera.near = fitted.near;
        reload.camera.far = fitted.far;
    }
    for (const SceneKey& k : sceneKeys()) {
        const std::string text = k.format(edited);
        if (text != k.format(reload) || gave(k.name)) out.add(k.name, text);
    }
}

// light<N>=FIELD:VALUE;... for each light with a field that moved since loading or that
// `base` gave, those fields in lightFields() order.
void addLights(Address& out, const PageRequest& base, const Scene& loaded, const Scene& edited) {
    for (std::size_t i = 0; i < edited.lights.size(); ++i) {
        const auto given = base.lights.find(int(i));
        std::string fields;
        for (const LightField& f : lightFields()) {
            const std::string text = f.format(edited.lights[i]);
            const bool gave = given != base.lights.end() && given->second.count(f.name) > 0;
            if (text != f.format(loaded.lights[i]) || gave)
                fields += (fields.empty() ? "" : ";") + std::string(f.name) + ":" + text;
        }
        if (!fields.empty()) out.add("light" + std::to_string(i), fields);
    }
}

}  // namespace

std::string writeAddress(const PageRequest& base, const Scene& loaded, const Scene& edited,
                         const RenderOptions& options, bool withSize) {
    if (edited.lights.size() != loaded.lights.size()) {
        throw Error(ErrorKind::InvalidInput,
                    "the address cannot add or remove lights: the scene loaded with " +
                        std::to_string(loaded.lights.size()) + ", the view has " +
                        std::to_string(edited.lights.size()));
    }
    Address out(base.scene);
    if (base.preset != Preset::Default) out.add("preset", toString(base.preset));
    if (base.ground) out.addFlag("ground");
    using Picture = PageRequest::Picture;
    if (base.picture == Picture::Truth) out.add("picture", "truth");
    if (base.picture == Picture::Score) out.add("picture", "score");
    if (!base.ui) out.add("ui", "off");
    addSceneKeys(out, base, loaded, edited);
    addLights(out, base, loaded, edited);
    const RenderOptions preset = presetOptions(loaded, base.preset);
    for (const OptionSpec& spec : optionSchema()) {
        if (spec.kind == OptionKind::Size && !withSize) continue;
        const std::string text = formatOption(spec, options);
        if (text != formatOption(spec, preset)) out.add(spec.name, text);
    }
    return out.text();
}

}  // namespace gnomon::web
