// EffectHarness: parse, compile and render effects in tests through the real pipeline (glslang,
// SPIRV-Cross, Mesa's OpenGL). One headless context per test process.
#pragma once

#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>
#include <runtime/EffectRenderer.h>
#include <runtime/GlApi.h>
#include <runtime/GlContext.h>
#include <runtime/Scene.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace shadowfx::test {

inline runtime::GlContext& sharedContext() {
    static std::unique_ptr<runtime::GlContext> context = [] {
        std::string error;
        runtime::ContextOptions options;
        auto created = runtime::createContext(options, error);
        if (!created) ADD_FAILURE() << "no GL context: " << error;
        return created;
    }();
    if (!context) throw std::runtime_error("no GL context");
    context->makeCurrent();
    return *context;
}

inline std::string sourcePath(const std::string& relative) {
    return std::string(SHADOWFX_SOURCE_DIR) + "/" + relative;
}

// Parses and compiles an effect (a file when `isFile`, else inline source named `name`), then creates
// its renderer. Fails the current test with the diagnostics on any error.
inline std::unique_ptr<runtime::EffectRenderer> loadEffect(const std::string& fileOrSource, bool isFile,
                                                           const std::string& name = "inline.fx") {
    sharedContext();
    fx::DiagnosticList diagnostics;
    fx::ParseOptions parseOptions;
    std::shared_ptr<fx::Effect> effect =
        isFile ? fx::parseEffectFile(fileOrSource, parseOptions, diagnostics)
               : fx::parseEffectSource(fileOrSource, name, parseOptions, diagnostics);
    if (!effect) {
        ADD_FAILURE() << "parse failed:\n" << diagnostics.str();
        return nullptr;
    }
    std::shared_ptr<fx::CompiledEffect> compiled =
        fx::compileEffect(effect, fx::CompileOptions{}, diagnostics);
    if (!compiled || diagnostics.hasErrors()) {
        ADD_FAILURE() << "compile failed:\n" << diagnostics.str();
        return nullptr;
    }
    std::unique_ptr<runtime::EffectRenderer> renderer =
        runtime::EffectRenderer::create(compiled, diagnostics);
    if (!renderer) ADD_FAILURE() << "renderer creation failed:\n" << diagnostics.str();
    return renderer;
}

// An effect file's renderer compiled with preprocessor definitions (`SHADOWFX_VISIBILITY`, a map size).
// Fails the current test with the diagnostics on any error.
inline std::unique_ptr<runtime::EffectRenderer> loadEffectWithDefines(
    const std::string& path, const std::vector<std::pair<std::string, std::string>>& defines) {
    sharedContext();
    fx::DiagnosticList diagnostics;
    fx::ParseOptions options;
    options.defines = defines;
    std::shared_ptr<fx::Effect> effect = fx::parseEffectFile(path, options, diagnostics);
    std::shared_ptr<fx::CompiledEffect> compiled =
        effect ? fx::compileEffect(effect, fx::CompileOptions{}, diagnostics) : nullptr;
    if (!compiled || diagnostics.hasErrors()) {
        ADD_FAILURE() << path << " does not compile:\n" << diagnostics.str();
        return nullptr;
    }
    auto renderer = runtime::EffectRenderer::create(compiled, diagnostics);
    if (!renderer) ADD_FAILURE() << diagnostics.str();
    return renderer;
}

// An effect file's renderer with every diagnostic of parsing, compiling and creating it, for tests that
// check warnings. Fails the current test on any error.
struct LoadedEffect {
    std::unique_ptr<runtime::EffectRenderer> renderer;
    fx::DiagnosticList diagnostics;
};

inline LoadedEffect loadEffectWithDiagnostics(const std::string& path) {
    sharedContext();
    LoadedEffect out;
    std::shared_ptr<fx::Effect> effect = fx::parseEffectFile(path, fx::ParseOptions{}, out.diagnostics);
    if (!effect) {
        ADD_FAILURE() << "parse failed:\n" << out.diagnostics.str();
        return out;
    }
    std::shared_ptr<const fx::CompiledEffect> compiled =
        fx::compileEffect(effect, fx::CompileOptions{}, out.diagnostics);
    if (!compiled || out.diagnostics.hasErrors()) {
        ADD_FAILURE() << "compile failed:\n" << out.diagnostics.str();
        return out;
    }
    out.renderer = runtime::EffectRenderer::create(compiled, out.diagnostics);
    if (!out.renderer) ADD_FAILURE() << "renderer creation failed:\n" << out.diagnostics.str();
    return out;
}

// How many diagnostics of `diagnostics` have `id`.
inline int countDiagnostics(const fx::DiagnosticList& diagnostics, fx::DiagId id) {
    int n = 0;
    for (const fx::Diagnostic& d : diagnostics.items()) n += d.id == id;
    return n;
}

// The pixels of `frame` whose colour is (r, g, b), within one step of 8 bits.
inline int countPixelsOfColour(const runtime::FrameImage& frame, int width, int height, int r, int g, int b) {
    int count = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const uint8_t* p = frame.pixel(x, y);
            count += std::abs(p[0] - r) <= 1 && std::abs(p[1] - g) <= 1 && std::abs(p[2] - b) <= 1;
        }
    return count;
}

// `outputs`: render targets the test reads back (FrameOptions::outputTargets), kept by leave-out.
inline bool render(runtime::EffectRenderer& renderer, const runtime::Scene& scene, int width, int height,
                   const std::string& technique = "", const std::vector<std::string>& outputs = {}) {
    fx::DiagnosticList diagnostics;
    runtime::FrameOptions options;
    options.width = width;
    options.height = height;
    options.technique = technique;
    options.outputTargets = outputs;
    const bool ok = renderer.render(scene, options, diagnostics);
    EXPECT_TRUE(ok && !diagnostics.hasErrors()) << diagnostics.str();
    return ok;
}

// Luminance in [0, 1] of an 8-bit RGBA pixel.
// An application's own GL texture: one texel of `rgba`. The caller deletes it.
inline GLuint applicationTexel(const std::array<uint8_t, 4>& rgba = {255, 128, 64, 255}) {
    GLuint texture = 0;
    gl::GenTextures(1, &texture);
    gl::BindTexture(GL_TEXTURE_2D, texture);
    gl::TexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, 1, 1);
    gl::TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    gl::BindTexture(GL_TEXTURE_2D, 0);
    return texture;
}

inline float luminance(const uint8_t* p) {
    return (0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]) / 255.0f;
}

// Fails on a blank or constant image: an image test that would pass on one is a defect.
inline ::testing::AssertionResult notConstant(const runtime::FrameImage& image) {
    if (image.rgba.empty()) return ::testing::AssertionFailure() << "empty image";
    size_t differing = 0;
    for (size_t i = 4; i < image.rgba.size(); i += 4)
        if (image.rgba[i] != image.rgba[0] || image.rgba[i + 1] != image.rgba[1] ||
            image.rgba[i + 2] != image.rgba[2])
            ++differing;
    if (differing < image.rgba.size() / 4 / 100)
        return ::testing::AssertionFailure()
               << "image is (nearly) constant: " << differing << " pixels differ";
    return ::testing::AssertionSuccess();
}

}  // namespace shadowfx::test
