// The shadowfx command as users script against it: exit codes, `path:line:column: error:` diagnostics for
// each class of bad input, no output image after a failure, and the --help of every subcommand.
#include "CliRunner.h"
#include "ScratchDirectory.h"
#include "WorkerCrashHook.h"

#include <gtest/gtest.h>

#include <runtime/ImageCompare.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace test_cli {

namespace {

using shadowfx::test::kSource;
using shadowfx::test::run;
using shadowfx::test::RunResult;

struct BadInput {
    const char* file;
    const char* location;  // "file:line:column:" as printed
    const char* message;   // a part of the message
};

// GoogleTest prints a parameter's bytes unless told otherwise.
void PrintTo(const BadInput& bad, std::ostream* out) {
    *out << bad.file;
}

class BadInputs : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInputs, RenderReportsTheUsersLocationExitsNonZeroAndWritesNoImage) {
    const BadInput& bad = GetParam();
    const shadowfx::test::ScratchDirectory scratch("bad");
    const std::string out = scratch / (std::string(bad.file) + ".png");
    std::ofstream(out) << "stale";  // a stale image from an earlier run must not survive a failure
    const RunResult result = run("render tests/data/bad/" + std::string(bad.file) + " --out " + out);
    EXPECT_FALSE(result.crashed) << result.output;
    EXPECT_EQ(result.exitCode, 1) << result.output;
    const std::string expected = "tests/data/bad/" + std::string(bad.location) + " error: ";
    EXPECT_NE(result.output.find(expected), std::string::npos) << "expected '" << expected << "' in:\n"
                                                               << result.output;
    EXPECT_NE(result.output.find(bad.message), std::string::npos) << result.output;
    EXPECT_FALSE(std::filesystem::exists(out));
}

INSTANTIATE_TEST_SUITE_P(
    Diagnostics, BadInputs,
    ::testing::Values(BadInput{"syntax_error.fx", "syntax_error.fx:2:18:", "expected ';' after '0.01'"},
                      BadInput{"unclosed_pass.fx", "unclosed_pass.fx:6:43:", "to close 'pass' at line 4"},
                      BadInput{"unknown_state.fx", "unknown_state.fx:7:9:", "CullMood"},
                      BadInput{"unknown_state_value.fx", "unknown_state_value.fx:7:19:", "Minimum"},
                      BadInput{"unknown_script_command.fx", "unknown_script_command.fx:11:26:", "Paint"},
                      BadInput{"missing_entry_point.fx", "missing_entry_point.fx:7:23:", "NoSuchFunction"},
                      BadInput{"hlsl_error.fx", "hlsl_error.fx:6:18:", "xyzq"},
                      BadInput{"missing_include.fx", "missing_include.fx:2:10:", "does_not_exist.fxh"},
                      BadInput{"script_unknown_pass.fx", "script_unknown_pass.fx:3:32:", "Shadow"},
                      BadInput{"unknown_format.fx", "unknown_format.fx:1:83:", "R33F"},
                      BadInput{"empty.fx", "empty.fx:1:1:", "the file has no techniques"}),
    [](const ::testing::TestParamInfo<BadInput>& info) {
        std::string name = info.param.file;
        return name.substr(0, name.find('.'));
    });

// The tool removes a stale image before it renders, and may run as root: a device given as the output must
// survive both a failed and a successful run (it once deleted /dev/null).
TEST(Cli, RenderToADeviceLeavesTheDevice) {
    ASSERT_TRUE(std::filesystem::is_character_file("/dev/null"));
    const RunResult failed = run("render tests/data/bad/syntax_error.fx --out /dev/null");
    EXPECT_EQ(failed.exitCode, 1) << failed.output;
    EXPECT_TRUE(std::filesystem::is_character_file("/dev/null"));
    const RunResult rendered = run("render effects/plain_lit.fx --width 32 --height 24 --out /dev/null");
    EXPECT_EQ(rendered.exitCode, 0) << rendered.output;
    EXPECT_TRUE(std::filesystem::is_character_file("/dev/null"));
}

TEST(Cli, RenderWritesAPng) {
    const shadowfx::test::ScratchDirectory scratch("cli_render");
    const std::string out = scratch / "render.png";
    const RunResult result = run("render effects/thesis_fxcomposer.fx --out " + out +
                                 " --width 160 --height 120 --set PCF=true --stats");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    std::ifstream png(out, std::ios::binary);
    char signature[8] = {};
    png.read(signature, 8);
    EXPECT_EQ(std::string(signature + 1, 3), "PNG");
    EXPECT_NE(result.output.find("passes"), std::string::npos) << result.output;
}

// An effect that writes its object as (0, 0, 0, 0), as NVIDIA's edge detectors write their lines: the PNG
// keeps that alpha unless --opaque asks for FX Composer's view of the colour alone.
TEST(Cli, RenderOpaqueWritesTheColourWithAlphaOne) {
    const shadowfx::test::ScratchDirectory scratch("cli_opaque");
    const std::string effect = scratch / "transparent.fx";
    std::ofstream(effect) << R"(float4x4 WorldViewProj : WorldViewProjection;
float4 VS(float3 p : POSITION) : POSITION { return mul(float4(p, 1), WorldViewProj); }
float4 PS() : COLOR { return 0; }
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)";
    auto objectAndBackground = [&](const std::string& options) {
        const std::string out = scratch / "frame.png";
        const RunResult result =
            run("render " + effect + " --scene teapot --width 32 --height 24 --out " + out + options);
        EXPECT_EQ(result.exitCode, 0) << result.output;
        std::string error;
        const std::optional<runtime::FrameImage> frame = runtime::readPng(out, error);
        EXPECT_TRUE(frame) << error;
        std::pair<std::vector<uint8_t>, std::vector<uint8_t>> pixels;
        if (!frame) return pixels;
        pixels.first.assign(frame->pixel(16, 12), frame->pixel(16, 12) + 4);  // the teapot
        pixels.second.assign(frame->pixel(0, 0), frame->pixel(0, 0) + 4);     // the host's background
        return pixels;
    };
    const auto plain = objectAndBackground("");
    EXPECT_EQ(plain.first, (std::vector<uint8_t>{0, 0, 0, 0}));
    EXPECT_EQ(plain.second, (std::vector<uint8_t>{64, 72, 96, 255}));
    const auto opaque = objectAndBackground(" --opaque");
    EXPECT_EQ(opaque.first, (std::vector<uint8_t>{0, 0, 0, 255}));
    EXPECT_EQ(opaque.second, plain.second);
}

TEST(Cli, CompilePrintsGlslForEveryPass) {
    const RunResult result = run("compile effects/thesis_fxcomposer.fx --technique main");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("pass RenderShadowMap, vertex shader RenderShadowMapVS"), std::string::npos);
    EXPECT_NE(result.output.find("pass RenderScene, pixel shader RenderScenePS"), std::string::npos);
    EXPECT_NE(result.output.find("#version 450"), std::string::npos);
    // A compute pass's one stage too.
    const RunResult compute = run("compile tests/data/d3d10/compute_particles.fx");
    ASSERT_EQ(compute.exitCode, 0) << compute.output;
    EXPECT_NE(compute.output.find("pass Advance, compute shader"), std::string::npos) << compute.output;
    EXPECT_NE(compute.output.find("local_size_x"), std::string::npos) << compute.output;
}

// The HLSL compiler crashes on the pixel shader (the workers' crash hook): every command that compiles
// reports it where the function is and exits 1, never with the signal; render writes no image.
TEST(Cli, ACrashOfTheHlslCompilerIsALocatedErrorForCompileCheckAndRender) {
    const shadowfx::test::WorkerCrashHook hook;
    const shadowfx::test::ScratchDirectory scratch("cli_glslang_crash");
    const std::string out = scratch / "render.png";
    for (const std::string& command : std::vector<std::string>{"compile", "check", "render --out " + out}) {
        const RunResult result = run(command + " tests/data/worker_crash.fx");
        EXPECT_FALSE(result.crashed) << command << "\n" << result.output;
        EXPECT_EQ(result.exitCode, 1) << command << "\n" << result.output;
        EXPECT_NE(result.output.find("tests/data/worker_crash.fx:9:8: error: the HLSL compiler "
                                     "crashed on this shader (signal 11)"),
                  std::string::npos)
            << command << "\n"
            << result.output;
    }
    EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(Cli, EverySubcommandHasHelp) {
    for (const char* command : {"render", "compile", "info"}) {
        const RunResult result = run(std::string(command) + " --help");
        EXPECT_EQ(result.exitCode, 0) << command;
        EXPECT_NE(result.output.find("usage: shadowfx " + std::string(command)), std::string::npos)
            << result.output;
    }
}

// A semantic nothing binds looks bound in the source while its value silently stays the default: render
// warns at the parameter, and info marks it and lists the semantics shadowfx binds.
TEST(Cli, AnUnboundSemanticIsALocatedWarningAndInfoListsTheBoundOnes) {
    const std::string effect = "tests/data/authoring/unbound_semantic.fx";
    const RunResult render = run("render " + effect + " --width 64 --height 48 --out /dev/null");
    EXPECT_EQ(render.exitCode, 0) << render.output;
    EXPECT_NE(
        render.output.find(effect + ":3:8: warning: parameter 'MapSize' has semantic 'ShadowMapDimensions', "
                                    "which shadowfx does not bind: it keeps its default value"),
        std::string::npos)
        << render.output;
    EXPECT_EQ(render.output.find("'WorldViewProjection', which"), std::string::npos) << render.output;

    const RunResult info = run("info " + effect);
    EXPECT_EQ(info.exitCode, 0) << info.output;
    EXPECT_NE(info.output.find("MapSize : ShadowMapDimensions  (not bound by shadowfx"), std::string::npos)
        << info.output;
    EXPECT_NE(info.output.find("semantics shadowfx binds"), std::string::npos) << info.output;
    EXPECT_NE(info.output.find(" WorldViewProjectionInverseTranspose "), std::string::npos) << info.output;
}

// The GL driver's warnings on the generated GLSL carry the GLSL's line numbers, which are nowhere in the
// effect: render prints them only when asked (--driver-log, not --verbose), at the pass, naming the shader.
TEST(Cli, DriverWarningsOnGeneratedGlslOnlyOnRequestAtThePass) {
    const std::string effect = "tests/data/authoring/driver_warning.fx";
    const RunResult verbose = run("render " + effect + " --width 64 --height 48 --verbose --out /dev/null");
    EXPECT_EQ(verbose.exitCode, 0) << verbose.output;
    EXPECT_EQ(verbose.output.find("used uninitialized"), std::string::npos) << verbose.output;

    const RunResult asked = run("render " + effect + " --width 64 --height 48 --driver-log --out /dev/null");
    EXPECT_EQ(asked.exitCode, 0) << asked.output;
    const std::string expected =
        effect + ":9:10: note: the GL driver on the generated GLSL of pixel shader 'PS' of pass 'lit': ";
    const size_t at = asked.output.find(expected);
    ASSERT_NE(at, std::string::npos) << asked.output;
    const std::string line = asked.output.substr(at, asked.output.find('\n', at) - at);
    EXPECT_NE(line.find("warning: `Gain' used uninitialized"), std::string::npos) << line;
    EXPECT_EQ(asked.output.find("vertex shader 'VS'"), std::string::npos) << asked.output;
}

// `new` writes into the working directory (the source root here), so only its refusals run in this test;
// the whole loop is CTest installed_authoring.
TEST(Cli, NewRefusesBadNamesAndSkeletonsWithoutWriting) {
    const RunResult missing = run("new");
    EXPECT_EQ(missing.exitCode, 2) << missing.output;
    EXPECT_NE(missing.output.find("expected one name, NAME"), std::string::npos) << missing.output;
    const RunResult badName = run("new 9lives");
    EXPECT_EQ(badName.exitCode, 2) << badName.output;
    EXPECT_FALSE(std::filesystem::exists(kSource + "/9lives.fx"));
    const RunResult badSkeleton = run("new unwritten --from esm");
    EXPECT_EQ(badSkeleton.exitCode, 2) << badSkeleton.output;
    EXPECT_NE(badSkeleton.output.find("--from must be pcf, vsm or minimal"), std::string::npos)
        << badSkeleton.output;
    EXPECT_FALSE(std::filesystem::exists(kSource + "/unwritten.fx"));
}

TEST(Cli, UsageErrorsExitWithTwo) {
    EXPECT_EQ(run("render effects/thesis_fxcomposer.fx").exitCode, 2);  // --out missing
    EXPECT_EQ(run("render effects/thesis_fxcomposer.fx --out x.png --backend vulkan").exitCode, 2);
    EXPECT_EQ(run("render effects/thesis_fxcomposer.fx --out x.png --scene nowhere").exitCode, 2);
    EXPECT_EQ(run("frobnicate").exitCode, 2);
}

TEST(Cli, UnknownTechniqueIsAnError) {
    const RunResult result =
        run("render effects/thesis_fxcomposer.fx --out /tmp/shadowfx_nt.png --technique nope");
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find("nope"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace test_cli
