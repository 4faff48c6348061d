// What the compiler resolves for the runtime so that the runtime reads no text: each parameter's semantic
// as an enum (fx/ParameterSemantics.h) with the light it names as an index, and what each stage's code
// does besides computing its outputs (fx::StageEffects), read from its SPIR-V.
#include <fx/CompiledEffect.h>
#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace fx::test_parameter_semantics {
namespace {

std::shared_ptr<CompiledEffect> compile(const std::string& source, const std::string& name) {
    DiagnosticList diagnostics;
    std::shared_ptr<Effect> effect = parseEffectSource(source, name, ParseOptions{}, diagnostics);
    EXPECT_TRUE(effect) << diagnostics.str();
    if (!effect) return nullptr;
    std::shared_ptr<CompiledEffect> compiled = compileEffect(effect, CompileOptions{}, diagnostics);
    EXPECT_TRUE(compiled) << diagnostics.str();
    return compiled;
}

const SemanticBinding& standard(const CompiledEffect& effect, const std::string& parameter) {
    const ParameterInfo* info = effect.findParameter(parameter);
    EXPECT_TRUE(info) << parameter;
    static const SemanticBinding kNone;
    return info ? info->standard : kNone;
}

int lightIndex(const CompiledEffect& effect, const std::string& light) {
    const auto found = std::find(effect.lights.begin(), effect.lights.end(), light);
    return found == effect.lights.end() ? -2 : static_cast<int>(found - effect.lights.begin());
}

TEST(ParameterSemantics, TheCompilerClassifiesEachParameterOnce) {
    const std::shared_ptr<CompiledEffect> effect = compile(R"(
float4x4 WvpIT : worldviewprojectionINVERSETRANSPOSE;
float4x4 gWorldViewProj;
float3 gEyePosW;
float3 SunPosition : LightPosition;
float3 PlainPosition : Position;
float4 SunColour : Diffuse < string Object = "sun"; >;
float4 ObjectColour : Diffuse;
float4x4 SunViewProjection : ViewProjection < string frustum = "sun"; >;
float Scale : LISPSMNSCALE;
string Choice : LiSPSMNOpt = "Reparametrized";
float4 MapSize : ShadowMapDimensions;
static const float4x4 Fixed : World = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
float4 VS(float4 p : POSITION) : POSITION {
    return mul(p, WvpIT) + mul(p, gWorldViewProj) + mul(p, SunViewProjection) + Fixed[0] +
           float4(gEyePosW + SunPosition + PlainPosition, Scale) + SunColour + ObjectColour + MapSize;
}
float4 PS() : COLOR { return 1; }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)",
                                                           "semantics.fx");
    ASSERT_TRUE(effect);
    const SemanticBinding& wvp = standard(*effect, "WvpIT");
    EXPECT_EQ(wvp.kind, SemanticKind::WorldViewProjection);
    EXPECT_TRUE(wvp.inverse && wvp.transpose && !wvp.byName);
    EXPECT_EQ(wvp.light, -1);
    EXPECT_EQ(semanticBindingName(wvp), "WorldViewProjectionInverseTranspose");

    // Written without a semantic, bound by the name FX11 applications set it by.
    const SemanticBinding& byName = standard(*effect, "gWorldViewProj");
    EXPECT_EQ(byName.kind, SemanticKind::WorldViewProjection);
    EXPECT_TRUE(byName.byName);
    EXPECT_EQ(standard(*effect, "gEyePosW").kind, SemanticKind::CameraPosition);

    // A light property without an annotation is light0's; a plain Position is the object's: no light.
    EXPECT_EQ(standard(*effect, "SunPosition").kind, SemanticKind::LightPosition);
    EXPECT_EQ(standard(*effect, "SunPosition").light, lightIndex(*effect, "light0"));
    EXPECT_EQ(standard(*effect, "PlainPosition").kind, SemanticKind::LightPosition);
    EXPECT_EQ(standard(*effect, "PlainPosition").light, -1);
    // Diffuse is the object's colour, or with an Object annotation the light's.
    EXPECT_EQ(standard(*effect, "SunColour").kind, SemanticKind::LightColor);
    EXPECT_EQ(standard(*effect, "SunColour").light, lightIndex(*effect, "sun"));
    EXPECT_EQ(standard(*effect, "ObjectColour").kind, SemanticKind::ObjectColor);
    EXPECT_EQ(standard(*effect, "SunViewProjection").kind, SemanticKind::ViewProjection);
    EXPECT_EQ(standard(*effect, "SunViewProjection").light, lightIndex(*effect, "sun"));

    // Tunables, whatever their type; the user's own semantics and statics are left alone.
    EXPECT_EQ(standard(*effect, "Scale").kind, SemanticKind::LispsmNScale);
    EXPECT_EQ(standard(*effect, "Choice").kind, SemanticKind::LispsmNOpt);
    EXPECT_EQ(standard(*effect, "MapSize").kind, SemanticKind::None);
    EXPECT_EQ(standard(*effect, "Fixed").kind, SemanticKind::None);

    // The parameters' lights come first, in parameter order.
    ASSERT_EQ(effect->lights.size(), 2u);
    EXPECT_EQ(effect->lights[0], "light0");
    EXPECT_EQ(effect->lights[1], "sun");
}

// What D3D samples' applications set by name besides matrices: lights (one per array element), their
// number, the material and the ambient light, only where the effect gives no value of its own.
TEST(ParameterSemantics, ApplicationSetLightsAndColoursAreReadByNameWithoutAnInitializer) {
    const std::shared_ptr<CompiledEffect> effect = compile(R"(
float3 g_LightDir[3];
float4 g_LightDiffuse[3];
int g_nNumLights;
float4 g_MaterialDiffuseColor;
float4 g_MaterialAmbientColor;
float4 g_LightAmbient;
float3 g_vLightDirView;
float3 g_vLightPosView;
float3 LightDirection;
float3 gLightDir = {0, 1, 0};
float4 DiffuseColor = {1, 0, 0, 1};
int NumLights = 2;
float3 Dirs[2] : LightDirection;
float3 Positions[2] : Position;
float4 VS(float4 p : POSITION) : POSITION {
    return p + float4(g_LightDir[2] + g_vLightDirView + g_vLightPosView + LightDirection + gLightDir +
                      Dirs[1] + Positions[1], g_nNumLights + NumLights) + g_LightDiffuse[1] +
           g_MaterialDiffuseColor + g_MaterialAmbientColor + g_LightAmbient + DiffuseColor;
}
technique t { pass p { VertexShader = compile vs_3_0 VS(); } }
)",
                                                           "application.fx");
    ASSERT_TRUE(effect);
    const SemanticBinding& directions = standard(*effect, "g_LightDir");
    EXPECT_EQ(directions.kind, SemanticKind::LightDirection);
    EXPECT_TRUE(directions.byName && directions.eachLight && directions.towardsLight &&
                !directions.viewSpace);
    EXPECT_EQ(directions.light, -1);
    EXPECT_EQ(semanticBindingName(directions), "LightDirection of each light, towards the light");
    const SemanticBinding& colours = standard(*effect, "g_LightDiffuse");
    EXPECT_EQ(colours.kind, SemanticKind::LightColor);
    EXPECT_TRUE(colours.eachLight && !colours.towardsLight);
    EXPECT_EQ(standard(*effect, "g_nNumLights").kind, SemanticKind::LightCount);
    EXPECT_EQ(standard(*effect, "g_MaterialDiffuseColor").kind, SemanticKind::ObjectColor);
    EXPECT_EQ(standard(*effect, "g_MaterialAmbientColor").kind, SemanticKind::ObjectColor);
    EXPECT_EQ(standard(*effect, "g_LightAmbient").kind, SemanticKind::Ambient);
    const SemanticBinding& inView = standard(*effect, "g_vLightDirView");
    EXPECT_EQ(inView.kind, SemanticKind::LightDirection);
    EXPECT_TRUE(inView.viewSpace && inView.towardsLight && !inView.eachLight);
    EXPECT_EQ(inView.light, lightIndex(*effect, "light0"));
    const SemanticBinding& positionInView = standard(*effect, "g_vLightPosView");
    EXPECT_EQ(positionInView.kind, SemanticKind::LightPosition);
    EXPECT_TRUE(positionInView.viewSpace && !positionInView.towardsLight);
    EXPECT_TRUE(standard(*effect, "LightDirection").towardsLight);

    // An initializer is the effect's own value: these stay the effect's.
    for (const char* own : {"gLightDir", "DiffuseColor", "NumLights"})
        EXPECT_EQ(standard(*effect, own).kind, SemanticKind::None) << own;

    // Written as a semantic: an array of a light's property is one element per light, pointing as the
    // semantic does; an array of the object's Position is nobody's.
    const SemanticBinding& semanticArray = standard(*effect, "Dirs");
    EXPECT_EQ(semanticArray.kind, SemanticKind::LightDirection);
    EXPECT_TRUE(semanticArray.eachLight && !semanticArray.towardsLight && !semanticArray.byName);
    EXPECT_FALSE(standard(*effect, "Positions").eachLight);
    EXPECT_EQ(standard(*effect, "Positions").light, -1);

    // A light count without a per-light array to keep it within, and an array of arrays, stay unbound
    // by the count and the elements.
    const std::shared_ptr<CompiledEffect> single = compile(R"(
int g_nNumLights;
float3 g_LightDir;
float3 Grid[2][3] : LightDirection;
float4 VS(float4 p : POSITION) : POSITION { return p + float4(g_LightDir + Grid[1][2], g_nNumLights); }
technique t { pass p { VertexShader = compile vs_3_0 VS(); } }
)",
                                                           "single.fx");
    ASSERT_TRUE(single);
    EXPECT_EQ(standard(*single, "g_nNumLights").kind, SemanticKind::None);
    EXPECT_EQ(standard(*single, "g_LightDir").kind, SemanticKind::LightDirection);
    EXPECT_FALSE(standard(*single, "Grid").eachLight);
}

// XNA's and MonoGame's stock effects, and effects in the style of D3D9's fixed-function lights, number
// their lights in the name; the numbers count from the lowest one the effect uses.
TEST(ParameterSemantics, NumberedLightsAreReadByNameAsTheSceneLightsInOrder) {
    const std::shared_ptr<CompiledEffect> xna = compile(R"(
float3 DirLight0Direction;
float3 DirLight0DiffuseColor;
float3 DirLight0SpecularColor;
float3 DirLight2Direction;
float3 AmbientLightColor;
float3 DirLight1Direction = {0, -1, 0};
float4 VS(float4 p : POSITION) : POSITION {
    return p + float4(DirLight0Direction + DirLight0DiffuseColor + DirLight0SpecularColor + DirLight2Direction +
                      AmbientLightColor + DirLight1Direction, 0);
}
technique t { pass p { VertexShader = compile vs_3_0 VS(); } }
)",
                                                        "xna.fx");
    ASSERT_TRUE(xna);
    const SemanticBinding& first = standard(*xna, "DirLight0Direction");
    EXPECT_EQ(first.kind, SemanticKind::LightDirection);
    // As XNA's DirectionalLight::Direction: the way the light travels, as the semantic points.
    EXPECT_TRUE(first.byName && !first.towardsLight && !first.eachLight);
    EXPECT_EQ(first.light, lightIndex(*xna, "light0"));
    EXPECT_EQ(standard(*xna, "DirLight0DiffuseColor").kind, SemanticKind::LightColor);
    EXPECT_EQ(standard(*xna, "DirLight0SpecularColor").light, lightIndex(*xna, "light0"));
    const SemanticBinding& third = standard(*xna, "DirLight2Direction");
    EXPECT_EQ(third.light, lightIndex(*xna, "light2"));
    EXPECT_EQ(semanticBindingName(third, "light2"), "LightDirection of light2");
    EXPECT_EQ(standard(*xna, "AmbientLightColor").kind, SemanticKind::Ambient);
    EXPECT_EQ(standard(*xna, "DirLight1Direction").kind, SemanticKind::None);  // the effect's own value

    const std::shared_ptr<CompiledEffect> fromOne = compile(R"(
float3 g_vLight1Pos;
float4 g_vLight2Color;
float3 LightDir3;
float3 Light123Pos;
float4 VS(float4 p : POSITION) : POSITION {
    return p + float4(g_vLight1Pos + g_vLight2Color.rgb + LightDir3 + Light123Pos, 0);
}
technique t { pass p { VertexShader = compile vs_3_0 VS(); } }
)",
                                                            "from_one.fx");
    ASSERT_TRUE(fromOne);
    EXPECT_EQ(standard(*fromOne, "g_vLight1Pos").kind, SemanticKind::LightPosition);
    EXPECT_EQ(standard(*fromOne, "g_vLight1Pos").light, lightIndex(*fromOne, "light0"));
    EXPECT_EQ(standard(*fromOne, "g_vLight2Color").light, lightIndex(*fromOne, "light1"));
    EXPECT_EQ(standard(*fromOne, "LightDir3").light, lightIndex(*fromOne, "light2"));
    EXPECT_EQ(standard(*fromOne, "Light123Pos").kind, SemanticKind::None);  // no light's number

    // Beside unnumbered light properties (light0's), numbered ones follow from light1 and point as the
    // unnumbered ones do, towards the light; a light an annotation names is that light.
    const std::shared_ptr<CompiledEffect> mixed = compile(R"(
float3 g_LightDir;
float3 g_LightDir2;
float4 g_LightDiffuse2;
float3 Light3Pos < string Object = "sun"; >;
float4 VS(float4 p : POSITION) : POSITION {
    return p + float4(g_LightDir + g_LightDir2 + g_LightDiffuse2.rgb + Light3Pos, 0);
}
technique t { pass p { VertexShader = compile vs_3_0 VS(); } }
)",
                                                          "mixed.fx");
    ASSERT_TRUE(mixed);
    EXPECT_EQ(standard(*mixed, "g_LightDir").light, lightIndex(*mixed, "light0"));
    const SemanticBinding& second = standard(*mixed, "g_LightDir2");
    EXPECT_EQ(second.light, lightIndex(*mixed, "light1"));
    EXPECT_TRUE(second.towardsLight);
    EXPECT_EQ(standard(*mixed, "g_LightDiffuse2").light, lightIndex(*mixed, "light1"));
    EXPECT_EQ(standard(*mixed, "Light3Pos").light, lightIndex(*mixed, "sun"));
    EXPECT_EQ(semanticBindingName(standard(*mixed, "g_LightDir2"), "light1"),
              "LightDirection of light1, towards the light");
    SemanticBinding inverse;
    inverse.kind = SemanticKind::ViewProjection;
    inverse.inverse = true;
    EXPECT_EQ(semanticBindingName(inverse, "light1"), "ViewProjectionInverse of light1");
}

// Arrays of matrices an application fills with its bones: placed in the world where the name says so.
TEST(ParameterSemantics, SkinningPalettesAreReadByName) {
    const std::shared_ptr<CompiledEffect> effect = compile(R"(
float4x3 Bones[72];
float4x4 g_mConstBoneWorld[255];
float4x3 amPalette[26];
float4x3 g_mWorldMatrixArray[26];
float4x4 g_mTreeMatrices[50];
float4x3 SkinBones[2] = {1,0,0, 0,1,0, 0,0,1, 0,0,0, 1,0,0, 0,1,0, 0,0,1, 0,0,0};
float4x4 Palette : WorldMatrixArray;
float4 VS(float4 p : POSITION) : POSITION {
    return float4(mul(p, Bones[1]) + mul(p, amPalette[1]) + mul(p, g_mWorldMatrixArray[1]) +
                  mul(p, SkinBones[1]), 1) + mul(p, g_mConstBoneWorld[1]) + mul(p, g_mTreeMatrices[1]) +
           mul(p, Palette);
}
technique t { pass p { VertexShader = compile vs_3_0 VS(); } }
)",
                                                           "palettes.fx");
    ASSERT_TRUE(effect);
    EXPECT_EQ(standard(*effect, "Bones").kind, SemanticKind::BonePalette);
    EXPECT_EQ(standard(*effect, "amPalette").kind, SemanticKind::BonePalette);
    EXPECT_EQ(standard(*effect, "g_mConstBoneWorld").kind, SemanticKind::WorldMatrixArray);
    EXPECT_EQ(standard(*effect, "g_mWorldMatrixArray").kind, SemanticKind::WorldMatrixArray);
    EXPECT_EQ(standard(*effect, "g_mTreeMatrices").kind, SemanticKind::None);  // instances, not bones
    EXPECT_EQ(standard(*effect, "SkinBones").kind, SemanticKind::None);        // the effect's own value
    EXPECT_EQ(standard(*effect, "Palette").kind, SemanticKind::WorldMatrixArray);
    EXPECT_FALSE(standard(*effect, "Palette").byName);
}

// Engines spell their own semantics (`MATRIX_WVP`, `WorldMatrix`, MTA's `LIGHTDIFFUSE`) and names (`WorldM`,
// `ViewProjMat`, XNA's `LightViewProj`, `DestinationDimensions`): read as a name would be, where no standard
// semantic is spelled. A semantic that spells nothing stays unbound.
TEST(ParameterSemantics, EngineSpellingsOfSemanticsAndNamesAreReadAsNames) {
    const std::shared_ptr<CompiledEffect> effect = compile(R"(
float4x4 mat : MATRIX_WVP;
float4x4 matView : MATRIX_WV;
float4x4 gWorld : WorldMatrix;
float4 gSun : LIGHTDIFFUSE;
float4x4 Odd : MATRIX_BONES;
float4x4 WorldM;
float4x4 ViewProjMat;
float4x4 LightViewProj;
float4x4 Light2View;
float2 DestinationDimensions;
float2 Resolution = {256, 256};
float2 HalfPixel;
float4 VS(float4 p : POSITION) : POSITION {
    return mul(mul(mul(mul(mul(mul(mul(mul(p, mat), matView), gWorld), Odd), WorldM), ViewProjMat),
                   LightViewProj), Light2View) + gSun + float4(DestinationDimensions + Resolution + HalfPixel, 0, 0);
}
technique t { pass p { VertexShader = compile vs_3_0 VS(); } }
)",
                                                           "spellings.fx");
    ASSERT_TRUE(effect);
    const SemanticBinding& wvp = standard(*effect, "mat");
    EXPECT_EQ(wvp.kind, SemanticKind::WorldViewProjection);
    EXPECT_TRUE(wvp.byName);
    EXPECT_EQ(standard(*effect, "matView").kind, SemanticKind::WorldView);
    EXPECT_EQ(standard(*effect, "gWorld").kind, SemanticKind::World);
    const SemanticBinding& sun = standard(*effect, "gSun");
    EXPECT_EQ(sun.kind, SemanticKind::LightColor);
    EXPECT_EQ(sun.light, lightIndex(*effect, "light0"));
    EXPECT_EQ(standard(*effect, "Odd").kind, SemanticKind::None);
    EXPECT_EQ(standard(*effect, "WorldM").kind, SemanticKind::World);
    EXPECT_EQ(standard(*effect, "ViewProjMat").kind, SemanticKind::ViewProjection);
    EXPECT_EQ(standard(*effect, "ViewProjMat").light, -1);  // the camera's
    const SemanticBinding& lightViewProj = standard(*effect, "LightViewProj");
    EXPECT_EQ(lightViewProj.kind, SemanticKind::ViewProjection);
    EXPECT_EQ(lightViewProj.light, lightIndex(*effect, "light0"));
    EXPECT_EQ(standard(*effect, "Light2View").kind, SemanticKind::View);
    EXPECT_EQ(standard(*effect, "Light2View").light, lightIndex(*effect, "light0"));  // the lowest number
    EXPECT_EQ(standard(*effect, "DestinationDimensions").kind, SemanticKind::ViewportPixelSize);
    EXPECT_EQ(standard(*effect, "Resolution").kind, SemanticKind::None);  // the effect's own value
    EXPECT_EQ(standard(*effect, "HalfPixel").kind, SemanticKind::None);
}

// Lights and materials held in structs, as Luna's D3D11 book effects and many engines keep them: each
// member bound by its name in its struct's context (a light's Diffuse is its colour, a material's the
// object's), the members only an application chooses given neutral values in the initial value. A struct
// with a semantic, or of no light or material, stays the user's.
const MemberBinding* memberBinding(const CompiledEffect& effect, const std::string& parameter,
                                   const std::string& member) {
    const ParameterInfo* info = effect.findParameter(parameter);
    EXPECT_TRUE(info) << parameter;
    if (!info) return nullptr;
    for (const MemberBinding& binding : info->memberBindings)
        if (binding.member == member) return &binding;
    return nullptr;
}

TEST(ParameterSemantics, MembersOfLightAndMaterialStructsBindByTheirNames) {
    const std::shared_ptr<CompiledEffect> effect = compile(R"(
struct DirectionalLight { float4 Ambient; float4 Diffuse; float4 Specular; float3 Direction; float pad; };
struct SpotLight { float4 Ambient; float4 Diffuse; float4 Specular; float3 Position; float Range;
                   float3 Direction; float Spot; float3 Att; float pad; };
struct Material { float4 Ambient; float4 Diffuse; float4 Specular; float4 Reflect; };
struct Params { float3 Color; float Shininess; };
struct Wave { float3 Direction; float Speed; };
struct MaterialBySemantic { float4 Tint : DIFFUSE; float4 Diffuse; };
cbuffer cbPerFrame { DirectionalLight gDirLights[3]; SpotLight gSpotLight; Params gMtrl; Wave gWave; };
cbuffer cbPerObject { Material gMaterial; MaterialBySemantic gOwn; };
Material Tagged : MaterialDiffuse;
float4 PS() : SV_Target {
    return gDirLights[1].Diffuse + gDirLights[0].Ambient + gSpotLight.Ambient + gSpotLight.Diffuse *
           gSpotLight.Range * gSpotLight.Spot + float4(gSpotLight.Att + gSpotLight.Position +
           gSpotLight.Direction + gMtrl.Color + gWave.Direction, gMtrl.Shininess + gWave.Speed) +
           gMaterial.Diffuse + gMaterial.Ambient + gMaterial.Specular + gMaterial.Reflect + Tagged.Diffuse + gOwn.Diffuse;
}
technique11 t { pass p { SetPixelShader(CompileShader(ps_5_0, PS())); } }
)",
                                                           "struct_members.fx");
    ASSERT_TRUE(effect);
    // An array of lights: element k is the scene's light k; the scene's ambient once, in the first light
    // struct.
    const MemberBinding* diffuse = memberBinding(*effect, "gDirLights", "Diffuse");
    ASSERT_TRUE(diffuse);
    EXPECT_EQ(diffuse->standard.kind, SemanticKind::LightColor);
    EXPECT_TRUE(diffuse->standard.eachLight);
    EXPECT_EQ(diffuse->firstComponent, 4u);
    EXPECT_EQ(diffuse->elementStride, 16u);
    ASSERT_TRUE(memberBinding(*effect, "gDirLights", "Specular"));
    EXPECT_EQ(memberBinding(*effect, "gDirLights", "Specular")->standard.kind, SemanticKind::LightColor);
    const MemberBinding* ambient = memberBinding(*effect, "gDirLights", "Ambient");
    ASSERT_TRUE(ambient);
    EXPECT_EQ(ambient->standard.kind, SemanticKind::Ambient);
    EXPECT_FALSE(ambient->standard.eachLight);  // element 0's alone
    const MemberBinding* direction = memberBinding(*effect, "gDirLights", "Direction");
    ASSERT_TRUE(direction);
    EXPECT_EQ(direction->standard.kind, SemanticKind::LightDirection);
    EXPECT_FALSE(direction->standard.towardsLight);  // Luna's light vector is -Direction
    EXPECT_FALSE(memberBinding(*effect, "gDirLights", "pad"));
    // One light: light0's; its ambient is the first struct's already.
    const MemberBinding* position = memberBinding(*effect, "gSpotLight", "Position");
    ASSERT_TRUE(position);
    EXPECT_EQ(position->standard.kind, SemanticKind::LightPosition);
    EXPECT_EQ(position->standard.light, lightIndex(*effect, "light0"));
    ASSERT_TRUE(memberBinding(*effect, "gSpotLight", "Range"));
    EXPECT_EQ(memberBinding(*effect, "gSpotLight", "Range")->standard.kind, SemanticKind::LightRange);
    EXPECT_FALSE(memberBinding(*effect, "gSpotLight", "Ambient"));
    // Members only an application chooses: no attenuation, a modest spot exponent, in the initial value.
    const size_t spot = effect->findParameter("gSpotLight") - effect->parameters.data();
    const std::vector<float>& spotValue = effect->initialValues[spot].data;
    ASSERT_EQ(spotValue.size(), 24u);
    EXPECT_EQ(spotValue[19], 8.0f);  // Spot
    EXPECT_EQ(std::vector<float>(spotValue.begin() + 20, spotValue.begin() + 23),
              (std::vector<float>{1.0f, 0.0f, 0.0f}));  // Att
    // A material: the object's colour, a white highlight with its power in Specular.w (Luna's), no
    // reflection.
    EXPECT_EQ(memberBinding(*effect, "gMaterial", "Diffuse")->standard.kind, SemanticKind::ObjectColor);
    EXPECT_EQ(memberBinding(*effect, "gMaterial", "Ambient")->standard.kind, SemanticKind::ObjectColor);
    EXPECT_FALSE(memberBinding(*effect, "gMaterial", "Specular"));
    const size_t material = effect->findParameter("gMaterial") - effect->parameters.data();
    EXPECT_EQ(effect->initialValues[material].data,
              (std::vector<float>{0, 0, 0, 0, 0, 0, 0, 0, 0.5f, 0.5f, 0.5f, 16.0f, 0, 0, 0, 0}));
    // A struct named as a material by its parameter; its power by name.
    EXPECT_EQ(memberBinding(*effect, "gMtrl", "Color")->standard.kind, SemanticKind::ObjectColor);
    const size_t mtrl = effect->findParameter("gMtrl") - effect->parameters.data();
    EXPECT_EQ(effect->initialValues[mtrl].data[3], 16.0f);
    // Neither a light nor a material, or a semantic of its own: the user's.
    EXPECT_TRUE(effect->findParameter("gWave")->memberBindings.empty());
    EXPECT_TRUE(effect->findParameter("Tagged")->memberBindings.empty());
    EXPECT_TRUE(effect->findParameter("gOwn")->memberBindings.empty());  // its members have semantics
}

TEST(ParameterSemantics, EveryListedNameClassifiesAsItself) {
    for (const std::string& name : standardSemanticNames()) {
        SCOPED_TRACE(name);
        // Whatever the type it is written on, a semantic the runtime lists is one it takes.
        const std::shared_ptr<CompiledEffect> effect =
            compile("float4x4 P : " + name +
                        ";\nfloat4 VS(float4 p : POSITION) : POSITION { return mul(p, P); }\n"
                        "technique t { pass p { VertexShader = compile vs_3_0 VS(); } }\n",
                    "named.fx");
        ASSERT_TRUE(effect);
        EXPECT_NE(standard(*effect, "P").kind, SemanticKind::None);
    }
}

const CompiledPass& onlyPass(const CompiledEffect& effect) {
    return effect.techniques.at(0).passes.at(0);
}

// What the runtime enables per program (clip planes, program point size) and whether a pass without
// colour writes may leave its pixel stage out: from the SPIR-V, never from the GLSL's text.
TEST(StageEffects, ComeFromTheCompiledCode) {
    const std::shared_ptr<CompiledEffect> plain = compile(R"(
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)",
                                                          "plain.fx");
    ASSERT_TRUE(plain);
    const StageEffects& none = onlyPass(*plain).fragment.effects;
    EXPECT_FALSE(none.discards || none.writesDepth || none.writesSampleMask || none.writesImages ||
                 none.writesBuffers || none.atomics);
    EXPECT_FALSE(onlyPass(*plain).vertex.effects.writesDiffuse);
    EXPECT_EQ(onlyPass(*plain).vertex.effects.clipDistances, 0);

    const std::shared_ptr<CompiledEffect> busy = compile(R"(
struct VOut { float4 Pos : POSITION; float4 Colour : COLOR0; float Size : PSIZE; float2 Clip : SV_ClipDistance0; };
VOut VS(float4 p : POSITION) { VOut o; o.Pos = p; o.Colour = p; o.Size = 2; o.Clip = p.xy; return o; }
struct POut { float4 Colour : COLOR0; float Depth : DEPTH; };
POut PS(float4 c : COLOR0) { clip(c.x - 0.5); POut o; o.Colour = c; o.Depth = c.y; return o; }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)",
                                                         "busy.fx");
    ASSERT_TRUE(busy);
    const StageEffects& vertex = onlyPass(*busy).vertex.effects;
    EXPECT_TRUE(vertex.writesDiffuse);
    EXPECT_TRUE(vertex.writesPointSize);
    EXPECT_EQ(vertex.clipDistances, 2);
    const StageEffects& pixel = onlyPass(*busy).fragment.effects;
    EXPECT_TRUE(pixel.discards);
    EXPECT_TRUE(pixel.writesDepth);
    EXPECT_FALSE(pixel.writesImages || pixel.atomics);
}

TEST(StageEffects, ImageStoresAndAtomics) {
    const std::shared_ptr<CompiledEffect> effect = compile(R"(
RWTexture2D<float4> Field < int Width = 8; int Height = 8; >;
RWStructuredBuffer<uint> Counts;
[numthreads(8, 8, 1)]
void Fill(uint3 id : SV_DispatchThreadID)
{
    Field[id.xy] = float4(id.x, id.y, 0, 1);
    InterlockedAdd(Counts[0], 1);
}
technique11 t { pass p { SetComputeShader(CompileShader(cs_5_0, Fill())); } }
)",
                                                           "compute.fx");
    ASSERT_TRUE(effect);
    const StageEffects& compute = onlyPass(*effect).compute.effects;
    EXPECT_TRUE(compute.writesImages);
    EXPECT_TRUE(compute.atomics);
    EXPECT_TRUE(compute.writesBuffers);
    EXPECT_FALSE(compute.discards);
}

}  // namespace
}  // namespace fx::test_parameter_semantics
