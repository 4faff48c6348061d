// Real FX Composer files must load, not only ours: an effect written the way NVIDIA's shader library
// wrote them (tests/data/fxcomposer/), and every effect shipped in effects/, through the whole pipeline.
#include "EffectHarness.h"
#include <runtime/BuiltinScenes.h>

#include <filesystem>

namespace shadowfx::test::test_fxcomposer_files {
namespace {

// The post-process pass reads the scene target through a sampler handed over as a `uniform` argument
// of its compile expression and swaps red and blue; so the final frame must be the scene target with
// its channels swapped, pixel for pixel (texel centres line up: ViewPortRatio 1, linear filtering).
TEST(FxComposerFiles, NvidiaStylePostProcessEffectRunsBothPasses) {
    sharedContext();
    fx::DiagnosticList diagnostics;
    std::shared_ptr<fx::Effect> effect =
        fx::parseEffectFile("tests/data/fxcomposer/nvidia_style_post.fx", fx::ParseOptions{}, diagnostics);
    ASSERT_TRUE(effect) << diagnostics.str();
    std::shared_ptr<fx::CompiledEffect> compiled =
        fx::compileEffect(effect, fx::CompileOptions{}, diagnostics);
    ASSERT_TRUE(compiled && !diagnostics.hasErrors()) << diagnostics.str();
    auto renderer = runtime::EffectRenderer::create(compiled, diagnostics);
    ASSERT_TRUE(renderer) << diagnostics.str();

    // `#PixFmt` in the include's macro (D3DX stringizing) must have produced the format string.
    const fx::Parameter* scene = effect->findParameter("SceneTexture");
    ASSERT_TRUE(scene);
    const fx::Annotation* format = scene->annotation("Format");
    ASSERT_TRUE(format);
    EXPECT_EQ(format->value.text, "A8R8G8B8");
    // Several declarators in one annotation, and a string from a parenthesised macro.
    const fx::Parameter* clear = effect->findParameter("ClearColor");
    ASSERT_TRUE(clear && clear->annotation("width") && clear->annotation("height"));
    EXPECT_EQ(clear->annotation("UIWidget")->value.text, "Color");

    const runtime::Scene boxes = *runtime::makeBuiltinScene("boxes");
    fx::DiagnosticList frameDiagnostics;
    runtime::FrameOptions options;
    options.width = 96;
    options.height = 64;
    runtime::FrameStats stats;
    ASSERT_TRUE(renderer->render(boxes, options, frameDiagnostics, &stats)) << frameDiagnostics.str();
    // Technique=Technique?Main:Fallback picks Main: the lit pass and the post pass.
    EXPECT_EQ(stats.passesRun, 2);

    const runtime::FrameImage frame = renderer->readFrame();
    ASSERT_TRUE(notConstant(frame));
    int width = 0, height = 0, channels = 0;
    auto sceneTarget = renderer->readTarget("SceneTexture", &width, &height, &channels);
    ASSERT_TRUE(sceneTarget);
    ASSERT_EQ(width, 96);
    ASSERT_EQ(height, 64);
    int mismatches = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float* s = &(*sceneTarget)[static_cast<size_t>((y * width + x) * channels)];
            const uint8_t* f = frame.pixel(x, y);
            if (std::abs(f[0] / 255.0f - s[2]) > 2.0f / 255 || std::abs(f[2] / 255.0f - s[0]) > 2.0f / 255)
                ++mismatches;
        }
    }
    EXPECT_EQ(mismatches, 0);

    // Missing ResourceName files are warnings (and neutral textures), not errors.
    int textureWarnings = 0;
    for (const fx::Diagnostic& d : diagnostics.items())
        textureWarnings += d.id == fx::DiagId::TextureFileNotFound && d.severity == fx::Severity::Warning;
    EXPECT_EQ(textureWarnings, 2) << diagnostics.str();
}

// 3ds Max's `Clear=SV_TARGETn` clears colour target n alone: tests/data/fxcomposer/clear_each_target.fx
// clears its two targets to red and to green, draws the object blue into both and shows them side by side;
// around the object, red on the left and green on the right.
TEST(FxComposerFiles, ClearOfANamedTargetClearsThatTargetAlone) {
    auto renderer = loadEffect("tests/data/fxcomposer/clear_each_target.fx", true);
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, *runtime::makeBuiltinScene("teapot"), 96, 64));
    const runtime::FrameImage frame = renderer->readFrame();
    int red = 0, green = 0, blue = 0, other = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 96; ++x) {
            const uint8_t* p = frame.pixel(x, y);
            const bool left = x < 48;
            if (p[0] == 255 && p[1] == 0 && p[2] == 0 && left)
                ++red;
            else if (p[0] == 0 && p[1] == 255 && p[2] == 0 && !left)
                ++green;
            else if (p[0] == 0 && p[1] == 0 && p[2] == 255)
                ++blue;
            else
                ++other;
        }
    EXPECT_GT(red, 48 * 64 / 4);
    EXPECT_GT(green, 48 * 64 / 4);
    EXPECT_GT(blue, 0);
    EXPECT_EQ(other, 0);
}

// Every effect shipped in effects/ parses, compiles, links on the GL driver and renders a frame that is
// not blank, with every technique.
TEST(FxComposerFiles, EveryShippedEffectLinksAndRendersEveryTechnique) {
    int effects = 0;
    for (const auto& entry : std::filesystem::directory_iterator("effects")) {
        if (entry.path().extension() != ".fx") continue;
        ++effects;
        SCOPED_TRACE(entry.path().string());
        auto renderer = loadEffect(entry.path().string(), true);
        ASSERT_TRUE(renderer);
        const runtime::Scene scene = *runtime::makeBuiltinScene("boxes");
        for (const fx::CompiledTechnique& technique : renderer->effect().techniques) {
            SCOPED_TRACE(technique.name);
            ASSERT_TRUE(render(*renderer, scene, 64, 48, technique.name));
            EXPECT_TRUE(notConstant(renderer->readFrame()));
        }
    }
    EXPECT_GE(effects, 2);
}

// The plain lit effect: surfaces facing the light are brighter than those facing away, and nothing is
// shadowed (a plane point in the box's shadow is as bright as a lit one).
TEST(FxComposerFiles, PlainLitEffectLightsWithoutShadows) {
    auto renderer = loadEffect("effects/plain_lit.fx", true);
    ASSERT_TRUE(renderer);
    const runtime::Scene scene = *runtime::makeBuiltinScene("boxes");
    ASSERT_TRUE(render(*renderer, scene, 320, 240));
    const runtime::FrameImage image = renderer->readFrame();
    ASSERT_TRUE(notConstant(image));
    const glm::vec3 toLight = -glm::normalize(scene.lights[0].direction);
    float shadowedLuminance = -1.0f, litLuminance = -1.0f;
    for (float x = -8.0f; x <= 8.0f && (shadowedLuminance < 0 || litLuminance < 0); x += 0.25f) {
        for (float z = -6.0f; z <= 8.0f; z += 0.25f) {
            const glm::vec3 p(x, 0.0f, z);
            auto pixel = runtime::projectToPixel(scene, p, 320, 240);
            if (!pixel || runtime::segmentOccluded(scene, scene.camera.position, p)) continue;
            const float l = luminance(image.pixel(static_cast<int>(pixel->x), static_cast<int>(pixel->y)));
            if (runtime::segmentOccluded(scene, p, p + toLight * 100.0f)) {
                if (shadowedLuminance < 0) shadowedLuminance = l;
            } else if (litLuminance < 0) {
                litLuminance = l;
            }
        }
    }
    ASSERT_GE(shadowedLuminance, 0.0f) << "no plane point in shadow found";
    ASSERT_GE(litLuminance, 0.0f);
    // Specular highlights vary a little across the plane; shadows would halve the value.
    EXPECT_NEAR(shadowedLuminance, litLuminance, 0.08f);
}

}  // namespace
}  // namespace shadowfx::test::test_fxcomposer_files
