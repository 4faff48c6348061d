// PassLowering: wrapper shapes, semantic rewriting, uniform arguments, depth-sampler rewrite.
#include "../../fx/src/PassLowering.h"  // private header: the lowering is tested directly

#include <fx/EffectParser.h>

#include <gtest/gtest.h>

namespace fx::test_pass_lowering {
namespace {

const char* kSource = R"(float4x4 WVP;
texture DepthTex : RENDERDEPTHSTENCILTARGET;
sampler DepthS = sampler_state { texture = <DepthTex>; };
texture ColorTex;
sampler ColorS = sampler_state { texture = <ColorTex>; };
struct VIn { float3 Pos : POSITION; float2 UV : TEXCOORD0; };
struct VOut { float4 Pos : POSITION; float2 UV : TEXCOORD0; float4 LP : TEXCOORD3; };
VOut VS(VIn IN, uniform float4x4 M, uniform float scale) {
    VOut o; o.Pos = mul(float4(IN.Pos, 1), M) * scale; o.UV = IN.UV; o.LP = o.Pos; return o; }
float4 PS(float4 LP : TEXCOORD3, float2 pix : VPOS, float face : VFACE, uniform bool pcf) : COLOR {
    return tex2Dproj(DepthS, LP) * tex2D(ColorS, LP.xy) + (pcf ? 1 : 0) + pix.x + face; }
float Unused() { return 1; }
technique t { pass p {
    VertexShader = compile vs_3_0 VS(mul(WVP, WVP), 2.0);
    PixelShader = compile ps_3_0 PS(true);
} }
)";

struct Lowered : ::testing::Test {
    std::shared_ptr<Effect> effect;
    void SetUp() override {
        DiagnosticList diags;
        effect = parseEffectSource(kSource, "lower.fx", ParseOptions{}, diags);
        ASSERT_TRUE(effect) << diags.str();
    }
    const Expr& compileOf(int state) {
        return effect->techniques[0].passes[0].states[static_cast<size_t>(state)].value;
    }
};

TEST_F(Lowered, VertexWrapper) {
    std::vector<LoweredArgument> args;
    DiagnosticList diags;
    auto vs = lowerStage(*effect, compileOf(0), ShaderStage::Vertex, args, diags);
    ASSERT_TRUE(vs) << diags.str();
    const std::string& h = vs->hlsl;
    EXPECT_NE(h.find("[[vk::location(0)]] float3 fx_in0"), std::string::npos) << h;
    EXPECT_NE(h.find("[[vk::location(2)]] float2 fx_in2"), std::string::npos) << h;
    EXPECT_NE(h.find("float4 fx_position : SV_Position;"), std::string::npos) << h;
    EXPECT_NE(h.find("[[vk::location(3)]] float4 fx_v3"), std::string::npos) << h;
    EXPECT_NE(h.find("fx_r = VS(fx_p0, fx_arg0, 2.0);"), std::string::npos) << h;  // literal inlined
    EXPECT_NE(h.find("float4x4 fx_arg0;"), std::string::npos);
    EXPECT_NE(h.find("float4x4 WVP;"), std::string::npos);
    EXPECT_NE(h.find("#line 8 \"lower.fx\""), std::string::npos);
    EXPECT_EQ(h.find("Unused"), std::string::npos);    // not reached
    EXPECT_EQ(h.find("DepthTex"), std::string::npos);  // textures are not emitted
    ASSERT_EQ(args.size(), 1u);
    EXPECT_EQ(args[0].memberName, "fx_arg0");
    EXPECT_EQ(args[0].expr.str(), "mul(WVP, WVP)");
}

TEST_F(Lowered, PixelWrapperAndDepthSampler) {
    std::vector<LoweredArgument> args;
    DiagnosticList diags;
    auto ps = lowerStage(*effect, compileOf(1), ShaderStage::Fragment, args, diags);
    ASSERT_TRUE(ps) << diags.str();
    const std::string& h = ps->hlsl;
    EXPECT_TRUE(args.empty());
    EXPECT_NE(h.find("fx_r = PS(fx_p0, fx_p1, fx_p2, true);"), std::string::npos) << h;
    EXPECT_NE(h.find("fx_p1 = floor(fx_fragCoord.xy);"), std::string::npos) << h;
    EXPECT_NE(h.find("(fx_frontFace ? 1.0 : -1.0)"), std::string::npos);
    EXPECT_NE(h.find("bool fx_frontFace : SV_IsFrontFace"), std::string::npos);
    EXPECT_NE(h.find("SV_Target0"), std::string::npos);
    EXPECT_NE(h.find("Texture2D fx_depth_DepthS;"), std::string::npos);
    EXPECT_NE(h.find("fx_tex2Dproj_DepthS( LP)"), std::string::npos) << h;
    EXPECT_EQ(h.find("fx_tex2D_ColorS"), std::string::npos);  // only depth samplers are rewritten
    EXPECT_NE(h.find("sampler2D ColorS;"), std::string::npos);
    EXPECT_EQ(ps->depthSamplers, std::vector<std::string>{"DepthS"});
}

TEST_F(Lowered, ArgumentCountAndProfileErrors) {
    Expr c = compileOf(1);
    c.args.push_back(c.args[0]);
    std::vector<LoweredArgument> args;
    DiagnosticList diags;
    EXPECT_FALSE(lowerStage(*effect, c, ShaderStage::Fragment, args, diags));
    EXPECT_EQ(diags.items().at(0).id, DiagId::CompileTooManyArguments);
    diags.clear();
    c = compileOf(1);
    c.args.clear();
    EXPECT_FALSE(lowerStage(*effect, c, ShaderStage::Fragment, args, diags));
    EXPECT_EQ(diags.items().at(0).id, DiagId::CompileArgumentMissing);
    diags.clear();
    EXPECT_FALSE(
        lowerStage(*effect, compileOf(0), ShaderStage::Fragment, args, diags));  // vs_3_0 as a pixel shader
    // A profile of the other stage is named as such ("'vs_3_0' is a vertex-shader profile, used for the pixel
    // shader"); UnsupportedProfile is for profiles no stage has.
    EXPECT_EQ(diags.items().at(0).id, DiagId::ProfileOfOtherStage);
}

TEST(SemanticTables, LocationsAreFixed) {
    EXPECT_EQ(vertexInputLocation("POSITION"), 0);
    EXPECT_EQ(vertexInputLocation("normal"), 1);
    EXPECT_EQ(vertexInputLocation("TEXCOORD"), 2);
    EXPECT_EQ(vertexInputLocation("TEXCOORD7"), 9);
    EXPECT_EQ(vertexInputLocation("COLOR1"), 11);
    EXPECT_EQ(vertexInputLocation("BLENDINDICES"), 15);
    EXPECT_EQ(vertexInputSemantic(4), "TEXCOORD2");
    EXPECT_EQ(varyingLocation("TEXCOORD5"), 5);
    EXPECT_EQ(varyingLocation("COLOR"), 8);
    EXPECT_EQ(varyingLocation("FOG"), 13);
    EXPECT_FALSE(varyingLocation("POSITION"));
    EXPECT_FALSE(varyingLocation("PSIZE"));
}

// A semantic index too long for an int (a fuzzer's input: it threw out of the compiler) reads as an index no
// table or limit takes, and a stage that writes it lowers without throwing.
TEST(SemanticTables, AnIndexTooLongForAnIntIsNoRegister) {
    EXPECT_EQ(splitSemantic("TEXCOORD12"), (std::pair<std::string, int>("TEXCOORD", 12)));
    EXPECT_EQ(splitSemantic("TEXCOORD99999999999"), (std::pair<std::string, int>("TEXCOORD", 1 << 30)));
    EXPECT_FALSE(varyingLocation("TEXCOORD99999999999"));
    DiagnosticList diags;
    const std::shared_ptr<Effect> effect = parseEffectSource(R"(
struct VOut { float4 Pos : POSITION; float4 T : TEXCOORD99999999999; float C : SV_ClipDistance99999999999; };
VOut VS(float3 p : POSITION) { VOut o; o.Pos = float4(p, 1); o.T = o.Pos; o.C = 1; return o; }
technique t { pass p { VertexShader = compile vs_3_0 VS(); } }
)",
                                                             "long_index.fx", ParseOptions{}, diags);
    ASSERT_TRUE(effect) << diags.str();
    std::vector<LoweredArgument> args;
    EXPECT_NO_THROW(lowerStage(*effect, effect->techniques[0].passes[0].states[0].value, ShaderStage::Vertex,
                               args, diags));
}

// D3D10 input layouts' names, as the SDK samples and applications spelled them.
TEST(SemanticTables, FreeVertexInputNamesMatchTheMeshStreamsByPrefix) {
    EXPECT_EQ(vertexStreamByName("POS"), 0);
    EXPECT_EQ(vertexStreamByName("PosL"), 0);
    EXPECT_EQ(vertexStreamByName("NORM"), 1);
    EXPECT_EQ(vertexStreamByName("TEXTURE0"), 2);
    EXPECT_EQ(vertexStreamByName("uv1"), 3);
    EXPECT_EQ(vertexStreamByName("TEX7"), 9);
    EXPECT_EQ(vertexStreamByName("COLOUR1"), 11);
    EXPECT_EQ(vertexStreamByName("TANGENT"), 12);
    EXPECT_EQ(vertexStreamByName("BITANGENT"), 13);
    EXPECT_EQ(vertexStreamByName("BINORM"), 13);
    EXPECT_EQ(vertexStreamByName("BLENDWEIGHTS"), 14);
    EXPECT_EQ(vertexStreamByName("BLENDIND"), 15);
    EXPECT_EQ(vertexStreamByName("WEIGHTS"), 14);  // the SDK's Skinning10
    EXPECT_EQ(vertexStreamByName("BONES"), 15);
    EXPECT_EQ(vertexStreamByName("JOINTS"), 15);
    EXPECT_FALSE(vertexStreamByName("TEXTURE8"));  // the mesh has no ninth UV stream
    EXPECT_FALSE(vertexStreamByName("POS1"));
    EXPECT_FALSE(vertexStreamByName("INST0"));
    EXPECT_FALSE(vertexStreamByName("PATCHUV"));
    EXPECT_FALSE(vertexStreamByName("TEX99999999999"));
    const std::optional<VertexStreamSlot> slot = vertexStreamAt(3);
    ASSERT_TRUE(slot);
    EXPECT_EQ(slot->stream, VertexStream::Texcoord);
    EXPECT_EQ(slot->index, 1);
    EXPECT_FALSE(vertexStreamAt(16));
}

}  // namespace
}  // namespace fx::test_pass_lowering
