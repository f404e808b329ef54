// Times one pass at a time for Renderer::setPassTiming: the GPU's work finished before and
// after (gl::Finisher), wall time in between (on Mesa 22.3, llvmpipe's timer queries read
// about 0 for fragment-heavy passes), and fragment shader invocations from a pipeline statistics
// query where the driver offers GL_ARB_pipeline_statistics_query.
#pragma once

#include <chrono>
#include <string>

#include "gl/Caps.h"
#include "gl/Objects.h"
#include "gl/State.h"
#include "gnomon/Renderer.h"

namespace gnomon::render {

class PassClock {
public:
    PassClock() {
        if (gl::activeCaps().pipelineStatistics) {
            mQuery = gl::Query("pass fragments", GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
        }
    }
    void start() {
        mFinisher.wait();
        if (mQuery) glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, mQuery.id());
        mStart = std::chrono::steady_clock::now();
    }
    PassTiming stop(std::string name, int light, std::uint64_t triangles) {
        mFinisher.wait();
        PassTiming t;
        t.milliseconds =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - mStart)
                .count();
        if (mQuery) {
            glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
            t.fragments = std::int64_t(mQuery.result());
        }
        t.name = std::move(name);
        t.light = light;
        t.triangles = triangles;
        return t;
    }

private:
    gl::Finisher mFinisher;
    gl::Query mQuery;
    std::chrono::steady_clock::time_point mStart;
};

}  // namespace gnomon::render
