#include "IndependentCaster.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>
#include <glm/gtc/type_ptr.hpp>

#include "gnomon/Error.h"
#include "truth/ShadowRays.h"

namespace gnomon::crosscheck {
namespace {

using K = CGAL::Simple_cartesian<double>;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Ray = K::Ray_3;
using Triangle = K::Triangle_3;
using Iterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<K, Iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

// Faces closer to edge-on than the reference's threshold are in their own attached shadow
// for both casters: a definition the two must share, not code.
constexpr double kEdgeOn = truth::ShadowRays::kEdgeOnCosine;

Vector vec(const glm::dvec3& v) {
    return Vector(v.x, v.y, v.z);
}
glm::dvec3 dvec(const Vector& v) {
    return {v.x(), v.y(), v.z()};
}
glm::dvec3 dvec(const Point& p) {
    return {p.x(), p.y(), p.z()};
}

// The scene's triangles in world space, each with its object, in double precision; the
// degenerate ones (which no ray can hit) left out, as CGAL's intersections require.
struct World {
    std::vector<Triangle> triangles;
    std::vector<int> objectOf;  // per triangle
    double size = 1.0;          // the diagonal of the triangles' box
};

World worldTriangles(const Scene& scene, double seconds) {
    World w;
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        const Object& object = scene.objects[o];
        const Mesh& mesh = scene.meshes[object.mesh];
        const glm::dmat4 m(object.worldFromModelAt(seconds));
        std::vector<Point> p;
        p.reserve(mesh.positions.size());
        for (const glm::vec3& v : mesh.positions) {
            const glm::dvec3 q = glm::dvec3(m * glm::dvec4(glm::dvec3(v), 1.0));
            p.emplace_back(q.x, q.y, q.z);
            lo = glm::min(lo, q);
            hi = glm::max(hi, q);
        }
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            Triangle t(p[mesh.indices[i]], p[mesh.indices[i + 1]], p[mesh.indices[i + 2]]);
            if (t.is_degenerate()) continue;
            w.triangles.push_back(t);
            w.objectOf.push_back(int(o));
        }
    }
    if (!w.triangles.empty()) w.size = std::max(glm::length(hi - lo), 1e-30);
    return w;
}

struct Hit {
    bool found = false;
    std::size_t triangle = 0;
    glm::dvec3 point{0.0};
    double t = 0.0;  // along the ray's direction as given (unnormalised)
};

// The nearest triangle along origin + t dir for t in (tmin, tmax), skipping `skip`.
Hit nearest(const Tree& tree, const World& w, const glm::dvec3& origin, const glm::dvec3& dir,
            double tmin, double tmax, std::size_t skip = std::numeric_limits<std::size_t>::max()) {
    const Iterator first = w.triangles.begin();
    const auto hit =
        tree.first_intersection(Ray(Point(origin.x, origin.y, origin.z), vec(dir)),
                                [&](Iterator id) { return std::size_t(id - first) == skip; });
    Hit h;
    if (!hit) return h;
    glm::dvec3 at;
    if (const Point* p = boost::get<Point>(&hit->first)) {
        at = dvec(*p);
    } else {  // the ray runs in the triangle's plane: its nearer end
        const K::Segment_3& s = boost::get<K::Segment_3>(hit->first);
        const glm::dvec3 a = dvec(s.source()), b = dvec(s.target());
        at = glm::dot(a - origin, dir) < glm::dot(b - origin, dir) ? a : b;
    }
    h.t = glm::dot(at - origin, dir) / glm::dot(dir, dir);
    if (!(h.t > tmin && h.t < tmax)) return h;
    h.found = true;
    h.triangle = std::size_t(hit->second - first);
    h.point = at;
    return h;
}

// Light l's direction from `p` and the distance to it; false where it does not reach.
bool towards(const Light& light, const glm::dvec3& p, glm::dvec3& toLight, double& distance) {
    const glm::dvec3 dir = glm::normalize(glm::dvec3(light.direction));
    distance = std::numeric_limits<double>::infinity();
    if (light.type == LightType::Directional || light.type == LightType::Area) {
        toLight = -dir;
        if (light.type == LightType::Area) distance = glm::dot(p - glm::dvec3(light.position), dir);
        return distance > 0.0;
    }
    const glm::dvec3 d = glm::dvec3(light.position) - p;
    distance = glm::length(d);
    if (!(distance > 0.0) || (light.range > 0.0f && distance >= light.range)) return false;
    toLight = d / distance;
    return light.type != LightType::Spot ||
           glm::dot(-toLight, dir) > std::cos(glm::radians(double(light.outerConeDegrees)));
}

bool opaque(const Scene& scene, int object) {
    return scene.materials[scene.objects[std::size_t(object)].material].alphaMode ==
           AlphaMode::Opaque;
}

}  // namespace

Agreement compareWithReference(const Scene& scene, const RenderOptions& options,
                               const truth::Reference& reference) {
    const Camera& camera = scene.camera;
    if (camera.projection != Projection::Perspective) {
        throw Error(ErrorKind::InvalidInput,
                    "crosscheck: only perspective cameras are traced (the scene's is "
                    "orthographic)");
    }
    const World w = worldTriangles(scene, options.time);
    Tree all(w.triangles.begin(), w.triangles.end());
    std::vector<Triangle> casting;
    std::vector<std::size_t> castingIndex;  // into w.triangles
    for (std::size_t i = 0; i < w.triangles.size(); ++i) {
        if (!scene.objects[std::size_t(w.objectOf[i])].castsShadows) continue;
        casting.push_back(w.triangles[i]);
        castingIndex.push_back(i);
    }
    const World casters{casting, {}, w.size};
    Tree shadowTree(casters.triangles.begin(), casters.triangles.end());

    // The camera's axes as a look-at builds them, and a ray per pixel centre whose component
    // along `ahead` is 1, so t is the view depth the near and far planes clip.
    const glm::dvec3 eye(camera.eye), ahead = glm::normalize(glm::dvec3(camera.centre) - eye);
    const glm::dvec3 right = glm::normalize(glm::cross(ahead, glm::dvec3(camera.up)));
    const glm::dvec3 up = glm::cross(right, ahead);
    const double aspect =
        camera.aspect > 0.0f ? camera.aspect : double(options.width) / double(options.height);
    const double tanHalf = std::tan(0.5 * glm::radians(double(camera.fovyDegrees)));
    // Shadow rays keep to the line through the surface point and skip the stretch within
    // this margin of its plane: in double precision a hundred-millionth of the scene is a
    // million rounding steps of the point, so the ray is the exact one. (The reference,
    // in float, skips 2e-6 of the scene: truth/ShadowRays.h.)
    const double margin = 1e-8 * w.size;

    Agreement a;
    const int lights = int(scene.lights.size());
    for (int y = 0; y < options.height; ++y) {
        for (int x = 0; x < options.width; ++x) {
            const double nx = (x + 0.5) / options.width * 2.0 - 1.0;
            const double ny = 1.0 - (y + 0.5) / options.height * 2.0;
            const glm::dvec3 dir = ahead + nx * tanHalf * aspect * right + ny * tanHalf * up;
            const Hit h = nearest(all, w, eye, dir, camera.near, camera.far);
            const int mine = h.found ? w.objectOf[h.triangle] : -1;
            const int theirs = reference.object[std::size_t(y) * options.width + x];
            if (mine < 0 && theirs < 0) continue;
            ++a.pixels;
            if ((mine >= 0 && !opaque(scene, mine)) || (theirs >= 0 && !opaque(scene, theirs))) {
                ++a.notCompared;
                continue;
            }
            if (mine != theirs) {
                ++a.otherSurface;
                continue;
            }
            if (!scene.objects[std::size_t(mine)].receivesShadows) continue;
            const Triangle& t = w.triangles[h.triangle];
            glm::dvec3 n = glm::normalize(dvec(CGAL::cross_product(t[1] - t[0], t[2] - t[0])));
            if (glm::dot(n, dir) > 0.0) n = -n;  // towards the camera
            for (int l = 0; l < lights; ++l) {
                const Light& light = scene.lights[std::size_t(l)];
                if (!light.enabled || !light.castsShadows) continue;
                glm::dvec3 toLight;
                double distance;
                const bool reaches =
                    towards(light, h.point, toLight, distance) && glm::dot(n, toLight) > kEdgeOn;
                const std::size_t at = reference.at(x, y, l);
                if (reaches != bool(reference.applies[at])) {
                    ++a.reachDiffers;
                    continue;
                }
                if (!reaches) continue;
                const glm::dvec3 from = h.point + toLight * (margin / glm::dot(n, toLight));
                const Hit block = nearest(shadowTree, casters, from, toLight, 0.0, distance);
                if (block.found && !opaque(scene, w.objectOf[castingIndex[block.triangle]])) {
                    ++a.notCompared;
                    continue;
                }
                ++a.pairs;
                const bool lit = !block.found, theirLit = reference.hard[at] > 0.5f;
                if (lit != theirLit) {
                    ++a.disagree;
                    a.referenceLit += theirLit ? 1 : 0;
                }
            }
        }
    }
    return a;
}

std::string describe(const Agreement& a) {
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(3);
    s << a.pairs << " pixel x light pairs compared, " << a.disagree << " disagree ("
      << 100.0 * a.disagreeShare() << " %, " << a.referenceLit << " lit by the reference); "
      << a.pixels << " pixels, " << a.otherSurface << " see another surface ("
      << 100.0 * a.otherSurfaceShare() << " %); " << a.reachDiffers
      << " pairs differ on whether the light reaches; " << a.notCompared
      << " not compared (masked or blended surfaces)";
    return s.str();
}

}  // namespace gnomon::crosscheck
