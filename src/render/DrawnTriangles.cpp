#include "render/DrawnTriangles.h"

namespace gnomon::render {

void DrawnTriangles::setMeshes(const Scene& scene, const std::vector<CullingSplit>& splits) {
    mPlaces.clear();
    for (std::size_t m = 0; m < scene.meshes.size(); ++m)
        mPlaces.push_back(trianglePlaces(scene.meshes[m].indices, splits[m].indices));
}

void DrawnTriangles::setObjects(const Scene& scene) {
    mObjectFirst.resize(scene.objects.size());
    std::size_t next = 0;
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        mObjectFirst[o] = std::uint32_t(next);
        next += scene.meshes[scene.objects[o].mesh].indices.size() / 3;
    }
    mTotal = next;
}

}  // namespace gnomon::render
