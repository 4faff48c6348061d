// CheckExpectations: what a technique promises `shadowfx check` in its Expect* annotations (docs/scoring.md),
// read from the effect's syntax or its compiled file: the scenes to check and per-scene bounds.
#pragma once

#include <fx/CompiledEffect.h>
#include <fx/Diagnostics.h>
#include <fx/Effect.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace runtime {

// A scene as the table and per-scene bounds name it: a scene file's stem, a built-in scene's name.
std::string sceneLabel(const std::string& scene);

// A bound for every scene, or one per scene where a technique's error differs by scene (a number, or a
// string "dual-l=0.25, teapot=0.12").
struct SceneBound {
    std::optional<double> everyScene;
    std::map<std::string, double> perScene;  // by scene label (a scene file's stem)

    bool declared() const { return everyScene || !perScene.empty(); }
    std::optional<double> forScene(const std::string& scene) const {
        if (everyScene) return everyScene;
        const auto found = perScene.find(scene);
        return found == perScene.end() ? std::nullopt : std::optional<double>(found->second);
    }
};

struct Expectations {
    std::vector<std::string> scenes{"boxes"};
    SceneBound misclassifiedBelow;    // percent of receiver pixels
    SceneBound penumbraMaeBelow;      // mean |visibility - truth| over the penumbra, area lights
    std::optional<float> areaRadius;  // light0's areaRadius for the penumbra check
    std::optional<int> mapSize;       // SHADOWFX_SHADOW_MAP_SIZE for the check's renders
    bool shadows = true;              // false: compile, render, non-blank and golden only
};

// Reads the Expect* annotations of `technique` (names case-insensitive, as annotation lookups are). A value
// of the wrong kind or an unknown Expect* name is an error at the annotation (ExpectationUnknown and the
// other Expect* ids); false then.
bool readExpectations(const fx::Technique& technique, Expectations& out, fx::DiagnosticSink& sink);
// The same of a technique of a compiled effect (a compiled effect file), whose annotations are values: the
// errors are located at the technique.
bool readExpectations(const fx::CompiledTechnique& technique, Expectations& out, fx::DiagnosticSink& sink);

}  // namespace runtime
