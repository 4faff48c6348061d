// VisibilityHarness: what the whole-effect tests that score shadows share: an effect compiled with
// SHADOWFX_VISIBILITY (its frame's red channel is the shadow term), a scene's ray-cast truth, and the
// numbers a technique declares in its annotations (ExpectMisclassifiedBelow, ...).
#pragma once

#include "EffectHarness.h"

#include <runtime/GBuffer.h>
#include <runtime/GroundTruth.h>
#include <runtime/ShadowMetrics.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace shadowfx::test {

inline std::unique_ptr<runtime::EffectRenderer> loadVisibilityEffect(
    const std::string& path, std::vector<std::pair<std::string, std::string>> defines = {}) {
    sharedContext();
    fx::DiagnosticList diagnostics;
    fx::ParseOptions options;
    options.defines = std::move(defines);
    options.defines.emplace_back("SHADOWFX_VISIBILITY", "1");
    auto effect = fx::parseEffectFile(sourcePath(path), options, diagnostics);
    auto compiled = effect ? fx::compileEffect(effect, fx::CompileOptions{}, diagnostics) : nullptr;
    if (!compiled || diagnostics.hasErrors()) {
        ADD_FAILURE() << diagnostics.str();
        return nullptr;
    }
    return runtime::EffectRenderer::create(std::shared_ptr<const fx::CompiledEffect>(std::move(compiled)),
                                           diagnostics);
}

struct SceneTruth {
    runtime::Scene scene;
    runtime::GBuffer gbuffer;
    runtime::GroundTruth truth;
    std::vector<uint8_t> receivers;
};

// The G-buffer of `scene`'s camera and light0's visibility at every pixel (soft where the light has an
// areaRadius, with `options.areaSamples`).
inline SceneTruth computeSceneTruth(runtime::Scene scene, int width, int height,
                                    const runtime::GroundTruthOptions& options = {}) {
    SceneTruth t;
    t.scene = std::move(scene);
    fx::DiagnosticList diagnostics;
    sharedContext();
    std::optional<runtime::GBuffer> gbuffer = runtime::renderGBuffer(t.scene, width, height, diagnostics);
    EXPECT_TRUE(gbuffer) << diagnostics.str();
    if (!gbuffer) return t;
    t.gbuffer = std::move(*gbuffer);
    t.truth = runtime::ShadowRayCaster(t.scene).compute(t.gbuffer, t.scene.lights.at(0), options);
    t.receivers = runtime::receiverMask(t.gbuffer, t.scene.lights.at(0));
    return t;
}

// A number a technique declares in its annotations; a test failure if it has none.
inline float techniqueAnnotationNumber(const fx::CompiledEffect& effect, const std::string& technique,
                                       const std::string& name) {
    for (const fx::CompiledTechnique& t : effect.techniques) {
        if (t.name != technique) continue;
        for (const fx::AnnotationValue& a : t.annotations)
            if (a.name == name) return a.value.asFloat();
    }
    ADD_FAILURE() << technique << " has no annotation " << name;
    return 0.0f;
}

}  // namespace shadowfx::test
