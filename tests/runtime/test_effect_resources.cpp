// The invariants of what an EffectRenderer keeps between frames, pinned on the classes that keep them:
// parameter values change only with their stamps (ParameterValues), a render target reallocated for a new
// frame size leaves no framebuffer attaching the old one (EffectTextures), every pass has its programs
// from load on (PassPrograms), a counted buffer has its counter and a view reaches its resource
// (StorageResources), and the scene's BVH follows its objects (SceneCache). Real glslang and real GL.
#include "effects/EffectHarness.h"

#include "EffectResources.h"

#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>
#include <runtime/Mesh.h>

#include <glm/gtc/matrix_transform.hpp>

namespace shadowfx::test::test_effect_resources {
namespace {

const char* kEffect = R"(
float4x4 WorldViewProjection : WorldViewProjection;
float Scale = 1.0;
float4 Tint = {1, 1, 1, 1};
texture Half : RenderColorTarget < float2 ViewPortRatio = {0.5, 0.5}; >;
texture Fixed : RenderColorTarget < int2 Dimensions = {16, 16}; >;
texture Unused : RenderColorTarget < int2 Dimensions = {8, 8}; >;
struct Out { float4 Position : POSITION; };
Out VS(float4 position : POSITION)
{
    Out o;
    o.Position = mul(float4(position.xyz * Scale, 1), WorldViewProjection);
    return o;
}
float4 PS() : COLOR { return Tint; }
technique t
{
    pass p < string Script = "RenderColorTarget0=Half; Draw=Geometry;"; >
    {
        VertexShader = compile vs_3_0 VS();
        PixelShader = compile ps_3_0 PS();
    }
}
)";

// `source` compiled, or a file's source where `isFile`.
std::shared_ptr<const fx::CompiledEffect> compile(const std::string& source, bool isFile = false) {
    sharedContext();
    fx::DiagnosticList diagnostics;
    std::shared_ptr<fx::Effect> effect =
        isFile ? fx::parseEffectFile(source, fx::ParseOptions{}, diagnostics)
               : fx::parseEffectSource(source, "resources.fx", fx::ParseOptions{}, diagnostics);
    std::shared_ptr<fx::CompiledEffect> compiled =
        effect ? fx::compileEffect(effect, fx::CompileOptions{}, diagnostics) : nullptr;
    EXPECT_TRUE(compiled && !diagnostics.hasErrors()) << diagnostics.str();
    return compiled;
}

// The resources a renderer of `effect` keeps (null, with the diagnostics as a failure, where they cannot be
// made).
std::unique_ptr<runtime::EffectResources> createResources(
    const std::shared_ptr<const fx::CompiledEffect>& effect) {
    fx::DiagnosticList diagnostics;
    std::unique_ptr<runtime::EffectResources> resources =
        runtime::EffectResources::create(effect, diagnostics);
    EXPECT_TRUE(resources) << diagnostics.str();
    return resources;
}

size_t indexOf(const fx::CompiledEffect& effect, const std::string& name) {
    for (size_t i = 0; i < effect.parameters.size(); ++i)
        if (effect.parameters[i].name == name) return i;
    ADD_FAILURE() << "no parameter " << name;
    return 0;
}

// The stamps of every parameter but `except`.
std::vector<uint64_t> otherStamps(const runtime::ParameterValues& values, size_t except) {
    std::vector<uint64_t> stamps = values.stamps().stamps;
    stamps.erase(stamps.begin() + static_cast<std::ptrdiff_t>(except));
    return stamps;
}

TEST(ParameterValues, AStoreTouchesItsOwnStampAlone) {
    const auto effect = compile(kEffect);
    ASSERT_TRUE(effect);
    runtime::ParameterValues values(effect->parameters, effect->initialValues);
    ASSERT_EQ(values.size(), effect->parameters.size());
    const size_t scale = indexOf(*effect, "Scale"), tint = indexOf(*effect, "Tint");
    EXPECT_FLOAT_EQ(values[scale].asFloat(), 1.0f);

    const std::vector<uint64_t> before = values.stamps().stamps;
    values.store(scale, fx::Value::scalar(2.0f));
    EXPECT_FLOAT_EQ(values[scale].asFloat(), 2.0f);
    EXPECT_NE(values.stamps().stamps[scale], before[scale]);
    std::vector<uint64_t> othersBefore = before;
    othersBefore.erase(othersBefore.begin() + static_cast<std::ptrdiff_t>(scale));
    EXPECT_EQ(otherStamps(values, scale), othersBefore);
    EXPECT_FALSE(values.isPinned(scale));

    // A scalar stored into a vector is broadcast, and the value takes the parameter's type.
    values.storeScalar(tint, 0.25f);
    EXPECT_EQ(values[tint].type.componentCount(), 4);
    EXPECT_EQ(values[tint].data, std::vector<float>(4, 0.25f));
}

TEST(ParameterValues, SemanticsLeaveAPinnedValueAndTouchOnlyWhatChanged) {
    const auto effect = compile(kEffect);
    ASSERT_TRUE(effect);
    runtime::ParameterValues values(effect->parameters, effect->initialValues);
    const runtime::SemanticBinder binder(effect->parameters, effect->lights);
    const size_t wvp = indexOf(*effect, "WorldViewProjection");
    runtime::RenderPortView port;
    port.projection = glm::mat4(2.0f);

    values.bindSemantics(binder, port, nullptr, 0.0f, runtime::SemanticBinder::Scope::All, nullptr);
    const uint64_t bound = values.stamps().stamps[wvp];
    EXPECT_NE(bound, 0u);
    EXPECT_FLOAT_EQ(values[wvp].data[0], 2.0f);
    // The same port again changes no value: no stamp moves, so no preshader or upload reruns.
    const std::vector<uint64_t> stamps = values.stamps().stamps;
    values.bindSemantics(binder, port, nullptr, 0.0f, runtime::SemanticBinder::Scope::All, nullptr);
    EXPECT_EQ(values.stamps().stamps, stamps);

    // The application's value stays over the semantic's.
    fx::Value own = values[wvp];
    own.data.assign(16, 7.0f);
    values.pin(wvp, own);
    EXPECT_TRUE(values.isPinned(wvp));
    values.bindSemantics(binder, port, nullptr, 0.0f, runtime::SemanticBinder::Scope::All, nullptr);
    EXPECT_EQ(values[wvp].data, std::vector<float>(16, 7.0f));
}

TEST(ParameterValues, ACopysStampsNeverMeetTheOriginals) {
    const auto effect = compile(kEffect);
    ASSERT_TRUE(effect);
    runtime::ParameterValues values(effect->parameters, effect->initialValues);
    const size_t scale = indexOf(*effect, "Scale");
    runtime::ParameterValues copy;
    copy.copyFrom(values);
    EXPECT_EQ(copy.all().size(), values.size());
    EXPECT_EQ(copy.stamps().stamps, values.stamps().stamps);
    copy.storeScalar(scale, 3.0f);
    values.storeScalar(scale, 3.0f);
    // Equal stamps mean equal values; the same value stored twice is still two changes.
    EXPECT_NE(copy.stamps().stamps[scale], values.stamps().stamps[scale]);
    EXPECT_FLOAT_EQ(values[scale].asFloat(), 3.0f);
}

TEST(EffectTextures, AResizedTargetLeavesNoFramebufferOnTheOldOne) {
    const auto effect = compile(kEffect);
    ASSERT_TRUE(effect);
    std::unique_ptr<runtime::EffectResources> resources = createResources(effect);
    ASSERT_TRUE(resources);
    runtime::EffectTextures& textures = *resources->textures;
    const size_t half = indexOf(*effect, "Half"), fixed = indexOf(*effect, "Fixed"),
                 unused = indexOf(*effect, "Unused");
    EXPECT_EQ(textures.find(half), nullptr);  // no frame has needed it yet

    std::vector<bool> needed(effect->parameters.size(), false);
    needed[half] = needed[fixed] = true;
    textures.ensureFrame(64, 40, &needed);
    ASSERT_NE(textures.find(half), nullptr);
    EXPECT_EQ(textures.find(half)->width(), 32);
    EXPECT_EQ(textures.find(half)->height(), 20);
    EXPECT_EQ(textures.find(fixed)->width(), 16);
    EXPECT_EQ(textures.find(unused), nullptr);
    EXPECT_EQ(textures.frameColor().width(), 64);
    EXPECT_EQ(textures.frameDepth().height(), 40);

    runtime::RenderTargets targets;
    targets.colors[0] = runtime::RenderTargetAttachment::wholeOf(textures.find(half));
    runtime::FramebufferFault fault;
    ASSERT_TRUE(textures.bindTargets(targets, fault));
    runtime::RenderTargets fixedTargets;
    fixedTargets.colors[0] = runtime::RenderTargetAttachment::wholeOf(textures.find(fixed));
    ASSERT_TRUE(textures.bindTargets(fixedTargets, fault));
    EXPECT_EQ(textures.framebufferCount(), 2u);

    // The same size again reallocates nothing.
    const uint64_t halfIdentity = textures.identity(static_cast<int>(half));
    const uint64_t fixedIdentity = textures.identity(static_cast<int>(fixed));
    textures.ensureFrame(64, 40, &needed);
    EXPECT_EQ(textures.identity(static_cast<int>(half)), halfIdentity);
    EXPECT_EQ(textures.framebufferCount(), 2u);

    // A new frame size: the ratio target follows it and its framebuffer goes; the fixed one stays.
    textures.ensureFrame(100, 60, nullptr);
    EXPECT_EQ(textures.find(half)->width(), 50);
    EXPECT_EQ(textures.find(half)->height(), 30);
    EXPECT_NE(textures.identity(static_cast<int>(half)), halfIdentity);
    EXPECT_EQ(textures.identity(static_cast<int>(fixed)), fixedIdentity);
    EXPECT_EQ(textures.framebufferCount(), 1u);
    EXPECT_NE(textures.find(unused), nullptr);  // null `needed`: every target
    EXPECT_EQ(textures.frameColor().width(), 100);

    // The next bind builds a framebuffer on the new texture, of its size.
    targets.colors[0] = runtime::RenderTargetAttachment::wholeOf(textures.find(half));
    ASSERT_TRUE(textures.bindTargets(targets, fault));
    EXPECT_EQ(targets.width(), 50);
    EXPECT_EQ(textures.framebufferCount(), 2u);
}

TEST(EffectTextures, SetRefusesARenderTarget) {
    const auto effect = compile(kEffect);
    ASSERT_TRUE(effect);
    std::unique_ptr<runtime::EffectResources> resources = createResources(effect);
    ASSERT_TRUE(resources);
    const size_t fixed = indexOf(*effect, "Fixed");
    resources->textures->ensureFrame(32, 32);
    const uint64_t identity = resources->textures->identity(static_cast<int>(fixed));
    runtime::TextureData data;
    data.width = data.height = 16;
    data.rgba.assign(16 * 16 * 4, 1.0f);
    fx::DiagnosticList refused;
    EXPECT_FALSE(resources->setTexture(fixed, data, refused));
    EXPECT_EQ(countDiagnostics(refused, fx::DiagId::SetTextureNotReadTexture), 1);
    EXPECT_EQ(resources->textures->identity(static_cast<int>(fixed)), identity);
}

TEST(PassPrograms, EveryPassHasItsProgramFromLoadOn) {
    const auto effect = compile(kEffect);
    ASSERT_TRUE(effect);
    fx::DiagnosticList diagnostics;
    std::unique_ptr<runtime::PassPrograms> programs = runtime::PassPrograms::create(*effect, diagnostics);
    ASSERT_TRUE(programs) << diagnostics.str();
    ASSERT_NE(programs->program(0, 0), nullptr);
    EXPECT_FALSE(programs->program(0, 0)->isCompute());
    EXPECT_EQ(programs->computeProgram(0, 0), nullptr);
    EXPECT_EQ(programs->streamOut(0, 0), nullptr);
    EXPECT_EQ(programs->techniquePreshaders(0).size(), 1u);
    // A variant is linked once and kept.
    const fx::CompiledPass& pass = effect->techniques[0].passes[0];
    runtime::GpuProgram* depthOnly = programs->depthOnlyProgram(0, 0, pass);
    ASSERT_NE(depthOnly, nullptr);
    EXPECT_EQ(programs->depthOnlyProgram(0, 0, pass), depthOnly);
}

uint32_t counterValue(const runtime::GpuBuffer& counter) {
    uint32_t value = 0xFFFFFFFFu;
    gl::GetNamedBufferSubData(counter.id(), 0, sizeof value, &value);
    return value;
}

// The storage is made from what the compiler resolved (fx::ParameterInfo::viewOf, elementCount), not from
// the annotations: the effect is given to the runtime without them.
TEST(StorageResources, ACountedBufferKeepsItsCounterAndAViewReachesItsResource) {
    const auto compiled = compile(sourcePath("tests/data/d3d10/compute_append_consume.fx"), true);
    ASSERT_TRUE(compiled);
    auto effect = std::make_shared<fx::CompiledEffect>(*compiled);
    for (fx::ParameterInfo& parameter : effect->parameters) parameter.annotations.clear();
    std::unique_ptr<runtime::EffectResources> resources = createResources(effect);
    ASSERT_TRUE(resources);
    runtime::StorageResources& storage = *resources->storage;
    const size_t live = indexOf(*effect, "Live"), spent = indexOf(*effect, "Spent"),
                 sparks = indexOf(*effect, "Sparks"), taken = indexOf(*effect, "Taken");
    EXPECT_EQ(storage.viewedResource(spent), live);
    EXPECT_EQ(storage.viewedResource(sparks), live);
    EXPECT_EQ(storage.viewedResource(live), live);

    // From load on: every counted buffer has its counter at zero, and room for its ElementCount.
    ASSERT_NE(storage.buffer(live), nullptr);
    ASSERT_NE(storage.counter(live), nullptr);
    ASSERT_NE(storage.counter(taken), nullptr);
    EXPECT_EQ(counterValue(*storage.counter(live)), 0u);
    const size_t room = storage.buffer(live)->size();
    EXPECT_GE(room, 64 * 12u);

    // Elements set through the consume view are the append buffer's: its counter counts them, and the
    // buffer keeps room for the ElementCount the shaders append up to.
    float elements[3][3] = {{0, 0, 1}, {0, 0, 2}, {0, 0, 3}};
    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(storage.set(spent, elements, 3, sizeof elements[0], diagnostics)) << diagnostics.str();
    EXPECT_EQ(counterValue(*storage.counter(live)), 3u);
    EXPECT_EQ(storage.buffer(live)->size(), room);
    // Elements of the wrong size are refused and change nothing.
    fx::DiagnosticList refused;
    EXPECT_FALSE(storage.set(live, elements, 3, 4, refused));
    EXPECT_EQ(countDiagnostics(refused, fx::DiagId::SetBufferPackedElementSize), 1);
    EXPECT_EQ(counterValue(*storage.counter(live)), 3u);

    const uint64_t dispatches = storage.dispatches();
    storage.countDispatch();
    EXPECT_EQ(storage.dispatches(), dispatches + 1);
}

TEST(SceneCache, TheBvhFollowsTheObjectsAndOnlyThem) {
    sharedContext();
    auto box = std::make_shared<runtime::Mesh>(runtime::makeBox(glm::vec3(1.0f)));
    const float half = box->boundsMax().x;
    runtime::Scene scene;
    scene.objects.resize(2);
    scene.objects[0].mesh = scene.objects[1].mesh = box;
    scene.objects.back().world = glm::translate(glm::mat4(1.0f), glm::vec3(10, 0, 0));
    runtime::SceneCache cache;
    EXPECT_FALSE(cache.valid());
    cache.update(scene);
    ASSERT_TRUE(cache.valid());
    const uint64_t stamp = cache.stamp();
    EXPECT_EQ(cache.meshCount(), 1u);
    EXPECT_EQ(cache.meshSlots(), std::vector<uint32_t>({0, 0}));
    EXPECT_NEAR(cache.bvh().rootBox().max.x, 10 + half, 1e-4f);

    // The same objects again: the same stamp, nothing rebuilt.
    cache.update(scene);
    EXPECT_EQ(cache.stamp(), stamp);

    // An object moved: a new stamp, and the BVH and bounds describe where it is now.
    scene.objects.back().world = glm::translate(glm::mat4(1.0f), glm::vec3(-20, 0, 0));
    cache.update(scene);
    EXPECT_NE(cache.stamp(), stamp);
    EXPECT_NEAR(cache.bvh().rootBox().min.x, -20 - half, 1e-4f);
    EXPECT_NEAR(cache.bvh().rootBox().max.x, half, 1e-4f);
}

}  // namespace
}  // namespace shadowfx::test::test_effect_resources
