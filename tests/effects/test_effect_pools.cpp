// Effect pools (runtime/EffectPool.h): effects created in one pool share the values of their parameters
// declared `shared`, as D3DXCreateEffectPool's effects did. Setting one through one effect changes what
// another draws; parameters that are not shared, and effects outside the pool, keep their own values.
#include "effects/EffectHarness.h"

#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>
#include <runtime/BuiltinScenes.h>
#include <runtime/EffectPool.h>
#include <runtime/EffectRenderer.h>

#include <gtest/gtest.h>

namespace test_effect_pools {

namespace {

using shadowfx::test::countPixelsOfColour;
using shadowfx::test::sharedContext;

constexpr int kWidth = 96;
constexpr int kHeight = 72;

// Draws every object in `Tint` (shared) times `Own` (this effect's).
const char* const kSource = R"(
shared float4 Tint = float4(1, 0, 0, 1);
float4 Own = float4(1, 1, 1, 1);
float4x4 WorldViewProjection : WorldViewProjection;
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, WorldViewProjection); }
float4 PS() : SV_Target { return Tint * Own; }
technique main { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)";

// A float Tint cannot share a float4's value.
const char* const kMismatchedSource = R"(
shared float Tint = 1;
float4x4 WorldViewProjection : WorldViewProjection;
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, WorldViewProjection); }
float4 PS() : SV_Target { return Tint; }
technique main { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)";

// Draws every object in red at Level 0 and in green at Level 2. The `looping` technique's script runs its
// pass once per index of Count, LoopGetIndex setting Level to each: 2 after the frame.
const char* const kLevelSource = R"(
shared int Level = 0;
int Count = 3;
float4x4 WorldViewProjection : WorldViewProjection;
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, WorldViewProjection); }
float4 PS() : SV_Target { float level = Level; return float4(1 - level * 0.5, level * 0.5, 0, 1); }
technique looping < string Script = "LoopByCount=Count; LoopGetIndex=Level; Pass=p; LoopEnd=;"; >
{
    pass p < string Script = "Draw=Geometry;"; >
    { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); }
}
technique main { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)";

std::unique_ptr<runtime::EffectRenderer> create(const char* source, const std::string& name,
                                                std::shared_ptr<runtime::EffectPool> pool,
                                                fx::DiagnosticList& diagnostics) {
    sharedContext();
    std::shared_ptr<fx::Effect> effect = fx::parseEffectSource(source, name, {}, diagnostics);
    std::shared_ptr<fx::CompiledEffect> compiled =
        effect ? fx::compileEffect(effect, {}, diagnostics) : nullptr;
    if (!compiled) return nullptr;
    return runtime::EffectRenderer::create(compiled, diagnostics, std::move(pool));
}

// Pixels of `renderer`'s frame of the boxes scene, drawn with `technique`, in (r, g, b).
int pixelsOf(runtime::EffectRenderer& renderer, int r, int g, int b, const std::string& technique = "") {
    static const runtime::Scene scene = *runtime::makeBuiltinScene("boxes");
    EXPECT_TRUE(shadowfx::test::render(renderer, scene, kWidth, kHeight, technique));
    return countPixelsOfColour(renderer.readFrame(), kWidth, kHeight, r, g, b);
}

TEST(EffectPools, SettingASharedParameterThroughOneEffectChangesWhatAnotherDraws) {
    auto pool = std::make_shared<runtime::EffectPool>();
    fx::DiagnosticList diagnostics;
    std::unique_ptr<runtime::EffectRenderer> first = create(kSource, "first.fx", pool, diagnostics);
    std::unique_ptr<runtime::EffectRenderer> second = create(kSource, "second.fx", pool, diagnostics);
    std::unique_ptr<runtime::EffectRenderer> outside = create(kSource, "outside.fx", nullptr, diagnostics);
    ASSERT_TRUE(first && second && outside) << diagnostics.str();

    // The objects cover a good part of the frame in the initial red: the counts below are not of a blank
    // frame.
    const int covered = pixelsOf(*second, 255, 0, 0);
    ASSERT_GT(covered, kWidth * kHeight / 20);
    EXPECT_EQ(pixelsOf(*second, 0, 255, 0), 0);

    ASSERT_TRUE(first->variable("Tint").setVector(glm::vec4(0.0f, 1.0f, 0.0f, 1.0f)));
    EXPECT_EQ(pixelsOf(*second, 0, 255, 0), covered);
    EXPECT_EQ(pixelsOf(*second, 255, 0, 0), 0);
    // Outside the pool the effect keeps its own value.
    EXPECT_EQ(pixelsOf(*outside, 255, 0, 0), covered);

    // A parameter that is not shared stays the effect's own: blue through the first effect's Own leaves
    // the second's green.
    ASSERT_TRUE(first->variable("Own").setVector(glm::vec4(0.0f, 0.0f, 1.0f, 1.0f)));
    EXPECT_EQ(pixelsOf(*second, 0, 255, 0), covered);

    // Set through the second effect by setParameter, and seen by the first through the pass API's
    // render path too.
    fx::Value white = second->parameter(*second->findParameter("Tint"));
    white.data = {1.0f, 1.0f, 1.0f, 1.0f};
    second->setParameter(*second->findParameter("Tint"), white);
    EXPECT_EQ(pixelsOf(*first, 0, 0, 255), covered);
}

// A SAS script sets a shared parameter for the pool as a setter does: the loop index the first effect's
// frame leaves in Level is the value the second effect draws with.
TEST(EffectPools, AScriptsValueOfASharedParameterChangesWhatAnotherDraws) {
    auto pool = std::make_shared<runtime::EffectPool>();
    fx::DiagnosticList diagnostics;
    std::unique_ptr<runtime::EffectRenderer> looping = create(kLevelSource, "looping.fx", pool, diagnostics);
    std::unique_ptr<runtime::EffectRenderer> drawing = create(kLevelSource, "drawing.fx", pool, diagnostics);
    ASSERT_TRUE(looping && drawing) << diagnostics.str();

    const int covered = pixelsOf(*drawing, 255, 0, 0, "main");
    ASSERT_GT(covered, kWidth * kHeight / 20);
    EXPECT_EQ(pixelsOf(*drawing, 0, 255, 0, "main"), 0);

    // The looping frame's last pass draws at Level 2.
    EXPECT_GT(pixelsOf(*looping, 0, 255, 0, "looping"), 0);
    ASSERT_NE(pool->find("Level"), nullptr);
    EXPECT_EQ(pool->find("Level")->value.asInt(), 2);
    EXPECT_EQ(pixelsOf(*drawing, 0, 255, 0, "main"), covered);
    EXPECT_EQ(pixelsOf(*drawing, 255, 0, 0, "main"), 0);
}

TEST(EffectPools, AnEffectJoiningLaterTakesThePoolsValue) {
    auto pool = std::make_shared<runtime::EffectPool>();
    fx::DiagnosticList diagnostics;
    std::unique_ptr<runtime::EffectRenderer> first = create(kSource, "first.fx", pool, diagnostics);
    ASSERT_TRUE(first) << diagnostics.str();
    ASSERT_TRUE(first->variable("Tint").setVector(glm::vec4(0.0f, 1.0f, 0.0f, 1.0f)));
    std::unique_ptr<runtime::EffectRenderer> later = create(kSource, "later.fx", pool, diagnostics);
    ASSERT_TRUE(later) << diagnostics.str();
    EXPECT_GT(pixelsOf(*later, 0, 255, 0), kWidth * kHeight / 20);
    EXPECT_EQ(pixelsOf(*later, 255, 0, 0), 0);
}

TEST(EffectPools, ASharedParameterOfAnotherTypeIsAnError) {
    auto pool = std::make_shared<runtime::EffectPool>();
    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(create(kSource, "first.fx", pool, diagnostics)) << diagnostics.str();
    EXPECT_FALSE(create(kMismatchedSource, "mismatched.fx", pool, diagnostics));
    bool reported = false;
    for (const fx::Diagnostic& d : diagnostics.items())
        reported = reported || (d.id == fx::DiagId::PoolSharedTypeMismatch && d.loc.file == "mismatched.fx" &&
                                d.loc.line == 2 &&
                                d.message.find("'Tint' is a float here but a float4") != std::string::npos);
    EXPECT_TRUE(reported) << diagnostics.str();
}

}  // namespace
}  // namespace test_effect_pools
