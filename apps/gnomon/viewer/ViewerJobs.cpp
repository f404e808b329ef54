// The viewer's work beyond drawing: the ground-truth score and gnomon tune (on threads of
// their own natively, a slice a frame in the page), and the files it writes (screenshots equal to
// `gnomon render`'s, scene files).
#include <algorithm>
#include <cmath>
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
    ScoreOptions scoreOptions;
    scoreOptions.explain = true;                 // the causes line of the score panel
    if (!kJobThreads) scoreOptions.threads = 1;  // the page's one thread
    job->task = std::make_unique<ScoreTask>(std::move(frame), mState.scene, options, scoreOptions);
    if (kJobThreads) {
        ScoreJob* raw = job.get();
        job->thread = std::thread([raw] {
            try {
                while (!raw->task->step(1.0)) {
                }
                raw->result = raw->task->result();
            } catch (const std::exception& e) {
                raw->error = e.what();
            }
            raw->done = true;
        });
    }
    mJob = std::move(job);
}

// A slice of the score on the app loop (no job threads).
void Viewer::stepScore() {
    try {
        if (mJob->task->step(kJobSliceSeconds)) {
            mJob->result = mJob->task->result();
            mJob->done = true;
        }
    } catch (const std::exception& e) {
        mJob->error = e.what();
        mJob->done = true;
    }
}

void Viewer::pollScore() {
    if (!mJob) return;
    if (!kJobThreads && !mJob->done) stepScore();
    if (!mJob->done) return;
    if (mJob->thread.joinable()) mJob->thread.join();
    if (mJob->result) {
        mScore = std::move(mJob->result);
        mScoredRevision = mJob->revision;
        ++mScoresDone;
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

// The search runs at most 384 pixels on the long side (each trial renders, scores and times
// the view; at the window's size a tune would take many minutes), over a copy of the scene.
void Viewer::startTune() {
    RenderOptions options = mMainOptions;
    options.debugView = DebugView::None;
    const float scale = std::min(1.0f, 384.0f / float(std::max(options.width, options.height)));
    options.width = std::max(16, int(std::lround(float(options.width) * scale)));
    options.height = std::max(16, int(std::lround(float(options.height) * scale)));
    mTuneError.clear();
    auto job = std::make_unique<TuneJob>();
    job->revision = mState.revision;
    job->scene = std::make_shared<Scene>(mState.scene);
    TuneJob* raw = job.get();
    TuneOptions tuneOptions;
    tuneOptions.maxSweeps = 2;
    auto onTrial = [raw](const TuneTrial& t) {
        char line[200];
        if (!t.failure.empty()) {
            std::snprintf(line, sizeof line, "failed: %s", t.flags.c_str());
        } else {
            std::snprintf(line, sizeof line, "%.3f%% in %.1f ms: %s", 100.0 * t.misclassified,
                          t.frameMs, t.flags.empty() ? "(current settings)" : t.flags.c_str());
        }
        ++raw->trials;
        const std::lock_guard<std::mutex> lock(raw->mutex);
        raw->latest = line;
    };
    if (kJobThreads) {
        job->thread = std::thread([raw, options, tuneOptions, onTrial] {
            try {
                raw->renderer = std::make_unique<Renderer>();
                raw->task = std::make_unique<TuneTask>(*raw->renderer, *raw->scene, options,
                                                       tuneOptions, onTrial);
                while (!raw->step(0.25)) {
                }
                raw->result = raw->task->result();
            } catch (const std::exception& e) {
                raw->error = e.what();
            }
            raw->task.reset();  // before the renderer it draws with, on its thread
            raw->renderer.reset();
            raw->done = true;
        });
    } else {
        job->task =
            std::make_unique<TuneTask>(mRenderer, *job->scene, options, tuneOptions, onTrial);
    }
    mTuneJob = std::move(job);
}

// A slice of the tune on the app loop, drawn with the viewer's renderer as a render or a
// bench would (fresh maps, no pass timing); the view is drawn again afterwards.
void Viewer::stepTune() {
    mRenderer.setFollowing(false);
    mRenderer.setPassTiming(false);
    try {
        if (mTuneJob->step(kJobSliceSeconds)) {
            mTuneJob->result = mTuneJob->task->result();
            mTuneJob->done = true;
        }
    } catch (const std::exception& e) {
        mTuneJob->error = e.what();
        mTuneJob->done = true;
    }
    mRenderer.setPassTiming(mMeasure);
    mRenderer.setFollowing(true);
    mRedraw = true;
}

void Viewer::pollTune() {
    if (!mTuneJob) return;
    if (!kJobThreads && !mTuneJob->done) stepTune();
    if (!mTuneJob->done) return;
    if (mTuneJob->thread.joinable()) mTuneJob->thread.join();
    if (mTuneJob->result) {
        mTune = std::move(mTuneJob->result);
        mTunedRevision = mTuneJob->revision;
        const TuneTrial& start = mTune->trials.front();
        const TuneTrial& best = mTune->best >= 0 ? mTune->trials[std::size_t(mTune->best)] : start;
        std::printf(
            "gnomon view: tune: %zu trials%s; best within %.1f ms: %s (misclassified "
            "%.4f, from %.4f)%s\n",
            mTune->trials.size(), mTune->timedOut ? " (stopped at its time limit)" : "",
            mTune->budgetMs, best.flags.empty() ? "the current settings" : best.flags.c_str(),
            best.misclassified, start.misclassified,
            mTune->shifted.done && !mTune->shifted.holds
                ? "; not borne out half a pixel away: the current settings are kept"
                : "");
    } else {
        mTuneError = mTuneJob->error;
        if (mScripted) fail("tune: " + mTuneJob->error);
    }
    mTuneJob.reset();
}

// The chosen settings' shadow options over the current ones (the view's size stays), and the
// map size they gave each light: the best's, where the views shifted by half a pixel bore its
// gain out (TuneResult::chosen).
void Viewer::applyTune() {
    if (!mTune || mTune->chosen < 0)
        throw Error(ErrorKind::InvalidInput, "apply-tune: no tune result to apply");
    const TuneTrial& best = mTune->trials[std::size_t(mTune->chosen)];
    mState.options.shadow = best.options.shadow;
    applyMapSizes(best.mapSizes, mState.scene);
    changed(true);
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

// The PNG gnomon render writes for these settings: the same renderer, read back, its maps
// fitted afresh as a single render's are (not held from the frames before).
void Viewer::screenshot(const std::string& path) {
    mRenderer.setFollowing(false);
    Image image = mRenderer.render(mState.scene, mMainOptions);
    mRenderer.setFollowing(true);
    writePng(path, image);
    mRedraw = true;
    mLastWritten = path;
    std::printf("gnomon view: wrote %s (%dx%d)\n", path.c_str(), mMainOptions.width,
                mMainOptions.height);
}

void Viewer::save(const std::string& path) {
    saveSceneFile(path, mState.source, mState.scene, mMainOptions, mState.ground, mState.up);
    mLastWritten = path;
    std::printf("gnomon view: wrote %s\n", path.c_str());
}

}  // namespace gnomon::cli::viewer
