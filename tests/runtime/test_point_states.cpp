// D3D9's point states through the pass API, with the application drawing points itself: `PointSize` sizes
// points of a vertex shader that writes no PSIZE, a vertex shader's PSIZE sizes its own (and wins over the
// state), and `PointSpriteEnable = TRUE` gives the pixel shader's TEXCOORD0 the position in the sprite,
// (0, 0) at its top left to (1, 1) at its bottom right, as D3D9 did.
#include "effects/EffectHarness.h"

#include <runtime/EffectPass.h>
#include <runtime/GlApi.h>

#include <algorithm>
#include <vector>

namespace shadowfx::test::test_point_states {
namespace {

const char* kEffect = R"(
float Size = 16;
struct Sized { float4 Position : POSITION; float PointSize : PSIZE; };
Sized SizedVS(float3 p : POSITION) { Sized o; o.Position = float4(p, 1); o.PointSize = Size; return o; }
float4 PlainVS(float3 p : POSITION) : POSITION { return float4(p, 1); }
float4 WhitePS() : COLOR { return 1; }
float4 SpritePS(float2 uv : TEXCOORD0) : COLOR { return float4(uv, 1, 1); }
technique FixedSize { pass p {
    PointSize = 9; VertexShader = compile vs_3_0 PlainVS(); PixelShader = compile ps_3_0 WhitePS(); } }
technique ShaderSize { pass p {
    pointsize = 3; VertexShader = compile vs_3_0 SizedVS(); PixelShader = compile ps_3_0 WhitePS(); } }
technique Sprites { pass p {
    POINTSPRITEENABLE = true; PointScaleEnable = true; PointScale_A = 0; PointSize_Min = 1;
    VertexShader = compile vs_3_0 SizedVS(); PixelShader = compile ps_3_0 SpritePS(); } }
)";

constexpr int kSize = 32;

// One point at the middle of a 32x32 framebuffer of the test's, drawn with the technique's pass; the
// pixels as glReadPixels gives them (row 0 is the top under the runtime's clip control).
struct PointFrame {
    std::vector<uint8_t> rgba;
    const uint8_t* at(int x, int y) const { return &rgba[(size_t(y) * kSize + size_t(x)) * 4]; }
    int lit() const {
        int count = 0;
        for (size_t i = 0; i < rgba.size(); i += 4) count += rgba[i + 2] > 0;
        return count;
    }
};

PointFrame drawPoint(runtime::EffectRenderer& renderer, const std::string& technique) {
    GLuint color = 0, framebuffer = 0, vao = 0, buffer = 0;
    gl::GenTextures(1, &color);
    gl::BindTexture(GL_TEXTURE_2D, color);
    gl::TexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, kSize, kSize);
    gl::GenFramebuffers(1, &framebuffer);
    gl::BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    gl::FramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, color, 0);
    gl::Viewport(0, 0, kSize, kSize);
    gl::ClearColor(0, 0, 0, 0);
    gl::Clear(GL_COLOR_BUFFER_BIT);

    runtime::EffectPass pass = renderer.technique(technique).pass(0);
    fx::DiagnosticList diagnostics;
    EXPECT_TRUE(pass.apply(&diagnostics)) << technique << ": " << diagnostics.str();
    const float point[3] = {0, 0, 0.5f};
    gl::GenVertexArrays(1, &vao);
    gl::BindVertexArray(vao);
    gl::GenBuffers(1, &buffer);
    gl::BindBuffer(GL_ARRAY_BUFFER, buffer);
    gl::BufferData(GL_ARRAY_BUFFER, sizeof(point), point, GL_STATIC_DRAW);
    for (const runtime::PassInput& input : pass.inputSignature()) {
        if (input.semantic.rfind("POSITION", 0) != 0) continue;
        gl::EnableVertexAttribArray(static_cast<GLuint>(input.location));
        gl::VertexAttribPointer(static_cast<GLuint>(input.location), 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    }
    gl::DrawArrays(GL_POINTS, 0, 1);

    PointFrame frame;
    frame.rgba.resize(size_t(kSize) * kSize * 4);
    gl::BindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    gl::ReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, frame.rgba.data());
    gl::BindVertexArray(0);
    gl::DeleteVertexArrays(1, &vao);
    gl::DeleteBuffers(1, &buffer);
    gl::BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::DeleteFramebuffers(1, &framebuffer);
    gl::DeleteTextures(1, &color);
    return frame;
}

TEST(PointStates, PointSizeStateSizesPointsOfAShaderWithoutPsize) {
    auto renderer = loadEffect(kEffect, false);
    ASSERT_TRUE(renderer);
    EXPECT_EQ(drawPoint(*renderer, "FixedSize").lit(), 9 * 9);
}

TEST(PointStates, PsizeOfTheVertexShaderWinsOverTheState) {
    auto renderer = loadEffect(kEffect, false);
    ASSERT_TRUE(renderer);
    EXPECT_EQ(drawPoint(*renderer, "ShaderSize").lit(), 16 * 16);
    ASSERT_TRUE(renderer->variable("Size").setFloat(6));
    EXPECT_EQ(drawPoint(*renderer, "ShaderSize").lit(), 6 * 6);
    EXPECT_EQ(drawPoint(*renderer, "FixedSize").lit(), 9 * 9) << "a program without PSIZE takes the state";
}

TEST(PointStates, SpriteTexcoordsRunFromTopLeftToBottomRight) {
    auto renderer = loadEffect(kEffect, false);
    ASSERT_TRUE(renderer);
    const PointFrame sprite = drawPoint(*renderer, "Sprites");
    ASSERT_EQ(sprite.lit(), 16 * 16);
    // The sprite covers pixels 8..23 both ways; texel centres of a 16-pixel sprite: u = (x - 8 + 0.5) / 16.
    for (int y = 8; y < 24; ++y)
        for (int x = 8; x < 24; ++x) {
            const uint8_t* p = sprite.at(x, y);
            EXPECT_NEAR(p[0], (x - 8 + 0.5) / 16 * 255, 2) << "u at (" << x << ", " << y << ")";
            EXPECT_NEAR(p[1], (y - 8 + 0.5) / 16 * 255, 2) << "v at (" << x << ", " << y << ")";
        }
}

// What the pixel shader reads cannot follow a tweakable: a PointSpriteEnable that is not a constant is a
// located error at the state.
TEST(PointStates, SpritesFromAParameterAreALocatedError) {
    sharedContext();
    fx::DiagnosticList diagnostics;
    auto effect = fx::parseEffectSource(
        "bool Sprites = true;\n"
        "float4 PS(float2 uv : TEXCOORD0) : COLOR { return float4(uv, 0, 1); }\n"
        "technique t { pass p { PointSpriteEnable = Sprites; PixelShader = compile ps_3_0 PS(); } }\n",
        "sprites.fx", {}, diagnostics);
    ASSERT_TRUE(effect) << diagnostics.str();
    EXPECT_FALSE(fx::compileEffect(effect, fx::CompileOptions{}, diagnostics));
    ASSERT_EQ(diagnostics.items().size(), 1u) << diagnostics.str();
    const fx::Diagnostic& d = diagnostics.items()[0];
    EXPECT_EQ(d.id, fx::DiagId::PointSpriteEnableNotConstant);
    EXPECT_EQ(d.loc.line, 3);
    EXPECT_EQ(d.loc.column, 24);
    EXPECT_EQ(d.message,
              "invalid value for state 'PointSpriteEnable': must be a constant (it decides what the "
              "pixel shader reads)");
}

}  // namespace
}  // namespace shadowfx::test::test_point_states
