// `shadowfx check` as a CI runs it: the real built tool on real effects, with copies of the shipped effect
// broken on purpose (bias removed, golden moved, golden missing) written to a temporary folder at test time.
// Each run uses one backend (EGL) to stay fast; the CTest `check` tests run both. A blank frame and a file
// without techniques are rows of runtime::runConformance, tested without the tool
// (tests/runtime/test_conformance_run.cpp).
#include "CliRunner.h"
#include "ScratchDirectory.h"

#include <gtest/gtest.h>

#include <runtime/EffectRenderer.h>
#include <runtime/ImageCompare.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace test_check_command {

namespace {

namespace fs = std::filesystem;

using shadowfx::test::kSource;
using shadowfx::test::run;
using shadowfx::test::RunResult;

std::string readText(const fs::path& path) {
    std::ifstream file(path);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

// The table row of `check` for `technique` and `scene`, or "" if there is none.
std::string row(const std::string& output, const std::string& technique, const std::string& scene,
                const std::string& check) {
    const std::regex pattern("^\\S+\\s+\\S+\\s+\\S+\\s+" + technique + "\\s+" + scene + "\\s+" + check +
                             "\\s.*$");
    std::istringstream lines(output);
    std::string line;
    while (std::getline(lines, line))
        if (std::regex_match(line, pattern)) return line;
    return "";
}

// A private copy of effects/thesis_fxcomposer.fx (includes and goldens too) in a fresh temporary folder,
// with `from` replaced by `to` in the effect's text.
class EffectCopy {
public:
    EffectCopy(const std::string& name, const std::string& from = "", const std::string& to = "",
               const std::string& effect = "thesis_fxcomposer")
        : mScratch("check_" + name), mDir(mScratch.path()) {
        fs::create_directories(mDir / "golden");
        fs::copy(kSource + "/effects/include", mDir / "include", fs::copy_options::recursive);
        fs::copy(kSource + "/effects/golden/" + effect, mDir / "golden" / effect,
                 fs::copy_options::recursive);
        std::string text = readText(kSource + "/effects/" + effect + ".fx");
        if (!from.empty()) {
            const size_t at = text.find(from);
            EXPECT_NE(at, std::string::npos) << from;
            if (at != std::string::npos) text.replace(at, from.size(), to);
        }
        mEffect = mDir / (effect + ".fx");
        std::ofstream(mEffect) << text;
    }
    std::string effect() const { return mEffect.string(); }
    fs::path dir() const { return mDir; }
    fs::path golden(const std::string& technique, const std::string& scene) const {
        return mDir / "golden" / mEffect.stem() / technique / (scene + ".png");
    }

private:
    shadowfx::test::ScratchDirectory mScratch;
    fs::path mDir;
    fs::path mEffect;
};

runtime::FrameImage readImage(const fs::path& path) {
    std::string error;
    std::optional<runtime::FrameImage> image = runtime::readPng(path.string(), error);
    EXPECT_TRUE(image) << error;
    return image.value_or(runtime::FrameImage{});
}

void writeImage(const runtime::FrameImage& image, const fs::path& path) {
    std::string error;
    ASSERT_TRUE(runtime::writePng(image, path.string(), error)) << error;
}

// The value of attribute `name` in the first element `element` of `xml`; -1 if absent.
long attribute(const std::string& xml, const std::string& element, const std::string& name) {
    std::smatch match;
    const std::regex pattern("<" + element + "\\b[^>]*\\b" + name + "=\"(\\d+)\"");
    return std::regex_search(xml, match, pattern) ? std::stol(match[1]) : -1;
}

long occurrences(const std::string& text, const std::string& what) {
    long count = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++count;
    return count;
}

// A check that could render nothing is not a pass. Mesa's EGL finds no driver under a wrong
// LIBGL_DRIVERS_PATH (OSMesa carries its own): the named backend is a FAIL and the exit status 1.
TEST(CheckCommand, NoGlContextExitsNonZero) {
    const shadowfx::test::ScratchDirectory scratch("check_no_context");
    setenv("LIBGL_DRIVERS_PATH", "/nonexistent", 1);
    const RunResult result =
        run("check effects/plain_lit.fx --backend egl --out " + (scratch / "out").string());
    unsetenv("LIBGL_DRIVERS_PATH");
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_NE(result.output.find("no backend could create a GL context"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("1 FAIL"), std::string::npos) << result.output;
}

TEST(CheckCommand, ShippedEffectsPassAndTheJunitReportCountsEveryCheck) {
    const shadowfx::test::ScratchDirectory scratch("check_shipped");
    const fs::path junit = scratch / "check.xml";
    const RunResult result =
        run("check effects/thesis_fxcomposer.fx effects/plain_lit.fx --backend egl --junit " +
            junit.string() + " --out " + (scratch / "out").string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(row(result.output, "main", "dual-l", "misclassified").find("PASS"), std::string::npos)
        << result.output;
    EXPECT_NE(row(result.output, "lit", "boxes", "golden").find("PASS"), std::string::npos) << result.output;
    EXPECT_EQ(row(result.output, "lit", "boxes", "misclassified"), "")
        << "plain_lit declares ExpectShadows = false";

    // A suite per effect and a case per check row; the XML's form is the report library's (its tests in
    // tests/report/test_conformance_report.cpp).
    const std::string xml = readText(junit);
    EXPECT_EQ(occurrences(xml, "<testsuite "), 2);
    const long testcases = occurrences(xml, "<testcase ");
    // thesis: 3 techniques (main, its D3D11 twin main11, hardware) x 2 scenes x (render, misclassified,
    // golden); plain_lit: 2 scenes x (render, golden)
    EXPECT_EQ(testcases, 3 * 2 * 3 + 2 * 2);
    EXPECT_EQ(attribute(xml, "testsuites", "tests"), testcases);
    EXPECT_EQ(attribute(xml, "testsuites", "failures"), 0);
    EXPECT_EQ(occurrences(xml, "<failure "), 0);
    fs::remove(junit);
}

TEST(CheckCommand, BiasRemovedFailsItsExpectationAndWritesTheImages) {
    // Without the depth bias the shadow map shadows the surfaces it was rendered from: acne.
    const EffectCopy copy("no_bias", "float UIStep = 0.0005;\n> = 0.004;",
                          "float UIStep = 0.0005;\n> = 0.0;");
    const fs::path out = copy.dir() / "out";
    const fs::path junit = copy.dir() / "junit.xml";
    const RunResult result = run("check " + copy.effect() + " --technique main --backend egl --out " +
                                 out.string() + " --junit " + junit.string());
    EXPECT_EQ(result.exitCode, 1) << result.output;
    const std::string misclassified = row(result.output, "main", "dual-l", "misclassified");
    EXPECT_EQ(misclassified.rfind("FAIL", 0), 0u) << result.output;
    EXPECT_EQ(row(result.output, "main", "dual-l", "render").rfind("PASS", 0), 0u) << result.output;
    for (const char* kind : {"result", "reference", "errormask"})
        EXPECT_TRUE(fs::exists(out / "thesis_fxcomposer" / "main" / ("dual-l." + std::string(kind) + ".png")))
            << kind;
    const std::string xml = readText(junit);
    EXPECT_GE(attribute(xml, "testsuites", "failures"), 2);  // the expectation on both scenes at least
    EXPECT_EQ(attribute(xml, "testsuites", "failures"), occurrences(xml, "<failure "));
}

TEST(CheckCommand, AGoldenShiftedByAFewPixelsFails) {
    const EffectCopy copy("shifted");
    const fs::path golden = copy.golden("main", "dual-l");
    const runtime::FrameImage image = readImage(golden);
    runtime::FrameImage moved = image;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            std::copy_n(image.pixel(std::max(x - 3, 0), y), 4,
                        &moved.rgba[(static_cast<size_t>(y) * image.width + x) * 4]);
    writeImage(moved, golden);
    const fs::path out = copy.dir() / "out";
    const RunResult result = run("check " + copy.effect() +
                                 " --technique main --scenes dual-l --backend egl --out " + out.string());
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_EQ(row(result.output, "main", "dual-l", "golden").rfind("FAIL", 0), 0u) << result.output;
    EXPECT_EQ(row(result.output, "main", "dual-l", "misclassified").rfind("PASS", 0), 0u) << result.output;
    EXPECT_TRUE(fs::exists(out / "thesis_fxcomposer" / "main" / "dual-l.errormask.png"));

    // Once the golden is right again, the images of the earlier failure are gone.
    writeImage(image, golden);
    const RunResult again = run("check " + copy.effect() +
                                " --technique main --scenes dual-l --backend egl --out " + out.string());
    EXPECT_EQ(again.exitCode, 0) << again.output;
    EXPECT_FALSE(fs::exists(out / "thesis_fxcomposer" / "main" / "dual-l.errormask.png"));
}

TEST(CheckCommand, AOnePixelDifferenceWithinToleranceAndTheSecondBackendPass) {
    const EffectCopy copy("one_pixel");
    const fs::path golden = copy.golden("main", "teapot");
    runtime::FrameImage image = readImage(golden);
    uint8_t* p = &image.rgba[(static_cast<size_t>(100) * image.width + 150) * 4];
    p[0] = 255, p[1] = 0, p[2] = 255;
    writeImage(image, golden);
    const RunResult result =
        run("check " + copy.effect() + " --technique main --scenes teapot --backend egl,osmesa");
    EXPECT_EQ(result.exitCode, 0) << result.output;
    const std::string line = row(result.output, "main", "teapot", "golden");
    EXPECT_EQ(line.rfind("PASS", 0), 0u) << result.output;
    EXPECT_NE(line.find(" 1 pixels differ"), std::string::npos) << line;
}

TEST(CheckCommand, AMissingGoldenFailsAndUpdateWritesIt) {
    const EffectCopy copy("missing");
    fs::remove(copy.golden("hardware", "teapot"));
    RunResult result = run("check " + copy.effect() + " --technique hardware --scenes teapot --backend egl");
    EXPECT_EQ(result.exitCode, 1) << result.output;
    const std::string line = row(result.output, "hardware", "teapot", "golden");
    EXPECT_EQ(line.rfind("FAIL", 0), 0u) << result.output;
    EXPECT_NE(line.find("missing golden"), std::string::npos) << line;

    result = run("check " + copy.effect() + " --technique hardware --scenes teapot --backend egl --update");
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_TRUE(fs::exists(copy.golden("hardware", "teapot")));
    result = run("check " + copy.effect() + " --technique hardware --scenes teapot --backend egl");
    EXPECT_EQ(result.exitCode, 0) << result.output;
}

// A new effect has no golden folder yet: no renderer has goldens, so the golden check is NOT_SUPPORTED (FAIL
// with --require-goldens), and --update creates the folder beside the effect.
TEST(CheckCommand, AnEffectWithoutGoldensYetIsNotSupportedUntilUpdateWritesThem) {
    const EffectCopy copy("no_goldens_yet");
    fs::remove_all(copy.dir() / "golden");
    const std::string check = "check " + copy.effect() + " --technique main --scenes dual-l --backend egl";
    RunResult result = run(check);
    EXPECT_EQ(result.exitCode, 0) << result.output;
    const std::string line = row(result.output, "main", "dual-l", "golden");
    EXPECT_EQ(line.rfind("NOT_SUPPORTED", 0), 0u) << result.output;
    EXPECT_NE(line.find("no goldens yet"), std::string::npos) << line;
    EXPECT_EQ(run(check + " --require-goldens").exitCode, 1);

    result = run(check + " --update");
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_TRUE(fs::exists(copy.golden("main", "dual-l")));
    result = run(check);
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(row(result.output, "main", "dual-l", "golden").rfind("PASS", 0), 0u) << result.output;
}

TEST(CheckCommand, ARendererWithoutGoldensIsNotSupportedUnlessRequired) {
    const EffectCopy copy("other_renderer");
    std::ofstream(copy.dir() / "golden" / "thesis_fxcomposer" / "renderer.txt") << "someothergpu\n";
    RunResult result = run("check " + copy.effect() + " --technique main --scenes dual-l --backend egl");
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(row(result.output, "main", "dual-l", "golden").rfind("NOT_SUPPORTED", 0), 0u) << result.output;
    result =
        run("check " + copy.effect() + " --technique main --scenes dual-l --backend egl --require-goldens");
    EXPECT_EQ(result.exitCode, 1) << result.output;
}

// A library ported from FX Composer carries no Expect* annotations and no goldens: every technique gets
// its render row (compile, link, GL errors, NaN, blank frame), goldens are NOT_SUPPORTED, and a technique
// that draws a blank frame still FAILs.
TEST(CheckCommand, ForeignEffectsWithoutExpectationsGetOneTableOfRenderChecks) {
    const shadowfx::test::ScratchDirectory scratch("check_foreign");
    const fs::path dir = scratch.path();
    fs::copy(kSource + "/tests/data/fxcomposer", dir, fs::copy_options::recursive);
    const fs::path junit = dir / "out.xml";
    RunResult result =
        run("check " + (dir / "material_phong.fx").string() + " " + (dir / "post_invert.fx").string() + " " +
            (dir / "sdk_skinned.fx").string() + " --backend egl --junit " + junit.string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    for (const char* technique : {"Simple", "Textured", "Main", "t0"}) {
        EXPECT_EQ(row(result.output, technique, "boxes", "render").rfind("PASS", 0), 0u)
            << technique << result.output;
        EXPECT_EQ(row(result.output, technique, "boxes", "golden").rfind("NOT_SUPPORTED", 0), 0u)
            << technique << result.output;
        EXPECT_EQ(row(result.output, technique, "boxes", "misclassified"), "") << technique << result.output;
    }
    EXPECT_EQ(attribute(readText(junit), "testsuites", "failures"), 0);
    // A library run reads as one line per effect and a summary.
    for (const char* line : {"\nmaterial_phong: drawn\n", "\npost_invert: drawn\n", "\nsdk_skinned: drawn\n",
                             "\n3 effects: 3 drawn, 0 blank, 0 failed\n"})
        EXPECT_NE(result.output.find(line), std::string::npos) << line << result.output;

    // The material effect with its draw removed: the host's background alone is a blank frame.
    std::string text = readText(dir / "material_phong.fx");
    for (size_t at; (at = text.find("Draw=geometry;")) != std::string::npos;) text.replace(at, 14, "");
    std::ofstream(dir / "material_phong.fx") << text;
    result = run("check " + (dir / "material_phong.fx").string() + " --backend egl");
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_EQ(row(result.output, "Simple", "boxes", "render").rfind("FAIL", 0), 0u) << result.output;
    EXPECT_NE(result.output.find("\nmaterial_phong: blank: Simple: the frame is "), std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find("\n1 effect: 0 drawn, 1 blank, 0 failed\n"), std::string::npos)
        << result.output;
}

TEST(CheckCommand, NanInARenderTargetFails) {
    // The shadow map is cleared to NaN; BlendOp=min keeps it, so the target holds NaN after the frame.
    const EffectCopy copy("nan", "> = {ZMaxValue, ZMaxValue, ZMaxValue, ZMaxValue};",
                          "> = {sqrt(-1.0), ZMaxValue, ZMaxValue, ZMaxValue};");
    const RunResult result =
        run("check " + copy.effect() + " --technique main --scenes dual-l --backend egl --out " +
            (copy.dir() / "out").string());
    EXPECT_EQ(result.exitCode, 1) << result.output;
    const std::string line = row(result.output, "main", "dual-l", "render");
    EXPECT_EQ(line.rfind("FAIL", 0), 0u) << result.output;
    EXPECT_NE(line.find("render target ShadowMap holds"), std::string::npos) << line;
}

TEST(CheckCommand, AValueCloseToItsBoundIsAQualityWarningThatDoesNotFail) {
    // main measures 0.076 % on teapot (llvmpipe): above 80% of a 0.09 bound, below the bound.
    const EffectCopy copy("warning", "float ExpectMisclassifiedBelow = 0.095;",
                          "float ExpectMisclassifiedBelow = 0.09;");
    const fs::path junit = copy.dir() / "junit.xml";
    const RunResult result = run("check " + copy.effect() +
                                 " --technique main --scenes teapot --backend egl --junit " + junit.string());
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(row(result.output, "main", "teapot", "misclassified").rfind("QUALITY_WARNING", 0), 0u)
        << result.output;
    const std::string xml = readText(junit);
    EXPECT_NE(xml.find("<system-out>QUALITY_WARNING: "), std::string::npos) << xml;
    EXPECT_EQ(attribute(xml, "testsuites", "failures"), 0);
}

TEST(CheckCommand, PenumbraBoundIsMeasuredOnlyUnderAnAreaLight) {
    // scenes/instanced_boxes.json has an area light (areaRadius 0.3); dual-l has none. The hardware
    // technique's hard shadow is judged over the penumbra (bench's penumbra MAE): 0.18 from the area-light
    // truth over its 273 penumbra pixels (measured on llvmpipe with 16 light samples), so a bound of 0.0002
    // must fail.
    const EffectCopy copy("penumbra", "float ExpectMisclassifiedBelow = 0.075;",
                          "float ExpectMisclassifiedBelow = 5; float ExpectPenumbraMaeBelow = 0.0002;");
    const RunResult result = run(
        "check " + copy.effect() +
        " --technique hardware --scenes dual-l,scenes/instanced_boxes.json --backend egl --area-samples 16");
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_EQ(row(result.output, "hardware", "dual-l", "penumbra").rfind("NOT_SUPPORTED", 0), 0u)
        << result.output;
    EXPECT_EQ(row(result.output, "hardware", "instanced_boxes", "penumbra").rfind("FAIL", 0), 0u)
        << result.output;
}

// ExpectAreaRadius gives the scenes an area light for the penumbra check alone, so dual-l and teapot,
// which have none, are judged; the golden and misclassified checks keep the scene as it is (they pass as
// in the shipped effect). Per-scene bounds judge each scene by its own: the hard shadow's penumbra MAE (0.21
// on dual-l, 0.16 on teapot) fails dual-l's 0.0002 and passes teapot's 0.3. A bound that a frame without
// shadows meets (its penumbra MAE is 0.43 on dual-l) fails: it checks nothing. --area-radius 0 takes the
// area light away again.
TEST(CheckCommand, ExpectAreaRadiusGivesThePenumbraBoundAnAreaLightPerScene) {
    const EffectCopy copy("area_radius", "float ExpectMisclassifiedBelow = 0.075;",
                          "float ExpectMisclassifiedBelow = 0.075; float ExpectAreaRadius = 2; "
                          "string ExpectPenumbraMaeBelow = \"dual-l=0.0002, teapot=0.3\";");
    const RunResult result =
        run("check " + copy.effect() + " --technique hardware --backend egl --area-samples 16");
    EXPECT_EQ(result.exitCode, 1) << result.output;
    const std::string dualL = row(result.output, "hardware", "dual-l", "penumbra");
    EXPECT_EQ(dualL.rfind("FAIL", 0), 0u) << result.output;
    EXPECT_NE(dualL.find("expected below 0.0002"), std::string::npos) << dualL;
    EXPECT_NE(dualL.find("areaRadius 2.000"), std::string::npos) << dualL;
    EXPECT_EQ(row(result.output, "hardware", "teapot", "penumbra").rfind("PASS", 0), 0u) << result.output;
    for (const char* scene : {"dual-l", "teapot"}) {
        EXPECT_EQ(row(result.output, "hardware", scene, "golden").rfind("PASS", 0), 0u) << result.output;
        EXPECT_EQ(row(result.output, "hardware", scene, "misclassified").rfind("PASS", 0), 0u)
            << result.output;
    }

    const EffectCopy loose("area_radius_loose", "float ExpectMisclassifiedBelow = 0.075;",
                           "float ExpectMisclassifiedBelow = 0.075; float ExpectAreaRadius = 2; "
                           "float ExpectPenumbraMaeBelow = 0.99;");
    const RunResult blank = run("check " + loose.effect() +
                                " --technique hardware --scenes dual-l --backend egl --area-samples 16");
    EXPECT_EQ(blank.exitCode, 1) << blank.output;
    const std::string line = row(blank.output, "hardware", "dual-l", "penumbra");
    EXPECT_EQ(line.rfind("FAIL", 0), 0u) << blank.output;
    EXPECT_NE(line.find("passes a frame without shadows"), std::string::npos) << line;

    const RunResult without = run("check " + loose.effect() +
                                  " --technique hardware --scenes dual-l --backend egl --area-radius 0");
    EXPECT_EQ(without.exitCode, 0) << without.output;
    EXPECT_EQ(row(without.output, "hardware", "dual-l", "penumbra").rfind("NOT_SUPPORTED", 0), 0u)
        << without.output;
}

TEST(CheckCommand, PerSceneBoundsNameEachSceneOnce) {
    const EffectCopy copy("per_scene", "float ExpectMisclassifiedBelow = 0.075;",
                          "string ExpectMisclassifiedBelow = \"dual-l=0.075\";");
    const RunResult result = run("check " + copy.effect() + " --technique hardware --backend egl");
    EXPECT_EQ(result.exitCode, 1) << result.output;
    const std::string line = row(result.output, "hardware", "-", "expectations");
    EXPECT_EQ(line.rfind("FAIL", 0), 0u) << result.output;
    EXPECT_NE(line.find("no bound for scene 'teapot' of ExpectScenes"), std::string::npos) << line;
}

TEST(CheckCommand, CompileErrorsFailWithTheirLocation) {
    const RunResult result = run("check tests/data/bad/hlsl_error.fx --backend egl");
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_NE(result.output.find("FAIL"), std::string::npos) << result.output;
    EXPECT_NE(row(result.output, "\\S+", "-", "compile").find("hlsl_error.fx:6:18: error:"),
              std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find("\nhlsl_error: failed: "), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("\n1 effect: 0 drawn, 0 blank, 1 failed\n"), std::string::npos)
        << result.output;
}

TEST(CheckCommand, BadExpectationAnnotationsFailAtTheirLocation) {
    const EffectCopy copy("bad_annotation", "float ExpectMisclassifiedBelow = 0.095;",
                          "float ExpectMisclassifiedBelow = \"low\";");
    const RunResult result = run("check " + copy.effect() + " --technique main --backend egl");
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_NE(result.output.find("thesis_fxcomposer.fx:"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("ExpectMisclassifiedBelow"), std::string::npos) << result.output;
}

TEST(CheckCommand, AMisspeltExpectationIsAnError) {
    const EffectCopy copy("misspelt", "float ExpectMisclassifiedBelow = 0.095;",
                          "float ExpectMisclasifiedBelow = 0.095;");
    const RunResult result = run("check " + copy.effect() + " --technique main --backend egl");
    EXPECT_EQ(result.exitCode, 1) << result.output;
    const std::string line = row(result.output, "main", "-", "expectations");
    EXPECT_EQ(line.rfind("FAIL", 0), 0u) << result.output;
    EXPECT_NE(line.find("thesis_fxcomposer.fx:"), std::string::npos) << line;
    EXPECT_NE(line.find("ExpectMisclasifiedBelow"), std::string::npos) << line;
}

TEST(CheckCommand, ListsTechniquesAndRejectsBadUsage) {
    const RunResult list = run("check --list-techniques effects/thesis_fxcomposer.fx");
    EXPECT_EQ(list.exitCode, 0);
    EXPECT_EQ(list.output, "main\nmain11\nhardware\n");
    EXPECT_EQ(run("check").exitCode, 2);
    EXPECT_EQ(run("check effects/plain_lit.fx --backend vulkan").exitCode, 2);
    EXPECT_EQ(run("check effects/plain_lit.fx --width 0").exitCode, 2);
    EXPECT_EQ(run("check effects/plain_lit.fx --technique nosuch").exitCode, 2);
    const RunResult help = run("check --help");
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.output.find("usage: shadowfx check"), std::string::npos);
}

// --host: an effect written for an application, without SAS scripts, is checked on the frame its host
// file describes (the shadow map drawn from the light, then the lit scene); a host file that cannot be
// read fails the run before anything renders.
TEST(CheckCommand, AHostFileDrawsTheApplicationsFrame) {
    const shadowfx::test::ScratchDirectory scratch("check_host");
    const RunResult result = run(
        "check tests/data/host/app_shadow.fx --host tests/data/host/app_shadow.json --technique RenderScene "
        "--scenes boxes --backend egl --out " +
        (scratch / "out").string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(row(result.output, "RenderScene", "boxes", "render").find("PASS"), std::string::npos)
        << result.output;
    const RunResult missing =
        run("check tests/data/host/app_shadow.fx --host no_such_host.json --backend egl --out " +
            (scratch / "out").string());
    EXPECT_EQ(missing.exitCode, 1) << missing.output;
    EXPECT_NE(missing.output.find("no_such_host.json"), std::string::npos) << missing.output;
}

}  // namespace
}  // namespace test_check_command
