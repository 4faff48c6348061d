// The CLI and compiled effect files: `compile --out` writes one, the commands load it in place of the
// source (by its content, whatever its name), `info` names where it came from, and a damaged file is one
// located error with exit status 1.
#include "CliRunner.h"
#include "ScratchDirectory.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

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

TEST_F(CompiledEffectCli, CheckAsksForTheSource) {
    const RunResult checked = run("check " + mFile);
    EXPECT_EQ(checked.exitCode, 2) << checked.output;
    EXPECT_NE(checked.output.find("give the .fx file"), std::string::npos) << checked.output;
}

}  // namespace
