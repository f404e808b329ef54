#include "render/RelativeScene.h"

#include "scene/SceneUtil.h"

namespace gnomon::render {

Camera RelativeScene::moved(const Camera& camera) const {
    Camera c = camera;
    makeRelative(c, mOrigin);
    return c;
}

const Scene& RelativeScene::of(const Scene& scene, double seconds) {
    if (!mValid || scene.revision.value() != mRevision) {
        // Reads every vertex (the bounds): only for a revision not seen before. Objects that
        // move later keep this origin: it is snapped to a grid of the scene's size.
        mOrigin = sceneOrigin(scene, seconds);
        mRevision = scene.revision.value();
        mValid = true;
        if (mOrigin == glm::vec3(0.0f)) {
            mCopy = Scene();  // nothing kept for a scene used as it is
        } else {
            mCopy = scene;
            for (Object& o : mCopy.objects)
                makeRelative(o, mOrigin);
        }
    }
    if (mOrigin == glm::vec3(0.0f)) return scene;
    // What the revision does not cover, every call (assigned in place: no allocation while
    // the lights keep their count).
    mCopy.camera = moved(scene.camera);
    mCopy.lights = scene.lights;
    for (Light& l : mCopy.lights)
        makeRelative(l, mOrigin);
    mCopy.ambient = scene.ambient;
    return mCopy;
}

}  // namespace gnomon::render
