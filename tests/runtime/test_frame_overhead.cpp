// What the per-frame path resolves and allocates: after the first frame, frames of the thesis effect (and
// of a technique whose script loops) look up no name (runtime/NameLookups.h counts every parameter, light,
// technique and semantic found by its text, and every literal parsed: the runtime resolves them when the
// effect is created) and make no heap allocation, counted by this binary's own global operator new between
// the markers around render(): the runtime keeps its per-frame data between frames (the frame plan, the
// working lists, the preshader VM's registers, FrameStats' lists). With an orbiting camera a few lists may
// still grow as the view shows more objects than any frame before (geometrically, so a handful of times at
// most).
//
// Only operator new is counted, and only on the thread that renders: the runtime is C++ and allocates
// through it (std::string, std::vector, std::map), while Mesa is C and allocates with malloc for its own
// state, which is the driver's business and not the runtime's per-frame overhead.
#include <private/runtime/NameLookups.h>
#include <runtime/BuiltinScenes.h>
#include <runtime/HostFileReader.h>
#include "effects/EffectHarness.h"

#include <fx/EffectFile.h>

#include <glm/gtc/matrix_transform.hpp>

#include <atomic>
#include <cstdlib>
#include <new>

namespace {

thread_local bool tCounting = false;
std::atomic<uint64_t> gAllocations{0};

void* allocate(std::size_t size, std::size_t alignment = 0) {
    if (tCounting) gAllocations.fetch_add(1, std::memory_order_relaxed);
    if (size == 0) size = 1;
    void* p = alignment > alignof(std::max_align_t)
                  ? std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment)
                  : std::malloc(size);
    if (!p) throw std::bad_alloc();
    return p;
}

}  // namespace

void* operator new(std::size_t size) {
    return allocate(size);
}
void* operator new[](std::size_t size) {
    return allocate(size);
}
void* operator new(std::size_t size, std::align_val_t alignment) {
    return allocate(size, static_cast<std::size_t>(alignment));
}
void* operator new[](std::size_t size, std::align_val_t alignment) {
    return allocate(size, static_cast<std::size_t>(alignment));
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    try {
        return allocate(size);
    } catch (const std::bad_alloc&) {
        return nullptr;
    }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
    try {
        return allocate(size);
    } catch (const std::bad_alloc&) {
        return nullptr;
    }
}
// GCC pairs a replaced operator new with the free() in these deletes and warns of a mismatch; the pairs are
// matched here (allocate() takes its memory from malloc), so the warning is silenced for the deletes alone
// (clang has no such warning).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
    std::free(p);
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

namespace {

using namespace runtime;

struct Overhead {
    uint64_t allocations = 0;
    uint64_t lookups = 0;
};

// Renders one warm-up frame of `technique`, then `frames` frames (the camera turned `orbitDegrees` about its
// target before each, as `shadowfx bench --camera-orbit` turns it), counting what those frames allocate
// and look up.
Overhead frameOverhead(std::unique_ptr<EffectRenderer> renderer, const std::string& technique,
                       const std::string& sceneName, int frames, float orbitDegrees, bool hostFrame = false) {
    std::optional<Scene> scene = makeBuiltinScene(sceneName);
    if (!renderer || !scene) {
        ADD_FAILURE() << "no renderer or no scene '" << sceneName << "'";
        return {};
    }
    FrameOptions options;
    options.width = 128;
    options.height = 96;
    options.technique = technique;
    options.timePasses = true;  // as bench measures the overhead
    fx::DiagnosticList diagnostics;
    FrameStats stats;
    EXPECT_TRUE(renderer->render(*scene, options, diagnostics, &stats)) << diagnostics.str();
    const glm::vec3 offset = scene->camera.position - scene->camera.target;
    Overhead overhead;
    for (int frame = 1; frame <= frames; ++frame) {
        const glm::mat4 turn =
            glm::rotate(glm::mat4(1.0f), glm::radians(orbitDegrees * static_cast<float>(frame)),
                        glm::vec3(0.0f, 1.0f, 0.0f));
        scene->camera.position = scene->camera.target + glm::vec3(turn * glm::vec4(offset, 0.0f));
        const uint64_t lookupsBefore = nameLookups();
        const uint64_t allocationsBefore = gAllocations.load();
        tCounting = true;
        const bool rendered = renderer->render(*scene, options, diagnostics, &stats);
        tCounting = false;
        overhead.allocations += gAllocations.load() - allocationsBefore;
        overhead.lookups += nameLookups() - lookupsBefore;
        EXPECT_TRUE(rendered) << diagnostics.str();
    }
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.str();
    // The frames drew something: a frame that skipped its work would allocate nothing either. (A host
    // file's frame draws through the pass API, which FrameStats does not count: its image shows it.)
    if (!hostFrame) {
        EXPECT_GT(stats.draws, 0);
    }
    const FrameImage image = renderer->readFrame();
    EXPECT_TRUE(shadowfx::test::notConstant(image));
    std::cout << sceneName << ": " << overhead.allocations << " allocations and " << overhead.lookups
              << " name lookups in " << frames << " frames\n";
    return overhead;
}

Overhead thesisOverhead(const std::string& sceneName, int frames, float orbitDegrees) {
    return frameOverhead(
        shadowfx::test::loadEffect(shadowfx::test::sourcePath("effects/thesis_fxcomposer.fx"), true), "main",
        sceneName, frames, orbitDegrees);
}

constexpr int kFrames = 100;

TEST(FrameOverhead, ThesisOnDualL) {
    const Overhead overhead = thesisOverhead("dual-l", kFrames, 0.0f);
    EXPECT_EQ(overhead.lookups, 0u);
    EXPECT_EQ(overhead.allocations, 0u);
}

// forest-fifth's 10,001 objects with the camera orbiting as `bench --camera-orbit 0.5` turns it: culled
// anew every frame, the shadow map reused.
TEST(FrameOverhead, ThesisOnForestFifthWithOrbitingCamera) {
    const Overhead overhead = thesisOverhead("forest-fifth", kFrames, 0.5f);
    EXPECT_EQ(overhead.lookups, 0u);
    EXPECT_LE(overhead.allocations, 10u);  // in all 100 frames: lists growing to the widest view so far
}

// A technique script that loops, its pass reading the loop's index and its clear colour a literal: the
// interpreter's loop stack and the index it stores keep their storage between frames (the dry run and the
// run each walk the loop).
constexpr const char* kLoopingEffect = R"(
int Count = 3;
int Level = 0;
float4x4 WorldViewProjection : WorldViewProjection;
float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProjection); }
float4 PS() : COLOR { return float4(1 - Level * 0.3, Level * 0.3, 0.2, 1); }
technique looping < string Script = "ClearSetColor=0.1,0.2,0.3,1; Clear=Color; ClearSetDepth=1; Clear=Depth;"
                                    "LoopByCount=Count; LoopGetIndex=Level; Pass=p; LoopEnd=;"; >
{
    pass p < string Script = "Draw=Geometry;"; >
    { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); ZFunc = LessEqual; }
}
)";

TEST(FrameOverhead, LoopingScriptOnDualL) {
    const Overhead overhead = frameOverhead(shadowfx::test::loadEffect(kLoopingEffect, false, "looping.fx"),
                                            "looping", "dual-l", kFrames, 0.0f);
    EXPECT_EQ(overhead.lookups, 0u);
    EXPECT_EQ(overhead.allocations, 0u);
}

// A STANDARDSGLOBAL selector whose condition is a parameter is evaluated every frame: by the indices the
// compiler gave the condition and both techniques, never by their names.
constexpr const char* kSelectingEffect = R"(
bool UseBright = true;
float4x4 WorldViewProjection : WorldViewProjection;
float Script : STANDARDSGLOBAL < string Script = "Technique=UseBright?bright:dim;"; > = 0.8;
float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProjection); }
float4 Bright() : COLOR { return float4(1, 1, 1, 1); }
float4 Dim() : COLOR { return float4(0.2, 0.2, 0.2, 1); }
technique dim { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Dim(); } }
technique bright { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Bright(); } }
)";

TEST(FrameOverhead, SelectorReadingAParameterOnDualL) {
    const Overhead overhead = frameOverhead(
        shadowfx::test::loadEffect(kSelectingEffect, false, "selecting.fx"), "", "dual-l", kFrames, 0.0f);
    EXPECT_EQ(overhead.lookups, 0u);
    EXPECT_EQ(overhead.allocations, 0u);
}

// A host file's frame (the application's own passes, fx/HostFile.h): its parameters, techniques, passes,
// targets and lights are resolved when the file is set and its lights fitted by the effect's binder, so
// frames after the first look up no name; each value is built in storage it keeps and stored in the
// parameter's own, so they allocate nothing either.
TEST(FrameOverhead, HostFileFramesOnDualL) {
    std::unique_ptr<EffectRenderer> renderer =
        shadowfx::test::loadEffect(shadowfx::test::sourcePath("tests/data/host/app_shadow.fx"), true);
    fx::DiagnosticList diagnostics;
    std::shared_ptr<const fx::HostFile> host =
        loadHostFile(shadowfx::test::sourcePath("tests/data/host/app_shadow.json"), diagnostics);
    ASSERT_TRUE(renderer && host && renderer->setHostFile(host, diagnostics)) << diagnostics.str();
    const Overhead overhead = frameOverhead(std::move(renderer), "", "dual-l", kFrames, 0.0f, true);
    EXPECT_EQ(overhead.lookups, 0u);
    EXPECT_EQ(overhead.allocations, 0u);
}

// A host file's step that dispatches a compute pass with a group count from a parameter: the count is read
// where the parameter holds it, not copied, so these frames allocate nothing either. Two frames put the
// particles on screen; then the count is 0, so that they stay there through the counted frames.
TEST(FrameOverhead, HostFileDispatchFramesOnDualL) {
    std::unique_ptr<EffectRenderer> renderer =
        shadowfx::test::loadEffect(shadowfx::test::sourcePath("tests/data/d3d10/compute_particles.fx"), true);
    fx::DiagnosticList diagnostics;
    std::shared_ptr<const fx::HostFile> host = parseHostJson(
        R"({"frame": [{"technique": "Particles", "pass": "Advance", "dispatch": ["GroupCount", 1, 1]},
                      {"technique": "Particles", "pass": "Draw", "draw": "nothing",
                       "clear": {"color": [0, 0, 0, 1]}},
                      {"technique": "Particles", "pass": "Draw", "draw": "quad"}]})",
        "dispatch.json", diagnostics);
    ASSERT_TRUE(renderer && host && renderer->setHostFile(host, diagnostics)) << diagnostics.str();
    const std::optional<Scene> scene = makeBuiltinScene("dual-l");
    ASSERT_TRUE(scene);
    FrameOptions options;
    options.width = 128;
    options.height = 96;
    for (int frame = 0; frame < 2; ++frame)
        ASSERT_TRUE(renderer->render(*scene, options, diagnostics)) << diagnostics.str();
    ASSERT_TRUE(renderer->variable("GroupCount").setInt(0));
    const Overhead overhead = frameOverhead(std::move(renderer), "", "dual-l", kFrames, 0.0f, true);
    EXPECT_EQ(overhead.lookups, 0u);
    EXPECT_EQ(overhead.allocations, 0u);
}

// A host file's scored frames (its visibility section, the effect compiled with SHADOWFX_VISIBILITY): whether
// a frame is the shadow factor was read from the effect's definitions when the file was set, so the frames
// look up no name. (They allocate: each reads its two frames back to divide them.)
TEST(FrameOverhead, HostFileScoredFramesLookUpNoName) {
    shadowfx::test::sharedContext();
    fx::DiagnosticList diagnostics;
    fx::ParseOptions parse;
    parse.defines = {{"SHADOWFX_VISIBILITY", "1"}};
    std::shared_ptr<const fx::CompiledEffect> compiled = fx::loadEffectFile(
        shadowfx::test::sourcePath("tests/data/host/app_shadow.fx"), parse, {}, diagnostics);
    std::shared_ptr<const fx::HostFile> host =
        loadHostFile(shadowfx::test::sourcePath("tests/data/host/app_shadow.json"), diagnostics);
    ASSERT_TRUE(compiled && host) << diagnostics.str();
    const std::unique_ptr<EffectRenderer> renderer = EffectRenderer::create(compiled, diagnostics);
    ASSERT_TRUE(renderer) << diagnostics.str();
    const uint64_t settingBefore = nameLookups();
    ASSERT_TRUE(renderer->setHostFile(host, diagnostics)) << diagnostics.str();
    EXPECT_GT(nameLookups() - settingBefore, 0u) << "setting the file resolves its names";
    const std::optional<Scene> scene = makeBuiltinScene("dual-l");
    ASSERT_TRUE(scene);
    FrameOptions options;
    options.width = 128;
    options.height = 96;
    ASSERT_TRUE(renderer->render(*scene, options, diagnostics)) << diagnostics.str();
    const uint64_t lookupsBefore = nameLookups();
    for (int frame = 0; frame < 10; ++frame)
        ASSERT_TRUE(renderer->render(*scene, options, diagnostics)) << diagnostics.str();
    EXPECT_EQ(nameLookups() - lookupsBefore, 0u);
    // The frames were scored: the shadow factor, grey, with shadow and light in it.
    const FrameImage image = renderer->readFrame();
    EXPECT_TRUE(shadowfx::test::notConstant(image));
    bool grey = true;
    for (size_t i = 0; i + 3 < image.rgba.size(); i += 4)
        grey = grey && image.rgba[i] == image.rgba[i + 1] && image.rgba[i] == image.rgba[i + 2];
    EXPECT_TRUE(grey) << "a scored frame holds the shadow factor in every channel";
}

// The compiler classified every parameter's semantic (fx::SemanticBinding) and every stage's effects
// (fx::StageEffects): creating a renderer reads neither from text.
TEST(FrameOverhead, CreatingTheThesisRendererLooksUpNoName) {
    shadowfx::test::sharedContext();
    fx::DiagnosticList diagnostics;
    std::shared_ptr<const fx::CompiledEffect> compiled =
        fx::loadEffectFile(shadowfx::test::sourcePath("effects/thesis_fxcomposer.fx"), {}, {}, diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    const uint64_t lookupsBefore = nameLookups();
    const std::unique_ptr<EffectRenderer> renderer = EffectRenderer::create(compiled, diagnostics);
    EXPECT_TRUE(renderer) << diagnostics.str();
    EXPECT_EQ(nameLookups() - lookupsBefore, 0u);
}

}  // namespace
