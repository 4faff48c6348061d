// PassTimer: the timing of one frame for FrameOptions::timePasses — a GL_TIME_ELAPSED query and a CPU
// clock per executed pass, and counters of the CPU time the runtime spends binding semantics, evaluating
// preshaders and inside GL calls. Disabled, every member is a no-op that reads no clock.
//
// GL_TIME_ELAPSED queries cannot nest, so a pass's query runs from its beginPass to the next pass's: a
// technique-level script command between two passes is charged to the earlier one.
#pragma once

#include <runtime/GlApi.h>

#include <runtime/FrameStats.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

namespace runtime {

class PassTimer {
public:
    // `queries`: where the frame's query names go, emptied first (kept by the caller between frames, so
    // that timing a frame allocates nothing).
    PassTimer(bool enabled, FrameStats& stats, std::vector<GLuint>& queries);
    ~PassTimer();
    PassTimer(const PassTimer&) = delete;
    PassTimer& operator=(const PassTimer&) = delete;

    bool enabled() const { return mEnabled; }
    void beginPass(const std::string& name);
    void countDraw() {
        if (mEnabled && !mStats.passTimings.empty()) ++mStats.passTimings.back().draws;
    }
    // Ends the last pass, records the CPU total, then waits for the GPU and reads every query.
    void finish();

    // Adds the lifetime of the scope to one of the FrameCpuTime counters (nothing when disabled). Scopes
    // nest: an inner scope's time is its own counter's, not the enclosing scope's, so that a loop over the
    // visible objects can be timed as one binding scope around its few GL or preshader scopes instead of
    // reading the clock twice per object and per counter (a clock read costs 30-150 ns in a VM, per
    // object more than the binding it measures).
    class Scope {
    public:
        Scope(const PassTimer& timer, uint64_t FrameCpuTime::*counter)
            : mTimer(timer.mEnabled ? &timer : nullptr),
              mCounter(timer.mEnabled ? &(timer.mStats.cpu.*counter) : nullptr) {
            if (!mTimer) return;
            mEnclosing = mTimer->mInnermost;
            mTimer->mInnermost = this;
            mStart = std::chrono::steady_clock::now();
        }
        ~Scope() {
            if (!mTimer) return;
            const uint64_t elapsed =
                static_cast<uint64_t>((std::chrono::steady_clock::now() - mStart).count());
            *mCounter += elapsed > mInnerNs ? elapsed - mInnerNs : 0;
            if (mEnclosing) mEnclosing->mInnerNs += elapsed;
            mTimer->mInnermost = mEnclosing;
        }
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;

    private:
        const PassTimer* mTimer;
        uint64_t* mCounter;
        Scope* mEnclosing = nullptr;
        uint64_t mInnerNs = 0;  // the time of the scopes nested in this one
        std::chrono::steady_clock::time_point mStart;
    };

private:
    void endPass();

    bool mEnabled;
    FrameStats& mStats;
    std::chrono::steady_clock::time_point mFrameStart;
    std::chrono::steady_clock::time_point mPassStart;
    std::vector<GLuint>& mQueries;  // one per entry of mStats.passTimings
    bool mPassOpen = false;
    bool mFinished = false;
    mutable Scope* mInnermost = nullptr;  // the scope open now, innermost first
};

}  // namespace runtime
