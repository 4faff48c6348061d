// The application's API (runtime/EffectPass.h, runtime/EffectVariable.h): an application that draws the
// thesis effect's passes itself, with its own vertex arrays, framebuffer and draw calls, gets the frame
// render(Scene) draws, byte for byte; lookups by name, semantic and index and annotations, missing ones
// included; values and textures set through handles reach the GPU; begin()/end() leave the GL state as
// they found it.
#include "LeaveOutFrames.h"
#include "effects/EffectHarness.h"

#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>
#include <runtime/BuiltinScenes.h>
#include <runtime/EffectPass.h>
#include <runtime/EffectRenderer.h>
#include <runtime/GlApi.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

namespace test_pass_api {

namespace {

using shadowfx::test::applicationTexel;
using shadowfx::test::differingPixels;
using shadowfx::test::notConstant;
using shadowfx::test::sharedContext;
using shadowfx::test::sourcePath;

std::shared_ptr<const fx::CompiledEffect> compileThesis() {
    fx::DiagnosticList diagnostics;
    fx::ParseOptions parse;
    parse.defines = {{"SHADOWFX_SHADOW_MAP_SIZE", "512"}};
    auto effect = fx::parseEffectFile(sourcePath("effects/thesis_fxcomposer.fx"), parse, diagnostics);
    EXPECT_TRUE(effect) << diagnostics.str();
    if (!effect) return nullptr;
    std::shared_ptr<const fx::CompiledEffect> compiled = fx::compileEffect(effect, {}, diagnostics);
    EXPECT_TRUE(compiled) << diagnostics.str();
    return compiled;
}

std::unique_ptr<runtime::EffectRenderer> load(std::shared_ptr<const fx::CompiledEffect> compiled) {
    sharedContext();
    fx::DiagnosticList diagnostics;
    auto renderer = runtime::EffectRenderer::create(std::move(compiled), diagnostics);
    EXPECT_TRUE(renderer) << diagnostics.str();
    return renderer;
}

// [SECTION] The application's side: buffers, vertex arrays and a framebuffer of its own

// A mesh in GL buffers, and a vertex array per pass laid out by the pass's input signature.
struct ApplicationMesh {
    GLuint positions = 0, normals = 0, texcoords = 0, indices = 0;
    GLsizei indexCount = 0;
    std::map<std::pair<size_t, size_t>, GLuint> vaos;  // by (technique, pass)

    explicit ApplicationMesh(const runtime::Mesh& mesh) {
        const auto upload = [](GLenum target, const void* data, size_t bytes) {
            GLuint buffer = 0;
            gl::GenBuffers(1, &buffer);
            gl::BindBuffer(target, buffer);
            gl::BufferData(target, static_cast<GLsizeiptr>(bytes), data, GL_STATIC_DRAW);
            return buffer;
        };
        positions = upload(GL_ARRAY_BUFFER, mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
        if (!mesh.normals.empty())
            normals = upload(GL_ARRAY_BUFFER, mesh.normals.data(), mesh.normals.size() * sizeof(glm::vec3));
        if (!mesh.texcoords.empty())
            texcoords =
                upload(GL_ARRAY_BUFFER, mesh.texcoords.data(), mesh.texcoords.size() * sizeof(glm::vec2));
        indices = upload(GL_ELEMENT_ARRAY_BUFFER, mesh.indices.data(), mesh.indices.size() * 4);
        indexCount = static_cast<GLsizei>(mesh.indices.size());
        gl::BindBuffer(GL_ARRAY_BUFFER, 0);
    }
    ~ApplicationMesh() {
        for (auto& [key, vao] : vaos) gl::DeleteVertexArrays(1, &vao);
        const GLuint buffers[] = {positions, normals, texcoords, indices};
        gl::DeleteBuffers(4, buffers);
    }

    // Binds the pass's vertex array (made on first use): each input fed by its semantic; an input the
    // mesh lacks reads a constant, the values the runtime's own meshes give it (runtime/GpuMesh.h).
    void bind(const runtime::EffectPass& pass) {
        GLuint& vao = vaos[{pass.techniqueIndex(), pass.index()}];
        const std::vector<runtime::PassInput> inputs = pass.inputSignature();
        if (!vao) {
            gl::GenVertexArrays(1, &vao);
            gl::BindVertexArray(vao);
            for (const runtime::PassInput& input : inputs) {
                const auto [buffer, components] = stream(input.semantic);
                if (!buffer) continue;
                gl::BindBuffer(GL_ARRAY_BUFFER, buffer);
                gl::EnableVertexAttribArray(static_cast<GLuint>(input.location));
                gl::VertexAttribPointer(static_cast<GLuint>(input.location), components, GL_FLOAT, GL_FALSE,
                                        0, nullptr);
            }
            gl::BindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices);
            gl::BindBuffer(GL_ARRAY_BUFFER, 0);
        }
        gl::BindVertexArray(vao);
        for (const runtime::PassInput& input : inputs) {
            if (stream(input.semantic).first) continue;
            const glm::vec4 constant = input.semantic.rfind("POSITION", 0) == 0 ? glm::vec4(0, 0, 0, 1)
                                       : input.semantic == "NORMAL"             ? glm::vec4(0, 1, 0, 0)
                                                                                : glm::vec4(0);
            gl::VertexAttrib4fv(static_cast<GLuint>(input.location), &constant.x);
        }
    }

    std::pair<GLuint, int> stream(const std::string& semantic) const {
        if (semantic == "POSITION" || semantic == "POSITION0") return {positions, 3};
        if (semantic == "NORMAL" || semantic == "NORMAL0") return {normals, 3};
        if (semantic == "TEXCOORD" || semantic == "TEXCOORD0") return {texcoords, 2};
        return {0, 0};
    }

    void draw() const { gl::DrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, nullptr); }
};

// The application's render target: RGBA8 colour and D24S8 depth, the formats of render(Scene)'s frame.
struct ApplicationTarget {
    GLuint color = 0, depth = 0, framebuffer = 0;
    int width, height;

    ApplicationTarget(int w, int h) : width(w), height(h) {
        const auto texture = [](GLenum format, int w, int h) {
            GLuint id = 0;
            gl::GenTextures(1, &id);
            gl::BindTexture(GL_TEXTURE_2D, id);
            gl::TexStorage2D(GL_TEXTURE_2D, 1, format, w, h);
            gl::BindTexture(GL_TEXTURE_2D, 0);
            return id;
        };
        color = texture(GL_RGBA8, w, h);
        depth = texture(GL_DEPTH24_STENCIL8, w, h);
        gl::GenFramebuffers(1, &framebuffer);
        gl::BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        gl::FramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, color, 0);
        gl::FramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, depth, 0);
        EXPECT_EQ(gl::CheckFramebufferStatus(GL_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
        gl::Viewport(0, 0, w, h);
    }
    ~ApplicationTarget() {
        gl::DeleteFramebuffers(1, &framebuffer);
        const GLuint textures[] = {color, depth};
        gl::DeleteTextures(2, textures);
    }

    // Colour to black, depth to 1, whatever write masks earlier tests left.
    void clear() const {
        gl::BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        gl::ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        gl::DepthMask(GL_TRUE);
        gl::Disable(GL_SCISSOR_TEST);
        gl::ClearColor(0, 0, 0, 1);
        gl::ClearDepth(1.0);
        gl::Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }

    runtime::FrameImage read() const {
        runtime::FrameImage image;
        image.width = width;
        image.height = height;
        image.rgba.resize(static_cast<size_t>(width) * static_cast<size_t>(height) * 4);
        gl::BindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
        gl::ReadBuffer(GL_COLOR_ATTACHMENT0);
        gl::PixelStorei(GL_PACK_ALIGNMENT, 1);
        gl::ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
        return image;
    }
};

// D3D9's Clear as the pass scripts state it: colour, depth (and the stencil beside it), every write open.
void clear(runtime::EffectRenderer& effect, const char* color, const char* depth, GLbitfield what) {
    const fx::Value rgba = effect.variable(color).value();
    gl::ClearColor(rgba.data[0], rgba.data[1], rgba.data[2], rgba.data[3]);
    gl::ClearDepth(effect.variable(depth).value().asFloat());
    gl::ClearStencil(0);
    gl::Clear(what);
}

// [SECTION] The thesis frame, drawn by the application

// The scene's matrices set by semantic and the light's by name, composed in the order the runtime's
// semantic binder composes them (D3D's World*View*Projection is proj*view*world in glm), so that both
// frames round alike: the thesis technique `main`, its Script followed by hand (clear the float map, draw
// the casters with BlendOp=min, clear the frame, draw the scene), gives render(Scene)'s frame byte for byte.
class ThesisFrame : public ::testing::TestWithParam<const char*> {};

TEST_P(ThesisFrame, DrawnThroughThePassApiEqualsRenderScene) {
    sharedContext();
    const int width = 160, height = 120;
    std::optional<runtime::Scene> scene = runtime::makeBuiltinScene(GetParam());
    ASSERT_TRUE(scene);
    std::shared_ptr<const fx::CompiledEffect> compiled = compileThesis();
    ASSERT_TRUE(compiled);
    auto host = load(compiled);
    auto effect = load(compiled);
    ASSERT_TRUE(host && effect);

    runtime::FrameOptions options;
    options.width = width;
    options.height = height;
    options.technique = "main";
    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(host->render(*scene, options, diagnostics)) << diagnostics.str();
    const runtime::FrameImage expected = host->readFrame();

    std::map<const runtime::Mesh*, std::unique_ptr<ApplicationMesh>> meshes;
    for (const runtime::SceneObject& object : scene->objects)
        if (object.mesh && !meshes.count(object.mesh.get()))
            meshes[object.mesh.get()] = std::make_unique<ApplicationMesh>(*object.mesh);
    ApplicationTarget target(width, height);

    const glm::mat4 view = scene->camera.view();
    const glm::mat4 projection = scene->camera.projection(static_cast<float>(width) / height);
    const std::optional<runtime::LightFit> light = effect->lightFit(*scene, "light0", options);
    ASSERT_TRUE(light);
    ASSERT_TRUE(effect->variable("LightViewMatrix").setMatrix(light->view));
    ASSERT_TRUE(effect->variable("LightProjectionMatrix").setMatrix(light->projection));
    ASSERT_TRUE(effect->variableBySemantic("ViewInverse").setMatrix(glm::inverse(view)));
    ASSERT_TRUE(effect->variableBySemantic("LightColor").setVector(scene->lights[0].color));
    ASSERT_TRUE(effect->variableBySemantic("Ambient").setVector(scene->ambient));
    const auto drawObjects = [&](const runtime::EffectPass& pass) {
        for (const runtime::SceneObject& object : scene->objects) {
            if (!object.mesh) continue;
            effect->variableBySemantic("World").setMatrix(object.world);
            effect->variableBySemantic("WorldInverseTranspose")
                .setMatrix(glm::transpose(glm::inverse(object.world)));
            effect->variableBySemantic("WorldViewProjection").setMatrix(projection * view * object.world);
            effect->variableBySemantic("Diffuse").setVector(object.color);
            ASSERT_TRUE(pass.commitChanges(&diagnostics)) << diagnostics.str();
            ApplicationMesh& mesh = *meshes[object.mesh.get()];
            mesh.bind(pass);
            mesh.draw();
        }
    };

    runtime::EffectTechnique technique = effect->technique("main");
    ASSERT_TRUE(technique.isValid());
    ASSERT_EQ(technique.passCount(), 3u);
    ASSERT_TRUE(technique.begin());
    const runtime::EffectPass clearMap = technique.pass("ClearShadowMap");
    ASSERT_TRUE(clearMap.apply(&diagnostics)) << diagnostics.str();
    clear(*effect, "ShadowClearColor", "ClearDepth",
          GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    const runtime::EffectPass shadowMap = technique.pass("RenderShadowMap");
    ASSERT_TRUE(shadowMap.apply(&diagnostics)) << diagnostics.str();
    drawObjects(shadowMap);
    const runtime::EffectPass lit = technique.pass("RenderScene");
    ASSERT_TRUE(lit.apply(&diagnostics)) << diagnostics.str();
    GLint bound = -1;
    gl::GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
    EXPECT_EQ(static_cast<GLuint>(bound), target.framebuffer)
        << "RenderColorTarget0= binds the application's";
    clear(*effect, "ClearColor", "ClearDepth",
          GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    drawObjects(lit);
    technique.end();
    gl::BindVertexArray(0);
    EXPECT_EQ(gl::GetError(), static_cast<GLenum>(GL_NO_ERROR));
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.str();

    const runtime::FrameImage actual = target.read();
    EXPECT_TRUE(notConstant(actual));
    EXPECT_EQ(differingPixels(expected, actual), 0u) << "of " << width * height << " pixels";
}

INSTANTIATE_TEST_SUITE_P(Scenes, ThesisFrame, ::testing::Values("boxes", "dual-l"), [](const auto& info) {
    std::string name = info.param;
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
});

// An application that draws into the effect's targets between two render(Scene) frames: the second frame
// draws its shadow map again instead of reusing what it left there (leave-out's cached passes), so it
// equals the first.
TEST(PassApi, RenderSceneAfterTheApplicationDrewIntoTheTargetsDrawsThemAgain) {
    sharedContext();
    std::optional<runtime::Scene> scene = runtime::makeBuiltinScene("boxes");
    ASSERT_TRUE(scene);
    auto effect = load(compileThesis());
    ASSERT_TRUE(effect);
    runtime::FrameOptions options;
    options.width = 160;
    options.height = 120;
    options.technique = "main";
    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(effect->render(*scene, options, diagnostics)) << diagnostics.str();
    const runtime::FrameImage first = effect->readFrame();

    ApplicationTarget target(options.width, options.height);
    runtime::EffectTechnique technique = effect->technique("main");
    ASSERT_TRUE(technique.begin());
    ASSERT_TRUE(technique.pass("ClearShadowMap").apply(&diagnostics)) << diagnostics.str();
    gl::ClearColor(0, 0, 0, 0);  // every receiver behind an occluder at depth 0: all in shadow
    gl::Clear(GL_COLOR_BUFFER_BIT);
    technique.end();

    runtime::FrameStats stats;
    ASSERT_TRUE(effect->render(*scene, options, diagnostics, &stats)) << diagnostics.str();
    const runtime::PassStats* shadow = shadowfx::test::findPass(stats, "RenderShadowMap");
    ASSERT_TRUE(shadow);
    EXPECT_EQ(shadow->leftOut, "") << "the map is drawn again";
    EXPECT_TRUE(notConstant(first));
    EXPECT_EQ(differingPixels(first, effect->readFrame()), 0u);
}

// [SECTION] Lookups and annotations

// A D3D10/11 effect with an array, an application texture, a technique in an fxgroup, one the parser leaves
// out (dynamic shader linkage, which GLSL has not) and one the compiler leaves out (GL has no SV_Coverage
// input).
constexpr const char* kPalette = R"(
float4x4 WorldViewProj : WORLDVIEWPROJECTION < string UIName = "Transform"; >;
float4 Palette[3] < float2 Range = {0.25, 4}; >;
float Gain < string UIName = "Gain"; float UIMax = 2.5; > = 1;
Texture2D Albedo;
SamplerState PointClamp { Filter = MIN_MAG_MIP_POINT; AddressU = CLAMP; AddressV = CLAMP; };
struct VsOut { float4 position : SV_Position; float2 uv : TEXCOORD0; };
VsOut VS(float3 position : POSITION, float2 uv : TEXCOORD0)
{
    VsOut o;
    o.position = mul(float4(position, 1), WorldViewProj);
    o.uv = uv;
    return o;
}
float4 PS(VsOut i) : SV_Target { return Albedo.Sample(PointClamp, i.uv) * Palette[1] * Gain; }
technique11 Linked
{
    pass
    {
        SetVertexShader(CompileShader(vs_5_0, VS()));
        SetPixelShader(BindInterfaces(CompileShader(ps_5_0, PS()), Light));
    }
}
float4 CoveragePS(VsOut i, uint mask : SV_Coverage) : SV_Target { return Palette[0] * mask; }
technique10 Coverage
{
    pass
    {
        SetVertexShader(CompileShader(vs_4_0, VS()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_4_0, CoveragePS()));
    }
}
fxgroup Palettes
{
    technique11 Plain < string Purpose = "palette"; int Order = 2; >
    {
        pass Tinted < float Weight = 0.5; >
        {
            SetVertexShader(CompileShader(vs_4_0, VS()));
            SetGeometryShader(NULL);
            SetPixelShader(CompileShader(ps_4_0, PS()));
        }
    }
}
)";

std::unique_ptr<runtime::EffectRenderer> loadPalette() {
    sharedContext();
    fx::DiagnosticList diagnostics;
    auto effect = fx::parseEffectSource(kPalette, "palette.fx", {}, diagnostics);
    EXPECT_TRUE(effect) << diagnostics.str();
    if (!effect) return nullptr;
    std::shared_ptr<const fx::CompiledEffect> compiled = fx::compileEffect(effect, {}, diagnostics);
    EXPECT_TRUE(compiled) << diagnostics.str();
    return compiled ? load(compiled) : nullptr;
}

TEST(PassApi, LooksVariablesUpByNameSemanticAndIndex) {
    auto effect = loadPalette();
    ASSERT_TRUE(effect);
    runtime::EffectVariable transform = effect->variableBySemantic("worldViewProjection");  // case-blind
    ASSERT_TRUE(transform.isValid());
    EXPECT_EQ(transform.name(), "WorldViewProj");
    EXPECT_EQ(effect->variable(transform.index()).name(), "WorldViewProj");
    EXPECT_EQ(effect->variable("WorldViewProj").index(), transform.index());
    EXPECT_FALSE(effect->variable("worldviewproj").isValid()) << "names are case-sensitive, as in HLSL";
    EXPECT_FALSE(effect->variable(effect->variableCount()).isValid());
    EXPECT_TRUE(effect->variable("Palette").element(2).isValid());
    EXPECT_FALSE(effect->variable("Palette").element(3).isValid());
    EXPECT_EQ(effect->technique("Palettes.Plain").index(), effect->technique("Plain").index());
    EXPECT_EQ(effect->technique("Plain").group(), "Palettes");
    EXPECT_EQ(effect->technique(size_t(0)).name(), "Plain");
    EXPECT_FALSE(effect->technique("Other.Plain").isValid());
    EXPECT_FALSE(effect->variable("Gain").element(0).isValid()) << "not an array";
    EXPECT_EQ(effect->variable("Palette").elementCount(), 3u);
    EXPECT_EQ(effect->variable("Palette").element(1).name(), "Palette[1]");
}

TEST(PassApi, MissingLookupsGiveInvalidHandlesThatDoNothing) {
    auto effect = loadPalette();
    ASSERT_TRUE(effect);
    runtime::EffectVariable missing = effect->variableBySemantic("NoSuchSemantic");
    EXPECT_FALSE(missing.isValid());
    EXPECT_FALSE(effect->variableBySemantic("").isValid());
    EXPECT_FALSE(missing.setMatrix(glm::mat4(1.0f)));
    EXPECT_FALSE(missing.setTexture(1));
    EXPECT_FALSE(missing.annotation("UIName").isValid());
    EXPECT_EQ(missing.annotation("UIName").asString(), "");
    EXPECT_EQ(missing.element(0).annotation(0).asFloat(), 0.0f);
    EXPECT_EQ(missing.name(), "");
    EXPECT_EQ(missing.value().asFloat(), 0.0f);

    runtime::EffectTechnique none = effect->technique("NoSuchTechnique");
    EXPECT_FALSE(none.isValid());
    EXPECT_EQ(none.passCount(), 0u);
    EXPECT_FALSE(none.pass(0).isValid());
    EXPECT_FALSE(none.pass(0).apply());
    EXPECT_FALSE(none.pass(0).commitChanges());
    EXPECT_TRUE(none.pass(0).inputSignature().empty());
    EXPECT_FALSE(none.begin());
    none.end();
    EXPECT_FALSE(effect->technique(effect->techniqueCount()).isValid());
    EXPECT_FALSE(effect->technique("Plain").pass("NoSuchPass").isValid());
    EXPECT_FALSE(effect->technique("Plain").pass(1).isValid());
    EXPECT_FALSE(effect->technique("Plain").annotation("Missing").isValid());
    EXPECT_FALSE(effect->technique("Plain").pass(0).annotation(5).isValid());
}

TEST(PassApi, SettersRefuseValuesOfAnotherType) {
    auto effect = loadPalette();
    ASSERT_TRUE(effect);
    EXPECT_FALSE(effect->variable("Gain").setMatrix(glm::mat4(1.0f)));
    EXPECT_FALSE(effect->variable("Gain").setVector(glm::vec3(1.0f)));
    EXPECT_FALSE(effect->variable("WorldViewProj").setFloat(1.0f));
    EXPECT_FALSE(effect->variable("WorldViewProj").setMatrix(glm::mat4x3(1.0f)));
    EXPECT_FALSE(effect->variable("Palette").setVector(glm::vec4(1.0f))) << "an array takes elements";
    EXPECT_FALSE(effect->variable("Palette").setFloatArray(std::vector<float>(13, 1.0f)));
    EXPECT_FALSE(effect->variable("Gain").setTexture(1)) << "not a texture";
    EXPECT_TRUE(effect->variable("Gain").setFloat(2.0f));
    EXPECT_EQ(effect->variable("Gain").value().asFloat(), 2.0f);
}

TEST(PassApi, ReadsAnnotationsOfParametersTechniquesAndPasses) {
    auto effect = loadPalette();
    ASSERT_TRUE(effect);
    runtime::EffectVariable gain = effect->variable("Gain");
    EXPECT_EQ(gain.annotationCount(), 2u);
    EXPECT_EQ(gain.annotation("uiname").asString(), "Gain") << "annotation names are case-blind";
    EXPECT_EQ(gain.annotation("UIMax").asFloat(), 2.5f);
    EXPECT_EQ(gain.annotation(1).name(), "UIMax");
    const fx::Value range = effect->variable("Palette").annotation("Range").value();
    EXPECT_EQ(range.data, (std::vector<float>{0.25f, 4.0f}));
    EXPECT_EQ(range.type.cols, 2);
    runtime::EffectTechnique plain = effect->technique("Plain");
    EXPECT_EQ(plain.annotation("Purpose").asString(), "palette");
    EXPECT_EQ(plain.annotation("Order").asInt(), 2);
    EXPECT_EQ(plain.pass("tinted").annotation("Weight").asFloat(), 0.5f);

    // The thesis effect's SAS annotations, where tools read them.
    auto thesis = load(compileThesis());
    ASSERT_TRUE(thesis);
    EXPECT_EQ(thesis->variable("Bias").annotation("UIName").asString(), "Depth bias");
    EXPECT_EQ(thesis->variable("ShadowMap").annotation("Dimensions").value().data,
              (std::vector<float>{512.0f, 512.0f}));
    EXPECT_EQ(thesis->technique("main").annotation("ExpectMapSize").asInt(), 1024);
    EXPECT_EQ(thesis->technique("main").pass("RenderShadowMap").annotation("Script").asString(),
              "RenderColorTarget0=ShadowMap;RenderDepthStencilTarget=ShadDepthTarget;RenderPort=light0;"
              "Draw=geometry;");
}

TEST(PassApi, ValidatesTechniquesWithTheReasonOneWasLeftOut) {
    auto effect = loadPalette();
    ASSERT_TRUE(effect);
    EXPECT_EQ(effect->techniqueCount(), 1u);
    const runtime::TechniqueValidation plain = effect->validateTechnique("Plain");
    EXPECT_TRUE(plain.valid);
    EXPECT_EQ(plain.reason, "");
    const runtime::TechniqueValidation coverage = effect->validateTechnique("Coverage");
    EXPECT_FALSE(coverage.valid);
    EXPECT_EQ(coverage.reason, "pixel input semantic 'SV_COVERAGE' is not supported");
    const runtime::TechniqueValidation linked = effect->validateTechnique("Linked");
    EXPECT_FALSE(linked.valid);
    EXPECT_EQ(
        linked.reason,
        "dynamic shader linkage (BindInterfaces) is not supported: GLSL has no interfaces to bind at run "
        "time");
    const runtime::TechniqueValidation missing = effect->validateTechnique("Missing");
    EXPECT_FALSE(missing.valid);
    EXPECT_EQ(missing.reason, "the effect has no technique 'Missing'");
}

TEST(PassApi, SaysWhatEachPassReadsAndTouches) {
    auto thesis = load(compileThesis());
    ASSERT_TRUE(thesis);
    runtime::EffectTechnique main = thesis->technique("main");
    const runtime::EffectPass shadow = main.pass("RenderShadowMap"), lit = main.pass("RenderScene");
    EXPECT_TRUE(thesis->variable("WorldMatrix").isUsed(shadow)) << "its compile argument reads it";
    EXPECT_TRUE(thesis->variable("Bias").isUsed(lit));
    EXPECT_FALSE(thesis->variable("Bias").isUsed(shadow));
    EXPECT_TRUE(thesis->variable("ShadowMapSampler").isUsed(lit));
    EXPECT_TRUE(thesis->variable("ShadowMap").isUsed(lit));
    EXPECT_FALSE(thesis->variable("ShadowMap").isUsed(shadow));
    EXPECT_FALSE(thesis->variable("Bias").isUsed(runtime::EffectPass{}));

    const std::vector<runtime::PassInput> inputs = shadow.inputSignature();
    ASSERT_FALSE(inputs.empty());
    EXPECT_TRUE(std::any_of(inputs.begin(), inputs.end(), [](const runtime::PassInput& input) {
        return input.semantic.rfind("POSITION", 0) == 0;
    }));

    const runtime::GlStateMask clearMask = main.pass("ClearShadowMap").stateMask();
    EXPECT_TRUE(clearMask.renderStates && clearMask.framebuffer);
    EXPECT_FALSE(clearMask.program) << "a pass without shaders binds no program";
    const runtime::GlStateMask litMask = lit.stateMask();
    EXPECT_TRUE(litMask.program && litMask.framebuffer);
    EXPECT_EQ(litMask.textureUnits.size(), 2u) << "the shadow map and the noise";
    EXPECT_FALSE(litMask.uniformBuffers.empty());
    const std::vector<std::string> lines = litMask.describe();
    EXPECT_NE(std::find(lines.begin(), lines.end(), "render states"), lines.end());
}

// What a pass reads is the compiler's list (fx::CompiledPass::readParameters), from each stage's SPIR-V:
// a D3D9 sampler every stage declares (glslang keeps them all) is used where the code samples it, with its
// texture; a D3D10 pair's texture and sampler where the pair is sampled; a read-write texture where a
// compute pass declares it; a matrix where a uniform block member the code reads holds it.
constexpr const char* kReadsEffect = R"(
float4x4 WorldViewProjection : WorldViewProjection;
texture Base;
sampler2D BaseSampler = sampler_state { Texture = <Base>; };
Texture2D Albedo;
SamplerState Linear;
RWTexture2D<float4> Field;
float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProjection); }
float4 Sampled(float2 uv : TEXCOORD0) : COLOR { return tex2D(BaseSampler, uv); }
float4 Flat() : COLOR { return 1; }
float4 Paired(float2 uv : TEXCOORD0) : SV_Target { return Albedo.Sample(Linear, uv); }
[numthreads(1, 1, 1)] void Fill(uint3 id : SV_DispatchThreadID) { Field[id.xy] = 1; }
technique d3d9 {
    pass sampled { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Sampled(); }
    pass flat { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Flat(); }
}
technique11 d3d11 {
    pass paired { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, Paired())); }
    pass fill { SetComputeShader(CompileShader(cs_5_0, Fill())); }
}
)";

TEST(PassApi, APassUsesWhatItsCodeReads) {
    std::unique_ptr<runtime::EffectRenderer> effect =
        shadowfx::test::loadEffect(kReadsEffect, false, "reads.fx");
    ASSERT_TRUE(effect);
    runtime::EffectTechnique d3d9 = effect->technique("d3d9"), d3d11 = effect->technique("d3d11");
    const runtime::EffectPass sampled = d3d9.pass("sampled"), flat = d3d9.pass("flat");
    const runtime::EffectPass paired = d3d11.pass("paired"), fill = d3d11.pass("fill");
    ASSERT_TRUE(sampled.isValid() && flat.isValid() && paired.isValid() && fill.isValid());
    const auto uses = [&effect](const char* name, const runtime::EffectPass& pass) {
        return effect->variable(name).isUsed(pass);
    };
    EXPECT_TRUE(uses("BaseSampler", sampled));
    EXPECT_TRUE(uses("Base", sampled)) << "the sampler's texture";
    EXPECT_FALSE(uses("BaseSampler", flat)) << "declared in its pixel stage, never sampled";
    EXPECT_FALSE(uses("Base", flat));
    EXPECT_TRUE(uses("Albedo", paired));
    EXPECT_TRUE(uses("Linear", paired));
    EXPECT_FALSE(uses("Albedo", sampled));
    EXPECT_TRUE(uses("Field", fill));
    EXPECT_FALSE(uses("Field", paired));
    EXPECT_TRUE(uses("WorldViewProjection", flat));
    EXPECT_FALSE(uses("WorldViewProjection", fill));
}

// [SECTION] Values and textures reach the GPU

// A clockwise full-screen quad, D3D's front face, its texture coordinates 0 to 1 from the top left.
runtime::Mesh fullScreenQuad() {
    runtime::Mesh quad;
    quad.positions = {{-1, 1, 0.5f}, {1, 1, 0.5f}, {1, -1, 0.5f}, {-1, -1, 0.5f}};
    quad.texcoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    quad.indices = {0, 1, 2, 0, 2, 3};
    return quad;
}

TEST(PassApi, ArrayElementsAndApplicationTexturesReachTheDraw) {
    auto effect = loadPalette();
    ASSERT_TRUE(effect);
    ApplicationTarget target(8, 8);
    const GLuint albedo = applicationTexel();

    ASSERT_TRUE(effect->variableBySemantic("WorldViewProjection").setMatrix(glm::mat4(1.0f)));
    runtime::EffectVariable palette = effect->variable("Palette");
    ASSERT_TRUE(palette.setFloatArray(std::vector<float>(12, 0.0f)));
    ASSERT_TRUE(palette.element(1).setVector(glm::vec4(0.25f, 1.0f, 1.0f, 1.0f)));
    EXPECT_EQ(palette.value().data[4], 0.25f);
    EXPECT_EQ(palette.element(1).value().data, (std::vector<float>{0.25f, 1.0f, 1.0f, 1.0f}));
    ASSERT_TRUE(effect->variable("Albedo").setTexture(albedo));

    ApplicationMesh mesh(fullScreenQuad());
    const runtime::EffectPass pass = effect->technique("Plain").pass(0);
    fx::DiagnosticList diagnostics;
    target.clear();
    ASSERT_TRUE(effect->technique("Plain").begin());
    ASSERT_TRUE(pass.apply(&diagnostics)) << diagnostics.str();
    mesh.bind(pass);
    mesh.draw();
    effect->technique("Plain").end();
    runtime::FrameImage image = target.read();
    EXPECT_EQ(image.pixel(4, 4)[0], 64);  // 1 x 0.25
    EXPECT_EQ(image.pixel(4, 4)[1], 128);
    EXPECT_EQ(image.pixel(4, 4)[2], 64);

    // A value set after apply() reaches the draw once committed.
    target.clear();
    ASSERT_TRUE(effect->technique("Plain").begin());
    ASSERT_TRUE(pass.apply(&diagnostics)) << diagnostics.str();
    ASSERT_TRUE(effect->variable("Gain").setFloat(0.0f));
    ASSERT_TRUE(pass.commitChanges(&diagnostics));
    mesh.bind(pass);
    mesh.draw();
    effect->technique("Plain").end();
    image = target.read();
    EXPECT_EQ(image.pixel(4, 4)[0], 0);
    EXPECT_EQ(image.pixel(4, 4)[1], 0);
    EXPECT_FALSE(effect->technique("Plain").pass(0).commitChanges()) << "end() closed the pass";
    gl::BindVertexArray(0);
    gl::DeleteTextures(1, &albedo);
}

// XNA's and MonoGame's stock effects declare their texture as a bare sampler, `sampler2D Texture :
// register(s0);`, and their applications set it through the sampler: white until then, also in a pass
// with a pixel shader alone (SpriteBatch's), which reads the host's picture only when render() draws it.
const char* kBareSampler = R"(
float4x4 WorldViewProj : WorldViewProjection;
sampler2D Texture : register(s0);
struct VsOut { float4 pos : POSITION; float2 uv : TEXCOORD0; };
VsOut VS(float3 p : POSITION, float2 uv : TEXCOORD0) {
    VsOut o = { mul(float4(p, 1), WorldViewProj), uv };
    return o;
}
float4 PS(float2 uv : TEXCOORD0) : COLOR { return tex2D(Texture, uv) * float4(0.5, 0.5, 0.5, 1); }
technique Textured { pass { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
technique Sprite { pass { PixelShader = compile ps_3_0 PS(); } }
)";

TEST(PassApi, AnApplicationSetsABareSamplersTexture) {
    std::unique_ptr<runtime::EffectRenderer> effect =
        shadowfx::test::loadEffect(kBareSampler, false, "bare_sampler.fx");
    ASSERT_TRUE(effect);
    ApplicationTarget target(8, 8);
    const GLuint texture = applicationTexel();
    ASSERT_TRUE(effect->variableBySemantic("WorldViewProjection").setMatrix(glm::mat4(1.0f)));

    ApplicationMesh mesh(fullScreenQuad());
    for (const char* technique : {"Textured", "Sprite"}) {
        SCOPED_TRACE(technique);
        const runtime::EffectPass pass = effect->technique(technique).pass(0);
        const auto drawn = [&]() {
            fx::DiagnosticList diagnostics;
            target.clear();
            EXPECT_TRUE(effect->technique(technique).begin());
            EXPECT_TRUE(pass.apply(&diagnostics)) << diagnostics.str();
            mesh.bind(pass);
            mesh.draw();
            effect->technique(technique).end();
            const runtime::FrameImage image = target.read();
            return std::vector<int>(image.pixel(4, 4), image.pixel(4, 4) + 3);
        };
        EXPECT_EQ(drawn(), (std::vector<int>{128, 128, 128}));  // the neutral white texture, halved
        ASSERT_TRUE(effect->variable("Texture").setTexture(texture));
        EXPECT_EQ(drawn(), (std::vector<int>{128, 64, 32}));
        ASSERT_TRUE(effect->variable("Texture").setTexture(0));
        EXPECT_EQ(drawn(), (std::vector<int>{128, 128, 128}));
    }
    gl::BindVertexArray(0);
    gl::DeleteTextures(1, &texture);
}

// [SECTION] State saved and restored

// Every value of the state a pass may touch, read back with plain GL queries (not GlStateSnapshot, which
// this test checks).
std::vector<double> stateFingerprint() {
    std::vector<double> out;
    const auto integers = [&](GLenum name, int count = 1) {
        GLint values[4] = {};
        gl::GetIntegerv(name, values);
        out.insert(out.end(), values, values + count);
    };
    const auto floats = [&](GLenum name, int count = 1) {
        GLfloat values[4] = {};
        gl::GetFloatv(name, values);
        out.insert(out.end(), values, values + count);
    };
    for (GLenum capability :
         {GL_DEPTH_TEST, GL_CULL_FACE, GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE,
          GL_POLYGON_OFFSET_POINT, GL_SCISSOR_TEST, GL_MULTISAMPLE, GL_DEPTH_CLAMP, GL_FRAMEBUFFER_SRGB,
          GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_MASK, GL_STENCIL_TEST})
        out.push_back(gl::IsEnabled(capability));
    for (GLuint i = 0; i < 8; ++i) {
        out.push_back(gl::IsEnabledi(GL_BLEND, i));
        for (GLenum name : {GL_BLEND_SRC_RGB, GL_BLEND_DST_RGB, GL_BLEND_SRC_ALPHA, GL_BLEND_DST_ALPHA,
                            GL_BLEND_EQUATION_RGB, GL_BLEND_EQUATION_ALPHA}) {
            GLint value = 0;
            gl::GetIntegeri_v(name, i, &value);
            out.push_back(value);
        }
        GLboolean mask[4] = {};
        gl::GetBooleani_v(GL_COLOR_WRITEMASK, i, mask);
        out.insert(out.end(), mask, mask + 4);
    }
    for (GLenum name : {GL_DEPTH_WRITEMASK,
                        GL_DEPTH_FUNC,
                        GL_FRONT_FACE,
                        GL_CULL_FACE_MODE,
                        GL_STENCIL_FUNC,
                        GL_STENCIL_REF,
                        GL_STENCIL_VALUE_MASK,
                        GL_STENCIL_FAIL,
                        GL_STENCIL_PASS_DEPTH_FAIL,
                        GL_STENCIL_PASS_DEPTH_PASS,
                        GL_STENCIL_WRITEMASK,
                        GL_STENCIL_BACK_FUNC,
                        GL_STENCIL_BACK_REF,
                        GL_STENCIL_BACK_VALUE_MASK,
                        GL_STENCIL_BACK_FAIL,
                        GL_STENCIL_BACK_PASS_DEPTH_FAIL,
                        GL_STENCIL_BACK_PASS_DEPTH_PASS,
                        GL_STENCIL_BACK_WRITEMASK,
                        GL_CURRENT_PROGRAM,
                        GL_DRAW_FRAMEBUFFER_BINDING,
                        GL_READ_FRAMEBUFFER_BINDING,
                        GL_ACTIVE_TEXTURE,
                        GL_UNIFORM_BUFFER_BINDING,
                        GL_SHADER_STORAGE_BUFFER_BINDING})
        integers(name);
    integers(GL_POLYGON_MODE, 2);
    integers(GL_VIEWPORT, 4);
    floats(GL_POLYGON_OFFSET_FACTOR);
    floats(GL_POLYGON_OFFSET_UNITS);
    floats(GL_BLEND_COLOR, 4);
    GLint sampleMask = 0;
    gl::GetIntegeri_v(GL_SAMPLE_MASK_VALUE, 0, &sampleMask);
    out.push_back(sampleMask);
    GLint active = 0;
    gl::GetIntegerv(GL_ACTIVE_TEXTURE, &active);
    for (GLuint unit = 0; unit < 16; ++unit) {
        gl::ActiveTexture(GL_TEXTURE0 + unit);
        integers(GL_TEXTURE_BINDING_2D);
        integers(GL_TEXTURE_BINDING_CUBE_MAP);
        integers(GL_SAMPLER_BINDING);
    }
    gl::ActiveTexture(static_cast<GLenum>(active));
    for (GLuint binding = 0; binding < 16; ++binding) {
        GLint buffer = 0, start = 0, size = 0;
        gl::GetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, binding, &buffer);
        gl::GetIntegeri_v(GL_UNIFORM_BUFFER_START, binding, &start);
        gl::GetIntegeri_v(GL_UNIFORM_BUFFER_SIZE, binding, &size);
        out.insert(out.end(),
                   {static_cast<double>(buffer), static_cast<double>(start), static_cast<double>(size)});
    }
    return out;
}

// An application's own state, unlike what any of the thesis passes sets.
void setApplicationState(const ApplicationTarget& target, GLuint texture, GLuint sampler, GLuint buffer) {
    gl::BindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    gl::Viewport(1, 2, 5, 6);
    gl::Enable(GL_BLEND);
    gl::BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    gl::BlendEquation(GL_MAX);
    gl::Enable(GL_DEPTH_TEST);
    gl::DepthFunc(GL_GREATER);
    gl::DepthMask(GL_FALSE);
    gl::Enable(GL_CULL_FACE);
    gl::CullFace(GL_FRONT);
    gl::FrontFace(GL_CCW);
    gl::ColorMaski(0, GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    gl::Enable(GL_SCISSOR_TEST);
    gl::StencilFuncSeparate(GL_BACK, GL_EQUAL, 3, 0x0f);
    gl::PolygonOffset(1.5f, 2.0f);
    gl::BlendColor(0.1f, 0.2f, 0.3f, 0.4f);
    for (GLuint unit = 0; unit < 4; ++unit) {
        gl::ActiveTexture(GL_TEXTURE0 + unit);
        gl::BindTexture(GL_TEXTURE_2D, texture);
        gl::BindSampler(unit, sampler);
    }
    gl::ActiveTexture(GL_TEXTURE3);
    for (GLuint binding = 0; binding < 4; ++binding)
        gl::BindBufferRange(GL_UNIFORM_BUFFER, binding, buffer, 256 * binding, 64);
    gl::UseProgram(0);
}

TEST(PassApi, EndRestoresTheStateBeginFound) {
    sharedContext();
    auto thesis = load(compileThesis());
    ASSERT_TRUE(thesis);
    ApplicationTarget target(32, 32);
    GLuint texture = 0, sampler = 0, buffer = 0;
    gl::GenTextures(1, &texture);
    gl::BindTexture(GL_TEXTURE_2D, texture);
    gl::TexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, 1, 1);
    gl::GenSamplers(1, &sampler);
    gl::GenBuffers(1, &buffer);
    gl::BindBuffer(GL_UNIFORM_BUFFER, buffer);
    gl::BufferData(GL_UNIFORM_BUFFER, 4096, nullptr, GL_STATIC_DRAW);

    runtime::EffectTechnique main = thesis->technique("main");
    const auto applyEveryPass = [&] {
        fx::DiagnosticList diagnostics;
        for (size_t p = 0; p < main.passCount(); ++p)
            ASSERT_TRUE(main.pass(p).apply(&diagnostics)) << diagnostics.str();
    };
    setApplicationState(target, texture, sampler, buffer);
    const std::vector<double> before = stateFingerprint();
    ASSERT_TRUE(main.begin());
    EXPECT_FALSE(main.begin()) << "one begin() at a time";
    applyEveryPass();
    EXPECT_NE(stateFingerprint(), before) << "the passes changed the state";
    main.end();
    EXPECT_EQ(stateFingerprint(), before);

    // D3DXFX_DONOTSAVESTATE: what the passes set stays.
    ASSERT_TRUE(main.begin(false));
    applyEveryPass();
    main.end();
    EXPECT_NE(stateFingerprint(), before);
    EXPECT_EQ(gl::GetError(), static_cast<GLenum>(GL_NO_ERROR));

    gl::UseProgram(0);
    gl::BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::DeleteTextures(1, &texture);
    gl::DeleteSamplers(1, &sampler);
    gl::DeleteBuffers(1, &buffer);
}

}  // namespace
}  // namespace test_pass_api
