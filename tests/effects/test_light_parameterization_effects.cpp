// The Parameterization annotation end to end (docs/techniques/light-space-parameterizations.md): focused.fx,
// lispsm.fx, tsm.fx and psm.fx bind their light matrices from the provider's fit, which is what
// RenderPort=light0 renders with (EffectRenderer::lightFit), not the uniform fit; an unknown or conflicting
// name is an error at the annotation. Pancaking clamps the casters before the receivers' depth range onto
// the map's near plane.
#include "VisibilityHarness.h"

#include <private/runtime/SceneBuilding.h>

#include <runtime/BuiltinScenes.h>
#include <runtime/LightParameterization.h>
#include <runtime/SceneFile.h>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstring>

namespace test_light_parameterization_effects {

namespace {

using namespace runtime;
using shadowfx::test::loadEffect;
using shadowfx::test::sourcePath;

glm::mat4 matrixParameter(const EffectRenderer& renderer, const std::string& name) {
    const std::optional<size_t> index = renderer.findParameter(name);
    EXPECT_TRUE(index.has_value()) << name;
    glm::mat4 m(0.0f);
    if (!index) return m;
    const fx::Value& value = renderer.parameter(*index);
    EXPECT_EQ(value.data.size(), 16u) << name;
    if (value.data.size() == 16) std::memcpy(glm::value_ptr(m), value.data.data(), sizeof(m));
    return m;
}

class ParameterizedEffect : public ::testing::TestWithParam<const char*> {};

TEST_P(ParameterizedEffect, BindsTheProvidersFitNotTheUniformOne) {
    auto renderer = loadEffect(sourcePath(std::string("effects/") + GetParam()), true);
    ASSERT_TRUE(renderer);
    const std::optional<Scene> scene = makeBuiltinScene("teapot");
    ASSERT_TRUE(scene);
    ASSERT_TRUE(shadowfx::test::render(*renderer, *scene, 160, 120));
    FrameOptions options;
    options.width = 160;
    options.height = 120;
    const std::optional<LightFit> fit = renderer->lightFit(*scene, "light0", options);
    ASSERT_TRUE(fit);
    EXPECT_EQ(matrixParameter(*renderer, "LightViewMatrix"), fit->view);
    EXPECT_EQ(matrixParameter(*renderer, "LightProjectionMatrix"), fit->projection);
    const Light& light = *scene->findLight("light0");
    const Bounds bounds = scene->bounds();
    EXPECT_NE(fit->projection, light.projection(bounds, nearestDepthFrom(*scene, light)));
    EXPECT_FALSE(renderer->lightFit(*scene, "no-such-light", options).has_value());
}

INSTANTIATE_TEST_SUITE_P(Effects, ParameterizedEffect,
                         ::testing::Values("focused.fx", "lispsm.fx", "tsm.fx", "psm.fx"),
                         [](const auto& info) {
                             return std::string(info.param).substr(0, std::strlen(info.param) - 3);
                         });

// A floating slab 6 m above the ground, and a camera 2 m up looking straight down at its shadow: the slab is
// outside the view, so B holds only the ground patch and, pancaked, the slab lies before the map's depth
// range.
Scene slabOverGround() {
    Scene scene;
    scene.name = "slab-over-ground";
    scene.objects.push_back(
        placeObject("ground", share(makePlane(40.0f, 40.0f)), glm::mat4(1.0f), glm::vec3(0.8f), 1));
    scene.objects.push_back(placeObject("slab", share(makeBox({3.0f, 0.5f, 3.0f})),
                                        glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 6.0f, 0.0f)),
                                        glm::vec3(0.8f), 2));
    scene.camera.position = {0.0f, 2.0f, 0.0f};
    scene.camera.target = {0.0f, 0.0f, 0.01f};
    scene.lights.push_back(fittedDirectionalLight(glm::vec3(0.25f, -1.0f, 0.0f), scene.bounds()));
    return scene;
}

TEST(Pancaking, CastersBeforeTheReceiversStillShadowThem) {
    const Scene scene = slabOverGround();
    const shadowfx::test::SceneTruth truth = shadowfx::test::computeSceneTruth(scene, 160, 120);
    ASSERT_FALSE(truth.truth.visibility.empty());
    auto renderer = shadowfx::test::loadVisibilityEffect("effects/focused.fx");
    ASSERT_TRUE(renderer);
    const std::optional<size_t> pancake = renderer->findParameter("Pancake");
    ASSERT_TRUE(pancake);
    fx::Value on = renderer->parameter(*pancake);
    on.data.assign(on.data.size(), 1.0f);

    FrameOptions options;
    options.width = 160;
    options.height = 120;
    auto misclassified = [&]() {
        EXPECT_TRUE(shadowfx::test::render(*renderer, scene, 160, 120));
        return compareVisibility(truth.truth.visibility, visibilityFromFrame(renderer->readFrame()),
                                 truth.receivers)
            .misclassifiedPercent;
    };
    const float whole = misclassified();
    const LightFit deep = *renderer->lightFit(scene, "light0", options);
    renderer->setParameter(*pancake, on);
    const float pancaked = misclassified();
    const LightFit flat = *renderer->lightFit(scene, "light0", options);

    // The case pancakes: the slab's top is before the near plane of the pancaked fit, not of the deep one.
    const glm::vec4 slabTop = flat.projection * flat.view * glm::vec4(0.0f, 6.25f, 0.0f, 1.0f);
    EXPECT_LT(slabTop.z / slabTop.w, -0.5f);
    const glm::vec4 slabTopDeep = deep.projection * deep.view * glm::vec4(0.0f, 6.25f, 0.0f, 1.0f);
    EXPECT_GE(slabTopDeep.z / slabTopDeep.w, 0.0f);
    // The shadow is there (a third of the view or more: the slab shadows x in [0, 3]) and the clamped slab
    // still casts it.
    size_t shadowed = 0;
    for (size_t i = 0; i < truth.truth.visibility.size(); ++i)
        shadowed += truth.receivers[i] && truth.truth.visibility[i] < 0.5f;
    EXPECT_GT(shadowed, truth.truth.visibility.size() / 3);
    EXPECT_LT(whole, 0.5f);
    EXPECT_LT(pancaked, whole + 0.2f) << "pancaked casters were clipped instead of clamped";
}

// psm.fx's tunables reach the provider through their semantics (PSMSlideBack): a long slide-back gives a
// different fit from the automatic one, the one fitLight computes with the same tunable.
TEST(PsmEffect, SlideBackParameterReachesTheProvider) {
    auto renderer = loadEffect(sourcePath("effects/psm.fx"), true);
    ASSERT_TRUE(renderer);
    const std::optional<Scene> scene = makeBuiltinScene("teapot");
    ASSERT_TRUE(scene);
    FrameOptions options;
    options.width = 160;
    options.height = 120;
    const std::optional<LightFit> automatic = renderer->lightFit(*scene, "light0", options);
    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(renderer->setParameterFromText("SlideBack", "500", diagnostics)) << diagnostics.str();
    const std::optional<LightFit> slid = renderer->lightFit(*scene, "light0", options);
    ASSERT_TRUE(automatic && slid);
    EXPECT_NE(automatic->projection, slid->projection);
    LightTunables tunables;
    tunables.psmSlideBack = 500.0f;
    const LightFit expected = fitLight(LightParameterization::PSM, *scene, scene->bounds(), 160.0f / 120.0f,
                                       *scene->findLight("light0"), tunables);
    EXPECT_EQ(slid->projection, expected.projection);
}

// lispsm.fx's NOpt (semantic LiSPSMNOpt) reaches the provider: "Wimmer2004" (the default) and "Scherzer2005"
// give the fits fitLight computes with those choices, which differ on the city field (its camera sees the
// scene begin far beyond the near plane); an unknown name is a located error and the fit stays.
TEST(LispsmEffect, NOptParameterReachesTheProvider) {
    auto renderer = loadEffect(sourcePath("effects/lispsm.fx"), true);
    ASSERT_TRUE(renderer);
    fx::DiagnosticList loading;
    const std::optional<Scene> scene = loadScene(sourcePath("scenes/city_field.json"), loading);
    ASSERT_TRUE(scene) << loading.str();
    FrameOptions options;
    options.width = 160;
    options.height = 120;
    const Light& light = *scene->findLight("light0");
    auto expected = [&](LispsmN choice) {
        LightTunables tunables;
        tunables.lispsmN = choice;
        return fitLight(LightParameterization::LiSPSM, *scene, scene->bounds(), 160.0f / 120.0f, light,
                        tunables);
    };
    const std::optional<LightFit> wimmer = renderer->lightFit(*scene, "light0", options);
    ASSERT_TRUE(wimmer);
    EXPECT_EQ(wimmer->projection, expected(LispsmN::Wimmer2004).projection);
    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(renderer->setParameterFromText("NOpt", "Scherzer2005", diagnostics)) << diagnostics.str();
    const std::optional<LightFit> scherzer = renderer->lightFit(*scene, "light0", options);
    ASSERT_TRUE(scherzer);
    EXPECT_EQ(scherzer->projection, expected(LispsmN::Scherzer2005).projection);
    EXPECT_NE(scherzer->projection, wimmer->projection);
    EXPECT_GT(scherzer->warp, wimmer->warp);

    ASSERT_TRUE(renderer->setParameterFromText("NOpt", "Lloyd2007", diagnostics));
    fx::DiagnosticList rendering;
    renderer->render(*scene, options, rendering);
    const auto error =
        std::find_if(rendering.items().begin(), rendering.items().end(),
                     [](const fx::Diagnostic& d) { return d.id == fx::DiagId::LispsmChoiceInvalid; });
    ASSERT_NE(error, rendering.items().end()) << rendering.str();
    EXPECT_NE(error->message.find("'Lloyd2007' is not a choice of LiSPSM's n"), std::string::npos)
        << error->message;
    EXPECT_NE(error->loc.line, 0);

    // The frame reads the string once per change of the parameter: an invalid choice stays reported every
    // frame it stands, and a valid one set again is read at the next frame.
    const auto reportsChoice = [](const fx::DiagnosticList& list) {
        return std::any_of(list.items().begin(), list.items().end(),
                           [](const fx::Diagnostic& d) { return d.id == fx::DiagId::LispsmChoiceInvalid; });
    };
    fx::DiagnosticList again;
    renderer->render(*scene, options, again);
    EXPECT_TRUE(reportsChoice(again)) << again.str();
    ASSERT_TRUE(renderer->setParameterFromText("NOpt", "Scherzer2005", diagnostics)) << diagnostics.str();
    fx::DiagnosticList valid;
    renderer->render(*scene, options, valid);
    EXPECT_FALSE(reportsChoice(valid)) << valid.str();
}

const fx::Diagnostic* findParameterizationError(const fx::DiagnosticList& diagnostics) {
    for (const fx::Diagnostic& d : diagnostics.items())
        if (d.id == fx::DiagId::ParameterizationUnknown || d.id == fx::DiagId::ParameterizationConflict)
            return &d;
    return nullptr;
}

std::string effectWith(const std::string& viewName, const std::string& projectionName) {
    return "float4x4 LightView : View < string frustum = \"light0\"; string Parameterization = \"" +
           viewName +
           "\"; >;\n"
           "float4x4 LightProjection : Projection < string frustum = \"light0\"; string Parameterization = "
           "\"" +
           projectionName +
           "\"; >;\n"
           "float4x4 WorldViewProjection : WorldViewProjection;\n"
           "float4 Vs(float4 p : POSITION) : POSITION { return mul(float4(p.xyz, 1), WorldViewProjection); "
           "}\n"
           "float4 Ps() : COLOR { return float4(1, 1, 1, 1); }\n"
           "technique t { pass p { VertexShader = compile vs_3_0 Vs(); PixelShader = compile ps_3_0 Ps(); } "
           "}\n";
}

fx::DiagnosticList renderReporting(const std::string& source) {
    fx::DiagnosticList diagnostics;
    auto renderer = loadEffect(source, false, "parameterized.fx");
    if (!renderer) return diagnostics;
    const std::optional<Scene> scene = makeBuiltinScene("boxes");
    FrameOptions options;
    options.width = 64;
    options.height = 48;
    renderer->render(*scene, options, diagnostics);
    return diagnostics;
}

TEST(ParameterizationAnnotation, UnknownNameIsAnErrorAtTheAnnotation) {
    const fx::DiagnosticList diagnostics = renderReporting(effectWith("Trapezoidal", "Trapezoidal"));
    const fx::Diagnostic* error = findParameterizationError(diagnostics);
    ASSERT_NE(error, nullptr) << diagnostics.str();
    EXPECT_EQ(error->id, fx::DiagId::ParameterizationUnknown);
    EXPECT_EQ(error->loc.line, 1);
    EXPECT_NE(error->message.find("LiSPSM"), std::string::npos) << error->message;
    EXPECT_NE(error->message.find("TSM"), std::string::npos) << error->message;
}

TEST(ParameterizationAnnotation, TwoNamesForOneLightAreAnError) {
    const fx::DiagnosticList diagnostics = renderReporting(effectWith("Focused", "LiSPSM"));
    const fx::Diagnostic* error = findParameterizationError(diagnostics);
    ASSERT_NE(error, nullptr) << diagnostics.str();
    EXPECT_EQ(error->id, fx::DiagId::ParameterizationConflict);
    EXPECT_EQ(error->loc.line, 2);
    EXPECT_NE(error->message.find("Focused"), std::string::npos) << error->message;
}

TEST(ParameterizationAnnotation, OneNameIsAccepted) {
    const fx::DiagnosticList diagnostics = renderReporting(effectWith("LiSPSM", "lispsm"));
    EXPECT_EQ(findParameterizationError(diagnostics), nullptr) << diagnostics.str();
}

}  // namespace
}  // namespace test_light_parameterization_effects
