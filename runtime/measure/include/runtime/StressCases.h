// StressCases: the named extreme configurations `shadowfx stress` runs every effect through — the stiff
// cases where shadow-map implementations break (light along the view, degenerate up vectors, grazing
// light, extreme near/far and field of view, scenes far from the origin or scaled, empty and degenerate
// scenes, a camera inside an occluder, a slow camera move for shimmer). Each case is a reproducible scene,
// camera and light, built from a built-in scene; nothing is random.
#pragma once

#include <runtime/Scene.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace runtime {

struct StressCase {
    std::string name;
    std::string description;
    Scene scene;
    // Where the exact (ray-cast) shadows are computed, when not on `scene` itself: for the translated
    // scene, the same scene at the origin, whose float geometry the ray caster resolves exactly.
    std::optional<Scene> truthScene;
    // The nearest ordinary configuration, whose error this case is held to ("" for an ordinary case).
    std::string ordinary;
    // A temporal case renders one frame per camera (scene.camera is the first); empty for a single frame.
    std::vector<Camera> cameraPath;
    // The case is expected to have no lit or shadowed receiver pixels (an empty scene, a camera inside an
    // occluder): only the finite-value and GL checks apply.
    bool expectNoReceivers = false;
    // Part of the reduced set that CI runs for every effect.
    bool reduced = false;
};

// Every case, ordinary ones first (a stress run measures them before the cases held to them).
std::vector<std::string> stressCaseNames();
// The cases CI runs (StressCase::reduced), in the same order.
std::vector<std::string> reducedStressCaseNames();
std::optional<StressCase> makeStressCase(std::string_view name);

}  // namespace runtime
