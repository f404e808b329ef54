#include "render/RelativeScene.h"

#include <glm/gtc/matrix_transform.hpp>

#include "scene/SceneUtil.h"

namespace gnomon::render {

namespace {

// p - origin, in double: the moved point is as exact as the float the world gave.
glm::vec3 minus(const glm::vec3& p, const glm::vec3& origin) {
    return glm::vec3(glm::dvec3(p) - glm::dvec3(origin));
}

}  // namespace

Camera RelativeScene::moved(const Camera& camera) const {
    Camera c = camera;
    c.eye = minus(camera.eye, mOrigin);
    c.centre = minus(camera.centre, mOrigin);
    return c;
}

const Scene& RelativeScene::of(const Scene& scene, double seconds) {
    if (!mValid || scene.revision.value() != mRevision) {
        // Reads every vertex (the bounds): only for a revision not seen before. Objects that
        // move later keep this origin: it is snapped to a grid of the scene's size.
        mOrigin = coordinateOrigin(worldBounds(scene, meshBounds(scene), seconds, false));
        mRevision = scene.revision.value();
        mValid = true;
        if (mOrigin == glm::vec3(0.0f)) {
            mCopy = Scene();  // nothing kept for a scene used as it is
        } else {
            mCopy = scene;
            const glm::dmat4 relativeFromWorld =
                glm::translate(glm::dmat4(1.0), -glm::dvec3(mOrigin));
            for (Object& o : mCopy.objects) {
                o.worldFromModel = glm::mat4(relativeFromWorld * glm::dmat4(o.worldFromModel));
                o.spin.pivot = minus(o.spin.pivot, mOrigin);
            }
        }
    }
    if (mOrigin == glm::vec3(0.0f)) return scene;
    // What the revision does not cover, every call (assigned in place: no allocation while
    // the lights keep their count).
    mCopy.camera = moved(scene.camera);
    mCopy.lights = scene.lights;
    for (Light& l : mCopy.lights) {
        l.position = minus(l.position, mOrigin);
        l.shadowCamera.target = minus(l.shadowCamera.target, mOrigin);
    }
    mCopy.ambient = scene.ambient;
    return mCopy;
}

}  // namespace gnomon::render
