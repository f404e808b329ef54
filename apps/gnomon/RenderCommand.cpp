// The render flags: made from the option schema, plus the scene edits (ground, camera, sun)
// every command shares.
#include <algorithm>
#include <cstdio>
#include <optional>

#include "RenderOptionsCli.h"
#include "gnomon/Error.h"
#include "gnomon/OptionSchema.h"

namespace gnomon::cli {
namespace {

const RenderOptions kDefaults;

[[noreturn]] void bad(const std::string& flag, const std::string& message) {
    throw Error(ErrorKind::InvalidInput, flag + ": " + message);
}

template <typename E>
E parseEnum(const std::string& flag, const std::string& value,
            std::optional<E> (*parse)(const std::string&), const char* choices) {
    if (auto v = parse(value)) return *v;
    bad(flag, "expected one of " + std::string(choices) + ", got '" + value + "'");
}

}  // namespace

UpAxis RenderFlags::upAxis() const {
    return parseEnum<UpAxis>("--up", up, parseUpAxis, "x, y, z");
}

void RenderFlags::editScene(Scene& scene) const {
    if (ground) addGround(scene);
    placeCameraAndSun(scene);
}

void RenderFlags::placeCameraAndSun(Scene& scene) const {
    auto given = [&](const char* flag) { return app && app->count(flag) > 0; };
    CameraAndSun edits;  // the library applies them, as it does the web page's address
    if (given("--camera-eye")) edits.eye = cameraEye;
    if (given("--camera-target")) edits.target = cameraTarget;
    if (given("--camera-fov")) edits.fovDegrees = cameraFov;
    if (given("--sun")) edits.sun = sun;
    gnomon::placeCameraAndSun(scene, edits);
    // No revision bump: the camera and the lights are read every frame.
}

void RenderFlags::add(CLI::App& a) {
    app = &a;
    a.add_option("--preset", preset,
                 "where options start: default, or textbook = the textbook's own numbers for the "
                 "scene (constant tolerance, its depth storage; acne included); flags given "
                 "override it (default: default)")
        ->type_name("default|textbook")
        ->group("Output");
    a.add_flag("--ground", ground,
               "add a grey ground under the scene (receives shadows, casts none), for models "
               "without a floor")
        ->group("Output");
    a.add_option("--up", up,
                 "the model file's up axis, turned to +y as it loads (glTF is y by its "
                 "specification; STL, older OBJ and CAD exports are often z)")
        ->type_name("x|y|z")
        ->group("Scene");
    a.add_option("--camera-eye", cameraEye, "place the camera's eye at X,Y,Z (world units)")
        ->type_name("X,Y,Z")
        ->group("Scene");
    a.add_option("--camera-target", cameraTarget, "point the camera at X,Y,Z")
        ->type_name("X,Y,Z")
        ->group("Scene");
    a.add_option("--camera-fov", cameraFov, "the camera's vertical field of view, 1..179 degrees")
        ->type_name("DEG")
        ->group("Scene");
    a.add_option("--sun", sun,
                 "light the scene by one sun instead of its lights: azimuth (degrees from +z "
                 "towards +x, where the light comes from) and elevation above the horizon "
                 "(0..90)")
        ->type_name("AZ,EL")
        ->group("Scene");
    for (const OptionSpec& spec : optionSchema()) {
        const std::string defaultText =
            *spec.defaultNote ? spec.defaultNote : formatOption(spec, kDefaults);
        const std::string range = spec.kind == OptionKind::Choice ||
                                          spec.kind == OptionKind::Switch ||
                                          spec.kind == OptionKind::Size
                                      ? ""
                                      : optionRange(spec) + "; ";
        a.add_option("--" + std::string(spec.name), values[spec.name],
                     std::string(spec.doc) + " (" + range + "default " + defaultText + ")")
            ->type_name(optionValueName(spec))
            ->group(toString(spec.group));
    }
}

RenderOptions RenderFlags::resolve(const Scene& scene) const {
    Preset p = Preset::Default;
    if (app->count("--preset") > 0)
        p = parseEnum("--preset", preset, parsePreset, "default, textbook");
    RenderOptions o = presetOptions(scene, p);
    apply(o);
    // Cascades belong to directional lights: a scene without a shadowed one shows no tint.
    const bool directional = std::any_of(scene.lights.begin(), scene.lights.end(), [](auto& l) {
        return l.enabled && l.castsShadows && l.type == LightType::Directional;
    });
    if (o.debugView == DebugView::Cascades && o.shadow.enabled && !directional) {
        std::fprintf(stderr,
                     "gnomon: warning: --debug-view cascades does nothing here: the scene has no "
                     "shadowed directional light\n");
    }
    // A camera turned away from the scene, or past it, draws the background only: said,
    // not left to a blank image.
    if (!cameraSeesScene(scene, o.width, o.height)) {
        const Camera& c = scene.camera;
        std::fprintf(stderr,
                     "gnomon: warning: the camera (eye %g,%g,%g, looking at %g,%g,%g) sees none "
                     "of the scene, or all of it within a pixel: the image holds the background "
                     "only\n",
                     c.eye.x, c.eye.y, c.eye.z, c.centre.x, c.centre.y, c.centre.z);
    }
    return o;
}

void RenderFlags::apply(RenderOptions& o) const {
    std::map<std::string, std::string> texts;  // the flags given
    for (const OptionSpec& spec : optionSchema())
        if (given(spec)) texts[spec.name] = values.at(spec.name);
    // A flag given that the other options make pointless: said once, not silently ignored.
    for (const std::string& warning : applyOptionTexts(texts, o))
        std::fprintf(stderr, "gnomon: warning: %s\n", warning.c_str());
}

bool RenderFlags::given(const OptionSpec& spec) const {
    return app->count("--" + std::string(spec.name)) > 0;
}

}  // namespace gnomon::cli
