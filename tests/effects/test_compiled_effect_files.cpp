// Every shipped effect renders from its compiled effect file (`shadowfx compile --out`) the frames it
// renders from source, byte for byte, every technique; the file loads through
// EffectRenderer::createFromFile, which needs no compiler.
#include "EffectHarness.h"
#include "ScratchDirectory.h"

#include <fx/CompileCache.h>
#include <fx/CompiledEffectFile.h>
#include <fx/EffectFile.h>
#include <runtime/BuiltinScenes.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace shadowfx::test::test_compiled_effect_files {
namespace {

// Small frames and maps: llvmpipe renders every technique of every effect in seconds, and a byte
// comparison needs no more.
constexpr int kWidth = 64;
constexpr int kHeight = 48;

TEST(CompiledEffectFiles, EveryShippedEffectRendersTheFramesOfItsSource) {
    sharedContext();
    std::vector<std::string> effects;
    for (const auto& entry : std::filesystem::directory_iterator(sourcePath("effects")))
        if (entry.path().extension() == ".fx") effects.push_back(entry.path().string());
    std::sort(effects.begin(), effects.end());
    ASSERT_GE(effects.size(), 10u);
    const ScratchDirectory scratch("compiled_effects");
    const runtime::Scene scene = *runtime::makeBuiltinScene("boxes");
    fx::ParseOptions parseOptions;
    parseOptions.defines = {{"SHADOWFX_SHADOW_MAP_SIZE", "256"}};
    fx::CompileCache cache;
    fx::CompileOptions options;
    options.cache = &cache;
    for (const std::string& path : effects) {
        SCOPED_TRACE(path);
        fx::DiagnosticList diagnostics;
        std::shared_ptr<fx::CompiledEffect> compiled =
            fx::loadEffectFile(path, parseOptions, options, diagnostics);
        ASSERT_TRUE(compiled) << diagnostics.str();
        const std::string file =
            (scratch.path() / (std::filesystem::path(path).stem().string() + ".sfxo")).string();
        ASSERT_TRUE(fx::writeCompiledEffectFile(*compiled, file, diagnostics)) << diagnostics.str();
        std::unique_ptr<runtime::EffectRenderer> fromSource =
            runtime::EffectRenderer::create(compiled, diagnostics);
        std::unique_ptr<runtime::EffectRenderer> fromFile =
            runtime::EffectRenderer::createFromFile(file, diagnostics);
        ASSERT_TRUE(fromSource && fromFile) << diagnostics.str();
        for (const fx::CompiledTechnique& technique : compiled->techniques) {
            SCOPED_TRACE("technique " + technique.name);
            ASSERT_TRUE(render(*fromSource, scene, kWidth, kHeight, technique.name));
            const runtime::FrameImage expected = fromSource->readFrame();
            EXPECT_TRUE(notConstant(expected));
            ASSERT_TRUE(render(*fromFile, scene, kWidth, kHeight, technique.name));
            EXPECT_EQ(fromFile->readFrame().rgba, expected.rgba) << "the compiled file renders another frame";
        }
    }
}

// A damaged file is an error at its path, and no renderer.
TEST(CompiledEffectFiles, ADamagedFileIsALocatedError) {
    sharedContext();
    const ScratchDirectory scratch("damaged_effect");
    fx::DiagnosticList diagnostics;
    std::shared_ptr<fx::CompiledEffect> compiled =
        fx::loadEffectFile(sourcePath("effects/plain_lit.fx"), {}, {}, diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    const std::string bytes = fx::serializeCompiledEffect(*compiled);
    const std::string file = (scratch.path() / "plain_lit.sfxo").string();
    std::ofstream(file, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    fx::DiagnosticList errors;
    EXPECT_FALSE(runtime::EffectRenderer::createFromFile(file, errors));
    ASSERT_EQ(errors.items().size(), 1u) << errors.str();
    EXPECT_EQ(errors.items()[0].id, fx::DiagId::CompiledEffectContentTruncated);
    EXPECT_EQ(errors.items()[0].loc.file, file);
}

}  // namespace
}  // namespace shadowfx::test::test_compiled_effect_files
