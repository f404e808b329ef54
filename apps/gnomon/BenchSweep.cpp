// `gnomon bench --sweep`: the scene and options of each value of the swept parameter.
#include "BenchSweep.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "LocalLights.h"
#include "gnomon/gnomon.h"

namespace gnomon::cli {
namespace {

// Splits every triangle into four by its edge midpoints (normals and colours interpolated).
void subdivide(Mesh& mesh) {
    std::vector<std::uint32_t> indices;
    indices.reserve(mesh.indices.size() * 4);
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
        mesh.positions.push_back(0.5f * (mesh.positions[a] + mesh.positions[b]));
        mesh.normals.push_back(glm::normalize(mesh.normals[a] + mesh.normals[b]));
        if (!mesh.colours.empty())
            mesh.colours.push_back(0.5f * (mesh.colours[a] + mesh.colours[b]));
        return std::uint32_t(mesh.positions.size() - 1);
    };
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const std::uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
        const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
        indices.insert(indices.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
    }
    mesh.indices = std::move(indices);
}

// Scene and options for one value of a sweep.
[[noreturn]] void unknownSweep(const std::string& param) {
    throw Error(ErrorKind::InvalidInput,
                "--sweep: expected lights, local-lights, map-size, triangles, cascades, filter "
                "or caster-detail, got '" +
                    param + "'");
}

}  // namespace

void applySweep(const std::string& param, const std::string& value, const Scene& base,
                const RenderOptions& baseOptions, Scene& scene, RenderOptions& options) {
    scene = base;
    options = baseOptions;
    auto integer = [&](int lo, int hi) {
        int v = 0;
        try {
            std::size_t used = 0;
            v = std::stoi(value, &used);
            if (used != value.size()) throw std::invalid_argument(value);
        } catch (const std::exception&) {
            throw Error(ErrorKind::InvalidInput, "--values: '" + value + "' is not a number");
        }
        if (v < lo || v > hi) {
            throw Error(ErrorKind::InvalidInput, "--values: " + param + " " + value +
                                                     " is outside " + std::to_string(lo) + ".." +
                                                     std::to_string(hi));
        }
        return v;
    };
    if (param == "map-size") {
        options.shadow.mapSize = integer(64, 8192);
    } else if (param == "cascades") {
        options.shadow.cascades = integer(1, 4);
    } else if (param == "caster-detail") {
        std::size_t used = 0;
        double v = 0.0;
        try {
            v = std::stod(value, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != value.size() || !(v >= 0.001 && v <= 1.0)) {
            throw Error(ErrorKind::InvalidInput,
                        "--values: caster-detail '" + value + "' is not in [0.001, 1]");
        }
        options.shadow.casterDetail = float(v);
    } else if (param == "filter") {
        const auto f = parseShadowFilter(value);
        if (!f) throw Error(ErrorKind::InvalidInput, "--values: unknown filter '" + value + "'");
        options.shadow.filter = *f;
    } else if (param == "lights") {
        // N spot lights on a ring over the scene, aimed at its centre.
        const int n = integer(1, 256);
        glm::vec3 lo, hi;
        sceneBounds(base, lo, hi);
        const glm::vec3 centre = 0.5f * (lo + hi);
        const float radius = std::max(0.5f * glm::length(hi - lo), 1e-3f);
        scene.lights.clear();
        for (int i = 0; i < n; ++i) {
            Light l;
            l.name = "sweep spot " + std::to_string(i);
            l.type = LightType::Spot;
            const float a = 6.2831853f * float(i) / float(n);
            l.position = centre + glm::vec3(0.7f * radius * std::cos(a), 0.8f * radius,
                                            0.7f * radius * std::sin(a));
            l.direction = glm::normalize(centre - l.position);
            l.innerConeDegrees = 35.0f;
            l.outerConeDegrees = 45.0f;
            l.intensity = 1.5f / float(n);
            l.shadowMapSize = baseOptions.shadow.mapSize;  // 0: a spot's own default
            scene.lights.push_back(l);
        }
        options.lightOnly = -1;
    } else if (param == "local-lights") {
        // N spot and point lights of limited range in the open space the view looks into,
        // instead of the scene's own (LocalLights.h), seen in the same picture.
        const int n = integer(1, kMaxLocalLights);
        const float aspect = float(baseOptions.width) / float(std::max(baseOptions.height, 1));
        scene.lights = placeLocalLights(base, n, aspect, baseOptions.time);
        options.lightOnly = -1;
    } else if (param == "triangles") {
        // Every triangle split into 4^k by its edge midpoints (k from the multiplier, a power
        // of 4): the same picture and draw calls, more triangles. (Copies of the scene would
        // either move the camera, changing the pixels shaded, or add draw calls.)
        const int multiplier = integer(1, 65536);
        int levels = 0;
        while ((1 << (2 * levels)) < multiplier)
            ++levels;
        if ((1 << (2 * levels)) != multiplier) {
            throw Error(ErrorKind::InvalidInput,
                        "--values: triangles " + value + " is not a power of 4 (1, 4, 16, ...)");
        }
        for (Mesh& mesh : scene.meshes) {
            for (int l = 0; l < levels; ++l)
                subdivide(mesh);
        }
    } else {
        unknownSweep(param);
    }
}

namespace {
// Each parameter's values when --values is not given.
std::vector<std::string> defaultValues(const std::string& param) {
    if (param == "lights") return {"1", "2", "4", "8", "16", "32", "64"};
    if (param == "local-lights") return {"1", "2", "4", "8", "16", "32", "64", "128", "256"};
    if (param == "map-size") return {"256", "512", "1024", "2048", "4096", "8192"};
    if (param == "triangles") return {"1", "4", "16", "64", "256", "1024", "4096"};
    if (param == "cascades") return {"1", "2", "3", "4"};
    if (param == "filter") return {"none", "hw2x2", "pcf", "poisson", "pcss"};
    if (param == "caster-detail") return {"1", "0.3", "0.1", "0.03", "0.01"};
    return {};
}

}  // namespace

// The values --sweep runs over: --values, else the parameter's defaults (none without
// --sweep).
std::vector<std::string> sweepValues(const BenchArgs& args) {
    std::vector<std::string> values;
    if (!args.sweep.empty()) {
        if (defaultValues(args.sweep).empty()) {
            unknownSweep(args.sweep);
        }
        if (args.values.empty()) {
            values = defaultValues(args.sweep);
        } else {
            std::stringstream in(args.values);
            for (std::string v; std::getline(in, v, ',');)
                if (!v.empty()) values.push_back(v);
        }
    } else if (!args.values.empty()) {
        throw Error(ErrorKind::InvalidInput, "--values needs --sweep");
    }
    return values;
}

}  // namespace gnomon::cli
