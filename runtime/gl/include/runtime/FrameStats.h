// FrameStats: what one rendered frame did, pass by pass: counts of draws, clears, culled objects and
// texels, and with FrameOptions::timePasses the GPU and CPU time of each pass (runtime/PassTimer.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace runtime {

// What one executed Pass= did (a pass run by a LoopByCount appears once per iteration).
struct PassStats {
    std::string pass;
    bool lightPort = false;  // RenderPort names a light
    std::string leftOut;     // "" ran; "dead" (nothing reads its writes), "cached" (targets kept from the
                             // last frame), "scene" (its LeaveOutWhen holds), or several joined by "+" in
                             // that order; a pass with only some operations left out ran
    int draws = 0;
    int objects = 0;         // objects drawn: one per draw, or several per instanced draw (batching)
    int depthOnlyDraws = 0;  // of `draws`, drawn without colour targets or pixel shader (depthOnlyPasses)
    int culled = 0;          // objects a Draw=Geometry left out
    uint64_t triangles = 0;
    int clears = 0;
    int depthOnlyClears = 0;     // of `clears`, bound as the pass's depth-only draws are (depthOnlyPasses)
    uint64_t texelsWritten = 0;  // cleared texels + fragments drawn (the latter with countTexels)
};

// One executed pass of a timed frame (FrameOptions::timePasses); a pass run by a LoopByCount appears once
// per iteration, in execution order.
struct PassTiming {
    std::string pass;
    uint64_t gpuNs = 0;  // GL_TIME_ELAPSED from the pass's start to the next pass's (its clears included)
    uint64_t cpuNs = 0;  // CPU time the runtime spent issuing the pass
    int draws = 0;
};

// Where a timed frame's CPU time went. Everything but `glNs` is the runtime's own overhead.
struct FrameCpuTime {
    uint64_t totalNs = 0;      // the whole render() call before waiting for the GPU
    uint64_t bindingNs = 0;    // semantic binding (SemanticBinder) and uniform upload
    uint64_t preshaderNs = 0;  // evaluating pass arguments and render-state preshaders
    uint64_t glNs = 0;         // inside GL draw, clear and framebuffer calls (the driver's share)
    // Script interpretation and the rest of the runtime: totalNs - bindingNs - preshaderNs - glNs.
    uint64_t scriptNs() const {
        const uint64_t known = bindingNs + preshaderNs + glNs;
        return totalNs > known ? totalNs - known : 0;
    }
};

// Counts of the work one frame did: what `render --stats` prints.
struct FrameStats {
    int passesRun = 0;  // Pass= commands executed (passes that only clear included)
    int draws = 0;
    int objects = 0;  // objects drawn (PassStats::objects)
    uint64_t triangles = 0;
    int clears = 0;
    int culled = 0;         // objects left out of Draw=Geometry commands
    int passesLeftOut = 0;  // Pass= commands none of whose clears and draws ran (PassStats::leftOut)
    // Preshader programs run (render states and compile arguments, fx/PreshaderProgram.h): only those
    // one of whose input parameters changed since their last run; 0 for a frame that changes nothing.
    uint64_t preshaderRuns = 0;
    // Batching's per-object records (FrameOptions::batching) packed: whole (an object first drawn or
    // changed), and their view part alone (only the port's or a light's matrices changed, as when the
    // camera moves: World*View*Projection packed again, World and the object's colour kept). Both 0 for a
    // frame that changes nothing.
    uint64_t recordsPacked = 0;
    uint64_t recordViewPartsPacked = 0;
    std::vector<PassStats> passes;
    std::vector<PassTiming> passTimings;  // only with FrameOptions::timePasses
    FrameCpuTime cpu;                     // only with FrameOptions::timePasses

    // Back to a frame that did nothing, the lists emptied but keeping their storage: a renderer filling
    // the same FrameStats every frame allocates nothing for them (`= {}` would free it).
    void reset() {
        std::vector<PassStats> keptPasses = std::move(passes);
        std::vector<PassTiming> keptTimings = std::move(passTimings);
        *this = {};
        keptPasses.clear();
        keptTimings.clear();
        passes = std::move(keptPasses);
        passTimings = std::move(keptTimings);
    }
};

}  // namespace runtime
