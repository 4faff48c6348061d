#include <runtime/PassTimer.h>

namespace runtime {

namespace {
uint64_t nanosecondsSince(std::chrono::steady_clock::time_point start) {
    return static_cast<uint64_t>(
        std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start)
            .count());
}
}  // namespace

PassTimer::PassTimer(bool enabled, FrameStats& stats, std::vector<GLuint>& queries)
    : mEnabled(enabled), mStats(stats), mQueries(queries) {
    mQueries.clear();
    if (mEnabled) mFrameStart = std::chrono::steady_clock::now();
}

PassTimer::~PassTimer() {
    if (!mEnabled) return;
    if (!mFinished && mPassOpen) gl::EndQuery(GL_TIME_ELAPSED);
    if (!mQueries.empty()) gl::DeleteQueries(static_cast<GLsizei>(mQueries.size()), mQueries.data());
}

void PassTimer::endPass() {
    if (!mPassOpen) return;
    {
        // The driver's share, as the draws' calls are: ending a query makes a software rasterizer hand the
        // pass's binned work to its threads, which at a 2048x2048 map takes longer than the runtime's
        // own work for the pass.
        Scope glTime(*this, &FrameCpuTime::glNs);
        gl::EndQuery(GL_TIME_ELAPSED);
    }
    mStats.passTimings.back().cpuNs = nanosecondsSince(mPassStart);
    mPassOpen = false;
}

void PassTimer::beginPass(const std::string& name) {
    if (!mEnabled) return;
    endPass();
    GLuint query = 0;
    {
        Scope glTime(*this, &FrameCpuTime::glNs);
        gl::GenQueries(1, &query);
    }
    mQueries.push_back(query);
    mStats.passTimings.push_back(PassTiming{name, 0, 0, 0});
    mPassStart = std::chrono::steady_clock::now();
    {
        Scope glTime(*this, &FrameCpuTime::glNs);
        gl::BeginQuery(GL_TIME_ELAPSED, query);
    }
    mPassOpen = true;
}

void PassTimer::finish() {
    if (!mEnabled || mFinished) return;
    endPass();
    mStats.cpu.totalNs = nanosecondsSince(mFrameStart);
    gl::Finish();
    for (size_t i = 0; i < mQueries.size(); ++i) {
        GLuint64 elapsed = 0;
        gl::GetQueryObjectui64v(mQueries[i], GL_QUERY_RESULT, &elapsed);  // waits for the result
        mStats.passTimings[i].gpuNs = elapsed;
    }
    mFinished = true;
}

}  // namespace runtime
