// D3D9 effects whose shaders D3D9 ran as written and whose lowering to glslang and GL must keep running:
// a pixel-shader input the vertex shader does not write (it reads 0), an array-typed input semantic
// (TEXCOORD1..n), a literal bool compile argument, a static initialized by a call of the effect's own
// function, a shadow-map depth sampler passed as a compile argument or on to other functions, a `for`
// variable read after its loop, a cube-map lookup in a direction that is not finite, samplers that no
// texture is given to, and per-instance transforms. Minimal effects
// written for these tests, checked by pixels.
#include "EffectHarness.h"
#include <runtime/BuiltinScenes.h>

namespace shadowfx::test::test_d3d9_lowering {
namespace {

// The scene's objects cover this share of the frame at least (the teapot at 64x48).
constexpr int kMinObjectPixels = 64 * 48 / 20;

// Renders the effect's technique (its first when none is named) on the teapot scene at 64x48 and checks
// that the frame is not one colour and that the objects came out in exactly the colour (r, g, b).
void expectObjectsInColour(runtime::EffectRenderer& renderer, int r, int g, int b,
                           const std::string& technique = "") {
    ASSERT_TRUE(render(renderer, *runtime::makeBuiltinScene("teapot"), 64, 48, technique));
    const runtime::FrameImage frame = renderer.readFrame();
    ASSERT_TRUE(notConstant(frame));
    EXPECT_GE(countPixelsOfColour(frame, 64, 48, r, g, b), kMinObjectPixels);
}

// The vertex shader writes TEXCOORD0 only; the pixel shader also reads TEXCOORD1 and COLOR1, which D3D9
// reads as 0. The objects come out in exactly the colour of the written part.
constexpr const char* kUnwrittenInput = R"(
float4x4 WorldViewProj : WorldViewProjection;
struct VsOut { float4 Position : POSITION; float2 Written : TEXCOORD0; };
VsOut VS(float3 Position : POSITION) {
    VsOut o;
    o.Position = mul(float4(Position, 1), WorldViewProj);
    o.Written = float2(0.2, 0.6);
    return o;
}
float4 PS(float2 Written : TEXCOORD0, float2 Unwritten : TEXCOORD1, float4 Colour : COLOR1) : COLOR {
    return float4(Written.x + Unwritten.x + Colour.r, Written.y + Unwritten.y + Colour.g, 0.4 + Colour.b, 1);
}
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)";

TEST(D3d9Lowering, PixelInputTheVertexShaderDoesNotWriteReadsZero) {
    auto renderer = loadEffect(kUnwrittenInput, false, "unwritten_input.fx");
    ASSERT_TRUE(renderer);
    expectObjectsInColour(*renderer, 51, 153, 102);
}

// `float2 Jitter[3] : TEXCOORD1` takes TEXCOORD1..3; `uniform bool` is given a literal `true`; the static
// is computed by a function of the effect (which glslang's HLSL front end reports as recursion when it
// stands in the static's initializer).
constexpr const char* kArraysAndStatics = R"(
float4x4 WorldViewProj : WorldViewProjection;
float Gain = 0.5;
float4 tint(float g) { float4 c = float4(g, g * 0.5, 0, 1); if (g > 2) c = 0; return c; }
static float4 Tint = tint(Gain);
struct VsOut { float4 Position : POSITION; float2 Jitter[3] : TEXCOORD1; };
VsOut VS(float3 Position : POSITION, uniform bool Spread) {
    VsOut o;
    o.Position = mul(float4(Position, 1), WorldViewProj);
    for (int i = 0; i < 3; i++) o.Jitter[i] = Spread ? float2(0.1 * i, 0.2) : float2(0, 0);
    return o;
}
float4 PS(float2 Jitter[3] : TEXCOORD1) : COLOR {
    return float4(Tint.r + Jitter[2].x, Tint.g + Jitter[1].x, Jitter[0].y, 1);
}
technique T { pass P { VertexShader = compile vs_2_0 VS(true); PixelShader = compile ps_2_0 PS(); } }
)";

TEST(D3d9Lowering, ArrayInputBoolLiteralArgumentAndStaticFromAFunction) {
    auto renderer = loadEffect(kArraysAndStatics, false, "arrays_and_statics.fx");
    ASSERT_TRUE(renderer);
    // (0.5 + 0.2, 0.25 + 0.1, 0.2): each element of the array came through its own semantic.
    expectObjectsInColour(*renderer, 179, 89, 51);
}

// The DirectX SDK's PRT samples' vertex shader: an array-typed input (`float4 Weights[1] : BLENDWEIGHT1`,
// which the mesh does not have) before a `uniform bool` given a literal. glslang refused the entry point's
// zeroing of the array as one cast (`(float4[1])0`: "cannot convert 'const int' to '4-component vector of
// float'"), which read like a fault of the literal; each shader draws its colour only when its argument
// is true.
constexpr const char* kArrayInputBeforeBool = R"(
float4x4 WorldViewProj : WorldViewProjection;
struct VsOut { float4 Position : POSITION; float4 Colour : COLOR0; };
VsOut VS(float4 Position : POSITION, int Cluster : BLENDWEIGHT, float4 Weights[1] : BLENDWEIGHT1,
         uniform bool Lit) {
    VsOut o;
    o.Position = mul(Position, WorldViewProj);
    o.Colour = Lit ? float4(0.2, 0.6, 0.4 + 0 * (Weights[0].x + Cluster), 1) : float4(1, 0, 1, 1);
    return o;
}
float4 PS(float4 Colour : COLOR0, uniform bool Lit) : COLOR { return Lit ? Colour : float4(1, 1, 0, 1); }
technique T { pass P { VertexShader = compile vs_2_0 VS(true); PixelShader = compile ps_2_0 PS(true); } }
)";

TEST(D3d9Lowering, BoolLiteralArgumentAfterAnArrayInput) {
    auto renderer = loadEffect(kArrayInputBeforeBool, false, "array_input_before_bool.fx");
    ASSERT_TRUE(renderer);
    expectObjectsInColour(*renderer, 51, 153, 102);
}

// FX Composer's shadow-map effects pass the depth target's sampler to the pixel shader as a compile
// argument (`compile ps_3_0 PS(ShadDepthSampler)`); D3DX bound it when it compiled the shader, so its
// lookups are depth comparisons as the global's own are. The reference depth 0 passes the comparison
// everywhere and 1 fails wherever an object wrote depth: red 1 and green 0 on the objects, where reading
// the stored depth as a colour would give the same value in both. The float after the sampler keeps its
// own argument. The sampler is declared after the shader, as FX Composer's quad include defines shaders
// that the effects including it pass their own samplers to.
constexpr const char* kDepthSamplerArgument = R"(
float4x4 WorldViewProj : WorldViewProjection;
float ClearDepth = 1.0;
struct VsOut { float4 Position : POSITION; float4 Projected : TEXCOORD0; };
VsOut VS(float3 Position : POSITION) {
    VsOut o;
    o.Position = mul(float4(Position, 1), WorldViewProj);
    o.Projected = float4(o.Position.xy / o.Position.w * float2(0.5, -0.5) + 0.5, 0, 1);
    return o;
}
float4 DepthPS() : COLOR { return 1; }
float4 PS(VsOut i, uniform sampler2D Depth, uniform float Blue) : COLOR {
    float4 near = float4(i.Projected.xy, 0, 1), far = float4(i.Projected.xy, 1, 1);
    return float4(tex2Dproj(Depth, near).x, tex2Dproj(Depth, far).x, Blue, 1);
}
texture ShadowColour : RENDERCOLORTARGET < float2 Dimensions = {64, 48}; string Format = "X8B8G8R8"; >;
texture ShadowDepth : RENDERDEPTHSTENCILTARGET < float2 Dimensions = {64, 48}; string Format = "D24S8_SHADOWMAP"; >;
sampler2D ShadowDepthSampler = sampler_state { texture = <ShadowDepth>; AddressU = Clamp; AddressV = Clamp;
    MinFilter = Point; MagFilter = Point; MipFilter = None; };
technique T < string Script =
    "RenderColorTarget0=ShadowColour; RenderDepthStencilTarget=ShadowDepth; ClearSetDepth=ClearDepth;"
    "Clear=Depth; Pass=Depth; RenderColorTarget0=; RenderDepthStencilTarget=; Pass=Lookup;"; > {
    pass Depth < string Script = "Draw=geometry;"; > {
        VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 DepthPS();
        ZEnable = true; ZWriteEnable = true; CullMode = None;
    }
    pass Lookup < string Script = "Draw=geometry;"; > {
        VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(ShadowDepthSampler, 0.4);
        ZEnable = true; CullMode = None;
    }
}
)";

TEST(D3d9Lowering, DepthSamplerCompileArgumentComparesDepth) {
    auto renderer = loadEffect(kDepthSamplerArgument, false, "depth_sampler_argument.fx");
    ASSERT_TRUE(renderer);
    expectObjectsInColour(*renderer, 255, 0, 102);
}

// The depth sampler passed on through function parameters: a pixel shader hands the global to a helper,
// and a pixel shader given it as a compile argument hands its parameter to a helper that hands it to
// another (NVIDIA's shadow includes: `float shadow(sampler2D s, float4 p) { return tex2Dproj(s, p).r; }`).
// D3D9 inlined every call, so each lookup is the depth comparison the global's own is, tex2Dlod's and
// tex2Dbias's too: red 1 and green 0 on the objects, as above. A colour sampler passed to the same helper
// keeps reading colour (blue, 0.4).
constexpr const char* kDepthSamplerPassedOn = R"(
float4x4 WorldViewProj : WorldViewProjection;
float ClearDepth = 1.0;
float4 ClearColour = {0.4, 0.4, 0.4, 1};
struct VsOut { float4 Position : POSITION; float4 Projected : TEXCOORD0; };
VsOut VS(float3 Position : POSITION) {
    VsOut o;
    o.Position = mul(float4(Position, 1), WorldViewProj);
    o.Projected = float4(o.Position.xy / o.Position.w * float2(0.5, -0.5) + 0.5, 0, 1);
    return o;
}
float4 DepthPS() : COLOR { return 1; }
texture ShadowColour : RENDERCOLORTARGET < float2 Dimensions = {64, 48}; string Format = "X8B8G8R8"; >;
texture ShadowDepth : RENDERDEPTHSTENCILTARGET < float2 Dimensions = {64, 48}; string Format = "D24S8_SHADOWMAP"; >;
sampler2D ShadowDepthSampler = sampler_state { texture = <ShadowDepth>; AddressU = Clamp; AddressV = Clamp;
    MinFilter = Point; MagFilter = Point; MipFilter = None; };
sampler2D ShadowColourSampler = sampler_state { texture = <ShadowColour>; AddressU = Clamp; AddressV = Clamp;
    MinFilter = Point; MagFilter = Point; MipFilter = None; };
float lookup(sampler2D s, float4 p) { return tex2Dproj(s, p).r; }
float level(sampler2D s, float4 p) { return tex2Dlod(s, float4(p.xyz, 0)).r; }
float shadow(float4 p, sampler2D s) { return lookup(s, p); }
float4 GlobalPS(VsOut i) : COLOR {
    float4 near = float4(i.Projected.xy, 0, 1), far = float4(i.Projected.xy, 1, 1);
    return float4(lookup(ShadowDepthSampler, near), level(ShadowDepthSampler, far),
                  lookup(ShadowColourSampler, near), 1);
}
float4 ArgumentPS(VsOut i, uniform sampler2D Depth) : COLOR {
    float4 near = float4(i.Projected.xy, 0, 1), far = float4(i.Projected.xy, 1, 1);
    return float4(shadow(near, Depth), tex2Dbias(Depth, far).r, lookup(ShadowColourSampler, near), 1);
}
#define SHADOW_TECHNIQUE(name, lookupShader) \
technique name < string Script = \
    "RenderColorTarget0=ShadowColour; RenderDepthStencilTarget=ShadowDepth; ClearSetDepth=ClearDepth;" \
    "ClearSetColor=ClearColour; Clear=Color; Clear=Depth; Pass=Depth;" \
    "RenderColorTarget0=; RenderDepthStencilTarget=; Pass=Lookup;"; > { \
    pass Depth < string Script = "Draw=geometry;"; > { \
        VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 DepthPS(); \
        ZEnable = true; ZWriteEnable = true; CullMode = None; ColorWriteEnable = 0; \
    } \
    pass Lookup < string Script = "Draw=geometry;"; > { \
        VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 lookupShader; \
        ZEnable = true; CullMode = None; \
    } \
}
SHADOW_TECHNIQUE(Global, GlobalPS())
SHADOW_TECHNIQUE(Argument, ArgumentPS(ShadowDepthSampler))
)";

TEST(D3d9Lowering, DepthSamplerPassedOnToFunctionsComparesDepth) {
    auto renderer = loadEffect(kDepthSamplerPassedOn, false, "depth_sampler_passed_on.fx");
    ASSERT_TRUE(renderer);
    for (const char* technique : {"Global", "Argument"}) {
        SCOPED_TRACE(technique);
        expectObjectsInColour(*renderer, 255, 0, 102, technique);
    }
}

// fxc declared a `for` loop's variable in the enclosing block (an XNA engine's antialiasing filter returns
// the step its search loop stopped at); the loop leaves at 3 of 8, so red is 0.3.
constexpr const char* kLoopVariableAfterTheLoop = R"(
float4x4 WorldViewProj : WorldViewProjection;
float Limit = 3;
float4 VS(float3 p : POSITION) : POSITION { return mul(float4(p, 1), WorldViewProj); }
float steps(float limit) {
    [unroll(8)] for (int i = 0; i < 8; i++) { if (i >= limit) break; }
    return i;
}
float4 PS() : COLOR { return float4(steps(Limit) / 10.0, 0.6, 0.4, 1); }
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)";

TEST(D3d9Lowering, LoopVariableReadAfterTheLoop) {
    auto renderer = loadEffect(kLoopVariableAfterTheLoop, false, "loop_variable.fx");
    ASSERT_TRUE(renderer);
    expectObjectsInColour(*renderer, 76, 153, 102);
}

// An XNA engine's material normalizes the camera's direction in the vertex shader, a zero vector where the
// application has not set the camera: every pixel looks its cube map up in a NaN direction, on which
// llvmpipe crashed. The cube map is the neutral grey stand-in, halved.
constexpr const char* kCubeLookupNotFinite = R"(
float4x4 WorldViewProj : WorldViewProjection;
texture EnvTexture;
samplerCUBE EnvSampler = sampler_state { Texture = <EnvTexture>; };
struct VsOut { float4 Position : POSITION; float3 Dir : TEXCOORD0; };
VsOut VS(float3 p : POSITION, float3 n : NORMAL) {
    VsOut o;
    o.Position = mul(float4(p, 1), WorldViewProj);
    o.Dir = normalize(n * 0);
    return o;
}
float4 PS(float3 Dir : TEXCOORD0) : COLOR { return float4(texCUBE(EnvSampler, Dir).rgb * 0.5, 1); }
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)";

TEST(D3d9Lowering, CubeLookupInADirectionThatIsNotFinite) {
    auto renderer = loadEffect(kCubeLookupNotFinite, false, "cube_not_finite.fx");
    ASSERT_TRUE(renderer);
    expectObjectsInColour(*renderer, 128, 128, 128);
}

// XNA's and MonoGame's stock effects declare bare samplers (`sampler2D Texture : register(s0);`) whose
// texture only their application sets: each reads the neutral white texture of its kind, as an effect's
// texture without contents does, so the material's colour shows through.
constexpr const char* kBareSamplers = R"(
float4x4 WorldViewProj : WorldViewProjection;
sampler2D Texture : register(s0);
samplerCUBE Environment : register(s1);
struct VsOut { float4 Position : POSITION; float2 Uv : TEXCOORD0; float3 Normal : TEXCOORD1; };
VsOut VS(float3 p : POSITION, float3 n : NORMAL, float2 uv : TEXCOORD0) {
    VsOut o;
    o.Position = mul(float4(p, 1), WorldViewProj);
    o.Uv = uv;
    o.Normal = n;
    return o;
}
float4 PS(float2 Uv : TEXCOORD0, float3 Normal : TEXCOORD1) : COLOR {
    return float4(tex2D(Texture, Uv).rgb * float3(0.2, 0.4, 0.6) + texCUBE(Environment, Normal).rgb * 0.2, 1);
}
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)";

TEST(D3d9Lowering, BareSamplersWithoutATextureReadWhite) {
    auto renderer = loadEffect(kBareSamplers, false, "bare_samplers.fx");
    ASSERT_TRUE(renderer);
    expectObjectsInColour(*renderer, 102, 153, 204);
}

// D3D9's untyped `sampler` took its dimension from the instruction that read it: the DirectX SDK's skybox
// samples its untyped environment texture through an untyped sampler with texCUBE. Both are a cube here
// (glslang would read the sampler as 2D, and the cube texture as an incomplete 2D one: black). The
// skybox's vertex shader hands the screen quad's position through: the pass draws the quad.
constexpr const char* kUntypedCube = R"(
texture g_EnvironmentTexture;
sampler EnvironmentSampler = sampler_state { Texture = (g_EnvironmentTexture); MinFilter = POINT; MagFilter = POINT; };
struct SkyboxVS_Output { float4 Pos : POSITION; float3 Tex : TEXCOORD0; };
SkyboxVS_Output SkyboxVS(float4 Pos : POSITION) {
    SkyboxVS_Output Output;
    Output.Pos = Pos;
    Output.Tex = Pos.xyz;
    return Output;
}
float4 SkyboxPS(SkyboxVS_Output Input) : COLOR {
    return texCUBE(EnvironmentSampler, float3(Input.Tex.x > 0 ? 1 : -1, 0.1, 0.1));
}
technique Skybox { pass p0 { VertexShader = compile vs_2_0 SkyboxVS(); PixelShader = compile ps_2_0 SkyboxPS(); } }
)";

TEST(D3d9Lowering, AnUntypedSamplerReadByTexCubeIsACubeSampler) {
    auto renderer = loadEffect(kUntypedCube, false, "untyped_cube.fx");
    ASSERT_TRUE(renderer);
    const std::optional<size_t> sampler = renderer->findParameter("EnvironmentSampler");
    ASSERT_TRUE(sampler);
    EXPECT_EQ(renderer->effect().parameters[*sampler].type.base, fx::BaseType::SamplerCube);
    // Faces +X red and -X green, the others blue: the quad's right half looks along +X.
    runtime::TextureData cube;
    cube.width = cube.height = 1;
    cube.rgba = {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1};
    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(renderer->setTexture(*renderer->findParameter("g_EnvironmentTexture"), cube, diagnostics))
        << diagnostics.str();
    ASSERT_TRUE(render(*renderer, *runtime::makeBuiltinScene("teapot"), 64, 48, "Skybox"));
    const runtime::FrameImage frame = renderer->readFrame();
    EXPECT_EQ(countPixelsOfColour(frame, 64, 48, 255, 0, 0), 32 * 48);
    EXPECT_EQ(countPixelsOfColour(frame, 64, 48, 0, 255, 0), 32 * 48);
}

// XNA's hardware instancing reads each instance's transform from a per-instance stream, as a matrix
// input over consecutive semantic indices (`: BLENDWEIGHT` in XNA 4, `: TEXCOORD1` in XNA 3): the meshes
// here hold no such streams, so it reads the identity and each object stands where its World puts it.
constexpr const char* kInstanceTransforms = R"(
float4x4 World;
float4x4 ViewProjection : ViewProjection;
float4 Place(float4 p, float4x4 instance) { return mul(mul(mul(p, transpose(instance)), World), ViewProjection); }
float4 Xna4(float4 p : POSITION0, float4x4 instance : BLENDWEIGHT) : POSITION { return Place(p, instance); }
float4 Xna3(float4 p : POSITION0, float4x4 instance : TEXCOORD1) : POSITION { return Place(p, instance); }
float4 Red() : COLOR { return float4(1, 0, 0, 1); }
technique Xna4 { pass { VertexShader = compile vs_3_0 Xna4(); PixelShader = compile ps_3_0 Red(); } }
technique Xna3 { pass { VertexShader = compile vs_3_0 Xna3(); PixelShader = compile ps_3_0 Red(); } }
)";

TEST(D3d9Lowering, AMatrixVertexInputIsAnInstanceTransformThatReadsTheIdentity) {
    auto renderer = loadEffect(kInstanceTransforms, false, "instance_transforms.fx");
    ASSERT_TRUE(renderer);
    expectObjectsInColour(*renderer, 255, 0, 0, "Xna4");
    expectObjectsInColour(*renderer, 255, 0, 0, "Xna3");
}

}  // namespace
}  // namespace shadowfx::test::test_d3d9_lowering
