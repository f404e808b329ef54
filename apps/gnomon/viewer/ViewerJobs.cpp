// The viewer's work beyond drawing: the ground-truth score on its own thread, and the files
// it writes (screenshots equal to `gnomon render`'s, scene files).
#include <cstdio>
#include <memory>
#include <thread>

#include "ViewerApp.h"

namespace gnomon::cli::viewer {

void Viewer::startScore() {
    RenderOptions options = mMainOptions;
    options.debugView = DebugView::None;  // frusta are lines over the same shadows
    mScoreError.clear();
    ScoreFrame frame = renderForScore(mRenderer, mState.scene, options);
    mRedraw = true;  // the renderer's last frame is now the scored one
    auto job = std::make_unique<ScoreJob>();
    job->revision = mState.revision;
    ScoreJob* raw = job.get();
    auto scene = std::make_shared<Scene>(mState.scene);
    job->thread = std::thread([raw, scene, options, frame = std::move(frame)]() mutable {
        try {
            raw->result = scoreFrame(std::move(frame), *scene, options, {}, &raw->progress);
        } catch (const std::exception& e) {
            raw->error = e.what();
        }
        raw->done = true;
    });
    mJob = std::move(job);
}

void Viewer::pollScore() {
    if (!mJob || !mJob->done) return;
    mJob->thread.join();
    if (mJob->result) {
        mScore = std::move(mJob->result);
        mScoredRevision = mJob->revision;
        mOverlayTexture = gl::Texture::display2D("score error map", mScore->errors);
        mOverlay = true;
        std::printf(
            "gnomon view: score: misclassified %.4f, false shadow %.4f, leak %.4f "
            "(%.2f s)\n",
            mScore->overall.misclassified, mScore->overall.falseShadow, mScore->overall.leak,
            mScore->traceSeconds);
    } else {
        mScoreError = mJob->error;
        if (mScripted) fail("score: " + mJob->error);
    }
    mJob.reset();
}

std::string Viewer::nextScreenshotPath() {
    const std::string base = mArgs.screenshotDir + "/gnomon-view-" + mState.scene.name + "-";
    for (int n = 1;; ++n) {
        char name[16];
        std::snprintf(name, sizeof name, "%03d.png", n);
        std::FILE* f = std::fopen((base + name).c_str(), "rb");
        if (!f) return base + name;
        std::fclose(f);
    }
}

// The PNG gnomon render writes for these settings: the same renderer, read back.
void Viewer::screenshot(const std::string& path) {
    writePng(path, mRenderer.render(mState.scene, mMainOptions));
    mRedraw = true;
    mLastWritten = path;
    std::printf("gnomon view: wrote %s (%dx%d)\n", path.c_str(), mMainOptions.width,
                mMainOptions.height);
}

void Viewer::save(const std::string& path) {
    saveSceneFile(path, mState.source, mState.scene, mMainOptions, mState.ground);
    mLastWritten = path;
    std::printf("gnomon view: wrote %s\n", path.c_str());
}

}  // namespace gnomon::cli::viewer
