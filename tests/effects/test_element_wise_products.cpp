// HLSL's `*` of two matrices multiplies them element by element (`m * n`, `m *= n`), of float and integer
// matrices alike, while mul() is their product; glslang's HLSL front end read `*` as a product until
// shadowfx rewrote it (docs/legalization.md, "Element-wise products"). A pixel shader checks each result
// against the values HLSL defines and draws yellow where every check holds: red for the element-wise
// products, green for mul(). A blank frame, or either check failing, has no yellow pixel. Products of
// constants, which glslang computes while it parses, are checked the same way.
#include "EffectHarness.h"

#include <runtime/BuiltinScenes.h>

#include <gtest/gtest.h>

#include <string>

namespace shadowfx::test::test_element_wise_products {
namespace {

const char* kProducts = R"(
float4x4 Wvp : WorldViewProjection;
float3x3 A = {1, 2, 3, 4, 5, 6, 7, 8, 9};
float3x3 B = {2, 3, 5, 7, 11, 13, 17, 19, 23};
int2x2 I = {1, -2, 3, 4};
int2x2 J = {5, 6, -7, 8};
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, Wvp); }
float4 PS() : SV_Target {
    float3x3 e = A * B;
    float3x3 f = A;
    f *= B;
    // A postfix step before the `*` on its line: glslang parses it as a prefix one, which moves the line.
    float3x3 g = A;
    for (int i = 0; i < 1; i++) g = g * B;
    int2x2 k = I * J;
    int2x2 l = I;
    l *= J;
    bool elementWise = e[0][1] == 6 && e[1][2] == 78 && e[2][0] == 119 && f[2][2] == 207 && f[0][0] == 2 &&
                       g[1][2] == 78 && k[0][1] == -12 && k[1][0] == -21 && l[1][1] == 32;
    // mul(A, B)[0][1] = 1*3 + 2*11 + 3*19; [2][0] = 7*2 + 8*7 + 9*17.
    float3x3 p = mul(A, B);
    bool product = p[0][1] == 82 && p[2][0] == 223;
    return float4(elementWise ? 1 : 0, product ? 1 : 0, 0, 1);
}
technique10 t { pass p { SetVertexShader(CompileShader(vs_4_0, VS())); SetPixelShader(CompileShader(ps_4_0, PS())); } }
)";

// `*` of constant matrices: literal constructors, `static const` matrices, a `const` local and a literal, a
// chain of three, integer matrices; a `static const` initialized with such a product stays a constant
// (an array's size); mul() of the same constants is still their product.
const char* kConstantProducts = R"(
float4x4 Wvp : WorldViewProjection;
static const float2x2 S = {1, 2, 3, 4};
static const float2x2 T = float2x2(5, 6, 7, 8);
static const float2x2 ST = S * T;
static const int N = (int)ST._m11;
static const int2x2 I = {1, -2, 3, 4};
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, Wvp); }
float4 PS() : SV_Target {
    float2x2 literals = float2x2(1, 2, 3, 4) * float2x2(5, 6, 7, 8);
    float2x2 statics = S * T;
    const float2x2 c = float2x2(2, 3, 5, 7);
    float2x2 local = c *
                     float2x2(1, 2, 3, 4);
    float2x2 chain = S * T * S;
    int2x2 k = I * int2x2(5, 6, -7, 8);
    float sized[N];
    bool elementWise = literals[0][1] == 12 && literals[1][0] == 21 && statics[1][1] == 32 &&
                       statics[0][0] == 5 && local[0][1] == 6 && local[1][1] == 28 && chain[1][1] == 128 &&
                       chain[1][0] == 63 && k[0][1] == -12 && k[1][0] == -21 && ST[1][0] == 21 && N == 32;
    float2x2 p = mul(S, T);
    float2x2 q = mul(float2x2(1, 2, 3, 4), float2x2(5, 6, 7, 8));
    bool product = p[0][0] == 19 && p[0][1] == 22 && p[1][0] == 43 && q[1][1] == 50;
    return float4(elementWise ? 1 : 0, product ? 1 : 0, 0, 1);
}
technique10 t { pass p { SetVertexShader(CompileShader(vs_4_0, VS())); SetPixelShader(CompileShader(ps_4_0, PS())); } }
)";

void expectAllYellow(const char* source, const char* path) {
    auto renderer = loadEffect(source, false, path);
    ASSERT_TRUE(renderer);
    auto scene = runtime::makeBuiltinScene("teapot", nullptr);
    ASSERT_TRUE(scene);
    constexpr int kWidth = 96, kHeight = 72;
    ASSERT_TRUE(render(*renderer, *scene, kWidth, kHeight));
    const runtime::FrameImage frame = renderer->readFrame();
    const int yellow = countPixelsOfColour(frame, kWidth, kHeight, 255, 255, 0);
    EXPECT_GT(yellow, kWidth * kHeight / 50);
    // Nothing the object covers fails a check (red or green alone, or black).
    EXPECT_EQ(countPixelsOfColour(frame, kWidth, kHeight, 0, 255, 0), 0);
    EXPECT_EQ(countPixelsOfColour(frame, kWidth, kHeight, 255, 0, 0), 0);
    EXPECT_EQ(countPixelsOfColour(frame, kWidth, kHeight, 0, 0, 0), 0);
}

TEST(ElementWiseProducts, StarMultipliesMatricesElementByElementAndMulIsTheirProduct) {
    expectAllYellow(kProducts, "products.fx");
}

TEST(ElementWiseProducts, StarOfConstantMatricesMultipliesElementByElementAndMulIsTheirProduct) {
    expectAllYellow(kConstantProducts, "constant_products.fx");
}

}  // namespace
}  // namespace shadowfx::test::test_element_wise_products
