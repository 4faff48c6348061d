// The instanced variant of a compiled pass (fx/InstancedPass.h): per-object members move from the
// uniform blocks into the object record, read by the instance's object index in both stages; the variant
// is valid GLSL 4.50; a pass it cannot express is refused, never rewritten half-way.
#include "Glsl450.h"

#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>
#include <fx/InstancedPass.h>

#include <gtest/gtest.h>

namespace fx::test_instanced_pass {
namespace {

using test::compilesAsGlsl450;

const char* kEffect = R"(
float4x4 WorldViewProjection : WorldViewProjection;
float4x4 World : World;
row_major float4x3 Skew : World;
float3 SurfaceColor : Diffuse = {0.8, 0.8, 0.8};
float4x4 LightView : View < string frustum = "light0"; >;
float3 LightDirection = {0, -1, 0};
struct VsOut { float4 Position : POSITION; float3 Normal : TEXCOORD0; float4 Light : TEXCOORD1; };
VsOut VS(float4 Position : POSITION, float3 Normal : NORMAL, uniform float4x4 WorldLight)
{
    VsOut OUT;
    OUT.Position = mul(Position, WorldViewProjection);
    OUT.Normal = mul(Normal, (float3x3)World) + mul(float4(Normal, 0), Skew);
    OUT.Light = mul(Position, WorldLight);
    return OUT;
}
float4 PS(VsOut IN) : COLOR
{
    return float4(SurfaceColor * saturate(dot(normalize(IN.Normal), -LightDirection)), 1) + IN.Light * 0.001;
}
technique main { pass P {
    VertexShader = compile vs_3_0 VS(mul(World, LightView));
    PixelShader = compile ps_3_0 PS();
} }
)";

const char* kUsesInstanceId = R"(
float4x4 WorldViewProjection : WorldViewProjection;
float4 VS(float4 Position : POSITION, uint Instance : SV_InstanceID) : POSITION
{ return mul(Position, WorldViewProjection) + Instance * 0.0; }
float4 PS() : COLOR { return 1; }
technique main { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)";

std::shared_ptr<CompiledEffect> compile(const char* source) {
    DiagnosticList diagnostics;
    auto effect = parseEffectSource(source, "instanced.fx", ParseOptions{}, diagnostics);
    EXPECT_TRUE(effect) << diagnostics.str();
    if (!effect) return nullptr;
    auto compiled = compileEffect(effect, CompileOptions{}, diagnostics);
    EXPECT_TRUE(compiled) << diagnostics.str();
    return compiled;
}

// Per-object flags for the parameters named (the runtime decides these from its semantics).
std::vector<bool> flags(const CompiledEffect& effect, std::initializer_list<const char*> names) {
    std::vector<bool> out(effect.parameters.size(), false);
    for (size_t i = 0; i < effect.parameters.size(); ++i)
        for (const char* name : names) out[i] = out[i] || effect.parameters[i].name == name;
    return out;
}

const UniformBinding* findMember(const std::vector<UniformBinding>& members, const std::string& name) {
    for (const UniformBinding& u : members)
        if (u.name == name) return &u;
    return nullptr;
}

TEST(InstancedPass, PerObjectMembersMoveToTheObjectRecord) {
    auto effect = compile(kEffect);
    ASSERT_TRUE(effect);
    const CompiledPass& pass = effect->techniques[0].passes[0];
    ASSERT_EQ(pass.arguments.size(), 1u);
    std::string whyNot;
    std::optional<InstancedPass> variant = instancedPass(
        pass, flags(*effect, {"WorldViewProjection", "World", "Skew", "SurfaceColor"}), {true}, whyNot);
    ASSERT_TRUE(variant) << whyNot;

    const StageProgram& vertex = variant->pass.vertex;
    const StageProgram& pixel = variant->pass.fragment;
    EXPECT_TRUE(compilesAsGlsl450(vertex));
    EXPECT_TRUE(compilesAsGlsl450(pixel));
    EXPECT_NE(vertex.glsl.find("fx_objects[fx_object].WorldViewProjection"), std::string::npos);
    EXPECT_NE(vertex.glsl.find("fx_objects[fx_object].fx_arg0"), std::string::npos);
    EXPECT_EQ(vertex.glsl.find(vertex.uniformBlockName + "_.World"), std::string::npos);
    EXPECT_NE(vertex.glsl.find("fx_instances[gl_InstanceID]"), std::string::npos);
    EXPECT_NE(pixel.glsl.find("flat in uint fx_object"), std::string::npos);
    EXPECT_NE(pixel.glsl.find("fx_objects[fx_object].SurfaceColor"), std::string::npos);
    // Per-frame values stay in the block.
    EXPECT_NE(pixel.glsl.find(pixel.uniformBlockName + "_.LightDirection"), std::string::npos);

    // Inactive in the blocks, active in the record, each member once, inside the record, not overlapping.
    const UniformBinding* blockWvp = findMember(vertex.uniforms, "WorldViewProjection");
    ASSERT_TRUE(blockWvp);
    EXPECT_FALSE(blockWvp->active);
    EXPECT_TRUE(findMember(pass.vertex.uniforms, "WorldViewProjection")->active);
    ASSERT_EQ(variant->record.size(), 5u);  // WorldViewProjection, World, Skew, fx_arg0, SurfaceColor
    EXPECT_EQ(variant->recordSize % 16, 0u);
    uint32_t end = 0;
    for (const UniformBinding& field : variant->record) {
        SCOPED_TRACE(field.name);
        EXPECT_TRUE(field.active);
        EXPECT_GE(field.offset, end);
        EXPECT_EQ(field.offset % (field.type.shape == Shape::Matrix || field.type.cols >= 3 ? 16 : 4), 0u);
        end = field.offset + field.size;
        if (field.type.shape == Shape::Matrix) {
            EXPECT_EQ(field.matrixStride, 16u);
        }
    }
    EXPECT_LE(end, variant->recordSize);
    const UniformBinding* skew = findMember(variant->record, "Skew");
    ASSERT_TRUE(skew);
    EXPECT_EQ(skew->size, 64u) << "a row_major float4x3 is four HLSL rows of one vec4 slot each";
}

TEST(InstancedPass, PixelStageWithoutPerObjectReadsGetsNoVarying) {
    auto effect = compile(kEffect);
    ASSERT_TRUE(effect);
    std::string whyNot;
    auto variant = instancedPass(effect->techniques[0].passes[0], flags(*effect, {"WorldViewProjection"}),
                                 {false}, whyNot);
    ASSERT_TRUE(variant) << whyNot;
    EXPECT_EQ(variant->record.size(), 1u);
    EXPECT_EQ(variant->pass.fragment.glsl, effect->techniques[0].passes[0].fragment.glsl);
    EXPECT_EQ(variant->pass.vertex.glsl.find("fx_objectOut"), std::string::npos);
    EXPECT_TRUE(compilesAsGlsl450(variant->pass.vertex));
}

TEST(InstancedPass, RefusesCodeThatReadsItsInstanceId) {
    auto effect = compile(kUsesInstanceId);
    ASSERT_TRUE(effect);
    std::string whyNot;
    EXPECT_FALSE(
        instancedPass(effect->techniques[0].passes[0], flags(*effect, {"WorldViewProjection"}), {}, whyNot));
    EXPECT_NE(whyNot.find("gl_InstanceID"), std::string::npos) << whyNot;
}

const char* kGeometryStage = R"(
float4x4 WorldViewProjection : WorldViewProjection;
struct V { float4 p : SV_Position; };
V VS(float4 Position : POSITION) { V v; v.p = mul(Position, WorldViewProjection); return v; }
[maxvertexcount(3)]
void GS(triangle V tri[3], inout TriangleStream<V> s) { s.Append(tri[0]); s.Append(tri[1]); s.Append(tri[2]); }
float4 PS() : SV_Target { return 1; }
technique11 main { pass P { SetVertexShader(CompileShader(vs_4_0, VS())); SetGeometryShader(CompileShader(gs_4_0, GS()));
                            SetPixelShader(CompileShader(ps_4_0, PS())); } }
)";

// A geometry stage between them would have to pass the object index on and read per-object values too.
TEST(InstancedPass, RefusesAPassWithAGeometryShader) {
    auto effect = compile(kGeometryStage);
    ASSERT_TRUE(effect);
    std::string whyNot;
    EXPECT_FALSE(
        instancedPass(effect->techniques[0].passes[0], flags(*effect, {"WorldViewProjection"}), {}, whyNot));
    EXPECT_NE(whyNot.find("geometry shader"), std::string::npos) << whyNot;
}

}  // namespace
}  // namespace fx::test_instanced_pass
