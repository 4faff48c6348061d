// Hot reload without a window: ReloadableEffect and FileWatcher on effects written to a temporary
// folder, rendered headlessly. Edits are written the way editors save (a temporary file renamed over the
// original), so the tests exercise the directory watch that makes that work.
#include "GlTestSupport.h"
#include "LiveGlObjects.h"

#include <fx/CompiledEffectFile.h>
#include <fx/EffectFile.h>
#include <runtime/BuiltinScenes.h>
#include <runtime/EffectPool.h>
#include <runtime/EffectRenderer.h>
#include <runtime/FileWatcher.h>
#include <runtime/ReloadableEffect.h>
#include <runtime/Scene.h>

#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

// A full-screen pass whose colour is tint() (from an include) plus a constant, scaled by Gain.
const char* kTintInclude = R"(float3 tint() { return float3(1, 0, 0); }
)";
const char* kMainEffect = R"(#include "tint.fxh"
float Gain < string UIWidget = "slider"; float UIMin = 0; float UIMax = 1; > = 1.0;
struct VSOut { float4 pos : POSITION; };
VSOut VS(float4 p : POSITION) { VSOut o; o.pos = p; return o; }
float4 PS(VSOut i) : COLOR
{
    return float4(tint() * Gain, 1) + float4(0, 0, 0, 0);
}
technique t
{
    pass p0 < string Script = "RenderColorTarget0=; Draw=Buffer;"; >
    {
        ZEnable = false;
        CullMode = None;
        VertexShader = compile vs_3_0 VS();
        PixelShader = compile ps_3_0 PS();
    }
}
)";

std::string readText(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// Saves like vim and VS Code do: write a temporary file, rename it over the original.
void saveLikeAnEditor(const fs::path& path, const std::string& text) {
    const fs::path temporary = path.string() + ".swp~";
    std::ofstream(temporary) << text;
    fs::rename(temporary, path);
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "'" << from << "' not in the text";
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

class HotReload : public ::testing::Test {
protected:
    void SetUp() override {
        testsupport::sharedContext();
        mDir = fs::temp_directory_path() / ("shadowfx_hot_reload_" + std::to_string(getpid()) + "_" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(mDir);
        fs::create_directories(mDir);
        std::ofstream(mDir / "tint.fxh") << kTintInclude;
        std::ofstream(mDir / "main.fx") << kMainEffect;
        mScene = *runtime::makeBuiltinScene("boxes");
    }
    void TearDown() override { fs::remove_all(mDir); }

    // The centre pixel of a 32x32 frame of the effect's current renderer.
    std::array<int, 3> centre(runtime::ReloadableEffect& effect) {
        fx::DiagnosticList diagnostics;
        runtime::FrameOptions options;
        options.width = options.height = 32;
        EXPECT_NE(effect.renderer(), nullptr);
        if (!effect.renderer()) return {-1, -1, -1};
        EXPECT_TRUE(effect.renderer()->render(mScene, options, diagnostics)) << diagnostics.str();
        const runtime::FrameImage frame = effect.renderer()->readFrame();
        const uint8_t* p = frame.pixel(16, 16);
        return {p[0], p[1], p[2]};
    }

    fs::path mDir;
    runtime::Scene mScene;
};

const std::array<int, 3> kRed{255, 0, 0};
const std::array<int, 3> kMagenta{255, 0, 255};
const std::array<int, 3> kGreen{0, 255, 0};

TEST_F(HotReload, EditChangesTheImage) {
    runtime::ReloadableEffect effect((mDir / "main.fx").string());
    ASSERT_TRUE(effect.reload()) << effect.errorText();
    EXPECT_EQ(centre(effect), kRed);

    saveLikeAnEditor(mDir / "main.fx", replaced(kMainEffect, "float4(0, 0, 0, 0)", "float4(0, 0, 1, 0)"));
    ASSERT_EQ(effect.reloadIfChanged(5000ms), runtime::ReloadableEffect::Result::Reloaded)
        << effect.errorText();
    EXPECT_EQ(effect.generation(), 2u);
    EXPECT_EQ(centre(effect), kMagenta);
}

// A compiled effect file reloads by reading it again: a new file changes the image, a damaged one is an
// error at the file and the last good effect stays.
TEST_F(HotReload, CompiledEffectFileReloadsWhenRewritten) {
    const auto compiledText = [](const std::string& source, const fs::path& dir) {
        fx::DiagnosticList diagnostics;
        std::ofstream(dir / "edit.fx") << source;
        auto compiled = fx::loadEffectFile((dir / "edit.fx").string(), {}, {}, diagnostics);
        EXPECT_TRUE(compiled) << diagnostics.str();
        return compiled ? fx::serializeCompiledEffect(*compiled) : std::string();
    };
    const fs::path file = mDir / "main.sfxo";
    std::ofstream(file, std::ios::binary) << compiledText(kMainEffect, mDir);
    runtime::ReloadableEffect effect(file.string());
    ASSERT_TRUE(effect.reload()) << effect.errorText();
    EXPECT_EQ(centre(effect), kRed);

    saveLikeAnEditor(file,
                     compiledText(replaced(kMainEffect, "float4(0, 0, 0, 0)", "float4(0, 0, 1, 0)"), mDir));
    ASSERT_EQ(effect.reloadIfChanged(5000ms), runtime::ReloadableEffect::Result::Reloaded)
        << effect.errorText();
    EXPECT_EQ(centre(effect), kMagenta);

    saveLikeAnEditor(file, compiledText(kMainEffect, mDir).substr(0, 100));
    ASSERT_EQ(effect.reloadIfChanged(5000ms), runtime::ReloadableEffect::Result::Failed);
    EXPECT_EQ(effect.errorText().rfind(file.string() + ": error: the compiled effect file is truncated", 0),
              0u)
        << effect.errorText();
    EXPECT_EQ(centre(effect), kMagenta);
}

TEST_F(HotReload, BrokenEditKeepsTheLastGoodEffectAndReportsTheLine) {
    runtime::ReloadableEffect effect((mDir / "main.fx").string());
    ASSERT_TRUE(effect.reload()) << effect.errorText();
    runtime::EffectRenderer* good = effect.renderer();

    // Line 7 loses its semicolon: an HLSL error glslang reports through #line at the user's line.
    saveLikeAnEditor(mDir / "main.fx",
                     replaced(kMainEffect, "float4(0, 0, 0, 0);", "float4(0, 0, 0, 0) oops;"));
    ASSERT_EQ(effect.reloadIfChanged(5000ms), runtime::ReloadableEffect::Result::Failed);
    EXPECT_TRUE(effect.lastReloadFailed());
    EXPECT_EQ(effect.renderer(), good);
    const std::string errors = effect.errorText();
    EXPECT_NE(errors.find("main.fx:7:"), std::string::npos) << errors;
    bool hasLine7 = false;
    for (const fx::Diagnostic& d : effect.diagnostics()) {
        hasLine7 |= d.severity == fx::Severity::Error && d.loc.line == 7 && d.loc.file.ends_with("main.fx");
    }
    EXPECT_TRUE(hasLine7) << errors;
    EXPECT_EQ(centre(effect), kRed);  // the old image is still produced

    // The next good save replaces it and clears the error.
    saveLikeAnEditor(mDir / "main.fx", replaced(kMainEffect, "float4(0, 0, 0, 0)", "float4(0, 0, 1, 0)"));
    ASSERT_EQ(effect.reloadIfChanged(5000ms), runtime::ReloadableEffect::Result::Reloaded)
        << effect.errorText();
    EXPECT_EQ(effect.errorText(), "");
    EXPECT_EQ(centre(effect), kMagenta);
}

TEST_F(HotReload, IncludeEditTriggersTheReload) {
    runtime::ReloadableEffect effect((mDir / "main.fx").string());
    ASSERT_TRUE(effect.reload()) << effect.errorText();
    ASSERT_EQ(effect.watchedFiles().size(), 2u);
    EXPECT_EQ(effect.reloadIfChanged(0ms), runtime::ReloadableEffect::Result::Unchanged);

    // An unrelated file in the same folder is not a reason to reload.
    std::ofstream(mDir / "notes.txt") << "unrelated";
    EXPECT_EQ(effect.reloadIfChanged(200ms), runtime::ReloadableEffect::Result::Unchanged);

    saveLikeAnEditor(mDir / "tint.fxh", "float3 tint() { return float3(0, 1, 0); }\n");
    ASSERT_EQ(effect.reloadIfChanged(5000ms), runtime::ReloadableEffect::Result::Reloaded)
        << effect.errorText();
    EXPECT_EQ(centre(effect), kGreen);
}

TEST_F(HotReload, WatcherDebouncesABurstIntoOneChange) {
    runtime::FileWatcher watcher;
    ASSERT_TRUE(watcher.valid());
    watcher.setFiles({(mDir / "main.fx").string()});
    for (int i = 0; i < 5; ++i) std::ofstream(mDir / "main.fx", std::ios::app) << "// " << i << "\n";
    const std::vector<std::string> changed = watcher.waitForChange(2000ms, 50ms);
    ASSERT_EQ(changed.size(), 1u);
    EXPECT_EQ(changed[0], fs::absolute(mDir / "main.fx").lexically_normal().string());
    EXPECT_TRUE(watcher.waitForChange(100ms).empty());  // the burst was reported once
}

TEST_F(HotReload, CompileCacheRecompilesOnlyTheChangedPass) {
    // The thesis effect, copied with its includes: three passes in `main`, two in `hardware`.
    const fs::path source = fs::path(SHADOWFX_SOURCE_DIR) / "effects";
    fs::copy(source / "thesis_fxcomposer.fx", mDir / "thesis.fx");
    fs::copy(source / "include", mDir / "include", fs::copy_options::recursive);
    runtime::ReloadableEffect effect((mDir / "thesis.fx").string());
    ASSERT_TRUE(effect.reload()) << effect.errorText();
    // Identical stages (the same vertex shader in both techniques) compile once, even the first time.
    const size_t unique = effect.lastStats().cacheMisses;
    const size_t stages = unique + effect.lastStats().cacheHits;
    EXPECT_GE(unique, 4u);

    // Nothing changed: every stage comes from the cache.
    ASSERT_TRUE(effect.reload()) << effect.errorText();
    EXPECT_EQ(effect.lastStats().cacheMisses, 0u);
    EXPECT_EQ(effect.lastStats().cacheHits, stages);

    // One pixel shader changes (RenderScenePS, used by main's RenderScene pass only): one stage compiles.
    const std::string text = readText(mDir / "thesis.fx");
    saveLikeAnEditor(mDir / "thesis.fx", replaced(text, "return Shade(IN, GetShadow(IN.LP));",
                                                  "return Shade(IN, GetShadow(IN.LP)) * 0.5;"));
    ASSERT_EQ(effect.reloadIfChanged(5000ms), runtime::ReloadableEffect::Result::Reloaded)
        << effect.errorText();
    EXPECT_EQ(effect.lastStats().cacheMisses, 1u);
    EXPECT_EQ(effect.lastStats().cacheHits, stages - 1);
}

TEST_F(HotReload, TweakedParametersSurviveAReload) {
    runtime::ReloadableEffect effect((mDir / "main.fx").string());
    ASSERT_TRUE(effect.reload()) << effect.errorText();
    const std::optional<size_t> gain = effect.renderer()->findParameter("Gain");
    ASSERT_TRUE(gain);
    effect.renderer()->setParameter(*gain, fx::Value::scalar(0.5f));

    // Gain moves to another index (a parameter is declared before it) but keeps its name and type.
    const std::string edited = replaced(kMainEffect, "float Gain", "float Unused = 2;\nfloat Gain");
    saveLikeAnEditor(mDir / "main.fx", edited);
    ASSERT_EQ(effect.reloadIfChanged(5000ms), runtime::ReloadableEffect::Result::Reloaded)
        << effect.errorText();
    const std::optional<size_t> moved = effect.renderer()->findParameter("Gain");
    ASSERT_TRUE(moved);
    EXPECT_NE(*moved, *gain);
    EXPECT_TRUE(effect.renderer()->isPinned(*moved));
    EXPECT_FLOAT_EQ(effect.renderer()->parameter(*moved).asFloat(), 0.5f);
    EXPECT_NEAR(centre(effect)[0], 128, 2);

    // A parameter whose type changed starts from its new initial value.
    saveLikeAnEditor(mDir / "main.fx", replaced(edited, "float Gain < string", "float3 Gain < string"));
    const runtime::ReloadableEffect::Result result = effect.reloadIfChanged(5000ms);
    ASSERT_EQ(result, runtime::ReloadableEffect::Result::Reloaded) << effect.errorText();
    const std::optional<size_t> retyped = effect.renderer()->findParameter("Gain");
    ASSERT_TRUE(retyped);
    EXPECT_FALSE(effect.renderer()->isPinned(*retyped));
}

// Two effects of one pool share Gain. A reload keeps the effect in the pool, with the pool's value of Gain
// (set through the other effect since the last load) rather than its old renderer's; a broken edit, here a
// Gain of another type than the pool's, keeps the last good renderer, still in the pool.
TEST_F(HotReload, AReloadInAPoolStaysAMemberWithThePoolsValues) {
    auto pool = std::make_shared<runtime::EffectPool>();
    const std::string shared = replaced(kMainEffect, "float Gain", "shared float Gain");
    std::ofstream(mDir / "main.fx") << shared;
    std::ofstream(mDir / "other.fx") << shared;
    runtime::ReloadableEffect effect((mDir / "main.fx").string(), {}, pool);
    runtime::ReloadableEffect other((mDir / "other.fx").string(), {}, pool);
    ASSERT_TRUE(effect.reload()) << effect.errorText();
    ASSERT_TRUE(other.reload()) << other.errorText();
    ASSERT_TRUE(other.renderer()->variable("Gain").setFloat(0.5f));
    EXPECT_NEAR(centre(effect)[0], 128, 2);

    ASSERT_TRUE(other.renderer()->variable("Gain").setFloat(0.25f));
    saveLikeAnEditor(mDir / "main.fx", replaced(shared, "float4(0, 0, 0, 0)", "float4(0, 0, 1, 0)"));
    ASSERT_EQ(effect.reloadIfChanged(5000ms), runtime::ReloadableEffect::Result::Reloaded)
        << effect.errorText();
    std::array<int, 3> pixel = centre(effect);
    EXPECT_NEAR(pixel[0], 64, 2);
    EXPECT_EQ(pixel[2], 255);  // the edit's blue: the new renderer draws
    ASSERT_TRUE(other.renderer()->variable("Gain").setFloat(1.0f));
    EXPECT_EQ(centre(effect), kMagenta);

    runtime::EffectRenderer* good = effect.renderer();
    saveLikeAnEditor(mDir / "main.fx", replaced(shared, "shared float Gain", "shared float3 Gain"));
    ASSERT_EQ(effect.reloadIfChanged(5000ms), runtime::ReloadableEffect::Result::Failed);
    EXPECT_EQ(effect.renderer(), good);
    EXPECT_NE(effect.errorText().find("main.fx:2:"), std::string::npos) << effect.errorText();
    EXPECT_NE(effect.errorText().find("'Gain' is a float3 here but a float"), std::string::npos)
        << effect.errorText();
    ASSERT_TRUE(other.renderer()->variable("Gain").setFloat(0.5f));
    pixel = centre(effect);
    EXPECT_NEAR(pixel[0], 128, 2);
    EXPECT_EQ(pixel[2], 255);
}

TEST_F(HotReload, TwoHundredReloadCyclesLeaveTheLiveGlObjectCountUnchanged) {
    runtime::ReloadableEffect effect((mDir / "main.fx").string());
    ASSERT_TRUE(effect.reload()) << effect.errorText();
    centre(effect);
    const shadowfx::test::LiveGlObjects before = shadowfx::test::countLiveGlObjects();
    EXPECT_GT(before.programs, 0);

    const std::string variants[2] = {kMainEffect,
                                     replaced(kMainEffect, "float4(0, 0, 0, 0)", "float4(0, 0, 1, 0)")};
    for (int cycle = 0; cycle < 200; ++cycle) {
        std::ofstream(mDir / "main.fx") << variants[(cycle + 1) % 2];
        ASSERT_TRUE(effect.reload()) << "cycle " << cycle << ": " << effect.errorText();
        centre(effect);
    }
    // A failed reload must not leak what it created before failing either.
    std::ofstream(mDir / "main.fx") << replaced(kMainEffect, "float4(0, 0, 0, 0);", "oops");
    EXPECT_FALSE(effect.reload());
    std::ofstream(mDir / "main.fx") << kMainEffect;
    ASSERT_TRUE(effect.reload()) << effect.errorText();
    centre(effect);
    EXPECT_EQ(shadowfx::test::countLiveGlObjects(), before);
}

}  // namespace
