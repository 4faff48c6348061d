// The CLI and compiled effect files: `compile --out` writes one, the commands load it in place of the
// source (by its content, whatever its name), `info` names where it came from, a damaged file is one
// located error with exit status 1, `check` and `stress` run what a compiled file allows them to, and
// texture files are found from wherever the file is loaded.
#include "CliRunner.h"
#include "ScratchDirectory.h"

#include <runtime/Image.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <optional>
#include <string>

namespace test_compiled_effect_cli {

namespace {

using shadowfx::test::run;
using shadowfx::test::RunResult;

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

class CompiledEffectCli : public ::testing::Test {
protected:
    void SetUp() override {
        const RunResult compiled = run(
            "compile effects/plain_lit.fx -D SHADOWFX_SHADOW_MAP_SIZE=256 -I effects/include --out " + mFile);
        ASSERT_EQ(compiled.exitCode, 0) << compiled.output;
        ASSERT_TRUE(std::filesystem::exists(mFile));
    }
    const shadowfx::test::ScratchDirectory mScratch{"compiled_cli"};
    const std::string mFile = (mScratch / "plain_lit.sfxo").string();
};

TEST_F(CompiledEffectCli, RenderAndInfoLoadTheFile) {
    const std::string png = (mScratch / "frame.png").string();
    const RunResult rendered = run("render " + mFile + " --width 64 --height 48 --out " + png);
    EXPECT_EQ(rendered.exitCode, 0) << rendered.output;
    EXPECT_TRUE(std::filesystem::exists(png));
    const RunResult info = run("info " + mFile);
    ASSERT_EQ(info.exitCode, 0) << info.output;
    EXPECT_NE(info.output.find("compiled from effects/plain_lit.fx by shadowfx "), std::string::npos)
        << info.output;
    EXPECT_NE(info.output.find("-D SHADOWFX_SHADOW_MAP_SIZE=256"), std::string::npos) << info.output;
    EXPECT_NE(info.output.find("-I effects/include"), std::string::npos) << info.output;
}

// Told apart by its magic: a compiled file named .fx loads as one.
TEST_F(CompiledEffectCli, TheContentDecidesNotTheName) {
    const std::string renamed = (mScratch / "looks_like_source.fx").string();
    std::filesystem::copy_file(mFile, renamed);
    const RunResult rendered = run("render " + renamed + " --width 32 --height 24 --out /dev/null");
    EXPECT_EQ(rendered.exitCode, 0) << rendered.output;
}

TEST_F(CompiledEffectCli, ATruncatedFileIsOneLocatedErrorAndNoImage) {
    const std::string bytes = readFile(mFile);
    const std::string truncated = (mScratch / "truncated.sfxo").string();
    std::ofstream(truncated, std::ios::binary) << bytes.substr(0, bytes.size() - 100);
    const std::string png = (mScratch / "none.png").string();
    const RunResult rendered = run("render " + truncated + " --out " + png);
    EXPECT_EQ(rendered.exitCode, 1) << rendered.output;
    EXPECT_FALSE(rendered.crashed);
    EXPECT_EQ(rendered.output.rfind(truncated + ": error: the compiled effect file is truncated: ", 0), 0u)
        << rendered.output;
    EXPECT_FALSE(std::filesystem::exists(png));
}

// The lines of `output` that hold every one of `words`, joined: check's table rows, stress's report lines.
std::string linesWith(const std::string& output, std::initializer_list<std::string> words) {
    std::string found;
    size_t start = 0;
    while (start < output.size()) {
        size_t end = output.find('\n', start);
        if (end == std::string::npos) end = output.size();
        const std::string line = output.substr(start, end - start);
        bool all = true;
        for (const std::string& word : words) all = all && line.find(word) != std::string::npos;
        if (all) found += line + "\n";
        start = end + 1;
    }
    return found;
}

// The thesis effect's main technique compiled to `file` with `defines` ("-D NAME=VALUE ...").
void compileThesis(const std::string& file, const std::string& defines) {
    const RunResult compiled =
        run("compile effects/thesis_fxcomposer.fx --technique main -D SHADOWFX_SHADOW_MAP_SIZE=1024 " +
            defines + " --out " + file);
    ASSERT_EQ(compiled.exitCode, 0) << compiled.output;
}

// check renders a compiled file as it stands; the scores need the SHADOWFX_VISIBILITY variant, which only
// the source compiles, so they are NOT_SUPPORTED and say why.
TEST(CompiledEffectCheck, RendersTheFileAndLeavesTheScoresToTheSource) {
    const shadowfx::test::ScratchDirectory scratch("compiled_check");
    const std::string file = (scratch / "thesis.sfxo").string();
    compileThesis(file, "");
    const RunResult checked =
        run("check " + file + " --scenes dual-l --backend egl --width 160 --height 120 " + "--out " +
            (scratch / "out").string());
    EXPECT_EQ(checked.exitCode, 0) << checked.output;
    const std::string render = linesWith(checked.output, {"main", "dual-l", "render"});
    EXPECT_NE(render.find("PASS"), std::string::npos) << checked.output;
    const std::string expectations = linesWith(checked.output, {"main", "dual-l", "expectations"});
    EXPECT_NE(expectations.find("NOT_SUPPORTED"), std::string::npos) << checked.output;
    EXPECT_NE(expectations.find("compiled effect file"), std::string::npos) << checked.output;
    EXPECT_EQ(checked.output.find("\nFAIL "), std::string::npos) << checked.output;

    const RunResult listed = run("check " + file + " --list-techniques");
    EXPECT_EQ(listed.exitCode, 0) << listed.output;
    EXPECT_EQ(listed.output, "main\n");
}

// stress scores a file compiled as the SHADOWFX_VISIBILITY variant (its frame is the shadow factor), and
// judges a file compiled without it on what needs no score.
TEST(CompiledEffectStress, ScoresTheVisibilityVariantAndJudgesAnotherUnscored) {
    const shadowfx::test::ScratchDirectory scratch("compiled_stress");
    const std::string visibility = (scratch / "visibility.sfxo").string();
    const std::string shaded = (scratch / "shaded.sfxo").string();
    compileThesis(visibility, "-D SHADOWFX_VISIBILITY=1");
    compileThesis(shaded, "");
    const RunResult stressed =
        run("stress " + visibility + " " + shaded + " --cases ordinary --out " + (scratch / "out").string());
    EXPECT_EQ(stressed.exitCode, 0) << stressed.output;
    const std::string json = readFile((scratch / "out" / "stress.json").string());
    ASSERT_FALSE(json.empty()) << stressed.output;
    // One result per file; only the visibility variant's carries an error.
    const size_t first = json.find("\"visibility.sfxo\"");
    const size_t second = json.find("\"shaded.sfxo\"");
    ASSERT_NE(first, std::string::npos) << json;
    ASSERT_NE(second, std::string::npos) << json;
    const size_t split = std::max(first, second);
    const std::string visibilityResult =
        first < second ? json.substr(first, split - first) : json.substr(first);
    const std::string shadedResult =
        second < first ? json.substr(second, split - second) : json.substr(second);
    EXPECT_NE(visibilityResult.find("\"misclassified_percent\": 0."), std::string::npos) << json;
    EXPECT_EQ(shadedResult.find("\"misclassified_percent\": 0."), std::string::npos) << json;
}

// A texture named by a relative path is looked for beside the compiled file, then beside its source.
TEST(CompiledEffectTextures, TexturesAreFoundBesideTheFileThenBesideTheSource) {
    const shadowfx::test::ScratchDirectory scratch("compiled_textures");
    const std::filesystem::path source = scratch / "source";
    std::filesystem::create_directories(source / "textures");
    std::ofstream(source / "tinted.fx") << R"(
float4x4 WorldViewProjection : WorldViewProjection;
texture Tint < string ResourceName = "textures/tint.png"; >;
sampler2D TintSampler = sampler_state { Texture = <Tint>; MinFilter = Point; MagFilter = Point; };
float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProjection); }
float4 PS() : COLOR { return tex2D(TintSampler, float2(0.5, 0.5)); }
technique main { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)";
    const auto writeColour = [](const std::filesystem::path& png, uint8_t r, uint8_t g, uint8_t b) {
        runtime::Image image = runtime::Image::makeBytes(4, 4, 4);
        for (size_t i = 0; i < image.bytes.size(); i += 4) {
            image.bytes[i] = r;
            image.bytes[i + 1] = g;
            image.bytes[i + 2] = b;
            image.bytes[i + 3] = 255;
        }
        std::string error;
        ASSERT_TRUE(image.writePng(png.string(), error)) << error;
    };
    writeColour(source / "textures" / "tint.png", 255, 0, 0);
    const std::filesystem::path build = scratch / "build";
    std::filesystem::create_directories(build);
    const std::string file = (build / "tinted.sfxo").string();
    const RunResult compiled = run("compile " + (source / "tinted.fx").string() + " --out " + file);
    ASSERT_EQ(compiled.exitCode, 0) << compiled.output;

    // Pixels of the frame `file` renders in (r, g, b), and the run's output.
    const auto pixelsOf = [&](const std::string& effect, uint8_t r, uint8_t g, uint8_t b,
                              std::string& output) {
        const std::string png = (scratch / "frame.png").string();
        std::filesystem::remove(png);
        const RunResult rendered = run("render " + effect + " --width 64 --height 48 --out " + png);
        output = rendered.output;
        EXPECT_EQ(rendered.exitCode, 0) << rendered.output;
        std::string error;
        const std::optional<runtime::Image> image = runtime::loadImageFile(png, error);
        if (!image) return -1;
        int count = 0;
        for (size_t i = 0; i + 3 < image->bytes.size(); i += 4)
            count += image->bytes[i] == r && image->bytes[i + 1] == g && image->bytes[i + 2] == b;
        return count;
    };
    std::string output;
    // No texture beside the file: the source's.
    const int red = pixelsOf(file, 255, 0, 0, output);
    EXPECT_GT(red, 64 * 48 / 20) << output;

    // Shipped elsewhere with textures of its own (green): those, found beside the file first.
    const std::filesystem::path shipped = scratch / "shipped";
    std::filesystem::create_directories(shipped / "textures");
    std::filesystem::copy_file(file, shipped / "tinted.sfxo");
    writeColour(shipped / "textures" / "tint.png", 0, 255, 0);
    EXPECT_EQ(pixelsOf((shipped / "tinted.sfxo").string(), 0, 255, 0, output), red) << output;

    // Found nowhere: the compiler's warning for a missing texture, and a neutral (white) texture.
    std::filesystem::remove_all(source / "textures");
    EXPECT_EQ(pixelsOf(file, 255, 255, 255, output), red) << output;
    EXPECT_NE(output.find("warning: cannot load texture 'textures/tint.png'; using a neutral texture"),
              std::string::npos)
        << output;
}

}  // namespace
}  // namespace test_compiled_effect_cli
