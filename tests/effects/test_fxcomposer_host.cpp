// FX Composer and DirectX SDK effects run as their host ran them: the host clears the frame to its
// background before a material effect that never clears, draws the scene where a post effect's script
// says ScriptExternal=color, picks the first technique a selector names that exists, binds
// `Object = "PointLight0"` to the scene's light0, and evaluates user functions in compile arguments on the
// host. Each effect here is written in one of those styles (tests/data/fxcomposer/); a blank frame fails
// every test.
#include "../../runtime/render/src/HostScene.h"
#include "EffectHarness.h"
#include <runtime/BuiltinScenes.h>

#include <array>
#include <cmath>
#include <filesystem>

namespace shadowfx::test::test_fxcomposer_host {
namespace {

constexpr int kWidth = 96;
constexpr int kHeight = 72;

bool isBackground(const uint8_t* p) {
    for (int c = 0; c < 3; ++c)
        if (std::abs(p[c] - std::lround(runtime::kHostBackground[c] * 255.0f)) > 1) return false;
    return true;
}

// The share of pixels that are not the host background.
double coverage(const runtime::FrameImage& frame) {
    size_t object = 0;
    for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x) object += !isBackground(frame.pixel(x, y));
    return static_cast<double>(object) / (frame.width * frame.height);
}

// A material effect (ScriptClass "object", no Clear anywhere, ZFunc LessEqual) draws the lit object on
// the host's background. Without the host clear the depth buffer rejects every fragment or the frame keeps
// whatever it held.
TEST(FxComposerHost, MaterialEffectThatNeverClearsDrawsTheLitObjectOnTheHostBackground) {
    LoadedEffect loaded = loadEffectWithDiagnostics("tests/data/fxcomposer/material_phong.fx");
    ASSERT_TRUE(loaded.renderer);
    // Technique?Simple:Simple10:Textured:Textured10 — Simple10 and Textured10 do not exist: warnings only.
    EXPECT_EQ(countDiagnostics(loaded.diagnostics, fx::DiagId::ScriptUnknownTechnique), 2)
        << loaded.diagnostics.str();
    EXPECT_EQ(countDiagnostics(loaded.diagnostics, fx::DiagId::TextureFileNotFound), 1)
        << loaded.diagnostics.str();
    const runtime::Scene scene = *runtime::makeBuiltinScene("teapot");
    fx::DiagnosticList diagnostics;
    runtime::FrameOptions options;
    options.width = kWidth;
    options.height = kHeight;
    runtime::FrameStats stats;
    ASSERT_TRUE(loaded.renderer->render(scene, options, diagnostics, &stats)) << diagnostics.str();
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.str();
    ASSERT_EQ(stats.passes.size(), 1u);
    const runtime::FrameImage frame = loaded.renderer->readFrame();
    ASSERT_TRUE(notConstant(frame));
    EXPECT_TRUE(isBackground(frame.pixel(0, 0)));
    EXPECT_TRUE(isBackground(frame.pixel(kWidth - 1, 0)));  // the sky above the ground plane
    const double covered = coverage(frame);
    EXPECT_GT(covered, 0.05);
    EXPECT_LT(covered, 0.9);
    // Lit: the brightest object pixel is far above the ambient term (0.07), so the lamp (bound through
    // "PointLight0" to the scene's light0) reaches it.
    float brightest = 0.0f;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            if (!isBackground(frame.pixel(x, y)))
                brightest = std::max(brightest, luminance(frame.pixel(x, y)));
    EXPECT_GT(brightest, 0.5f);
}

// The lamp parameter names "PointLight0" (and its colour "Pointlight0"): moving the scene's light0 must
// change the picture, which it cannot if the names do not bind.
TEST(FxComposerHost, LightNamedPointLight0FollowsTheScenesLight0) {
    LoadedEffect loaded = loadEffectWithDiagnostics("tests/data/fxcomposer/material_phong.fx");
    ASSERT_TRUE(loaded.renderer);
    runtime::Scene scene = *runtime::makeBuiltinScene("teapot");
    ASSERT_FALSE(scene.lights.empty());
    ASSERT_TRUE(scene.findLight("PointLight0"));
    ASSERT_TRUE(scene.findLight("SPOTLIGHT0"));
    ASSERT_TRUE(scene.findLight("DirectionalLight0"));
    EXPECT_EQ(scene.findLight("Light7"), nullptr);
    // "lightN" that no light is named is the N-th light, whatever the scene named it.
    scene.lights[0].name = "sun";
    EXPECT_EQ(scene.findLight("light0"), &scene.lights[0]);
    EXPECT_EQ(scene.findLight("PointLight0"), &scene.lights[0]);
    EXPECT_EQ(scene.findLight("light1"), nullptr);
    EXPECT_EQ(scene.findLight("light00x"), nullptr);
    // A scene that names its lights light1 and light2 means those names: light0 is none of them.
    runtime::Scene fromOne = scene;
    fromOne.lights[0].name = "light1";
    fromOne.lights.push_back(scene.lights[0]);
    fromOne.lights[1].name = "light2";
    EXPECT_EQ(fromOne.findLight("light0"), nullptr);
    EXPECT_EQ(fromOne.findLight("light1"), &fromOne.lights[0]);
    EXPECT_EQ(fromOne.findLight("light2"), &fromOne.lights[1]);
    scene.lights[0].name = "light0";
    ASSERT_TRUE(render(*loaded.renderer, scene, kWidth, kHeight));
    const runtime::FrameImage first = loaded.renderer->readFrame();
    scene.lights[0].position = -scene.lights[0].position;
    scene.lights[0].direction = -scene.lights[0].direction;
    ASSERT_TRUE(render(*loaded.renderer, scene, kWidth, kHeight));
    const runtime::FrameImage second = loaded.renderer->readFrame();
    ASSERT_TRUE(notConstant(second));
    int differing = 0;
    for (size_t i = 0; i < first.rgba.size(); i += 4)
        differing += std::abs(first.rgba[i] - second.rgba[i]) > 8;
    EXPECT_GT(differing, kWidth * kHeight / 50);
}

// A post effect built on ScriptExternal=color: the host draws the scene into SceneTexture (declared with
// ViewPortRatio only), and the effect's pass inverts it into the frame. With Amount 0 the frame is the
// host's scene itself; with Amount 1 every pixel is its inverse.
TEST(FxComposerHost, PostEffectProcessesTheSceneTheHostDrawsAtScriptExternal) {
    LoadedEffect loaded = loadEffectWithDiagnostics("tests/data/fxcomposer/post_invert.fx");
    ASSERT_TRUE(loaded.renderer);
    const runtime::Scene scene = *runtime::makeBuiltinScene("boxes");
    const size_t amount = *loaded.renderer->findParameter("Amount");

    loaded.renderer->setParameter(amount, fx::Value::scalar(0.0f));
    ASSERT_TRUE(render(*loaded.renderer, scene, kWidth, kHeight));
    const runtime::FrameImage plain = loaded.renderer->readFrame();
    ASSERT_TRUE(notConstant(plain));  // the scene, not the empty target

    loaded.renderer->setParameter(amount, fx::Value::scalar(1.0f));
    ASSERT_TRUE(render(*loaded.renderer, scene, kWidth, kHeight));
    const runtime::FrameImage inverted = loaded.renderer->readFrame();
    ASSERT_TRUE(notConstant(inverted));
    int mismatches = 0;
    for (size_t i = 0; i < plain.rgba.size(); i += 4)
        for (int c = 0; c < 3; ++c)
            mismatches += std::abs(255 - plain.rgba[i + c] - inverted.rgba[i + c]) > 2;
    EXPECT_EQ(mismatches, 0);
    // The script's own clear (ClearColor black) shows where the scene has no object: inverted to white.
    EXPECT_EQ(inverted.pixel(0, 0)[0], 255);
}

// FX Composer's "preprocess" effects: a technique without passes whose script clears colour and depth to
// the effect's values, then lets the host draw the scene. The depth clear looked for the draw after it in
// the frame's plan, found the host's, and read it as a draw of a pass the technique does not have.
TEST(FxComposerHost, TechniqueWithoutPassesClearsToItsColourUnderTheHostsScene) {
    LoadedEffect loaded = loadEffectWithDiagnostics("tests/data/fxcomposer/preprocess_clear.fx");
    ASSERT_TRUE(loaded.renderer);
    ASSERT_EQ(loaded.renderer->effect().techniques.size(), 1u);
    ASSERT_TRUE(loaded.renderer->effect().techniques[0].passes.empty());
    const runtime::Scene scene = *runtime::makeBuiltinScene("teapot");
    ASSERT_TRUE(render(*loaded.renderer, scene, kWidth, kHeight));
    const runtime::FrameImage frame = loaded.renderer->readFrame();
    ASSERT_TRUE(notConstant(frame));                  // the host's scene over the clear
    const uint8_t* sky = frame.pixel(kWidth - 1, 0);  // above the ground plane: the effect's Backdrop
    EXPECT_EQ(sky[0], 0);
    EXPECT_NEAR(sky[1], 128, 1);
    EXPECT_EQ(sky[2], 255);
    const double covered = coverage(frame);  // the host's background nowhere, the scene drawn on the clear
    EXPECT_GT(covered, 0.99);
}

// The host's material lights by the mesh's normals: a plane facing a directional light is one flat colour
// (with positions read as normals, as a lost stream binding once did, its shade would follow its pixels'
// positions), and turning the light away from the plane darkens it.
TEST(FxComposerHost, HostSceneShadesByTheMeshsNormals) {
    LoadedEffect loaded = loadEffectWithDiagnostics("tests/data/fxcomposer/post_invert.fx");
    ASSERT_TRUE(loaded.renderer);
    loaded.renderer->setParameter(*loaded.renderer->findParameter("Amount"), fx::Value::scalar(0.0f));
    runtime::Scene scene;
    runtime::SceneObject plane;
    plane.mesh = std::make_shared<runtime::Mesh>(runtime::makePlane(40.0f, 40.0f, 8));
    plane.color = glm::vec3(1.0f);
    scene.objects.push_back(plane);
    scene.camera.position = {0.0f, 6.0f, -6.0f};
    scene.lights.push_back(runtime::Light{});  // straight down onto the plane

    // The centre half of the frame, all on the plane; the brightest and darkest red there.
    const auto redRange = [&](const runtime::FrameImage& frame) {
        int low = 255, high = 0;
        for (int y = kHeight / 4; y < 3 * kHeight / 4; ++y)
            for (int x = kWidth / 4; x < 3 * kWidth / 4; ++x) {
                low = std::min<int>(low, frame.pixel(x, y)[0]);
                high = std::max<int>(high, frame.pixel(x, y)[0]);
            }
        return std::pair{low, high};
    };
    ASSERT_TRUE(render(*loaded.renderer, scene, kWidth, kHeight));
    const auto [low, high] = redRange(loaded.renderer->readFrame());
    EXPECT_LE(high - low, 1);
    EXPECT_GE(low, 250);  // lit head-on: 0.2 + 0.8 of white

    scene.lights.front().direction = glm::normalize(glm::vec3(1.0f, -0.25f, 0.0f));
    ASSERT_TRUE(render(*loaded.renderer, scene, kWidth, kHeight));
    const auto [grazingLow, grazingHigh] = redRange(loaded.renderer->readFrame());
    EXPECT_LE(grazingHigh - grazingLow, 1);
    EXPECT_LT(grazingHigh, 150);  // 0.2 + 0.8 * 0.24 of white
}

// A DirectX SDK style effect: D3DCOLOR ints above INT_MAX, arrays sized by static const ints, skinning
// and point-size inputs, a centroid varying, a matrix varying, vs_1_1/vs_2_0 in a shader array, and a
// compile argument that calls the effect's own function (evaluated on the host at every frame).
TEST(FxComposerHost, DirectXSdkEffectRendersAndEvaluatesItsUserFunctionOnTheHost) {
    LoadedEffect loaded = loadEffectWithDiagnostics("tests/data/fxcomposer/sdk_skinned.fx");
    ASSERT_TRUE(loaded.renderer);
    runtime::EffectRenderer& renderer = *loaded.renderer;
    EXPECT_EQ(renderer.parameter(*renderer.findParameter("BackgroundColor")).asInt(),
              static_cast<int32_t>(0xff202080u));
    EXPECT_EQ(renderer.parameter(*renderer.findParameter("Mask")).asInt(), -1);
    const runtime::Scene scene = *runtime::makeBuiltinScene("boxes");
    auto meanObjectLuminance = [&](float brightness) {
        renderer.setParameter(*renderer.findParameter("Brightness"), fx::Value::scalar(brightness));
        EXPECT_TRUE(render(renderer, scene, kWidth, kHeight));
        const runtime::FrameImage frame = renderer.readFrame();
        EXPECT_TRUE(notConstant(frame));
        double sum = 0;
        int n = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x)
                if (!isBackground(frame.pixel(x, y))) sum += luminance(frame.pixel(x, y)), ++n;
        EXPECT_GT(n, kWidth * kHeight / 20);
        return n ? sum / n : 0.0;
    };
    // gain(b, 1.5) = saturate(1.5 b + 0.25): 0.4 at b = 0.1, 1 at b = 0.9.
    const double dim = meanObjectLuminance(0.1f);
    const double bright = meanObjectLuminance(0.9f);
    EXPECT_GT(bright, dim * 1.5);
}

// A vertex shader with `PixelShader = NULL` (the DirectX SDK's vs_1_1 effects) ran D3D9's fixed-function
// pixel stage: the object shows its interpolated COLOR0.
TEST(FxComposerHost, NullPixelShaderDrawsTheVertexColour) {
    auto renderer = loadEffect(R"(float4x4 Wvp : WorldViewProjection;
struct V { float4 Pos : POSITION; float4 Diffuse : COLOR0; };
V VS(float4 p : POSITION) { V o; o.Pos = mul(p, Wvp); o.Diffuse = float4(1, 0, 0, 1); return o; }
technique t { pass p { VertexShader = compile vs_1_1 VS(); PixelShader = null; } }
)",
                               false);
    ASSERT_TRUE(renderer);
    const runtime::Scene scene = *runtime::makeBuiltinScene("teapot");
    ASSERT_TRUE(render(*renderer, scene, kWidth, kHeight));
    const runtime::FrameImage frame = renderer->readFrame();
    ASSERT_TRUE(notConstant(frame));
    EXPECT_TRUE(isBackground(frame.pixel(0, 0)));
    int red = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const uint8_t* p = frame.pixel(x, y);
            red += p[0] == 255 && p[1] == 0 && p[2] == 0;
        }
    EXPECT_GT(red, kWidth * kHeight / 20);
}

// FXCOMPOSER_RESETPULSE is true in the first frame after the effect is created and after reset(), false
// in the others: a script's LoopByCount reads it before the frame's first pass (the clear pass runs only
// then) and a shader reads it as a uniform (the left half green in a reset frame, blue in the others). The
// clear pass draws ClearTint, changed to yellow after the first frame: the right half stays the red of the
// last reset frame (a scene effect's frame is kept), yellow after reset().
TEST(FxComposerHost, ResetPulseIsTrueInTheFirstFrameAndAfterReset) {
    auto renderer = loadEffect(R"(bool bReset : FXCOMPOSER_RESETPULSE;
float4 ClearTint = {1, 0, 0, 1};
float Script : STANDARDSGLOBAL < string ScriptClass = "scene"; string ScriptOrder = "standard";
    string ScriptOutput = "color"; string Script = "Technique=Main;"; > = 0.8;
struct Q { float4 Pos : POSITION; float2 UV : TEXCOORD0; };
Q QuadVS(float3 p : POSITION, float3 uv : TEXCOORD0) { Q o; o.Pos = float4(p, 1); o.UV = uv.xy; return o; }
float4 ClearPS(Q i) : COLOR { return ClearTint; }
float4 MarkPS(Q i) : COLOR {
    clip(0.5 - i.UV.x);
    return bReset ? float4(0, 1, 0, 1) : float4(0, 0, 1, 1);
}
technique Main < string Script = "RenderColorTarget0=; RenderDepthStencilTarget=;"
    "LoopByCount=bReset; Pass=clear; LoopEnd=; Pass=mark;"; > {
    pass clear < string Script = "Draw=Buffer;"; > {
        VertexShader = compile vs_3_0 QuadVS(); PixelShader = compile ps_3_0 ClearPS(); ZEnable = false; }
    pass mark < string Script = "Draw=Buffer;"; > {
        VertexShader = compile vs_3_0 QuadVS(); PixelShader = compile ps_3_0 MarkPS(); ZEnable = false; }
}
)",
                               false);
    ASSERT_TRUE(renderer);
    const runtime::Scene scene = *runtime::makeBuiltinScene("teapot");
    const auto expectFrame = [&](bool resetFrame, std::array<int, 3> right) {
        ASSERT_TRUE(render(*renderer, scene, kWidth, kHeight));
        const runtime::FrameImage frame = renderer->readFrame();
        const uint8_t* left = frame.pixel(kWidth / 4, kHeight / 2);
        const uint8_t* rightPixel = frame.pixel(3 * kWidth / 4, kHeight / 2);
        EXPECT_EQ(left[0], 0);
        EXPECT_EQ(left[1], resetFrame ? 255 : 0);
        EXPECT_EQ(left[2], resetFrame ? 0 : 255);
        for (int c = 0; c < 3; ++c) EXPECT_EQ(rightPixel[c], right[c]) << "channel " << c;
    };
    constexpr std::array<int, 3> kRed{255, 0, 0}, kYellow{255, 255, 0};
    expectFrame(true, kRed);
    renderer->setParameter(*renderer->findParameter("ClearTint"), fx::Value::vector({1, 1, 0, 1}));
    expectFrame(false, kRed);
    expectFrame(false, kRed);
    renderer->reset();
    // A frame that cannot run (no such technique) leaves the reset to the next frame that does.
    fx::DiagnosticList refused;
    runtime::FrameOptions unknownTechnique;
    unknownTechnique.width = kWidth;
    unknownTechnique.height = kHeight;
    unknownTechnique.technique = "NoSuchTechnique";
    EXPECT_FALSE(renderer->render(scene, unknownTechnique, refused));
    expectFrame(true, kYellow);
    expectFrame(false, kYellow);
}

// NVIDIA's paint_brush.fx in miniature: the reset pulse, the brush's place, the effect's STANDARDSGLOBAL
// annotations and its techniques after the shaders they share: a full-screen quad, a white canvas, a green
// one over the left half, and a blue stroke around BrushPos.
std::string paintingEffect(const std::string& brushPos, const std::string& standardsGlobal,
                           const std::string& techniques) {
    return "bool bReset : FXCOMPOSER_RESETPULSE;\nfloat2 BrushPos = {" + brushPos +
           "};\nfloat Script : STANDARDSGLOBAL < " + standardsGlobal + R"( > = 0.8;
struct Q { float4 Pos : POSITION; float2 UV : TEXCOORD0; };
Q QuadVS(float3 p : POSITION, float3 uv : TEXCOORD0) { Q o; o.Pos = float4(p, 1); o.UV = uv.xy; return o; }
float4 CanvasPS(Q i) : COLOR { return float4(1, 1, 1, 1); }
float4 LeftCanvasPS(Q i) : COLOR { clip(0.5 - i.UV.x); return float4(0, 1, 0, 1); }
float4 SplatPS(Q i) : COLOR { return float4(0, 0, 1, length(i.UV - BrushPos) < 0.15 ? 1 : 0); }
)" + techniques;
}

// A painting technique: its canvas pass (pixel shader `canvas`) on the reset pulse, then the stroke.
std::string paintingTechnique(const std::string& name, const std::string& canvasPass,
                              const std::string& canvas) {
    return "technique " + name + R"( < string Script = "RenderColorTarget0=; RenderDepthStencilTarget=;"
    "LoopByCount=bReset; Pass=)" +
           canvasPass + R"(; LoopEnd=; Pass=splat;"; > {
    pass )" +
           canvasPass +
           R"( < string Script = "Draw=Buffer;"; > {
        VertexShader = compile vs_3_0 QuadVS(); PixelShader = compile ps_3_0 )" +
           canvas + R"((); ZEnable = false; }
    pass splat < string Script = "Draw=Buffer;"; > {
        VertexShader = compile vs_3_0 QuadVS(); PixelShader = compile ps_3_0 SplatPS(); ZEnable = false;
        AlphaBlendEnable = true; SrcBlend = SrcAlpha; DestBlend = InvSrcAlpha; }
}
)";
}

// A scene effect that paints into the frame over many frames and clears it only on a reset (NVIDIA's
// paint_brush.fx): the host clears nothing before its frames after the first, so a stroke painted in one
// frame is still there in the next, on the canvas the reset drew, as FX Composer kept the frame for it. A
// frame of a new size starts on the host's background again; a material effect's frames always do.
TEST(FxComposerHost, SceneEffectKeepsWhatItPaintedInTheFrameUntilAResetOrANewSize) {
    const auto paintEffect = [](const std::string& scriptClass) {
        return paintingEffect("0.25, 0.5",
                              "string ScriptClass = \"" + scriptClass +
                                  "\"; string ScriptOrder = \"standard\"; string ScriptOutput = \"color\"; "
                                  "string Script = \"Technique=Main;\";",
                              paintingTechnique("Main", "revert", "CanvasPS"));
    };
    const runtime::Scene scene = *runtime::makeBuiltinScene("teapot");
    const auto isWhite = [](const uint8_t* p) { return p[0] == 255 && p[1] == 255 && p[2] == 255; };
    const auto isPaint = [](const uint8_t* p) { return p[0] == 0 && p[1] == 0 && p[2] == 255; };
    // The frame's corner (canvas), the first stroke (left) and the second (right), at a width x height frame.
    struct Frame {
        const uint8_t *corner, *left, *right;
    };
    const auto paintFrame = [&](runtime::EffectRenderer& renderer, float brushX, int width, int height,
                                runtime::FrameImage& image) -> Frame {
        renderer.setParameter(*renderer.findParameter("BrushPos"), fx::Value::vector({brushX, 0.5f}));
        EXPECT_TRUE(render(renderer, scene, width, height));
        image = renderer.readFrame();
        EXPECT_TRUE(notConstant(image));
        return {image.pixel(1, 1), image.pixel(width / 4, height / 2),
                image.pixel(3 * width / 4, height / 2)};
    };

    auto scenePaint = loadEffect(paintEffect("scene"), false);
    ASSERT_TRUE(scenePaint);
    runtime::FrameImage image;
    Frame frame = paintFrame(*scenePaint, 0.25f, kWidth, kHeight, image);  // the reset frame
    EXPECT_TRUE(isWhite(frame.corner));
    EXPECT_TRUE(isPaint(frame.left));
    EXPECT_TRUE(isWhite(frame.right));
    frame = paintFrame(*scenePaint, 0.75f, kWidth, kHeight, image);
    EXPECT_TRUE(isWhite(frame.corner));
    EXPECT_TRUE(isPaint(frame.left)) << "the stroke of the frame before is gone";
    EXPECT_TRUE(isPaint(frame.right));
    // A new size: new frame targets, cleared by the host; no reset, so no canvas.
    frame = paintFrame(*scenePaint, 0.75f, kWidth / 2, kHeight / 2, image);
    EXPECT_TRUE(isBackground(frame.corner));
    EXPECT_TRUE(isBackground(frame.left));
    EXPECT_TRUE(isPaint(frame.right));
    scenePaint->reset();
    frame = paintFrame(*scenePaint, 0.75f, kWidth / 2, kHeight / 2, image);
    EXPECT_TRUE(isWhite(frame.corner));
    EXPECT_TRUE(isWhite(frame.left));
    EXPECT_TRUE(isPaint(frame.right));

    // A material effect's frame starts on the host's background in every frame.
    auto objectPaint = loadEffect(paintEffect("object"), false);
    ASSERT_TRUE(objectPaint);
    paintFrame(*objectPaint, 0.25f, kWidth, kHeight, image);
    frame = paintFrame(*objectPaint, 0.75f, kWidth, kHeight, image);
    EXPECT_TRUE(isBackground(frame.corner));
    EXPECT_TRUE(isBackground(frame.left));
    EXPECT_TRUE(isPaint(frame.right));
}

// A frame that runs another technique than the frame before starts a picture, as a reset does: the host
// clears it and FXCOMPOSER_RESETPULSE is true in it, so the new technique is not handed the old one's
// strokes. Main paints a white canvas over the frame on the pulse, Other a green one over the left half
// only (the right half then shows what the host handed it); both paint a blue stroke at BrushPos.
TEST(FxComposerHost, AFrameOfAnotherTechniqueStartsAPictureAsAResetDoes) {
    auto renderer =
        loadEffect(paintingEffect("0.75, 0.5",
                                  "string ScriptClass = \"scene\"; string ScriptOrder = \"standard\"; "
                                  "string ScriptOutput = \"color\";",
                                  paintingTechnique("Main", "canvas", "CanvasPS") +
                                      paintingTechnique("Other", "canvas", "LeftCanvasPS")),
                   false);
    ASSERT_TRUE(renderer);
    const runtime::Scene scene = *runtime::makeBuiltinScene("teapot");
    const auto isWhite = [](const uint8_t* p) { return p[0] == 255 && p[1] == 255 && p[2] == 255; };
    const auto isGreen = [](const uint8_t* p) { return p[0] == 0 && p[1] == 255 && p[2] == 0; };
    const auto isPaint = [](const uint8_t* p) { return p[0] == 0 && p[1] == 0 && p[2] == 255; };
    // The frame's top corners and the strokes' places, left and right.
    struct Frame {
        const uint8_t *leftCorner, *rightCorner, *left, *right;
    };
    runtime::FrameImage image;
    const auto paintFrame = [&](const std::string& technique, float brushX) -> Frame {
        renderer->setParameter(*renderer->findParameter("BrushPos"), fx::Value::vector({brushX, 0.5f}));
        EXPECT_TRUE(render(*renderer, scene, kWidth, kHeight, technique));
        image = renderer->readFrame();
        EXPECT_TRUE(notConstant(image));
        return {image.pixel(1, 1), image.pixel(kWidth - 2, 1), image.pixel(kWidth / 4, kHeight / 2),
                image.pixel(3 * kWidth / 4, kHeight / 2)};
    };

    Frame frame = paintFrame("Main", 0.75f);  // the first frame: a reset frame
    EXPECT_TRUE(isWhite(frame.leftCorner));
    EXPECT_TRUE(isWhite(frame.left));
    EXPECT_TRUE(isPaint(frame.right));
    // Another technique: cleared (the right half on the host's background, Main's stroke gone) and the
    // pulse true (Other's canvas on the left half).
    frame = paintFrame("Other", 0.25f);
    EXPECT_TRUE(isGreen(frame.leftCorner)) << "no reset pulse in the first frame of another technique";
    EXPECT_TRUE(isPaint(frame.left));
    EXPECT_TRUE(isBackground(frame.rightCorner)) << "the new technique was handed the old one's frame";
    EXPECT_TRUE(isBackground(frame.right)) << "the old technique's stroke is still there";
    // The same technique again: its frame kept, no pulse (the left stroke not painted over).
    frame = paintFrame("Other", 0.75f);
    EXPECT_TRUE(isGreen(frame.leftCorner));
    EXPECT_TRUE(isPaint(frame.left));
    EXPECT_TRUE(isPaint(frame.right));
    EXPECT_TRUE(isBackground(frame.rightCorner));
    // Back to the first: a new picture on its canvas, Other's strokes gone.
    frame = paintFrame("Main", 0.75f);
    EXPECT_TRUE(isWhite(frame.leftCorner));
    EXPECT_TRUE(isWhite(frame.left));
    EXPECT_TRUE(isWhite(frame.rightCorner));
    EXPECT_TRUE(isPaint(frame.right));
}

// Every effect written in FX Composer's or the DirectX SDK's style (tests/data/fxcomposer/, the encoded
// copies included) compiles without errors and draws a frame that is not blank with every technique.
TEST(FxComposerHost, EveryFxComposerStyleEffectDrawsANonBlankFrameWithEveryTechnique) {
    const runtime::Scene scene = *runtime::makeBuiltinScene("teapot");
    int effects = 0;
    for (const char* folder : {"tests/data/fxcomposer", "tests/data/fxcomposer/encodings"}) {
        for (const auto& entry : std::filesystem::directory_iterator(folder)) {
            if (entry.path().extension() != ".fx") continue;
            ++effects;
            SCOPED_TRACE(entry.path().string());
            LoadedEffect loaded = loadEffectWithDiagnostics(entry.path().string());
            ASSERT_TRUE(loaded.renderer);
            for (const fx::CompiledTechnique& technique : loaded.renderer->effect().techniques) {
                SCOPED_TRACE(technique.name);
                ASSERT_TRUE(render(*loaded.renderer, scene, kWidth, kHeight, technique.name));
                EXPECT_TRUE(notConstant(loaded.renderer->readFrame()));
            }
        }
    }
    EXPECT_GE(effects, 10);
}

// The material effect as Windows editors save it (UTF-8 with a byte-order mark, UTF-16 LE with CRLF,
// UTF-16 BE, CRLF): each copy renders the original's frame exactly.
TEST(FxComposerHost, EncodedCopiesRenderTheOriginalsFrame) {
    const runtime::Scene scene = *runtime::makeBuiltinScene("teapot");
    LoadedEffect original = loadEffectWithDiagnostics("tests/data/fxcomposer/material_phong.fx");
    ASSERT_TRUE(original.renderer);
    ASSERT_TRUE(render(*original.renderer, scene, kWidth, kHeight));
    const runtime::FrameImage expected = original.renderer->readFrame();
    ASSERT_TRUE(notConstant(expected));
    for (const char* copy : {"material_phong_utf8_bom.fx", "material_phong_utf16le.fx",
                             "material_phong_utf16be.fx", "material_phong_crlf.fx"}) {
        SCOPED_TRACE(copy);
        LoadedEffect loaded =
            loadEffectWithDiagnostics(std::string("tests/data/fxcomposer/encodings/") + copy);
        ASSERT_TRUE(loaded.renderer);
        ASSERT_TRUE(render(*loaded.renderer, scene, kWidth, kHeight));
        EXPECT_EQ(loaded.renderer->readFrame().rgba, expected.rgba);
    }
}

// XNA-era games include a shared header whose placeholder technique has its pass commented out, and pick
// their techniques by name: the default is the first technique that draws, with a note at the empty one.
TEST(FxComposerHost, TheDefaultTechniqueIsTheFirstThatDraws) {
    auto renderer = loadEffect(R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
technique CommonTechnique
{
/*  pass { VertexShader = compile vs_1_0 CommonVS(); } */
}
float4 VS(float4 p : POSITION0) : POSITION0 { return mul(p, WorldViewProjection); }
float4 PS() : COLOR0 { return float4(1, 0.5, 0.25, 1); }
technique Draw { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)",
                               false, "empty_first_technique.fx");
    ASSERT_TRUE(renderer);
    const runtime::Scene scene = *runtime::makeBuiltinScene("teapot");
    fx::DiagnosticList diagnostics;
    runtime::FrameOptions options;
    options.width = kWidth;
    options.height = kHeight;
    ASSERT_TRUE(renderer->render(scene, options, diagnostics)) << diagnostics.str();
    EXPECT_EQ(countDiagnostics(diagnostics, fx::DiagId::EmptyTechniqueSkipped), 1) << diagnostics.str();
    EXPECT_NE(
        diagnostics.str().find("empty_first_technique.fx:3:11: note: technique 'CommonTechnique' has no "
                               "passes and no script; the first technique that draws, 'Draw', runs"),
        std::string::npos)
        << diagnostics.str();
    const runtime::FrameImage frame = renderer->readFrame();
    EXPECT_GT(countPixelsOfColour(frame, kWidth, kHeight, 255, 128, 64), kWidth * kHeight / 10);
}

}  // namespace
}  // namespace shadowfx::test::test_fxcomposer_host
