// What D3DX9 computed on the host for an effect, computed here too and recomputed when its inputs change:
// statics over host-bound parameters passed as compile arguments, and the effect's own functions called
// from them, with the intrinsics D3DX's preshaders had. Each test is a minimal effect in the manner of FX
// Composer's shader library, rendered and checked by pixels.
#include "EffectHarness.h"
#include <runtime/BuiltinScenes.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace shadowfx::test::test_d3d9_host_evaluation {
namespace {

// What the tests of host-evaluated functions render: the teapot, small. An object colour counts where it
// covers a twentieth of the frame.
constexpr int kTeapotWidth = 64, kTeapotHeight = 48, kMinTeapotPixels = kTeapotWidth * kTeapotHeight / 20;

// Sets `parameter` to `value` (none: the effect's own value stands), renders the teapot and requires the
// object in `colour` (0-255), the colour the host's evaluation of the effect's functions gives it.
void expectTeapotColour(runtime::EffectRenderer& renderer, const char* parameter, const std::string& value,
                        std::array<int, 3> colour) {
    if (parameter) {
        fx::DiagnosticList diagnostics;
        ASSERT_TRUE(renderer.setParameterFromText(parameter, value, diagnostics)) << diagnostics.str();
    }
    ASSERT_TRUE(render(renderer, *runtime::makeBuiltinScene("teapot"), kTeapotWidth, kTeapotHeight));
    const runtime::FrameImage frame = renderer.readFrame();
    ASSERT_TRUE(notConstant(frame));
    EXPECT_GE(countPixelsOfColour(frame, kTeapotWidth, kTeapotHeight, colour[0], colour[1], colour[2]),
              kMinTeapotPixels);
}

// A scene pass into a target, then a full-screen pass that copies it with the half-texel offset D3D9
// needed, computed as FX Composer's quad include computes it: a static over the viewport size, which the
// runtime binds only when it knows the frame's size (the parameter has no default, so a value computed
// from the defaults alone is 0.5 / 0 and every pixel reads one point of the target).
constexpr const char* kTexelOffsetPost = R"(
float4x4 WvpXf : WorldViewProjection;
float4x4 WorldXf : World;

half2 QuadScreenSize : VIEWPORTPIXELSIZE < string UIWidget = "None"; >;
half QuadTexOffset < string UIWidget = "None"; > = 0.5;
static half2 QuadTexelOffsets = half2(QuadTexOffset / (QuadScreenSize.x), QuadTexOffset / (QuadScreenSize.y));

texture SceneTexture : RENDERCOLORTARGET < float2 ViewPortRatio = {1.0, 1.0}; string Format = "A8R8G8B8"; >;
sampler2D SceneSampler = sampler_state {
    texture = <SceneTexture>; AddressU = Clamp; AddressV = Clamp;
    MagFilter = Linear; MinFilter = Linear; MipFilter = Point;
};
texture DepthBuffer : RENDERDEPTHSTENCILTARGET < float2 ViewPortRatio = {1.0, 1.0}; string Format = "D24S8"; >;

struct QuadVertexOutput { half4 Position : POSITION; half2 UV : TEXCOORD0; };

QuadVertexOutput ScreenQuadVS2(half3 Position : POSITION, half3 TexCoord : TEXCOORD0, uniform half2 TexelOffsets) {
    QuadVertexOutput OUT;
    OUT.Position = half4(Position, 1);
    OUT.UV = half2(TexCoord.xy + TexelOffsets);
    return OUT;
}

float4 SceneVS(float3 Position : POSITION, float3 Normal : NORMAL, out float3 WorldNormal : TEXCOORD0) : POSITION {
    WorldNormal = mul(float4(Normal, 0), WorldXf).xyz;
    return mul(float4(Position, 1), WvpXf);
}
float4 ScenePS(float3 WorldNormal : TEXCOORD0) : COLOR {
    return float4(0.5 + 0.5 * normalize(WorldNormal), 1);
}
float4 CopyPS(QuadVertexOutput IN, uniform sampler2D Source) : COLOR {
    return tex2D(Source, IN.UV);
}

float4 ClearColor = {0.1, 0.1, 0.1, 1};
float ClearDepth = 1.0;

technique Main < string Script =
    "RenderColorTarget0=SceneTexture; RenderDepthStencilTarget=DepthBuffer;"
    "ClearSetColor=ClearColor; ClearSetDepth=ClearDepth; Clear=Color; Clear=Depth;"
    "Pass=Scene; RenderColorTarget0=; RenderDepthStencilTarget=; Pass=Copy;"; > {
    pass Scene < string Script = "Draw=geometry;"; > {
        VertexShader = compile vs_3_0 SceneVS();
        PixelShader = compile ps_3_0 ScenePS();
        ZEnable = true;
        CullMode = None;
    }
    pass Copy < string Script = "Draw=Buffer;"; > {
        VertexShader = compile vs_3_0 ScreenQuadVS2(QuadTexelOffsets);
        PixelShader = compile ps_3_0 CopyPS(SceneSampler);
        ZEnable = false;
    }
}
)";

// Every channel of `frame` at (x, y) lies within the range of the target's texels around it: the copy may
// filter between neighbours, it may not read somewhere else.
int pixelsOutsideNeighbourhood(const runtime::FrameImage& frame, const std::vector<float>& target, int width,
                               int height, int channels) {
    int outside = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const uint8_t* f = frame.pixel(x, y);
            for (int c = 0; c < 3; ++c) {
                float low = 1.0f, high = 0.0f;
                for (int dy = -1; dy <= 1; ++dy) {
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int sx = std::clamp(x + dx, 0, width - 1),
                                  sy = std::clamp(y + dy, 0, height - 1);
                        const float s = target[static_cast<size_t>((sy * width + sx) * channels + c)];
                        low = std::min(low, s);
                        high = std::max(high, s);
                    }
                }
                const float v = f[c] / 255.0f;
                if (v < low - 2.0f / 255 || v > high + 2.0f / 255) {
                    ++outside;
                    break;
                }
            }
        }
    }
    return outside;
}

TEST(D3d9HostEvaluation, StaticTexelOffsetFollowsTheViewportSize) {
    auto renderer = loadEffect(kTexelOffsetPost, false, "texel_offset_post.fx");
    ASSERT_TRUE(renderer);
    const runtime::Scene scene = *runtime::makeBuiltinScene("teapot");
    for (const auto& [width, height] : {std::pair{96, 64}, std::pair{64, 80}}) {
        SCOPED_TRACE(std::to_string(width) + "x" + std::to_string(height));
        ASSERT_TRUE(render(*renderer, scene, width, height, "", {"SceneTexture"}));
        const runtime::FrameImage frame = renderer->readFrame();
        ASSERT_TRUE(notConstant(frame));
        int w = 0, h = 0, channels = 0;
        auto target = renderer->readTarget("SceneTexture", &w, &h, &channels);
        ASSERT_TRUE(target);
        ASSERT_EQ(w, width);
        ASSERT_EQ(h, height);
        EXPECT_EQ(pixelsOutsideNeighbourhood(frame, *target, width, height, channels), 0);
    }
}

// A compile argument computed by the effect's own function, with a local declared without a value,
// component assignments, nested if/else and an intrinsic, over a tweakable: evaluated on the host, and
// again when the tweakable changes (the other branch is taken then).
constexpr const char* kBranchingFunction = R"(
float4x4 WorldViewProj : WorldViewProjection;
float Level = 0.8;
float3 hue_of(float3 c) {
    float3 r = (0.0).xxx;
    float m = max(c.x, max(c.y, c.z));
    float3 unused;
    r.z = m;
    if (m != 0) {
        r.y = 0.5;
        if (c.x == m) r.x = 0.25;
        else r.x = 0.75;
    }
    return r;
}
static float3 Derived = hue_of(float3(Level, 0.2, 0.1));
float4 VS(float3 Position : POSITION) : POSITION { return mul(float4(Position, 1), WorldViewProj); }
float4 PS(uniform float3 Colour) : COLOR { return float4(Colour, 1); }
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(Derived); } }
)";

TEST(D3d9HostEvaluation, FunctionWithBranchesFollowsItsInput) {
    auto renderer = loadEffect(kBranchingFunction, false, "branching_function.fx");
    ASSERT_TRUE(renderer);
    expectTeapotColour(*renderer, nullptr, "", {64, 128, 204});     // (0.25, 0.5, 0.8)
    expectTeapotColour(*renderer, "Level", "0.1", {191, 128, 51});  // (0.75, 0.5, 0.2)
}

// The hue, saturation and value of a colour, in the style of FX Composer's colour-space include: a chain of
// else-ifs and two wrap-arounds over one vector, the shape whose inlined expression grows fastest. The
// host's value must equal the formula's for colours that take each branch of the chain.
constexpr const char* kHueSaturationValue = R"(
float4x4 WorldViewProj : WorldViewProjection;
float3 Key = {0.2, 0.7, 0.3};
float lowest(float3 c) { float m = (c.x < c.y) ? c.x : c.y; m = (m < c.z) ? m : c.z; return m; }
float highest(float3 c) { float m = (c.x > c.y) ? c.x : c.y; m = (m > c.z) ? m : c.z; return m; }
float3 to_hsv(float3 c) {
    float3 hsv = (0.0).xxx;
    float hi = highest(c);
    float span = hi - lowest(c);
    hsv.z = hi;
    if (span != 0) {
        hsv.y = span / hi;
        float3 d;
        d = (((hi.xxx - c) / 6.0) + (span / 2.0)) / span;
        if (c.x == hi) hsv.x = d.z - d.y;
        else if (c.y == hi) hsv.x = (1.0 / 3.0) + d.x - d.z;
        else if (c.z == hi) hsv.x = (2.0 / 3.0) + d.y - d.x;
        if (hsv.x < 0.0) { hsv.x += 1.0; }
        if (hsv.x > 1.0) { hsv.x -= 1.0; }
    }
    return hsv;
}
static float3 KeyHsv = to_hsv(Key);
float4 VS(float3 Position : POSITION) : POSITION { return mul(float4(Position, 1), WorldViewProj); }
float4 PS(uniform float3 Colour) : COLOR { return float4(Colour, 1); }
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(KeyHsv); } }
)";

// Smith 1978, "Color gamut transform pairs", the hexcone model: hue in [0, 1), saturation, value.
std::array<float, 3> hueSaturationValue(float r, float g, float b) {
    const float hi = std::max({r, g, b}), lo = std::min({r, g, b}), span = hi - lo;
    if (span == 0.0f) return {0.0f, 0.0f, hi};
    float h = hi == r ? (g - b) / span : hi == g ? 2.0f + (b - r) / span : 4.0f + (r - g) / span;
    h /= 6.0f;
    if (h < 0.0f) h += 1.0f;
    return {h, span / hi, hi};
}

TEST(D3d9HostEvaluation, ChainedBranchesOverOneVector) {
    auto renderer = loadEffect(kHueSaturationValue, false, "hue_saturation_value.fx");
    ASSERT_TRUE(renderer);
    for (const std::array<float, 3>& key :
         {std::array<float, 3>{0.2f, 0.7f, 0.3f}, {0.9f, 0.1f, 0.3f}, {0.1f, 0.2f, 0.8f}}) {
        const std::string text =
            std::to_string(key[0]) + "," + std::to_string(key[1]) + "," + std::to_string(key[2]);
        SCOPED_TRACE(text);
        const std::array<float, 3> hsv = hueSaturationValue(key[0], key[1], key[2]);
        expectTeapotColour(
            *renderer, "Key", text,
            {static_cast<int>(std::lround(hsv[0] * 255)), static_cast<int>(std::lround(hsv[1] * 255)),
             static_cast<int>(std::lround(hsv[2] * 255))});
    }
}

// Loops in a function evaluated on the host, unrolled as fxc unrolled them: a `for` bounded by a `static
// const`, a `while`, nested loops, `++`/`+=` steps and a loop attribute; and early returns.
constexpr const char* kLoopingFunction = R"(
float4x4 WorldViewProj : WorldViewProjection;
float Level = 0.5;
static const int kTerms = 4;
float early(float x) {
    if (x < 0.3) return 0.5;
    else if (x > 0.9) { return 0; }
    float half_x = x * 0.5;
    return half_x;
}
float3 series(float x) {
    float3 sum = 0;
    float weight = 1;
    [unroll] for (int i = 0; i < kTerms; i++) {
        float term = x * weight;
        sum.x += term;
        weight *= 0.5;
    }
    int k = 0;
    while (k < 3) { sum.y += 0.1; k += 1; }
    for (int a = 0; a < 2; ++a)
        for (int b = 0; b < a + 1; b++) sum.z += 0.1;
    sum.z += early(x);
    return sum;
}
static float3 Derived = series(Level);
float4 VS(float3 Position : POSITION) : POSITION { return mul(float4(Position, 1), WorldViewProj); }
float4 PS(uniform float3 Colour) : COLOR { return float4(Colour, 1); }
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(Derived); } }
)";

TEST(D3d9HostEvaluation, FunctionWithLoopsFollowsItsInput) {
    auto renderer = loadEffect(kLoopingFunction, false, "looping_function.fx");
    ASSERT_TRUE(renderer);
    // x * (1 + 1/2 + 1/4 + 1/8), 3 * 0.1, (1 + 2) * 0.1 + x / 2
    expectTeapotColour(*renderer, nullptr, "", {239, 77, 140});
    expectTeapotColour(*renderer, "Level", "0.2", {96, 77, 204});  // early: 0.5
}

// `break` and `continue` in loops of a function evaluated on the host, on conditions over the input: the
// steps before a ramp passes the level, a sum that skips some indices, the counter read after the loop
// that left early, and a loop that always leaves in its first iteration.
constexpr const char* kLeavingLoops = R"(
float4x4 WorldViewProj : WorldViewProjection;
float Level = 0.5;
float steps(float x) {
    float s = 0;
    for (int i = 0; i < 8; i++) {
        if (i * 0.125 >= x) break;
        s += 0.1;
    }
    return s;
}
float skipping(float x) {
    float s = 0;
    for (int j = 0; j < 4; j++) {
        if (j == 1) continue;
        if (j * 0.25 > x) { continue; }
        s += 0.2;
    }
    return s;
}
float counter(float x) {
    int k;
    for (k = 0; k < 8; k++)
        if (k * 0.25 >= x) break;
    float s = k * 0.1;
    while (true) { s += 0.05; break; s = 1; }
    return s;
}
static float3 Derived = float3(steps(Level), skipping(Level), counter(Level));
float4 VS(float3 Position : POSITION) : POSITION { return mul(float4(Position, 1), WorldViewProj); }
float4 PS(uniform float3 Colour) : COLOR { return float4(Colour, 1); }
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(Derived); } }
)";

TEST(D3d9HostEvaluation, LoopsLeftByBreakAndContinueFollowTheirInput) {
    auto renderer = loadEffect(kLeavingLoops, false, "leaving_loops.fx");
    ASSERT_TRUE(renderer);
    // 4 steps below 0.5; j = 0 and 2 summed; k = 2, plus 0.05
    expectTeapotColour(*renderer, nullptr, "", {102, 102, 64});
    // 2 steps below 0.2; j = 0 alone; k = 1, plus 0.05
    expectTeapotColour(*renderer, "Level", "0.2", {51, 51, 38});
}

// FX Composer's shadow includes build their texture-space bias as a static matrix from a function of a
// tweakable (`static float4x4 BiasXf = make_bias_mat(Bias);`); compile arguments computed from it on the
// host (a row vector times the matrix, one element) follow the tweakable.
constexpr const char* kMatrixFunction = R"(
float4x4 WorldViewProj : WorldViewProjection;
float Bias = 0.25;
float4x4 make_bias_mat(float b) {
    float4x4 m = float4x4(0.5, 0, 0, 0, 0, -0.5, 0, 0, 0, 0, 1, 0, 0.5, 0.5, -b, 1);
    return transpose(transpose(m));
}
static float4x4 BiasXf = make_bias_mat(Bias);
float4 VS(float3 p : POSITION) : POSITION { return mul(float4(p, 1), WorldViewProj); }
float4 PS(uniform float2 Corner, uniform float Depth) : COLOR { return float4(Corner, Depth, 1); }
technique T { pass P { VertexShader = compile vs_3_0 VS();
    PixelShader = compile ps_3_0 PS(mul(float4(0.2, -0.4, 0, 1), BiasXf).xy, -BiasXf._43); } }
)";

TEST(D3d9HostEvaluation, MatrixFromAFunctionFollowsItsInput) {
    auto renderer = loadEffect(kMatrixFunction, false, "matrix_function.fx");
    ASSERT_TRUE(renderer);
    // (0.1 + 0.5, 0.2 + 0.5, bias)
    expectTeapotColour(*renderer, "Bias", "0.25", {153, 178, 64});
    expectTeapotColour(*renderer, "Bias", "0.5", {153, 178, 128});
}

// The intrinsics D3DX's preshaders ran as sequences of their own instructions (ldexp, rcp, mad, sinh,
// cosh, tanh, reflect, faceforward, any, all, lit), in a function of a tweakable evaluated on the host.
constexpr const char* kComposedIntrinsics = R"(
float4x4 WorldViewProj : WorldViewProjection;
float Level = 0.5;
float3 composed(float l) {
    float3 r = reflect(float3(1, -1, 0), float3(0, 1, 0));
    float3 n = faceforward(float3(0, 0, 1), float3(0, 0, 1), float3(0, 0, 1));
    float4 li = lit(0.5, l, 2);
    return float3(ldexp(l, -1) + rcp(4) * r.y, mad(l, 0.5, 0.25) + tanh(0) + sinh(0),
                  li.z + cosh(0) * 0.1 + n.z * 0.1 + 0.05 + (any(float2(0, l)) ? 0 : 0.5) +
                      (all(float2(l - 0.5, 1)) ? 0.1 : 0));
}
float4 VS(float3 p : POSITION) : POSITION { return mul(float4(p, 1), WorldViewProj); }
float4 PS(uniform float3 Colour) : COLOR { return float4(Colour, 1); }
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(composed(Level)); } }
)";

TEST(D3d9HostEvaluation, IntrinsicsComposedOfPreshaderInstructions) {
    auto renderer = loadEffect(kComposedIntrinsics, false, "composed_intrinsics.fx");
    ASSERT_TRUE(renderer);
    // At 0.5: (0.25 + 0.25, 0.5, 0.25 + 0.1 - 0.1 + 0.05), all() false. At 0.9: (0.45 + 0.25, 0.7,
    // 0.81 + 0.05 + 0.1), all() true; any() is true at both.
    expectTeapotColour(*renderer, "Level", "0.5", {128, 128, 76});
    expectTeapotColour(*renderer, "Level", "0.9", {179, 179, 245});
}

// sincos writes its second and third arguments: both locals follow the tweakable.
constexpr const char* kSineAndCosine = R"(
float4x4 WorldViewProj : WorldViewProjection;
float Angle = 0.5;
float2 direction(float a) { float s, c; sincos(a, s, c); return float2(s, c); }
float4 VS(float3 p : POSITION) : POSITION { return mul(float4(p, 1), WorldViewProj); }
float4 PS(uniform float2 d) : COLOR { return float4(d, 0.4, 1); }
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(direction(Angle)); } }
)";

TEST(D3d9HostEvaluation, SincosWritesBothOfItsOutputs) {
    auto renderer = loadEffect(kSineAndCosine, false, "sine_and_cosine.fx");
    ASSERT_TRUE(renderer);
    // (sin 0.5, cos 0.5) = (0.479, 0.878); (sin 1.2, cos 1.2) = (0.932, 0.362).
    expectTeapotColour(*renderer, "Angle", "0.5", {122, 224, 102});
    expectTeapotColour(*renderer, "Angle", "1.2", {238, 92, 102});
}

// A `return` inside a loop, as fxc's preshaders ran it: the first iteration whose test passes gives the
// value, from a loop and from the inner one of two nested loops, on a test over the tweakable.
constexpr const char* kReturnInLoop = R"(
float4x4 WorldViewProj : WorldViewProjection;
float Level = 0.35;
float first_above(float x) {
    for (int i = 0; i < 8; i++) {
        if (i * 0.125 >= x) return i * 0.1;
    }
    return 1;
}
float nested(float x) {
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++)
            if (a * 3 + b >= x * 10) return (a * 3 + b) * 0.05 + 0.1;
    return 0.9;
}
static float3 Derived = float3(first_above(Level), nested(Level), 0.5);
float4 VS(float3 Position : POSITION) : POSITION { return mul(float4(Position, 1), WorldViewProj); }
float4 PS(uniform float3 Colour) : COLOR { return float4(Colour, 1); }
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(Derived); } }
)";

TEST(D3d9HostEvaluation, ReturnInsideALoopFollowsItsInput) {
    auto renderer = loadEffect(kReturnInLoop, false, "return_in_loop.fx");
    ASSERT_TRUE(renderer);
    // 0.35: i = 3 (0.375) gives 0.3, a * 3 + b = 4 gives 0.3. 0.65: i = 6 gives 0.6, 7 gives 0.45.
    expectTeapotColour(*renderer, nullptr, "", {77, 77, 128});
    expectTeapotColour(*renderer, "Level", "0.65", {153, 115, 128});
}

// Functions that write their `out` and `inout` parameters, called as statements and inside an expression,
// in a compile argument over a tweakable.
constexpr const char* kOutParameters = R"(
float4x4 WorldViewProj : WorldViewProjection;
float Level = 0.5;
void split(float x, out float hi, out float lo) { hi = x * 0.5 + 0.25; lo = x * 0.25; }
void raise(inout float3 c, float by) {
    c.z += by;
    if (c.z > 0.6) c.z = 0.6;
}
float halve(float x, out float rest) { rest = x * 0.5; return x - rest; }
float3 shade(float x) {
    float h, l;
    split(x, h, l);
    float3 c = float3(h, l, 0.2);
    raise(c, x * 0.5);
    float rest;
    c.y += halve(0.2, rest) * 0 + rest * 0.5;
    return c;
}
float4 VS(float3 Position : POSITION) : POSITION { return mul(float4(Position, 1), WorldViewProj); }
float4 PS(uniform float3 Colour) : COLOR { return float4(Colour, 1); }
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(shade(Level)); } }
)";

TEST(D3d9HostEvaluation, OutAndInoutParametersFollowTheirInput) {
    auto renderer = loadEffect(kOutParameters, false, "out_parameters.fx");
    ASSERT_TRUE(renderer);
    // 0.5: (0.5, 0.125 + 0.05, 0.45). 1.0: (0.75, 0.25 + 0.05, 0.6, 0.7 raised past the limit).
    expectTeapotColour(*renderer, nullptr, "", {128, 45, 115});
    expectTeapotColour(*renderer, "Level", "1.0", {191, 77, 153});
}

// Writes to a matrix's members, as D3DX's preshaders ran them: one-based (`._11`) and zero-based
// (`._m01`) elements, several at once (`._22_44 = float2(...)`, `._m30_m32 = ...`), an element by row and
// column (`m[1][2]`), a row (`m[2] = float4(...)`) and a row's component; a compile argument multiplies a
// vector by the matrix. The colour must be the product computed here from the same writes.
constexpr const char* kMatrixMemberWrites = R"(
float4x4 WorldViewProj : WorldViewProjection;
float Level = 0.3;
float4x4 build(float k) {
    float4x4 m = (float4x4)0;
    m._11 = k;
    m._m01 = 0.5 * k;
    m[1][2] = 1 - k;
    m[2] = float4(0.1, k, 0.2, 0);
    m._22_44 = float2(0.25, 1);
    m._m30_m32 = m._m30_m32 + float2(k, 0.05);
    m[3].y = 0.5 * m._11;
    return m;
}
static float4x4 Built = build(Level);
float4 VS(float3 Position : POSITION) : POSITION { return mul(float4(Position, 1), WorldViewProj); }
float4 PS(uniform float3 Colour) : COLOR { return float4(Colour, 1); }
technique T { pass P { VertexShader = compile vs_3_0 VS();
    PixelShader = compile ps_3_0 PS(mul(float4(0.5, 0.4, 0.3, 0.2), Built).xyz); } }
)";

// The colour kMatrixMemberWrites draws for Level `k`: its matrix built element by element (m[row][column])
// and the row vector (0.5, 0.4, 0.3, 0.2) times it, in 0-255.
std::array<int, 3> matrixMemberWritesColour(float k) {
    float m[4][4] = {};
    m[0][0] = k;
    m[0][1] = 0.5f * k;
    m[1][2] = 1 - k;
    m[2][0] = 0.1f, m[2][1] = k, m[2][2] = 0.2f, m[2][3] = 0;
    m[1][1] = 0.25f, m[3][3] = 1;
    m[3][0] += k, m[3][2] += 0.05f;
    m[3][1] = 0.5f * m[0][0];
    const float v[4] = {0.5f, 0.4f, 0.3f, 0.2f};
    std::array<int, 3> colour{};
    for (int c = 0; c < 3; ++c) {
        float sum = 0;
        for (int r = 0; r < 4; ++r) sum += v[r] * m[r][c];
        colour[static_cast<size_t>(c)] = static_cast<int>(std::lround(sum * 255));
    }
    return colour;
}

TEST(D3d9HostEvaluation, MatrixMemberWritesFollowTheirInput) {
    auto renderer = loadEffect(kMatrixMemberWrites, false, "matrix_member_writes.fx");
    ASSERT_TRUE(renderer);
    expectTeapotColour(*renderer, nullptr, "", matrixMemberWritesColour(0.3f));
    expectTeapotColour(*renderer, "Level", "0.8", matrixMemberWritesColour(0.8f));
}

// Local arrays: elements written in a loop, a flat initializer list of vectors, a read and a write at an
// index known only from the tweakable, and a component of an element written.
constexpr const char* kLocalArrays = R"(
float4x4 WorldViewProj : WorldViewProjection;
float Spread = 0.5;
float3 ramp(float s) {
    float w[4];
    for (int i = 0; i < 4; i++) w[i] = i * s;
    float2 pairs[2] = {0.1, 0.2, 0.3, 0.4};
    int k = s > 0.3 ? 1 : 0;
    w[k] += 0.1;
    pairs[1].y = pairs[k].x;
    return float3(w[2] * 0.5, pairs[1].y, w[1]);
}
static float3 Derived = ramp(Spread);
float4 VS(float3 Position : POSITION) : POSITION { return mul(float4(Position, 1), WorldViewProj); }
float4 PS(uniform float3 Colour) : COLOR { return float4(Colour, 1); }
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(Derived); } }
)";

TEST(D3d9HostEvaluation, LocalArraysFollowTheirInput) {
    auto renderer = loadEffect(kLocalArrays, false, "local_arrays.fx");
    ASSERT_TRUE(renderer);
    // 0.5: w = (0, 0.6, 1, 1.5), k = 1. 0.2: w = (0.1, 0.2, 0.4, 0.6), k = 0.
    expectTeapotColour(*renderer, nullptr, "", {128, 77, 153});
    expectTeapotColour(*renderer, "Spread", "0.2", {51, 26, 51});
}

// Local structs, and struct values passed to, returned from and selected between in functions: `(S)0`,
// members and their components written, a struct argument changed in its callee (a copy), a select
// between two structs on the tweakable.
constexpr const char* kLocalStructs = R"(
float4x4 WorldViewProj : WorldViewProjection;
float Level = 0.4;
struct Tint { float3 colour; float weight; };
Tint make_tint(float x) {
    Tint t = (Tint)0;
    t.colour = float3(x, 0.5 * x, 0.2);
    t.weight = 0.5;
    return t;
}
Tint brighter(Tint t, float by) { t.colour.g += by; t.weight *= 2; return t; }
float3 tinted(float x) {
    Tint t = brighter(make_tint(x), 0.1);
    Tint u;
    u.colour = t.colour * 0.5 * t.weight;
    u.weight = 0;
    Tint chosen = x > 0.7 ? t : u;
    return chosen.colour + make_tint(x).weight * 0;
}
float4 VS(float3 Position : POSITION) : POSITION { return mul(float4(Position, 1), WorldViewProj); }
float4 PS(uniform float3 Colour) : COLOR { return float4(Colour, 1); }
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(tinted(Level)); } }
)";

TEST(D3d9HostEvaluation, LocalStructsFollowTheirInput) {
    auto renderer = loadEffect(kLocalStructs, false, "local_structs.fx");
    ASSERT_TRUE(renderer);
    // 0.4: u, half of (0.4, 0.3, 0.2). 0.8: t, (0.8, 0.5, 0.2).
    expectTeapotColour(*renderer, nullptr, "", {51, 38, 26});
    expectTeapotColour(*renderer, "Level", "0.8", {204, 128, 51});
}

// A loop the host cannot unroll (its bound a tweakable, or more iterations than fxc unrolled) is an error
// where the host expression calls the function, naming the loop.
TEST(D3d9HostEvaluation, LoopsTheHostCannotUnrollAreReportedAtTheCall) {
    sharedContext();
    for (const auto& [bound, message] :
         {std::pair{"Count",
                    "parameter_loop.fx:4:56: error: function 'total' cannot be evaluated on the host: the "
                    "loop at parameter_loop.fx:2:53 has no count known when the effect is compiled"},
          std::pair{"2000",
                    "parameter_loop.fx:4:56: error: function 'total' cannot be evaluated on the host: the "
                    "loop at parameter_loop.fx:2:53 runs more than 1024 iterations"}}) {
        fx::DiagnosticList diagnostics;
        auto effect = fx::parseEffectSource(
            std::string("int Count = 3;\n"
                        "float total(float x) { float s = 0; for (int i = 0; i < ") +
                bound +
                "; i++) s = x; return s; }\n"
                "float4 PS(uniform float v) : COLOR { return v; }\n"
                "technique T { pass P { PixelShader = compile ps_3_0 PS(total(0.25)); } }\n",
            "parameter_loop.fx", {}, diagnostics);
        EXPECT_FALSE(effect);
        EXPECT_NE(diagnostics.str().find(message), std::string::npos) << diagnostics.str();
    }
}

}  // namespace
}  // namespace shadowfx::test::test_d3d9_host_evaluation
