// LeaveOutFrames: what the tests of leave-out share (test_leave_out.cpp, test_cascades.cpp,
// test_psm_cube_passes.cpp): one 320x240 frame with its statistics, a pass's record by name, and how many
// pixels two frames differ in (leave-out must change none).
#pragma once

#include "effects/EffectHarness.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <string>

namespace shadowfx::test {

struct StatsFrame {
    runtime::FrameImage image;
    runtime::FrameStats stats;
};

inline StatsFrame renderWithStats(runtime::EffectRenderer& renderer, const runtime::Scene& scene,
                                  const std::string& technique, bool leaveOut) {
    runtime::FrameOptions options;
    options.width = 320;
    options.height = 240;
    options.technique = technique;
    options.leaveOut = leaveOut;
    options.countTexels = true;
    fx::DiagnosticList diagnostics;
    StatsFrame frame;
    EXPECT_TRUE(renderer.render(scene, options, diagnostics, &frame.stats)) << diagnostics.str();
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.str();
    frame.image = renderer.readFrame();
    return frame;
}

inline const runtime::PassStats* findPass(const runtime::FrameStats& stats, const std::string& name) {
    for (const runtime::PassStats& pass : stats.passes)
        if (pass.pass == name) return &pass;
    return nullptr;
}

inline size_t differingPixels(const runtime::FrameImage& a, const runtime::FrameImage& b) {
    if (a.rgba.size() != b.rgba.size()) return std::max(a.rgba.size(), b.rgba.size()) / 4;
    size_t differing = 0;
    for (size_t i = 0; i < a.rgba.size(); i += 4)
        differing += std::memcmp(&a.rgba[i], &b.rgba[i], 4) != 0 ? 1 : 0;
    return differing;
}

}  // namespace shadowfx::test
