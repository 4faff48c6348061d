// D3D9 fixed-function passes: a pass without shaders that sets transforms, lights, material, texture
// stages and fog runs as D3D9 ran it, through generated stages (parse, compile, EffectRenderer on
// llvmpipe); a vertex shader with the fixed-function pixel stage samples stage 0's texture; what the
// generated pipeline does not offer is a located error. Full-screen passes (a D3D9 pixel shader alone, a
// D3D10 pass-through vertex shader) read the host's picture.
#include "effects/EffectHarness.h"

#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>
#include <runtime/BuiltinScenes.h>
#include <runtime/GlApi.h>

#include <algorithm>

namespace shadowfx::test::test_fixed_function_passes {
namespace {

constexpr int kSize = 96;

// Two lights: a red directional one from the side `SIDE` names and a green point light above; the noise
// texture modulates the lit colour on stage 0.
const char* kEffect = R"(
float4x4 World : WORLD;
float4x4 View : VIEW;
float4x4 Projection : PROJECTION;
float4 KeyColor = float4(1, 0, 0, 1);
float4 LightPositions[2] = { float4(0, 12, 0, 1), float4(0, 0, 0, 1) };
texture Noise < string Procedural = "noise"; int Seed = 3; float2 Dimensions = {32, 32}; >;

#define TRANSFORMS WorldTransform[0] = <World>; ViewTransform = <View>; ProjectionTransform = <Projection>;
#define LIGHTS(side)                                                                                  \
    Lighting = true; NormalizeNormals = true; MaterialDiffuse = float4(1, 1, 1, 1);                   \
    LightEnable[0] = true; LightType[0] = Directional; LightDirection[0] = float4(side, 0, 0, 0);     \
    LightDiffuse[0] = (KeyColor);                                                                     \
    LightEnable[1] = true; LightType[1] = Point; LightPosition[1] = <LightPositions[0]>;              \
    LightDiffuse[1] = float4(0, 0.5, 0, 1); LightRange[1] = 100; LightAttenuation0[1] = 1;

technique FromRight { pass p { VertexShader = null; PixelShader = null; TRANSFORMS LIGHTS(-1) } }
technique FromLeft { pass p { TRANSFORMS LIGHTS(1) } }
technique Textured { pass p { TRANSFORMS LIGHTS(-1)
    Texture[0] = <Noise>; ColorOp[0] = Modulate; ColorArg1[0] = Texture; ColorArg2[0] = Diffuse; } }
// The key light alone, and the same diffuse term written as a vertex shader in world space.
technique KeyOnly { pass p { TRANSFORMS Lighting = true; NormalizeNormals = true;
    LightEnable[0] = true; LightType[0] = Directional; LightDirection[0] = float4(-1, 0, 0, 0);
    LightDiffuse[0] = (KeyColor); } }
struct KeyOut { float4 position : POSITION; float4 diffuse : COLOR0; };
KeyOut KeyVS(float4 p : POSITION, float3 n : NORMAL) {
    KeyOut o;
    o.position = mul(float4(p.xyz, 1), mul(World, mul(View, Projection)));
    o.diffuse = float4(KeyColor.rgb * saturate(dot(normalize(mul(n, (float3x3)World)), float3(1, 0, 0))), 1);
    return o;
}
technique KeyReference { pass p { VertexShader = compile vs_3_0 KeyVS(); } }
technique Unlit { pass p { TRANSFORMS Lighting = false; } }
technique LinearFog { pass p { TRANSFORMS LIGHTS(-1)
    FogEnable = true; FogVertexMode = Linear; FogColor = 0xff0000ff; FogStart = 0; FogEnd = 0.01; } }
technique TableFog { pass p { TRANSFORMS LIGHTS(-1)
    FogEnable = true; FogTableMode = Exp2; FogColor = float4(0, 0, 1, 1); FogDensity = 50; } }
technique FogFar { pass p { TRANSFORMS Lighting = false;
    FogEnable = true; FogTableMode = Linear; FogColor = float4(0, 0, 1, 1); FogStart = 7; FogEnd = 11; } }

// A vertex shader and D3D9's fixed-function pixel stage: stage 0 modulates the texture by the diffuse.
struct VsOut { float4 position : POSITION; float4 diffuse : COLOR0; float2 uv : TEXCOORD0; };
VsOut VS(float4 p : POSITION, float2 uv : TEXCOORD0) {
    VsOut o;
    o.position = mul(p, mul(World, mul(View, Projection)));
    o.diffuse = float4(1, 1, 0, 1);
    o.uv = uv;
    return o;
}
technique ShaderAndStages { pass p { VertexShader = compile vs_3_0 VS(); Texture[0] = <Noise>; } }
technique ShaderOnly { pass p { VertexShader = compile vs_3_0 VS(); } }

// Lights without transforms: the host's world, view and projection, as D3D9 kept the application's.
technique HostTransforms { pass p { LIGHTS(-1) } }
// Texture stages alone, no shader and no vertex state: D3D9 still ran the vertex pipeline, with the host's
// transforms.
#define NOISE_STAGE Lighting = false; Texture[0] = <Noise>; ColorOp[0] = SelectArg1; ColorArg1[0] = Texture;
technique StagesOnly { pass p { NOISE_STAGE } }
technique StagesAndTransforms { pass p { TRANSFORMS NOISE_STAGE } }

// A pixel shader alone: a full-screen pass over the quad, its coordinates in both sets, diffuse white.
float4 ScreenPS(float2 uv : TEXCOORD0, float2 uv1 : TEXCOORD1, float4 diffuse : COLOR0) : COLOR0 {
    return float4(uv.x, uv1.y, diffuse.b * 0.5, 1);
}
technique ScreenPass { pass p { VertexShader = null; PixelShader = compile ps_2_0 ScreenPS(); ZEnable = false; } }
technique ScreenPassUnset { pass p { PixelShader = compile ps_2_0 ScreenPS(); } }
)";

const runtime::Scene& teapot() {
    static const runtime::Scene scene = *runtime::makeBuiltinScene("teapot");
    return scene;
}

runtime::FrameImage frame(runtime::EffectRenderer& renderer, const std::string& technique) {
    EXPECT_TRUE(render(renderer, teapot(), kSize, kSize, technique)) << technique;
    return renderer.readFrame();
}

// What the frame's corner shows: the clear colour, where nothing was drawn.
bool isBackground(const runtime::FrameImage& image, int x, int y) {
    return std::equal(image.pixel(x, y), image.pixel(x, y) + 3, image.pixel(0, 0));
}

// The mean of one channel over the drawn pixels of the left or the right half.
double meanChannel(const runtime::FrameImage& image, int channel, bool right) {
    double sum = 0;
    int count = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = right ? kSize / 2 : 0; x < (right ? kSize : kSize / 2); ++x) {
            if (isBackground(image, x, y)) continue;
            sum += image.pixel(x, y)[channel];
            ++count;
        }
    return count ? sum / count : 0.0;
}

// The drawn pixels of (r, g, b), within one step, and the drawn pixels in all.
std::pair<int, int> drawnOfColour(const runtime::FrameImage& image, int r, int g, int b) {
    int drawn = 0;
    int matching = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            if (isBackground(image, x, y)) continue;
            ++drawn;
            const uint8_t* p = image.pixel(x, y);
            matching += std::abs(p[0] - r) <= 1 && std::abs(p[1] - g) <= 1 && std::abs(p[2] - b) <= 1;
        }
    return {matching, drawn};
}

// Pixels where a channel of `a`, as `map` reads it (the pixel, the channel), and the same channel of `b`
// differ by more than `tolerance`.
template <class Map>
int differingPixels(const runtime::FrameImage& a, const runtime::FrameImage& b, int tolerance, Map map) {
    int count = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            for (int c = 0; c < 3; ++c)
                if (std::abs(map(a.pixel(x, y), c) - b.pixel(x, y)[c]) > tolerance) {
                    ++count;
                    break;
                }
    return count;
}

int differingPixels(const runtime::FrameImage& a, const runtime::FrameImage& b, int tolerance) {
    return differingPixels(a, b, tolerance, [](const uint8_t* p, int c) { return int(p[c]); });
}

TEST(FixedFunctionPasses, LightsAsAVertexShaderWouldLightThem) {
    auto renderer = loadEffect(kEffect, false, "fixed_function.fx");
    ASSERT_TRUE(renderer);
    // A red directional light from +x: the sides facing it are red, the others black, as the hand-written
    // world-space N.L draws them.
    const runtime::FrameImage key = frame(*renderer, "KeyOnly");
    ASSERT_TRUE(notConstant(key));
    const auto [lit, drawn] = drawnOfColour(key, 0, 0, 0);
    EXPECT_GT(lit, drawn / 10) << "the ground and the far side face away";
    int bright = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) bright += key.pixel(x, y)[0] > 200 && key.pixel(x, y)[1] < 2;
    EXPECT_GT(bright, 20) << "the side facing the light";
    EXPECT_LE(differingPixels(key, frame(*renderer, "KeyReference"), 2), kSize * kSize / 100);

    // Two lights: the point light above adds green to both; moving the key light moves the red.
    const runtime::FrameImage right = frame(*renderer, "FromRight");
    const runtime::FrameImage left = frame(*renderer, "FromLeft");
    ASSERT_TRUE(notConstant(right));
    EXPECT_GT(meanChannel(right, 1, true), 20);
    EXPECT_NEAR(meanChannel(right, 1, true), meanChannel(left, 1, true), 2);
    EXPECT_LT(meanChannel(right, 2, true), 2);
    int redder = 0, lessRed = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            redder += right.pixel(x, y)[0] > left.pixel(x, y)[0] + 50;
            lessRed += right.pixel(x, y)[0] + 50 < left.pixel(x, y)[0];
        }
    EXPECT_GT(redder, 20);
    EXPECT_GT(lessRed, 20);

    // The key light's colour follows its parameter, as a preshader did.
    ASSERT_TRUE(renderer->variable("KeyColor").setVector(glm::vec4(0, 0, 1, 1)));
    const runtime::FrameImage blue = frame(*renderer, "FromRight");
    int blueLit = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            if (!isBackground(blue, x, y)) {
                EXPECT_LE(blue.pixel(x, y)[0], 1);
            }
            blueLit += blue.pixel(x, y)[2] == right.pixel(x, y)[0] && right.pixel(x, y)[0] > 100;
        }
    EXPECT_GT(blueLit, 20);
}

TEST(FixedFunctionPasses, StageZeroModulatesTheTexture) {
    auto renderer = loadEffect(kEffect, false, "fixed_function.fx");
    ASSERT_TRUE(renderer);
    const runtime::FrameImage lit = frame(*renderer, "FromRight");
    const runtime::FrameImage textured = frame(*renderer, "Textured");
    ASSERT_TRUE(notConstant(textured));
    // Noise in [0, 1] times the lit colour: never brighter, darker on the whole.
    int brighter = 0, darker = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            if (isBackground(lit, x, y)) continue;
            for (int c = 0; c < 3; ++c) brighter += textured.pixel(x, y)[c] > lit.pixel(x, y)[c] + 2;
            darker += textured.pixel(x, y)[1] + 20 < lit.pixel(x, y)[1];
        }
    EXPECT_EQ(brighter, 0);
    EXPECT_GT(darker, kSize * kSize / 20);

    // Without lighting the vertex colour passes, white where the mesh has none.
    const auto [white, drawn] = drawnOfColour(frame(*renderer, "Unlit"), 255, 255, 255);
    EXPECT_GT(drawn, kSize * kSize / 10);
    EXPECT_EQ(white, drawn);
}

TEST(FixedFunctionPasses, FogTakesTheFarPixels) {
    auto renderer = loadEffect(kEffect, false, "fixed_function.fx");
    ASSERT_TRUE(renderer);
    // Everything beyond 0.01 units is fog: every drawn pixel is the fog colour, by vertex and by table fog.
    for (const char* technique : {"LinearFog", "TableFog"}) {
        const auto [blue, drawn] = drawnOfColour(frame(*renderer, technique), 0, 0, 255);
        EXPECT_GT(drawn, kSize * kSize / 10) << technique;
        EXPECT_EQ(blue, drawn) << technique;
    }
    // Linear table fog from 7 to 11 units: the far pixels are bluer than the near ones, and the unfogged
    // white is gone from the far end.
    const runtime::FrameImage far = frame(*renderer, "FogFar");
    ASSERT_TRUE(notConstant(far));
    double nearRed = 0, farRed = 0;
    int nearCount = 0, farCount = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            if (isBackground(far, x, y)) continue;
            (y < kSize / 2 ? farRed : nearRed) += far.pixel(x, y)[0];  // the ground recedes upwards
            ++(y < kSize / 2 ? farCount : nearCount);
        }
    ASSERT_GT(nearCount, 0);
    ASSERT_GT(farCount, 0);
    EXPECT_GT(nearRed / nearCount, farRed / farCount + 20);
}

TEST(FixedFunctionPasses, VertexShaderWithTheFixedFunctionPixelStage) {
    auto renderer = loadEffect(kEffect, false, "fixed_function.fx");
    ASSERT_TRUE(renderer);
    // Without texture-stage states the runtime's stand-in passes the diffuse: one colour.
    const auto [yellow, drawn] = drawnOfColour(frame(*renderer, "ShaderOnly"), 255, 255, 0);
    EXPECT_GT(drawn, kSize * kSize / 10);
    EXPECT_EQ(yellow, drawn);
    // Texture[0] set: stage 0 modulates the noise by the yellow.
    const runtime::FrameImage textured = frame(*renderer, "ShaderAndStages");
    ASSERT_TRUE(notConstant(textured));
    EXPECT_LT(drawnOfColour(textured, 255, 255, 0).first, drawn / 2);
    EXPECT_LT(meanChannel(textured, 2, true), 2);
}

TEST(FixedFunctionPasses, TransformsNotSetAreTheHosts) {
    auto renderer = loadEffect(kEffect, false, "fixed_function.fx");
    ASSERT_TRUE(renderer);
    const runtime::FrameImage host = frame(*renderer, "HostTransforms");
    ASSERT_TRUE(notConstant(host));
    EXPECT_EQ(differingPixels(host, frame(*renderer, "FromRight"), 1), 0);
}

TEST(FixedFunctionPasses, TextureStagesAloneDrawThroughTheHostsTransforms) {
    auto renderer = loadEffect(kEffect, false, "fixed_function.fx");
    ASSERT_TRUE(renderer);
    const runtime::FrameImage stages = frame(*renderer, "StagesOnly");
    ASSERT_TRUE(notConstant(stages));
    EXPECT_EQ(differingPixels(stages, frame(*renderer, "StagesAndTransforms"), 1), 0);
}

TEST(FixedFunctionPasses, PixelShaderAloneDrawsAFullScreenQuad) {
    auto renderer = loadEffect(kEffect, false, "fixed_function.fx");
    ASSERT_TRUE(renderer);
    for (const char* technique : {"ScreenPass", "ScreenPassUnset"}) {
        SCOPED_TRACE(technique);
        const runtime::FrameImage image = frame(*renderer, technique);
        ASSERT_TRUE(notConstant(image));
        // Every pixel: red the x coordinate, green the y coordinate from the top, blue half the white.
        int off = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const uint8_t* p = image.pixel(x, y);
                off += std::abs(p[0] - (x + 0.5) * 255.0 / kSize) > 2 ||
                       std::abs(p[1] - (y + 0.5) * 255.0 / kSize) > 2 || std::abs(p[2] - 128) > 1;
            }
        EXPECT_EQ(off, 0);
    }
}

// The DirectX SDK's post-processing passes and SpriteBatch's pixel shaders sample a texture their
// application bound: the scene it had rendered, or the sprite. The effect gives those samplers nothing;
// the host binds its picture of the scene there, the frame the host draws at `ScriptExternal=color`
// (technique HostScene), and the application's own texture where it gave one. A sampler with a texture
// of the effect's keeps it: a file's, a texture function's, or a read-write texture's view that a compute
// pass fills.
const char* kPostProcess = R"(
texture g_txSrcColor;
sampler2D g_samSrcColor = sampler_state { Texture = <g_txSrcColor>; MinFilter = Point; MagFilter = Point; };
sampler2D Sprite : register(s1);
texture Noise < string Procedural = "noise"; >;
sampler2D NoiseSampler = sampler_state { Texture = <Noise>; };
RWTexture2D<float4> Field < int Width = 8; int Height = 8; >;
Texture2D FieldView < string ViewOf = "Field"; >;
sampler2D FieldSampler = sampler_state { Texture = <FieldView>; MinFilter = Point; MagFilter = Point; };
float4 InvertPS(float2 uv : TEXCOORD0) : COLOR0 { return float4(1 - tex2D(g_samSrcColor, uv).rgb, 1); }
float4 SwizzlePS(float2 uv : TEXCOORD0) : COLOR0 { return float4(tex2D(Sprite, uv).bgr, 1); }
float4 NoisePS(float2 uv : TEXCOORD0) : COLOR0 { return tex2D(NoiseSampler, uv); }
[numthreads(8, 8, 1)]
void FillCS(uint3 id : SV_DispatchThreadID) { Field[id.xy] = float4(1, 0, 1, 1); }
float4 FieldPS(float2 uv : TEXCOORD0) : COLOR0 { return tex2D(FieldSampler, uv); }
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float4 SceneVS(float3 p : POSITION) : POSITION { return mul(float4(p, 1), WorldViewProjection); }
technique Invert { pass p { VertexShader = null; PixelShader = compile ps_2_0 InvertPS(); } }
technique Swizzle { pass p { PixelShader = compile ps_2_0 SwizzlePS(); } }
technique Noise { pass p { PixelShader = compile ps_2_0 NoisePS(); } }
technique Field < string Script = "Pass=Fill; Pass=Show;"; > {
    pass Fill < string Script = "Dispatch=1,1;"; > { ComputeShader = compile cs_5_0 FillCS(); }
    pass Show { PixelShader = compile ps_3_0 FieldPS(); }
}
technique Scene { pass p { VertexShader = compile vs_2_0 SceneVS(); PixelShader = compile ps_2_0 InvertPS(); } }
technique HostScene < string Script = "ScriptExternal=color;"; > { }
)";

// `source` parsed and compiled; null where either fails (the diagnostics say why).
std::unique_ptr<fx::CompiledEffect> compileSource(const std::string& source, const std::string& path,
                                                  fx::DiagnosticList& diagnostics) {
    auto parsed = fx::parseEffectSource(source, path, {}, diagnostics);
    return parsed ? fx::compileEffect(parsed, fx::CompileOptions{}, diagnostics) : nullptr;
}

TEST(FixedFunctionPasses, AFullScreenPassSamplesTheHostsPictureWhereTheEffectGivesNoTexture) {
    fx::DiagnosticList diagnostics;
    const auto compiled = compileSource(kPostProcess, "post_process.fx", diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    // The samplers of the technique's last pass that the compiler marks; -1 where it has no such pass.
    const auto readsHostPicture = [&](const std::string& technique) {
        const fx::CompiledTechnique* t = compiled->findTechnique(technique);
        if (!t || t->passes.empty() || t->passes.back().fragment.samplers.empty()) {
            ADD_FAILURE() << technique << ": no pass that samples";
            return -1;
        }
        int marked = 0;
        for (const fx::SamplerBinding& binding : t->passes.back().fragment.samplers)
            marked += binding.read && binding.hostPicture;
        return marked;
    };
    EXPECT_EQ(readsHostPicture("Invert"), 1);   // a texture without contents
    EXPECT_EQ(readsHostPicture("Swizzle"), 1);  // a bare sampler
    EXPECT_EQ(readsHostPicture("Noise"), 0);    // the effect's own texture
    EXPECT_EQ(readsHostPicture("Field"), 0);    // a view of what a compute pass writes
    EXPECT_EQ(readsHostPicture("Scene"), 0);    // not a full-screen pass
    // A note at each such sampler says so.
    EXPECT_EQ(countDiagnostics(diagnostics, fx::DiagId::SamplerReadsHostPicture), 2) << diagnostics.str();

    auto renderer = loadEffect(kPostProcess, false, "post_process.fx");
    ASSERT_TRUE(renderer);
    const runtime::FrameImage host = frame(*renderer, "HostScene");
    ASSERT_TRUE(notConstant(host));
    // The teapot scene over the host background (64, 72, 96), which covers part of the frame.
    EXPECT_GT(countPixelsOfColour(host, kSize, kSize, 64, 72, 96), kSize * kSize / 4);
    EXPECT_LT(countPixelsOfColour(host, kSize, kSize, 64, 72, 96), kSize * kSize * 9 / 10);
    const auto inverse = [](const uint8_t* p, int c) { return 255 - p[c]; };
    const auto swizzle = [](const uint8_t* p, int c) { return int(p[2 - c]); };
    EXPECT_EQ(differingPixels(frame(*renderer, "Invert"), host, 1, inverse), 0);
    EXPECT_EQ(differingPixels(frame(*renderer, "Swizzle"), host, 1, swizzle), 0);
    // The effect's own textures: noise, and the compute pass's magenta.
    EXPECT_GT(differingPixels(frame(*renderer, "Noise"), host, 1), kSize * kSize / 2);
    EXPECT_EQ(countPixelsOfColour(frame(*renderer, "Field"), kSize, kSize, 255, 0, 255), kSize * kSize);
    // Leave-out draws the same frame as a frame drawn in full.
    {
        fx::DiagnosticList drawn;
        runtime::FrameOptions options;
        options.width = options.height = kSize;
        options.technique = "Invert";
        options.leaveOut = false;
        ASSERT_TRUE(renderer->render(teapot(), options, drawn)) << drawn.str();
        EXPECT_EQ(differingPixels(renderer->readFrame(), host, 1, inverse), 0);
    }

    // The application's texture wins, a GL texture of its own given to the sampler or texels given to the
    // texture, until it takes it back.
    const GLuint blue = applicationTexel({0, 0, 255, 255});
    ASSERT_TRUE(renderer->variable("Sprite").setTexture(blue));
    EXPECT_EQ(countPixelsOfColour(frame(*renderer, "Swizzle"), kSize, kSize, 255, 0, 0), kSize * kSize);
    ASSERT_TRUE(renderer->variable("Sprite").setTexture(0));
    EXPECT_EQ(differingPixels(frame(*renderer, "Swizzle"), host, 1, swizzle), 0);
    gl::DeleteTextures(1, &blue);
    runtime::TextureData red;
    red.width = red.height = 1;
    red.rgba = {1.0f, 0.0f, 0.0f, 1.0f};
    ASSERT_TRUE(renderer->setTexture(*renderer->findParameter("g_txSrcColor"), red, diagnostics))
        << diagnostics.str();
    EXPECT_EQ(countPixelsOfColour(frame(*renderer, "Invert"), kSize, kSize, 0, 255, 255), kSize * kSize);
}

// A D3D10 post-processing pass has a vertex shader of its own that hands the application's clip-space
// quad to the rasterizer unchanged (the DirectX SDK's `QuadVS`). The compiler reads such a shader's body:
// the pass draws the runtime's quad, and its samplers without a texture read the host's picture, as a D3D9
// pass with a pixel shader alone does. Any other vertex shader, one feeding a geometry shader, or one in a
// pass whose own script says what it draws, draws as it did.
const char* kD3D10PostProcess = R"(
Texture2D g_txScene;
SamplerState PointSampler { Filter = MIN_MAG_MIP_POINT; AddressU = Clamp; AddressV = Clamp; };
float4x4 g_mWorldViewProj;
struct QuadVS_Input { float4 Pos : POSITION; float2 Tex : TEXCOORD0; };
struct QuadVS_Output { float4 Pos : SV_POSITION; float2 Tex : TEXCOORD0; };
QuadVS_Output QuadVS(QuadVS_Input Input) {
    QuadVS_Output Output;
    Output.Pos = Input.Pos;
    Output.Tex = Input.Tex;
    return Output;
}
struct FreeNamed { float3 Pos : POS; float2 Tex : TEXTURE0; };
void WidenVS(FreeNamed In, out float4 oPos : SV_Position, out float2 oTex : TEXCOORD0) {
    oTex = In.Tex;
    oPos = float4(In.Pos.xy, 0, 1);
}
struct Float3Input { float3 Pos : POSITION; float2 Tex : TEXCOORD0; };
QuadVS_Output ComponentsVS(Float3Input I) {
    QuadVS_Output O;
    O.Pos.x = I.Pos.x;
    O.Pos.y = I.Pos.y;
    O.Pos.z = I.Pos.z;
    O.Pos.w = 1.0f;
    O.Tex = I.Tex;
    return O;
}
QuadVS_Output InPlaceVS(QuadVS_Input Input) {
    Input.Pos = mul(Input.Pos, g_mWorldViewProj);
    QuadVS_Output Output;
    Output.Pos = Input.Pos;
    Output.Tex = Input.Tex;
    return Output;
}
QuadVS_Output HalveVS(Float3Input I) {
    QuadVS_Output O;
    O.Pos = float4(I.Pos.xy, 0, 2);
    O.Tex = I.Tex;
    return O;
}
QuadVS_Output FlattenVS(QuadVS_Input Input) {
    QuadVS_Output Output;
    Output.Pos = Input.Pos;
    Output.Pos.y = 0;
    Output.Tex = Input.Tex;
    return Output;
}
QuadVS_Output SceneVS(QuadVS_Input Input) {
    QuadVS_Output Output;
    Output.Pos = mul(Input.Pos, g_mWorldViewProj);
    Output.Tex = Input.Tex;
    return Output;
}
[maxvertexcount(3)]
void SceneGS(triangle QuadVS_Output In[3], inout TriangleStream<QuadVS_Output> Out) {
    for (int i = 0; i < 3; ++i) {
        QuadVS_Output v = In[i];
        v.Pos = mul(In[i].Pos, g_mWorldViewProj);
        Out.Append(v);
    }
}
float4 InvertPS(QuadVS_Output Input) : SV_TARGET {
    return float4(1 - g_txScene.Sample(PointSampler, Input.Tex).rgb, 1);
}
#define PASS(vs, gs) pass p0 { SetVertexShader(CompileShader(vs_4_0, vs())); SetGeometryShader(gs); \
    SetPixelShader(CompileShader(ps_4_0, InvertPS())); }
technique10 Invert { PASS(QuadVS, NULL) }
technique10 Widened { PASS(WidenVS, NULL) }
technique10 Components { PASS(ComponentsVS, NULL) }
technique10 Flattened { PASS(FlattenVS, NULL) }
technique10 InPlace { PASS(InPlaceVS, NULL) }
technique10 Halved { PASS(HalveVS, NULL) }
technique10 Scripted < string Script = "Pass=p0;"; > {
    pass p0 < string Script = "Draw=Buffer;"; > { SetVertexShader(CompileShader(vs_4_0, QuadVS()));
        SetGeometryShader(NULL); SetPixelShader(CompileShader(ps_4_0, InvertPS())); }
}
technique10 Scene { PASS(SceneVS, NULL) }
technique10 Expanded { PASS(QuadVS, CompileShader(gs_4_0, SceneGS())) }
technique HostScene < string Script = "ScriptExternal=color;"; > { }
)";

TEST(FixedFunctionPasses, AD3D10PassThroughVertexShaderDrawsTheScreenQuadOverTheHostsPicture) {
    fx::DiagnosticList diagnostics;
    const auto compiled = compileSource(kD3D10PostProcess, "quad_vs.fx", diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    // Whether the technique's pass draws the quad (Draw=Buffer), and whether its sampler reads the picture.
    const auto quadAndPicture = [&](const std::string& technique) {
        const fx::CompiledTechnique* t = compiled->findTechnique(technique);
        if (!t || t->passes.size() != 1) {
            ADD_FAILURE() << technique << ": not one pass";
            return std::pair(false, false);
        }
        const fx::CompiledPass& pass = t->passes.front();
        const bool buffer = pass.script.size() == 1 &&
                            pass.script.front().kind == fx::ScriptCommand::Kind::Draw &&
                            pass.script.front().draw == fx::ScriptCommand::DrawWhat::Buffer;
        const bool picture = std::any_of(pass.fragment.samplers.begin(), pass.fragment.samplers.end(),
                                         [](const fx::SamplerBinding& b) { return b.read && b.hostPicture; });
        return std::pair(buffer, picture);
    };
    const std::pair quad(true, true), meshes(false, false);
    EXPECT_EQ(quadAndPicture("Invert"), quad);       // the SDK's QuadVS
    EXPECT_EQ(quadAndPicture("Widened"), quad);      // free names, out parameters, xy completed by 0 and 1
    EXPECT_EQ(quadAndPicture("Components"), quad);   // one component at a time (HDAO's)
    EXPECT_EQ(quadAndPicture("Flattened"), meshes);  // a component written after the copy
    EXPECT_EQ(quadAndPicture("InPlace"), meshes);    // the input transformed before the copy
    EXPECT_EQ(quadAndPicture("Halved"), meshes);     // w = 2
    EXPECT_EQ(quadAndPicture("Scene"), meshes);      // transformed
    EXPECT_EQ(quadAndPicture("Expanded"), meshes);   // a geometry shader places the vertices
    // Its own script draws the quad; the sampler is the effect's (FX Composer's passes render the scene into
    // their textures).
    EXPECT_EQ(quadAndPicture("Scripted"), std::pair(true, false));
    // The note names the pair's texture, at its declaration.
    EXPECT_EQ(countDiagnostics(diagnostics, fx::DiagId::TextureReadsHostPicture), 1) << diagnostics.str();
    EXPECT_NE(
        diagnostics.str().find("quad_vs.fx:2:11: note: texture 'g_txScene', sampled through 'PointSampler'"),
        std::string::npos)
        << diagnostics.str();

    auto renderer = loadEffect(kD3D10PostProcess, false, "quad_vs.fx");
    ASSERT_TRUE(renderer);
    const runtime::FrameImage host = frame(*renderer, "HostScene");
    ASSERT_TRUE(notConstant(host));
    const auto inverse = [](const uint8_t* p, int c) { return 255 - p[c]; };
    EXPECT_EQ(differingPixels(frame(*renderer, "Invert"), host, 1, inverse), 0);
    EXPECT_EQ(differingPixels(frame(*renderer, "Widened"), host, 1, inverse), 0);
    EXPECT_EQ(differingPixels(frame(*renderer, "Components"), host, 1, inverse), 0);
    // The effect's texture without contents, white: black where the quad covers the frame.
    EXPECT_EQ(countPixelsOfColour(frame(*renderer, "Scripted"), kSize, kSize, 0, 0, 0), kSize * kSize);
    // The scene's meshes through the transforming shader, the effect's white texture inverted: black where
    // they stand, the host background around them.
    const runtime::FrameImage scene = frame(*renderer, "Scene");
    EXPECT_GT(countPixelsOfColour(scene, kSize, kSize, 0, 0, 0), kSize * kSize / 10);
    EXPECT_LT(countPixelsOfColour(scene, kSize, kSize, 0, 0, 0), kSize * kSize * 9 / 10);
    EXPECT_GT(countPixelsOfColour(scene, kSize, kSize, 64, 72, 96), kSize * kSize / 10);
}

// Compiles `passBody` as the one pass of an effect; returns the diagnostics.
fx::DiagnosticList compileDiagnostics(const std::string& passBody) {
    fx::DiagnosticList diagnostics;
    compileSource("float4x4 World;\ntexture T;\nint Op = 4;\ntechnique t { pass p {\n" + passBody + "\n} }\n",
                  "fixed_function_errors.fx", diagnostics);
    return diagnostics;
}

TEST(FixedFunctionPasses, WhatIsNotGeneratedIsALocatedError) {
    const struct {
        const char* pass;
        fx::DiagId id;
        int column;
        const char* message;
    } cases[] = {
        {"  WorldTransform[0] = <World>; ColorOp[0] = BumpEnvMap;", fx::DiagId::FixedFunctionStageOperation,
         32,
         "the fixed-function pipeline generated for this pass cannot run the operation 22 of texture stage "
         "0"},
        {"  WorldTransform[0] = <World>; ColorOp[0] = <Op>;", fx::DiagId::FixedFunctionStateNotConstant, 45,
         "invalid value for state 'ColorOp': must be a constant"},
        {"  Texture[0] = <T>; ColorOp[1] = Add; ColorOp[2] = Modulate;",
         fx::DiagId::FixedFunctionTextureStageBeyondSecond, 39,
         "the fixed-function pipeline generated for this pass cannot run texture stage 2"},
        {"  WorldTransform[1] = <World>;", fx::DiagId::FixedFunctionVertexBlending, 3,
         "the fixed-function pipeline generated for this pass cannot run WorldTransform[1]"},
        {"  LightEnable[8] = true;", fx::DiagId::FixedFunctionLightBeyondEighth, 3,
         "the fixed-function pipeline generated for this pass cannot run light 8"},
    };
    for (const auto& c : cases) {
        const fx::DiagnosticList diagnostics = compileDiagnostics(c.pass);
        const std::string text = diagnostics.str();
        ASSERT_EQ(diagnostics.errorCount(), 1u) << c.pass << "\n" << text;
        const fx::Diagnostic& d = diagnostics.items().front();
        EXPECT_EQ(d.id, c.id) << text;
        EXPECT_EQ(d.loc.file, "fixed_function_errors.fx") << text;
        EXPECT_EQ(d.loc.line, 5) << text;
        EXPECT_EQ(d.loc.column, c.column) << text;
        EXPECT_EQ(d.message.rfind(c.message, 0), 0u) << text;
    }
}

}  // namespace
}  // namespace shadowfx::test::test_fixed_function_passes
