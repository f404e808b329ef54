// The page's address read as the CLI reads its flags: the same option schema, the same
// parser and checks (applyOptionTexts), the same loaders and scene edits (PageEdits.h).
#include "PageRequest.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "PageEdits.h"
#include "gnomon/Error.h"
#include "gnomon/OptionSchema.h"

namespace gnomon::web {
namespace {

[[noreturn]] void refuse(const std::string& message) {
    throw Error(ErrorKind::InvalidInput, message);
}

// %XX escapes and '+' (a space in form encoding) decoded; a stray '%' is kept as it is.
std::string decoded(const std::string& text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '+') {
            out += ' ';
        } else if (c == '%' && i + 2 < text.size() && std::isxdigit((unsigned char)text[i + 1]) &&
                   std::isxdigit((unsigned char)text[i + 2])) {
            out += char(std::stoi(text.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            out += c;
        }
    }
    return out;
}

// The CLI's scene edits that the address takes by their flags' names.
const std::vector<std::string> kCliEdits = {"camera-eye", "camera-target", "camera-fov", "sun"};

// Every key the address takes, for the nearest-name hint.
std::vector<std::string> knownKeys() {
    std::vector<std::string> keys = {"scene", "preset", "ground", "picture", "ui", "light0"};
    keys.insert(keys.end(), kCliEdits.begin(), kCliEdits.end());
    for (const SceneKey& k : sceneKeys())
        keys.push_back(k.name);
    for (const OptionSpec& spec : optionSchema())
        keys.push_back(spec.name);
    return keys;
}

bool isSceneKey(const std::string& key) {
    const auto& keys = sceneKeys();
    return std::find(kCliEdits.begin(), kCliEdits.end(), key) != kCliEdits.end() ||
           std::any_of(keys.begin(), keys.end(), [&](const SceneKey& k) { return key == k.name; });
}

void setKey(PageRequest& r, const std::string& key, const std::string& value) {
    if (key == "scene") {
        if (value.empty()) refuse("scene: give a built-in scene's name or a bundled model");
        r.scene = value;
    } else if (key == "preset") {
        const auto p = parsePreset(value);
        if (!p) refuse("--preset: expected one of default, textbook, got '" + value + "'");
        r.preset = *p;
    } else if (key == "ground") {
        if (value != "" && value != "on" && value != "off")
            refuse("ground: expected on or off, got '" + value + "'");
        r.ground = value != "off";
    } else if (key == "picture") {
        using Picture = PageRequest::Picture;
        if (value == "render") {
            r.picture = Picture::Render;
        } else if (value == "truth") {
            r.picture = Picture::Truth;
        } else if (value == "score") {
            r.picture = Picture::Score;
        } else {
            refuse("picture: expected render, truth or score, got '" + value + "'");
        }
    } else if (key == "ui") {
        if (value != "" && value != "on" && value != "off")
            refuse("ui: expected on or off, got '" + value + "'");
        r.ui = value != "off";
    } else if (isSceneKey(key)) {
        r.edits[key] = value;
    } else if (const int light = lightKeyIndex(key); light >= 0) {
        r.lights[light] = parseLightFields(key, value);
    } else if (findOption(key)) {
        r.options[key] = value;
    } else {
        const std::string nearest = nearestName(key, knownKeys());
        refuse("unknown option in the address: '" + key + "'" +
               (nearest.empty() ? "" : "; did you mean " + nearest + "?"));
    }
}

// The one glTF file in a bundled model's folder.
std::string modelIn(const std::filesystem::path& folder) {
    namespace fs = std::filesystem;
    std::vector<fs::path> models;
    for (const fs::directory_entry& e : fs::directory_iterator(folder)) {
        const std::string ext = e.path().extension().string();
        if (e.is_regular_file() && (ext == ".gltf" || ext == ".glb")) models.push_back(e.path());
    }
    if (models.size() != 1) {
        refuse("cannot load scene '" + folder.string() + "': the folder holds " +
               std::to_string(models.size()) + " glTF files; name one (FOLDER/FILE)");
    }
    return models.front().string();
}

}  // namespace

std::string sceneSource(const std::string& name, const std::string& bundle) {
    namespace fs = std::filesystem;
    const auto builtins = builtinScenes();
    const bool builtin = std::any_of(builtins.begin(), builtins.end(),
                                     [&](const SceneInfo& s) { return s.name == name; });
    std::error_code ec;
    const fs::path inBundle = fs::path(bundle) / name;
    if (!builtin && !bundle.empty() && name.find("..") == std::string::npos &&
        fs::exists(inBundle, ec)) {
        return fs::is_directory(inBundle, ec) ? modelIn(inBundle) : inBundle.string();
    }
    return name;  // a built-in scene, or a path; loadScene says what is wrong with it
}

PageRequest parseAddress(const std::string& address) {
    PageRequest r;
    std::string text = address.rfind('#', 0) == 0 ? address.substr(1) : address;
    std::vector<std::string> seen;
    std::size_t at = 0;
    while (at <= text.size()) {
        std::size_t end = text.find('&', at);
        if (end == std::string::npos) end = text.size();
        const std::string part = text.substr(at, end - at);
        at = end + 1;
        if (part.empty()) continue;
        const std::size_t eq = part.find('=');
        const std::string key = decoded(part.substr(0, eq));
        const std::string value = eq == std::string::npos ? "" : decoded(part.substr(eq + 1));
        if (std::find(seen.begin(), seen.end(), key) != seen.end())
            refuse("the address gives '" + key + "' twice");
        seen.push_back(key);
        setKey(r, key, value);
    }
    return r;
}

PageScene loadRequest(const PageRequest& request, const std::string& bundle) {
    PageScene out;
    out.scene = loadScene(sceneSource(request.scene, bundle));
    if (request.ground) addGround(out.scene);
    applySceneEdits(request, out.scene);  // after the ground, as the CLI's editScene
    out.warnings = out.scene.warnings;
    out.options = presetOptions(out.scene, request.preset);
    for (const std::string& w : applyOptionTexts(request.options, out.options))
        out.warnings.push_back(w);
    if (!cameraSeesScene(out.scene, out.options.width, out.options.height))
        out.warnings.push_back("the camera sees none of the scene: the picture is background");
    return out;
}

}  // namespace gnomon::web
