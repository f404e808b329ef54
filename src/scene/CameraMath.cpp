#include "scene/CameraMath.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace gnomon {

glm::mat4 safeLookAt(const glm::vec3& eye, const glm::vec3& centre, const glm::vec3& up) {
    const glm::vec3 forward = glm::normalize(centre - eye);
    glm::vec3 u = up;
    // Not normalised first: a zero `up` must take the fallback, not produce NaN.
    const float upLength = glm::length(u);
    if (!(upLength > 0.0f) || !(glm::length(glm::cross(forward, u)) >= 1e-3f * upLength)) {
        const glm::vec3 a = glm::abs(forward);
        u = (a.x <= a.y && a.x <= a.z) ? glm::vec3(1, 0, 0)
            : (a.y <= a.z)             ? glm::vec3(0, 1, 0)
                                       : glm::vec3(0, 0, 1);
    }
    return glm::lookAt(eye, centre, u);
}

glm::mat4 viewFromWorld(const Camera& camera) {
    return safeLookAt(camera.eye, camera.centre, camera.up);
}

glm::mat4 clipFromView(const Camera& camera, float aspect) {
    const float a = camera.aspect > 0.0f ? camera.aspect : aspect;
    if (camera.projection == Projection::Orthographic) {
        return glm::ortho(camera.left, camera.right, camera.bottom, camera.top, camera.near,
                          camera.far);
    }
    return glm::perspective(glm::radians(camera.fovyDegrees), a, camera.near, camera.far);
}

PixelRayTerms pixelRayTerms(const Camera& camera, int width, int height) {
    PixelRayTerms t;
    const glm::mat4 view = viewFromWorld(camera);
    t.right = glm::vec3(view[0][0], view[1][0], view[2][0]);
    t.up = glm::vec3(view[0][1], view[1][1], view[2][1]);
    t.ahead = -glm::vec3(view[0][2], view[1][2], view[2][2]);
    t.viewAspect = camera.aspect > 0.0f ? camera.aspect : float(width) / float(height);
    t.tanHalf = std::tan(0.5f * glm::radians(camera.fovyDegrees));
    t.ortho = camera.projection == Projection::Orthographic;
    t.pixelAtUnit =
        t.ortho ? (camera.top - camera.bottom) / float(height) : 2.0f * t.tanHalf / float(height);
    return t;
}

}  // namespace gnomon
