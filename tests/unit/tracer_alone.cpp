// The tracer without Embree, as a build for the browser links it: gnomon_tracer alone
// (AlphaRays, Bvh, BvhTracer), no gnomon_truth, no Embree. Link errors fail this test at
// build time; at run time the camera's central ray must meet tutorial-room, and a ray
// straight up from the floor must be blocked under the cube and free beside it.
#include <cstdio>

#include "gnomon/Scene.h"
#include "truth/Tracer.h"

int main() {
    using namespace gnomon;
    const Scene scene = builtinScene("tutorial-room");
    std::vector<std::vector<glm::vec3>> positions;
    for (const Object& obj : scene.objects) {
        const glm::mat4 m = obj.worldFromModelAt(0.0);
        std::vector<glm::vec3> p;
        for (const glm::vec3& q : scene.meshes[obj.mesh].positions)
            p.push_back(glm::vec3(m * glm::vec4(q, 1.0f)));
        positions.push_back(std::move(p));
    }
    const std::vector<truth::AlphaSurface> alpha(scene.objects.size());
    const auto tracer = truth::makeBvhTracer({&scene, &positions, &alpha, {}});
    const glm::vec3 eye = scene.camera.eye;
    const truth::TraceHit hit =
        tracer->nearest(eye, glm::normalize(scene.camera.centre - eye), 0.0f, 1e4f);
    // The cube spans x -4..-2, y 0..2, z -3..-1 on the floor (y 0): a floor point under it,
    // straight up, is in its shadow; one beside the room's boxes is not.
    const float under = tracer->transmitted({-3.0f, 0.001f, -2.0f}, {0, 1, 0}, 0.0f, 1e4f, nullptr);
    const float open = tracer->transmitted({0.0f, 0.001f, 2.0f}, {0, 1, 0}, 0.0f, 1e4f, nullptr);
    std::printf("central ray: object %d at %g; under the cube %g, in the open %g\n", hit.object,
                double(hit.t), double(under), double(open));
    return hit.hit() && under == 0.0f && open == 1.0f ? 0 : 1;
}
