// A swizzle of several matrix elements (`M._11_22`, `M._m00_m11`) reads the elements fxc read, in HLSL's
// row-major naming (`_rc`: row r, column c, from 1; `_mrc` from 0); writes to one store into them. Each
// technique draws the whole frame, its left half from one expression and its right half from another, all
// of whose channels lie strictly between 0 and 1: glslang's constant in a swizzle's place (an element index,
// 0 to 3) cannot give them, nor can a blank frame.
#include "effects/EffectHarness.h"

#include <runtime/BuiltinScenes.h>

#include <array>
#include <cmath>

namespace shadowfx::test::test_matrix_swizzles {
namespace {

const char* kEffect = R"(
float4x4 M = { 0.10, 0.20, 0.30, 0.40,
               0.50, 0.60, 0.70, 0.80,
               0.90, 0.15, 0.25, 0.35,
               0.45, 0.55, 0.65, 0.75 };
int Seven = 7;
struct Frame { float4x4 m; };
struct QuadOut { float4 Position : POSITION; float2 UV : TEXCOORD0; };
QuadOut QuadVS(float4 Position : POSITION, float2 UV : TEXCOORD0) {
    QuadOut OUT;
    OUT.Position = Position;
    OUT.UV = UV;
    return OUT;
}
float4 PairsPS(QuadOut IN) : COLOR {
    return IN.UV.x < 0.5 ? float4(M._11_22, M._m01_m10) : float4(M._m23_m32, M._41_14);
}
float4 TriplesAndQuadsPS(QuadOut IN) : COLOR {
    if (IN.UV.x < 0.5) return float4(M._12_23_34, M._44);
    return M._14_23_32_41;
}
float4 ChainsPS(QuadOut IN) : COLOR {
    Frame f;
    f.m = transpose(M);
    float4x4 both[2];
    both[0] = M;
    both[1] = f.m;
    float4 left = float4(M._31_42.yx, M._11_22.y, f.m._21_12.x);
    float4 right = float4(both[Seven - 6]._12_21, ((float3x3)M)._33_11);
    return IN.UV.x < 0.5 ? left : right;
}
float4x4 halved() { return M * 0.5; }
float4 CallsPS(QuadOut IN) : COLOR {
    return IN.UV.x < 0.5 ? float4(halved()._12_21, halved()._m00_m11.yx) : halved()._31_42_13_24;
}
float4 WritesPS(QuadOut IN) : COLOR {
    float4x4 w = M;
    w._12_21 = float2(0.3, 0.9);
    float4x4 v = M;
    v._13_31_44 = float3(0.05, 0.95, 0.85);
    return IN.UV.x < 0.5 ? float4(w._m01, w._m10, w._11, w._22) : float4(v._m02, v._m20, v._m33, v._m12);
}
void toQuarter(out float x) { x = 0.25; }
float4 ElementWritesPS(QuadOut IN) : COLOR {
    float4x4 w = M;
    w._12_21.y = 0.95;
    w._33_44[0] = 0.05;
    toQuarter(w._13_31.x);
    w._22_11.x *= 0.5;
    w._34_43.x++;
    return IN.UV.x < 0.5 ? float4(w._21, w._33, w._13, w._22) : float4(w._12, w._11, w._31, w._34 - 1.0);
}
// Each technique draws the whole frame with one pixel shader.
#define FULL_FRAME(name, pixelShader) \
    technique name < string Script = "Pass=p;"; > { \
        pass p < string Script = "Draw=Buffer;"; > { \
            ZEnable = false; \
            CullMode = None; \
            VertexShader = compile vs_3_0 QuadVS(); \
            PixelShader = compile ps_3_0 pixelShader(); \
        } \
    }
FULL_FRAME(Pairs, PairsPS)
FULL_FRAME(TriplesAndQuads, TriplesAndQuadsPS)
FULL_FRAME(Chains, ChainsPS)
FULL_FRAME(Calls, CallsPS)
FULL_FRAME(Writes, WritesPS)
FULL_FRAME(ElementWrites, ElementWritesPS)
)";

using Rgba = std::array<float, 4>;

// Every channel of the pixel at (x, y) is `expected` within two steps of 8 bits.
::testing::AssertionResult pixelIs(const runtime::FrameImage& image, int x, int y, const Rgba& expected) {
    const uint8_t* p = image.pixel(x, y);
    for (int c = 0; c < 4; ++c)
        if (std::abs(p[c] - expected[c] * 255.0f) > 2.0f)
            return ::testing::AssertionFailure()
                   << "pixel (" << x << ", " << y << ") is (" << int(p[0]) << ", " << int(p[1]) << ", "
                   << int(p[2]) << ", " << int(p[3]) << "), expected 255 * (" << expected[0] << ", "
                   << expected[1] << ", " << expected[2] << ", " << expected[3] << ")";
    return ::testing::AssertionSuccess();
}

struct Halves {
    const char* technique;
    Rgba left, right;
};

TEST(MatrixSwizzles, ReadAndWriteTheElementsFxcDid) {
    auto renderer = loadEffect(kEffect, false);
    ASSERT_TRUE(renderer);
    const runtime::Scene scene = *runtime::makeBuiltinScene("boxes");
    const Halves expected[] = {
        {"Pairs", {0.10f, 0.60f, 0.20f, 0.50f}, {0.35f, 0.65f, 0.45f, 0.40f}},
        {"TriplesAndQuads", {0.20f, 0.70f, 0.35f, 0.75f}, {0.40f, 0.70f, 0.15f, 0.45f}},
        {"Chains", {0.55f, 0.90f, 0.60f, 0.20f}, {0.50f, 0.20f, 0.25f, 0.10f}},
        {"Calls", {0.10f, 0.25f, 0.30f, 0.05f}, {0.45f, 0.275f, 0.15f, 0.40f}},
        {"Writes", {0.30f, 0.90f, 0.10f, 0.60f}, {0.05f, 0.95f, 0.85f, 0.70f}},
        // One element of a swizzle written: `_21`, `_33`, `_13` (an `out` argument), `_22` (`*=`), `_34`
        // (`++`); the rest as M holds them.
        {"ElementWrites", {0.95f, 0.05f, 0.25f, 0.30f}, {0.20f, 0.10f, 0.90f, 0.35f}},
    };
    for (const Halves& halves : expected) {
        SCOPED_TRACE(halves.technique);
        ASSERT_TRUE(render(*renderer, scene, 64, 32, halves.technique));
        const runtime::FrameImage image = renderer->readFrame();
        ASSERT_TRUE(notConstant(image));
        EXPECT_TRUE(pixelIs(image, 16, 16, halves.left));
        EXPECT_TRUE(pixelIs(image, 48, 16, halves.right));
    }
}

}  // namespace
}  // namespace shadowfx::test::test_matrix_swizzles
