// A D3D9 pass's sampler-register states (`AddressU[0] = CLAMP;`, `MagFilter[0] = LINEAR;`,
// `Texture[1] = <t>;`, `Sampler[0] = (s);`) reach the sampler its pixel shader has bound to that register,
// through the whole pipeline (parse, compile, EffectRenderer on llvmpipe), and the pass API applies them
// the same way: one full-screen pass samples 16x16 white noise over uv in [-1, 2], three tiles across.
#include "effects/EffectHarness.h"

#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>
#include <runtime/BuiltinScenes.h>
#include <runtime/EffectPass.h>

#include <algorithm>

namespace shadowfx::test::test_pass_sampler_states {
namespace {

constexpr int kSize = 48;  // three tiles of the 16x16 texture, one texel per pixel

const char* kEffect = R"(
texture Noise < string Procedural = "noise"; int Seed = 5; float2 Dimensions = {16, 16}; >;
sampler WrapSampler = sampler_state { Texture = <Noise>; MinFilter = POINT; MagFilter = POINT;
                                      AddressU = WRAP; AddressV = WRAP; };
sampler ClampSampler = sampler_state { Texture = <Noise>; AddressU = CLAMP; AddressV = CLAMP; };
sampler Bare : register(s1);  // no states and no texture of its own: the pass gives them
sampler Unused;
struct Quad { float4 Position : POSITION; float2 UV : TEXCOORD0; };
Quad VS(float4 p : POSITION, float2 uv : TEXCOORD0) { Quad o; o.Position = p; o.UV = uv * 3 - 1; return o; }
float4 PS(float2 uv : TEXCOORD0) : COLOR { return tex2D(WrapSampler, uv); }
float4 PSBare(float2 uv : TEXCOORD0) : COLOR { return tex2D(Bare, uv); }
// WrapSampler is declared first: s0, whatever the order the code samples in; ClampSampler s1.
float4 PSTwo(float2 uv : TEXCOORD0) : COLOR {
    return float4(tex2D(ClampSampler, uv).g, tex2D(WrapSampler, uv).r, 0, 1);
}
#define QUAD_PASS < string Script = "RenderColorTarget0=; Draw=Buffer;"; >

technique Own { pass p QUAD_PASS {
    ZEnable = false; VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
technique PassClamps { pass p QUAD_PASS {
    ZEnable = false; VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS();
    addressu[0] = Clamp; ADDRESSV[0] = clamp; } }
// Before the pixel shader, a state the sampler's block sets is the sampler's when the shader is set.
technique BeforeShader { pass p QUAD_PASS {
    ZEnable = false; AddressU[0] = CLAMP; AddressV[0] = CLAMP;
    VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
technique SamplerState { pass p QUAD_PASS {
    ZEnable = false; VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS();
    Sampler[0] = (ClampSampler); MagFilter[0] = POINT; } }
technique TextureOnBare { pass p QUAD_PASS {
    ZEnable = false; VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PSBare();
    Texture[1] = <Noise>; AddressU[1] = CLAMP; AddressV[1] = CLAMP; } }
technique SecondRegister { pass p QUAD_PASS {
    ZEnable = false; VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PSTwo();
    AddressU[1] = WRAP; AddressV[1] = WRAP; } }
)";

const runtime::Scene& boxes() {
    static const runtime::Scene scene = *runtime::makeBuiltinScene("boxes");
    return scene;
}

runtime::FrameImage frame(runtime::EffectRenderer& renderer, const std::string& technique) {
    EXPECT_TRUE(render(renderer, boxes(), kSize, kSize, technique)) << technique;
    return renderer.readFrame();
}

bool samePixel(const runtime::FrameImage& image, int x0, int y0, int x1, int y1) {
    const uint8_t* a = image.pixel(x0, y0);
    const uint8_t* b = image.pixel(x1, y1);
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

// Wrapped: the left tile repeats the middle one texel for texel.
::testing::AssertionResult wraps(const runtime::FrameImage& image) {
    for (int y = 16; y < 32; ++y)
        for (int x = 0; x < 16; ++x)
            if (!samePixel(image, x, y, x + 16, y))
                return ::testing::AssertionFailure()
                       << "pixel (" << x << ", " << y << ") is not the one 16 right";
    return ::testing::AssertionSuccess();
}

// Clamped: every row of the left tile is its edge texel's colour, and the middle tile is not constant.
::testing::AssertionResult clamps(const runtime::FrameImage& image) {
    for (int y = 16; y < 32; ++y)
        for (int x = 0; x < 16; ++x)
            if (!samePixel(image, x, y, 16, y))
                return ::testing::AssertionFailure() << "pixel (" << x << ", " << y << ") is not the edge's";
    return ::testing::AssertionSuccess();
}

TEST(PassSamplerStates, AddressingOfARegisterReachesTheSamplerBoundToIt) {
    auto renderer = loadEffect(kEffect, false);
    ASSERT_TRUE(renderer);
    const runtime::FrameImage own = frame(*renderer, "Own");
    ASSERT_TRUE(notConstant(own));
    EXPECT_TRUE(wraps(own));
    EXPECT_FALSE(clamps(own));

    const runtime::FrameImage clamped = frame(*renderer, "PassClamps");
    ASSERT_TRUE(notConstant(clamped));
    EXPECT_TRUE(clamps(clamped));
    EXPECT_FALSE(wraps(clamped));
    // The middle tile is the texture as it is in both.
    EXPECT_TRUE(std::equal(own.pixel(16, 20), own.pixel(32, 20), clamped.pixel(16, 20)));

    EXPECT_TRUE(wraps(frame(*renderer, "BeforeShader"))) << "the sampler's own AddressU, set with the shader";
    const runtime::FrameImage sampler = frame(*renderer, "SamplerState");
    EXPECT_TRUE(clamps(sampler)) << "Sampler[0] = (ClampSampler) sets its addressing";
    EXPECT_TRUE(std::equal(own.pixel(16, 20), own.pixel(32, 20), sampler.pixel(16, 20)));

    const runtime::FrameImage bare = frame(*renderer, "TextureOnBare");
    ASSERT_TRUE(notConstant(bare)) << "Texture[1] binds the noise to the sampler at register(s1)";
    EXPECT_TRUE(clamps(bare));

    const runtime::FrameImage second = frame(*renderer, "SecondRegister");
    ASSERT_TRUE(notConstant(second));
    EXPECT_TRUE(wraps(second)) << "WrapSampler, declared first, is s0; ClampSampler s1, which the pass wraps";
}

TEST(PassSamplerStates, PassApiAppliesThemAsRenderDoes) {
    auto renderer = loadEffect(kEffect, false);
    ASSERT_TRUE(renderer);
    const runtime::FrameImage rendered = frame(*renderer, "PassClamps");
    ASSERT_TRUE(clamps(rendered));

    runtime::EffectTechnique technique = renderer->technique("PassClamps");
    ASSERT_TRUE(technique.isValid());
    runtime::EffectPass pass = technique.pass(0);
    ASSERT_TRUE(pass.isValid());
    ASSERT_TRUE(pass.apply());
    const fx::CompiledPass& compiled = renderer->effect().techniques[pass.techniqueIndex()].passes[0];
    const auto binding =
        std::find_if(compiled.fragment.samplers.begin(), compiled.fragment.samplers.end(),
                     [](const fx::SamplerBinding& b) { return b.glslName == "WrapSampler"; });
    ASSERT_NE(binding, compiled.fragment.samplers.end());
    ASSERT_GE(binding->passSampler, 0);
    GLint bound = 0, wrapS = 0;
    gl::ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(binding->unit));
    gl::GetIntegerv(GL_SAMPLER_BINDING, &bound);
    ASSERT_NE(bound, 0);
    gl::GetSamplerParameteriv(static_cast<GLuint>(bound), GL_TEXTURE_WRAP_S, &wrapS);
    EXPECT_EQ(wrapS, GL_CLAMP_TO_EDGE);
}

TEST(PassSamplerStates, UnknownSamplerOrTextureIsALocatedError) {
    fx::DiagnosticList diagnostics;
    auto effect = fx::parseEffectSource(
        "texture T;\nsampler S;\nfloat4 PS() : COLOR { return tex2D(S, float2(0, 0)); }\n"
        "technique t { pass p { PixelShader = compile ps_3_0 PS();\n"
        "  Texture[0] = <Missing>; Sampler[0] = (T); MinFilter[0] = Bilinear; } }\n",
        "sampler_states.fx", {}, diagnostics);
    const std::string text = diagnostics.str();
    ASSERT_EQ(diagnostics.items().size(), 3u) << text;
    const struct {
        fx::DiagId id;
        int column;
        const char* message;
    } expected[] = {
        {fx::DiagId::UnknownIdentifier, 16, "unknown identifier 'Missing'"},
        {fx::DiagId::SamplerStateNotSampler, 41,
         "invalid value for state 'Sampler': 'T' is a texture, not a sampler"},
        {fx::DiagId::UnknownStateValue, 60, "'Bilinear' is not a value of state 'MinFilter'"},
    };
    for (size_t i = 0; i < 3; ++i) {
        const fx::Diagnostic& d = diagnostics.items()[i];
        EXPECT_EQ(d.id, expected[i].id) << text;
        EXPECT_EQ(d.severity, fx::Severity::Error) << text;
        EXPECT_EQ(d.loc.line, 5) << text;
        EXPECT_EQ(d.loc.column, expected[i].column) << text;
        EXPECT_EQ(d.message.rfind(expected[i].message, 0), 0u) << text;
    }
}

}  // namespace
}  // namespace shadowfx::test::test_pass_sampler_states
