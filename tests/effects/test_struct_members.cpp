// Struct members in the variable API (runtime/EffectVariable.h), as FX11's GetMemberByName, ByIndex and
// BySemantic: a member of a struct parameter, or of an element of an array of structs, set through its
// handle changes the bytes of the uniform block the shader reads, so the frame's colour; the layout the
// compiler reflected survives the compiled effect file; lookups of members that are not there give invalid
// handles that do nothing.
#include "effects/EffectHarness.h"

#include <fx/CompiledEffectFile.h>
#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>
#include <runtime/BuiltinScenes.h>
#include <runtime/EffectRenderer.h>

#include <gtest/gtest.h>

namespace test_struct_members {

namespace {

using shadowfx::test::countPixelsOfColour;
using shadowfx::test::sharedContext;

constexpr int kWidth = 96;
constexpr int kHeight = 72;

// The pixel colour: Surface's colour when enabled, scaled by its gain, its red and green through its
// matrix (a row vector times `mix`), plus the colour of the second light's material. Every member is zero
// until the test sets it, so the objects start black.
const char* const kSource = R"(
struct Material
{
    float3 color : DIFFUSE;
    bool enabled;
    float gain;
    float2x2 mix;
};
struct Light
{
    float4 tint;
    Material material;
};
Material Surface;
Light Lights[2];
float Gain;
float4x4 WorldViewProjection : WorldViewProjection;
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, WorldViewProjection); }
float4 PS() : SV_Target
{
    float3 c = Surface.enabled ? Surface.color * Surface.gain : float3(0, 0, 0);
    float2 rg = mul(c.rg, Surface.mix);
    return float4(float3(rg, c.b) + Lights[1].material.color, 1);
}
technique main { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)";

std::shared_ptr<fx::CompiledEffect> compile() {
    fx::DiagnosticList diagnostics;
    std::shared_ptr<fx::Effect> effect = fx::parseEffectSource(kSource, "members.fx", {}, diagnostics);
    std::shared_ptr<fx::CompiledEffect> compiled =
        effect ? fx::compileEffect(effect, {}, diagnostics) : nullptr;
    EXPECT_TRUE(compiled) << diagnostics.str();
    return compiled;
}

std::unique_ptr<runtime::EffectRenderer> load(std::shared_ptr<const fx::CompiledEffect> compiled) {
    sharedContext();
    fx::DiagnosticList diagnostics;
    auto renderer = compiled ? runtime::EffectRenderer::create(std::move(compiled), diagnostics) : nullptr;
    EXPECT_TRUE(renderer) << diagnostics.str();
    return renderer;
}

int pixelsOf(runtime::EffectRenderer& renderer, int r, int g, int b) {
    static const runtime::Scene scene = *runtime::makeBuiltinScene("boxes");
    EXPECT_TRUE(shadowfx::test::render(renderer, scene, kWidth, kHeight));
    return countPixelsOfColour(renderer.readFrame(), kWidth, kHeight, r, g, b);
}

// Sets members one by one and checks the colour each step gives; `effect` is fresh.
void drawsWhatTheMembersSay(runtime::EffectRenderer& effect) {
    runtime::EffectVariable surface = effect.variable("Surface");
    EXPECT_EQ(pixelsOf(effect, 0, 255, 0), 0) << "every member is zero: the objects are black";

    // Red through a matrix whose only 1 is in row 0, column 1: green if the matrix lands in its rows
    // as HLSL declares them, black if transposed. The bool and the float after it must land too.
    glm::mat2 mix(0.0f);
    mix[0][1] = 1.0f;  // HLSL mix[0][1] (fx/Value.h: a glm matrix holds HLSL's rows as its columns)
    ASSERT_TRUE(surface.member("color").setVector(glm::vec3(1.0f, 0.0f, 0.0f)));
    ASSERT_TRUE(surface.member("enabled").setBool(true));
    ASSERT_TRUE(surface.member("gain").setFloat(1.0f));
    ASSERT_TRUE(surface.member("mix").setMatrix(mix));
    const int covered = pixelsOf(effect, 0, 255, 0);
    ASSERT_GT(covered, kWidth * kHeight / 20);

    // A member of a struct in an element of an array of structs.
    runtime::EffectVariable light = effect.variable("Lights").element(1).member("material").member("color");
    ASSERT_TRUE(light.isValid());
    EXPECT_EQ(light.name(), "Lights[1].material.color");
    ASSERT_TRUE(light.setVector(glm::vec3(0.0f, 0.0f, 1.0f)));
    EXPECT_EQ(pixelsOf(effect, 0, 255, 255), covered);

    // By semantic, without regard to case, as FX11's GetMemberBySemantic.
    runtime::EffectVariable diffuse = surface.memberBySemantic("diffuse");
    EXPECT_EQ(diffuse.name(), "Surface.color");
    EXPECT_EQ(diffuse.semantic(), "DIFFUSE");
    ASSERT_TRUE(diffuse.setVector(glm::vec3(0.0f)));
    EXPECT_EQ(pixelsOf(effect, 0, 0, 255), covered);

    // The first light's material is not read: setting it changes nothing.
    ASSERT_TRUE(effect.variable("Lights").element(0).member(1).member(0).setVector(glm::vec3(1.0f)));
    EXPECT_EQ(pixelsOf(effect, 0, 0, 255), covered);
}

TEST(StructMembers, SetThroughTheApiChangeTheColourDrawn) {
    auto effect = load(compile());
    ASSERT_TRUE(effect);
    drawsWhatTheMembersSay(*effect);
}

TEST(StructMembers, KeepTheirLayoutInTheCompiledEffectFile) {
    std::shared_ptr<fx::CompiledEffect> compiled = compile();
    ASSERT_TRUE(compiled);
    fx::DiagnosticList diagnostics;
    std::shared_ptr<fx::CompiledEffect> read =
        fx::deserializeCompiledEffect(fx::serializeCompiledEffect(*compiled), "members.sfxo", diagnostics);
    ASSERT_TRUE(read) << diagnostics.str();
    auto effect = load(read);
    ASSERT_TRUE(effect);
    drawsWhatTheMembersSay(*effect);
}

TEST(StructMembers, ReadBackAsPartsOfTheParametersValue) {
    auto effect = load(compile());
    ASSERT_TRUE(effect);
    runtime::EffectVariable surface = effect->variable("Surface");
    EXPECT_EQ(surface.memberCount(), 4u);
    EXPECT_EQ(surface.member(2).name(), "Surface.gain");
    EXPECT_EQ(surface.member("mix").type().hlslName(), "float2x2");
    ASSERT_TRUE(surface.member("gain").setFloat(0.5f));
    ASSERT_TRUE(surface.member("color").setVector(glm::vec3(1.0f, 2.0f, 3.0f)));
    // A struct's value is its members' numbers in declaration order: color, enabled, gain, mix.
    const std::vector<float> expected{1, 2, 3, 0, 0.5f, 0, 0, 0, 0};
    EXPECT_EQ(surface.value().data, expected);
    EXPECT_EQ(surface.member("gain").value().asFloat(), 0.5f);
    EXPECT_EQ(surface.member("color").value().data, (std::vector<float>{1, 2, 3}));

    // The whole struct takes all its numbers at once (D3DX's SetRawValue), and each of Lights'
    // elements holds a float4 and a Material.
    fx::Value raw;
    raw.data = {0, 0, 0, 1, 0.25f, 1, 0, 0, 1};
    ASSERT_TRUE(surface.setValue(raw));
    EXPECT_EQ(surface.member("gain").value().asFloat(), 0.25f);
    EXPECT_EQ(effect->variable("Lights").value().data.size(), 2u * (4u + 9u));
    EXPECT_EQ(effect->variable("Lights").element(1).member("material").memberCount(), 4u);
}

TEST(StructMembers, MissingMembersGiveInvalidHandlesThatDoNothing) {
    auto effect = load(compile());
    ASSERT_TRUE(effect);
    runtime::EffectVariable surface = effect->variable("Surface");
    runtime::EffectVariable lights = effect->variable("Lights");
    EXPECT_FALSE(surface.member("Color").isValid()) << "member names are case-sensitive, as in HLSL";
    EXPECT_FALSE(surface.member("missing").isValid());
    EXPECT_FALSE(surface.member(4).isValid());
    EXPECT_FALSE(surface.memberBySemantic("SPECULAR").isValid());
    EXPECT_FALSE(surface.memberBySemantic("").isValid());
    EXPECT_FALSE(lights.member("material").isValid()) << "an array's members are its elements'";
    EXPECT_EQ(lights.memberCount(), 0u);
    EXPECT_FALSE(lights.element(2).member(0).isValid());
    EXPECT_FALSE(surface.member("color").member(0).isValid()) << "a float3 has no members";
    EXPECT_FALSE(effect->variable("Gain").member("x").isValid());
    EXPECT_FALSE(effect->variable("Missing").member("color").member("x").isValid());

    runtime::EffectVariable missing = surface.member("missing");
    EXPECT_EQ(missing.name(), "");
    EXPECT_EQ(missing.memberCount(), 0u);
    EXPECT_FALSE(missing.setVector(glm::vec3(1.0f)));
    EXPECT_FALSE(missing.setFloat(1.0f));
    EXPECT_EQ(missing.value().asFloat(), 0.0f);

    // Setters of another type refuse, and a member has no texture or annotations.
    EXPECT_FALSE(surface.member("gain").setVector(glm::vec3(1.0f)));
    EXPECT_FALSE(surface.member("color").setVector(glm::vec4(1.0f)));
    EXPECT_FALSE(surface.member("mix").setMatrix(glm::mat4(1.0f)));
    EXPECT_FALSE(surface.setFloat(1.0f)) << "a struct takes its members' numbers, not a float";
    EXPECT_FALSE(surface.member("color").setTexture(1));
    EXPECT_EQ(surface.member("color").annotationCount(), 0u);
    fx::Value tooMany;
    tooMany.data.assign(10, 1.0f);
    EXPECT_FALSE(surface.setValue(tooMany));
    EXPECT_EQ(surface.value().data, std::vector<float>(9, 0.0f)) << "nothing was set";
}

}  // namespace
}  // namespace test_struct_members
