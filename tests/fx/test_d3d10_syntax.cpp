// The Direct3D 10/11 effect form (what FX11 compiles) on the fx side (no GL): technique10/technique11 and
// fxgroup, Set*Shader and Set*State in passes, state objects expanded with D3D10's defaults (which differ
// from D3D9's), D3D10 sampler defaults, cbuffer members as parameters, (texture, sampler) pairs, and the
// techniques GL cannot run left out with a located warning.
#include <fx/CompiledEffect.h>
#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <set>

namespace fx::test_d3d10_syntax {
namespace {

std::shared_ptr<const CompiledEffect> compile(const std::string& source, DiagnosticList& diagnostics) {
    std::shared_ptr<Effect> effect = parseEffectSource(source, "d3d10.fx", ParseOptions{}, diagnostics);
    if (!effect) return nullptr;
    return compileEffect(effect, CompileOptions{}, diagnostics);
}

// "file:line:column: severity: message", as the CLI prints it.
std::string str(const Diagnostic& d) {
    return d.loc.file + ":" + std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) + ": " +
           std::string(severityName(d.severity)) + ": " + d.message;
}

const Diagnostic* find(const DiagnosticList& diagnostics, DiagId id) {
    for (const Diagnostic& d : diagnostics.items())
        if (d.id == id) return &d;
    return nullptr;
}

// The constant a pass sets a state to (the last setting wins, as the runtime applies them in order).
std::optional<double> stateOf(const CompiledPass& pass, RenderStateId id) {
    std::optional<double> value;
    for (const RenderStateSetting& s : pass.states)
        if (s.id == id) value = s.constant;
    return value;
}

const char* kShaders = R"(
cbuffer PerObject : register(b0)
{
    float4x4 Wvp : WorldViewProjection;
    float4 Tint < string UIName = "Tint"; > = {1, 0.5, 0.25, 1};
};
struct VsOut { float4 Position : SV_Position; float2 Uv : UV_COORDS; };
VsOut VS(float3 p : POSITION, uint id : SV_VertexID)
{
    VsOut o;
    o.Position = mul(float4(p, 1), Wvp);
    o.Uv = float2(id & 1, id >> 1);
    return o;
}
float4 PS(VsOut i) : SV_Target0 { return Tint * float4(i.Uv, 1, 1); }
)";

std::string withTechniques(const std::string& techniques) {
    return std::string(kShaders) + techniques;
}

// [SECTION] Techniques, groups and shaders

TEST(D3d10Syntax, Technique10Technique11AndGroupsCompile) {
    DiagnosticList diagnostics;
    auto compiled = compile(withTechniques(R"(
VertexShader SharedVs = CompileShader(vs_4_0, VS());
technique10 T10 { pass P { SetVertexShader(SharedVs); SetGeometryShader(NULL); SetPixelShader(CompileShader(ps_4_0, PS())); } }
fxgroup Materials < string Note = "group"; >
{
    technique11 Plain { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetHullShader(NULL); SetDomainShader(NULL);
                               SetPixelShader(CompileShader(ps_5_0, PS())); SetComputeShader(NULL); } }
}
fxgroup Other { technique11 Plain { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(NULL); } } }
)"),
                            diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.str();
    ASSERT_EQ(compiled->techniques.size(), 3u);
    EXPECT_EQ(compiled->findTechnique("T10"), &compiled->techniques[0]);
    EXPECT_EQ(compiled->findTechnique("Plain"), &compiled->techniques[1]);
    EXPECT_EQ(compiled->findTechnique("Materials.Plain"), &compiled->techniques[1]);
    EXPECT_EQ(compiled->findTechnique("Other.Plain"), &compiled->techniques[2]);
    EXPECT_EQ(compiled->techniques[2].group, "Other");
    EXPECT_FALSE(compiled->techniques[0].passes[0].vertex.glsl.empty());
    EXPECT_NE(compiled->techniques[0].passes[0].vertex.glsl.find("gl_VertexID"), std::string::npos);
    EXPECT_TRUE(compiled->techniques[2].passes[0].fragment.glsl.empty());
}

// FX10 effects name "no shader" through a variable and declare the views their application binds; a
// struct-typed cbuffer member (a light or material record) reaches the code.
TEST(D3d10Syntax, NullShaderVariablesViewVariablesAndStructMembersCompile) {
    DiagnosticList diagnostics;
    auto compiled = compile(withTechniques(R"(
struct Material { float4 Diffuse; float4 Specular; };
cbuffer PerMaterial { Material gMaterial; Material gLayers[2]; };
RenderTargetView g_pRTV;
DepthStencilView g_pDSV;
GeometryShader gsNone = NULL;
VertexShader vsMain = CompileShader(vs_4_0, VS());
float4 MaterialPS(VsOut i) : SV_Target { return gMaterial.Diffuse + gLayers[1].Specular + Tint; }
technique10 Pool { pass { SetVertexShader(vsMain); SetGeometryShader(gsNone); SetPixelShader(CompileShader(ps_4_0, MaterialPS()));
    OMSetRenderTargets(g_pRTV, NULL, g_pDSV); } }
)"),
                            diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.str();
    const CompiledPass& pass = compiled->techniques.at(0).passes.at(0);
    EXPECT_TRUE(pass.geometry.glsl.empty());
    EXPECT_NE(pass.fragment.glsl.find("gMaterial"), std::string::npos) << pass.fragment.glsl;
    EXPECT_NE(pass.fragment.glsl.find("gLayers"), std::string::npos) << pass.fragment.glsl;
    ASSERT_TRUE(compiled->findParameter("g_pRTV"));
    EXPECT_EQ(compiled->findParameter("g_pDSV")->type.hlslName(), "DepthStencilView");
}

// OMSetRenderTargets takes the application's views and NULL; anything else is a located error.
TEST(D3d10Syntax, OMSetRenderTargetsTakesViewVariablesOrNull) {
    DiagnosticList diagnostics;
    auto compiled = compile(withTechniques(R"(
RenderTargetView g_pRTV;
technique10 Views { pass { SetVertexShader(CompileShader(vs_4_0, VS())); SetPixelShader(CompileShader(ps_4_0, PS()));
    OMSetRenderTargets(g_pRTV, Tint); } }
)"),
                            diagnostics);
    EXPECT_FALSE(compiled);
    const Diagnostic* d = find(diagnostics, DiagId::UnexpectedToken);
    ASSERT_NE(d, nullptr) << diagnostics.str();
    EXPECT_NE(
        str(*d).find("expected a RenderTargetView or DepthStencilView variable or NULL (at most nine), found "
                     "'Tint'"),
        std::string::npos)
        << str(*d);
}

TEST(D3d10Syntax, TechniqueSelectedByGroupQualifiedName) {
    DiagnosticList diagnostics;
    std::shared_ptr<Effect> effect = parseEffectSource(withTechniques(R"(
fxgroup A { technique11 T { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } } }
fxgroup B { technique11 T { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(NULL); } } }
)"),
                                                       "d3d10.fx", ParseOptions{}, diagnostics);
    ASSERT_TRUE(effect) << diagnostics.str();
    CompileOptions options;
    options.technique = "B.T";
    auto compiled = compileEffect(effect, options, diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    ASSERT_EQ(compiled->techniques.size(), 1u);
    EXPECT_EQ(compiled->techniques[0].group, "B");
}

TEST(D3d10Syntax, StreamOutDeclarationsAreReadEntryByEntryAndAMalformedEntryIsLocated) {
    // Every form D3D10's and FX11's declarations take: slots, semantic indices, partial masks, gaps, any
    // case; each entry names an output of VS (SV_Position, a float4, and UV_COORDS, a float2).
    DiagnosticList good;
    auto effect = parseEffectSource(withTechniques(R"(
GeometryShader A = ConstructGSWithSO(CompileShader(vs_4_0, VS()), "SV_POSITION.xyzw; UV_COORDS.xy");
GeometryShader B = ConstructGSWithSO(CompileShader(vs_4_0, VS()), "0:SV_Position; 1:UV_COORDS.y; $SKIP.xy; sv_position.rgba;");
GeometryShader C = ConstructGSWithSO(CompileShader(vs_5_0, VS()), "SV_POSITION.xyzw", NULL, "2:UV_COORDS0.x", NULL, 0);
)"),
                                    "d3d10.fx", ParseOptions{}, good);
    ASSERT_TRUE(effect) << good.str();
    EXPECT_FALSE(good.hasErrors()) << good.str();

    DiagnosticList bad;
    parseEffectSource(withTechniques(R"(
GeometryShader A = ConstructGSWithSO(CompileShader(vs_4_0, VS()), "SV_POSITION.xyz; UV_COORDS.xz; TIMER.x");
GeometryShader B = ConstructGSWithSO(CompileShader(vs_4_0, VS()), "7:POSITION; .xy; TEX-COORD; UV_COORDS1; UV_COORDS.xyz");
GeometryShader C = ConstructGSWithSO(CompileShader(vs_4_0, VS()));
)"),
                      "d3d10.fx", ParseOptions{}, bad);
    std::vector<std::string> errors;
    std::vector<DiagId> ids;
    for (const Diagnostic& d : bad.items())
        if (d.severity == Severity::Error) {
            errors.push_back(str(d));
            ids.push_back(d.id);
        }
    ASSERT_EQ(errors.size(), 8u) << bad.str();
    EXPECT_EQ(ids,
              (std::vector<DiagId>{DiagId::StreamOutMaskInvalid, DiagId::StreamOutOutputMissing,
                                   DiagId::StreamOutSlotInvalid, DiagId::StreamOutSemanticMissing,
                                   DiagId::StreamOutSemanticNameInvalid, DiagId::StreamOutOutputMissing,
                                   DiagId::StreamOutMaskBeyondOutput, DiagId::ConstructGSWithSOCallInvalid}));
    // Each entry's error stands at the entry's first character inside the string.
    const std::string at = "error: invalid stream-output declaration entry ";
    EXPECT_EQ(errors[0], "d3d10.fx:17:85: " + at +
                             "'UV_COORDS.xz': 'xz' is not a component mask (contiguous components of xyzw)");
    EXPECT_EQ(errors[1], "d3d10.fx:17:99: " + at + "'TIMER.x': 'VS' writes no output 'TIMER'");
    EXPECT_EQ(errors[2], "d3d10.fx:18:68: " + at + "'7:POSITION': the output slot is not one of 0..3");
    EXPECT_EQ(errors[3], "d3d10.fx:18:80: " + at + "'.xy': it names no semantic");
    EXPECT_EQ(errors[4], "d3d10.fx:18:85: " + at +
                             "'TEX-COORD': 'TEX-COORD' is not a semantic name with an optional index");
    EXPECT_EQ(errors[5], "d3d10.fx:18:96: " + at + "'UV_COORDS1': 'VS' writes no output 'UV_COORDS1'");
    EXPECT_EQ(errors[6],
              "d3d10.fx:18:108: " + at + "'UV_COORDS.xyz': output 'UV_COORDS' of 'VS' has 2 components");
    EXPECT_NE(errors[7].find("d3d10.fx:19:20: error: invalid compile expression: expected "
                             "ConstructGSWithSO(shader, \"declaration\")"),
              std::string::npos)
        << errors[7];
}

TEST(D3d10Syntax, TechniquesGlCannotRunAreLeftOutWithALocatedWarning) {
    DiagnosticList diagnostics;
    auto compiled = compile(withTechniques(R"(
technique11 Computed { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetComputeShader(CompileShader(cs_5_0, PS())); } }
technique11 Linked { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(BindInterfaces(CompileShader(ps_5_0, PS()), Light)); } }
technique11 Kept { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
)"),
                            diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    ASSERT_EQ(compiled->techniques.size(), 1u);
    EXPECT_EQ(compiled->techniques[0].name, "Kept");
    std::vector<std::string> warnings;
    std::vector<DiagId> ids;
    const Diagnostic* computed = nullptr;
    for (const Diagnostic& d : diagnostics.items())
        if (d.severity == Severity::Warning) {
            warnings.push_back(str(d));
            ids.push_back(d.id);
            if (d.id == DiagId::TechniqueRefused) computed = &d;
        }
    ASSERT_EQ(warnings.size(), 2u) << diagnostics.str();
    EXPECT_EQ(ids, (std::vector<DiagId>{DiagId::TechniqueRefusedDynamicLinkage, DiagId::TechniqueRefused}));
    // The parser's refusal is reported first, then the compiler's.
    EXPECT_NE(warnings[0].find("'Linked' is left out: dynamic shader linkage (BindInterfaces)"),
              std::string::npos)
        << warnings[0];
    // The compiler's refusal stands at the technique; the error that keeps it out follows as its note.
    EXPECT_EQ(
        warnings[1],
        "d3d10.fx:17:13: warning: technique 'Computed' is left out: it does not compile (its first error "
        "follows)");
    ASSERT_TRUE(computed) << diagnostics.str();
    ASSERT_EQ(computed->notes.size(), 1u);
    EXPECT_EQ(computed->notes[0].id, DiagId::ComputeNumThreadsMissing);
    EXPECT_EQ(str(computed->notes[0]),
              "d3d10.fx:15:8: note: compute shader 'PS' has no [numthreads(x, y, z)] attribute");
}

// [SECTION] Stream output

// ConstructGSWithSO's declaration lowered to transform-feedback varyings: the outputs by their GLSL names,
// `$SKIP` as gl_SkipComponentsN, output slots separated by gl_NextBuffer, each slot's stride, the elements
// a drawing pass reads; a vertex shader's output captured from the pass's vertex stage; what GL cannot
// capture (part of an output) leaves its technique out.
TEST(D3d10Syntax, StreamOutputDeclarationsBecomeTransformFeedbackVaryings) {
    DiagnosticList diagnostics;
    auto compiled = compile(withTechniques(R"(
struct Captured { float3 pos : POSITION; float2 uv : UV_COORDS; uint kind : KIND; };
[maxvertexcount(1)]
void GS(point VsOut input[1], inout PointStream<Captured> stream)
{
    Captured c;
    c.pos = input[0].Position.xyz;
    c.uv = input[0].Uv;
    c.kind = 1;
    stream.Append(c);
}
GeometryShader Gs = ConstructGSWithSO(CompileShader(gs_4_0, GS()), "POSITION.xyz; $SKIP.x; 1:UV_COORDS.xy; 3:KIND.x");
technique10 Slots < string Script = "Pass=P;"; > { pass P < int StreamOutVertices = 100; > { SetVertexShader(CompileShader(vs_4_0, VS())); SetGeometryShader(Gs); SetPixelShader(NULL); } }
technique10 Vertices { pass { SetVertexShader(CompileShader(vs_4_0, VS()));
    SetGeometryShader(ConstructGSWithSO(CompileShader(vs_4_0, VS()), "SV_POSITION.xyzw"));
    SetPixelShader(CompileShader(ps_4_0, PS())); } }
technique10 Partial { pass { SetVertexShader(CompileShader(vs_4_0, VS()));
    SetGeometryShader(ConstructGSWithSO(CompileShader(vs_4_0, VS()), "UV_COORDS.xy")); SetPixelShader(CompileShader(ps_4_0, PS())); } }
technique10 Whole { pass { SetVertexShader(CompileShader(vs_4_0, VS()));
    SetGeometryShader(ConstructGSWithSO(CompileShader(vs_4_0, VS()), "SV_POSITION.xyzw; UV_COORDS.xy")); SetPixelShader(NULL); } }
)"),
                            diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    ASSERT_EQ(compiled->techniques.size(), 3u) << diagnostics.str();

    const CompiledPass& slots = compiled->techniques[0].passes[0];
    ASSERT_TRUE(slots.streamOut) << slots.geometry.glsl;
    const StreamOutput& so = *slots.streamOut;
    ASSERT_EQ(so.varyings.size(), 7u);
    for (size_t i : {0u, 3u, 6u}) {
        EXPECT_EQ(so.varyings[i].rfind("gl_", 0), std::string::npos) << so.varyings[i];
        EXPECT_NE(slots.geometry.glsl.find(" " + so.varyings[i] + ";"), std::string::npos) << so.varyings[i];
    }
    EXPECT_EQ(so.varyings[1], "gl_SkipComponents1");
    EXPECT_EQ(so.varyings[2], "gl_NextBuffer");
    EXPECT_EQ(so.varyings[4], "gl_NextBuffer");
    EXPECT_EQ(so.varyings[5], "gl_NextBuffer");
    EXPECT_EQ(so.strides[0], 16u);
    EXPECT_EQ(so.strides[1], 8u);
    EXPECT_EQ(so.strides[2], 0u);
    EXPECT_EQ(so.strides[3], 4u);
    ASSERT_EQ(so.elements.size(), 3u);
    EXPECT_EQ(so.elements[0].semantic, "POSITION0");
    EXPECT_EQ(so.elements[0].components, 3);
    EXPECT_EQ(so.elements[1].semantic, "UV_COORDS0");
    EXPECT_EQ(so.elements[1].slot, 1);
    EXPECT_EQ(so.elements[2].semantic, "KIND0");
    EXPECT_EQ(so.elements[2].slot, 3);
    EXPECT_EQ(so.elements[2].component, StreamOutElement::Component::UInt);
    EXPECT_EQ(so.primitive, StreamOutput::Primitive::Points);
    EXPECT_FALSE(so.rasterizes);
    EXPECT_EQ(so.capacity, 100);
    // Not rasterized: the POSITION the declaration names stays a varying, gl_Position is not written.
    EXPECT_EQ(slots.geometry.glsl.find("gl_Position ="), std::string::npos) << slots.geometry.glsl;

    const CompiledPass& vertices = compiled->techniques[1].passes[0];
    ASSERT_TRUE(vertices.streamOut);
    EXPECT_TRUE(vertices.geometry.glsl.empty());
    EXPECT_EQ(vertices.streamOut->varyings, std::vector<std::string>{"gl_Position"});
    EXPECT_EQ(vertices.streamOut->strides[0], 16u);
    EXPECT_TRUE(vertices.streamOut->rasterizes);
    EXPECT_EQ(vertices.streamOut->primitive, StreamOutput::Primitive::Triangles);

    // Not rasterized, a vertex shader's outputs keep their types: the float2 is captured whole.
    const CompiledPass& whole = compiled->techniques[2].passes[0];
    ASSERT_TRUE(whole.streamOut);
    ASSERT_EQ(whole.streamOut->varyings.size(), 2u);
    EXPECT_NE(whole.vertex.glsl.find("out vec2 " + whole.streamOut->varyings[1] + ";"), std::string::npos)
        << whole.vertex.glsl;
    EXPECT_EQ(whole.streamOut->strides[0], 24u);
    EXPECT_FALSE(whole.streamOut->rasterizes);

    const Diagnostic* partial = find(diagnostics, DiagId::TechniqueRefused);
    ASSERT_NE(partial, nullptr) << diagnostics.str();
    EXPECT_NE(str(*partial).find("technique 'Partial' is left out"), std::string::npos) << str(*partial);
    ASSERT_EQ(partial->notes.size(), 1u) << diagnostics.str();
    EXPECT_EQ(partial->notes[0].id, DiagId::StreamOutPartialFloat4Varying);
    EXPECT_EQ(partial->notes[0].message,
              "stream-output entry 'UV_COORDS.xy' captures part of an output; GL captures whole outputs (4 "
              "components here, a float4 varying)");
}

// `string DrawAuto = "pass";` names a stream-output pass of the technique; anything else is a located error.
TEST(D3d10Syntax, DrawAutoNamesAStreamOutputPass) {
    DiagnosticList diagnostics;
    auto compiled = compile(withTechniques(R"(
technique10 T { pass Plain < string DrawAuto = "Plain"; > { SetVertexShader(CompileShader(vs_4_0, VS())); SetPixelShader(CompileShader(ps_4_0, PS())); } }
)"),
                            diagnostics);
    EXPECT_FALSE(compiled);
    const Diagnostic* error = find(diagnostics, DiagId::DrawAutoNotStreamingPass);
    ASSERT_NE(error, nullptr) << diagnostics.str();
    EXPECT_NE(str(*error).find("d3d10.fx:17:37: error: invalid annotation 'DrawAuto'"), std::string::npos)
        << str(*error);
    EXPECT_NE(
        str(*error).find("expected the name of a pass of technique 'T' whose geometry shader streams out "
                         "(ConstructGSWithSO); 'Plain' is not one"),
        std::string::npos)
        << str(*error);
}

// A technique whose code uses what the pass lowering cannot express is left out with a located warning
// while another technique runs (D3DX's next valid technique); alone, its errors fail the effect.
TEST(D3d10Syntax, ATechniqueTheLoweringCannotExpressIsLeftOutWhileAnotherRuns) {
    const std::string coverage = R"(
float4 CoveragePS(VsOut i, uint mask : SV_Coverage) : SV_Target { return Tint * mask; }
technique11 Coverage { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, CoveragePS())); } }
)";
    DiagnosticList diagnostics;
    auto compiled = compile(withTechniques(coverage + R"(
technique11 Plain { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
)"),
                            diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.str();
    ASSERT_EQ(compiled->techniques.size(), 1u);
    EXPECT_EQ(compiled->techniques[0].name, "Plain");
    EXPECT_FALSE(compiled->techniques[0].passes[0].fragment.glsl.empty());
    const Diagnostic* refused = find(diagnostics, DiagId::TechniqueRefused);
    ASSERT_TRUE(refused) << diagnostics.str();
    EXPECT_EQ(
        str(*refused),
        "d3d10.fx:18:13: warning: technique 'Coverage' is left out: it does not compile (its first error "
        "follows)");
    ASSERT_EQ(refused->notes.size(), 1u) << diagnostics.str();
    EXPECT_EQ(refused->notes[0].id, DiagId::PixelInputSemanticUnsupported);
    EXPECT_EQ(str(refused->notes[0]),
              "d3d10.fx:17:33: note: pixel input semantic 'SV_COVERAGE' is not supported");

    DiagnosticList alone;
    EXPECT_FALSE(compile(withTechniques(coverage), alone));
    const Diagnostic* error = find(alone, DiagId::PixelInputSemanticUnsupported);
    ASSERT_TRUE(error) << alone.str();
    EXPECT_EQ(error->severity, Severity::Error);
    EXPECT_FALSE(find(alone, DiagId::TechniqueRefused)) << alone.str();
}

TEST(D3d10Syntax, AnEffectWhoseTechniquesAreAllLeftOutFails) {
    DiagnosticList diagnostics;
    auto effect = parseEffectSource(withTechniques(R"(
technique11 OnlyOne { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(BindInterfaces(CompileShader(ps_5_0, PS()), Light)); } }
)"),
                                    "d3d10.fx", ParseOptions{}, diagnostics);
    EXPECT_FALSE(effect);
    const Diagnostic* d = find(diagnostics, DiagId::AllTechniquesRefusedDynamicLinkage);
    ASSERT_TRUE(d) << diagnostics.str();
    EXPECT_EQ(d->loc.line, 17);  // the BindInterfaces
    EXPECT_NE(str(*d).find("'OnlyOne', dynamic shader linkage"), std::string::npos) << str(*d);
}

// A geometry shader's declaration as the parser records it, and the pass's geometry stage as GLSL: the
// input primitive and vertex count reach the layout qualifiers, the stream element's members their
// varying locations, and the pixel shader's input takes the element member's type (float2).
TEST(D3d10Syntax, GeometryShadersBecomeTheGeometryStageOfThePass) {
    const char* source = R"(
float4x4 Wvp : WorldViewProjection;
float Grow = 0.1;
struct V { float4 p : SV_Position; float4 c : COLOR0; };
struct G { float4 p : SV_Position; float2 uv : TEXCOORD2; float4 c : COLOR0; };
V VS(float3 p : POSITION) { V v; v.p = mul(float4(p, 1), Wvp); v.c = 1; return v; }
[maxvertexcount(6)]
void GS(triangle V tri[3], inout TriangleStream<G> s, uniform float scale)
{
    for (int i = 0; i < 3; ++i) { G g; g.p = tri[i].p * (1 + Grow * scale); g.uv = g.p.xy; g.c = tri[i].c; s.Append(g); }
}
float4 PS(G g) : SV_Target { return g.c * g.uv.x; }
GeometryShader Shared = CompileShader(gs_4_0, GS(Grow * 2));
technique10 T { pass { SetVertexShader(CompileShader(vs_4_0, VS())); SetGeometryShader(Shared);
                       SetPixelShader(CompileShader(ps_4_0, PS())); } }
)";
    DiagnosticList diagnostics;
    std::shared_ptr<Effect> effect = parseEffectSource(source, "d3d10.fx", ParseOptions{}, diagnostics);
    ASSERT_TRUE(effect) << diagnostics.str();
    const FunctionDecl* gs = effect->findFunctions("GS").front();
    EXPECT_EQ(gs->maxVertexCount, 6);
    EXPECT_EQ(gs->params[0].primitive, "triangle");
    EXPECT_EQ(gs->params[1].stream, "TriangleStream");
    EXPECT_EQ(gs->params[1].type.structName, "G");
    auto compiled = compileEffect(effect, CompileOptions{}, diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    const CompiledPass& pass = compiled->techniques[0].passes[0];
    const std::string& glsl = pass.geometry.glsl;
    EXPECT_EQ(pass.geometry.stage, ShaderStage::Geometry);
    EXPECT_NE(glsl.find("layout(triangles) in;"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("max_vertices = 6"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("layout(location = 2) out vec2"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("layout(location = 8) out vec4"), std::string::npos) << glsl;
    EXPECT_NE(pass.fragment.glsl.find("layout(location = 2) in vec2"), std::string::npos)
        << pass.fragment.glsl;
    // Its own uniform block, holding the parameter it reads and its compile argument.
    EXPECT_EQ(pass.geometry.uniformBlockBinding, 2);
    std::vector<std::string> members;
    for (const UniformBinding& u : pass.geometry.uniforms)
        if (u.active) members.push_back(u.name);
    EXPECT_NE(std::find(members.begin(), members.end(), "Grow"), members.end());
    EXPECT_NE(std::find(members.begin(), members.end(), "fx_arg0"), members.end());
}

// Hull and domain shaders as the parser records them and as GL's tessellation stages: the hull shader's
// attributes and patches, three control points per patch, the partitioning and (GL-wound) output
// topology declared in the evaluation stage, each stage with its own uniform block.
TEST(D3d10Syntax, HullAndDomainShadersBecomeTheTessellationStagesOfThePass) {
    const char* source = R"(
float Factor = 4;
struct V { float3 p : POSITION; };
struct C { float e[3] : SV_TessFactor; float i : SV_InsideTessFactor; };
struct D { float4 p : SV_Position; };
V VS(float3 p : POSITION) { V v; v.p = p; return v; }
C PCF(InputPatch<V, 3> ip) { C c; c.e[0] = c.e[1] = c.e[2] = c.i = Factor; return c; }
[domain("tri")]
[partitioning("fractional_odd")]
[outputtopology("triangle_cw")]
[outputcontrolpoints(3)]
[patchconstantfunc("PCF")]
V HS(InputPatch<V, 3> ip, uint i : SV_OutputControlPointID) { return ip[i]; }
[domain("tri")]
D DS(C c, float3 uvw : SV_DomainLocation, const OutputPatch<V, 3> op)
{
    D d; d.p = float4(uvw.x * op[0].p + uvw.y * op[1].p + uvw.z * op[2].p, 1); return d;
}
float4 PS() : SV_Target { return 1; }
technique11 T { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetHullShader(CompileShader(hs_5_0, HS()));
                       SetDomainShader(CompileShader(ds_5_0, DS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
)";
    DiagnosticList diagnostics;
    std::shared_ptr<Effect> effect = parseEffectSource(source, "d3d10.fx", ParseOptions{}, diagnostics);
    ASSERT_TRUE(effect) << diagnostics.str();
    const FunctionDecl* hs = effect->findFunctions("HS").front();
    ASSERT_EQ(hs->attributes.size(), 5u);
    ASSERT_TRUE(hs->attribute("PatchConstantFunc"));
    EXPECT_EQ(hs->attribute("PatchConstantFunc")->argument, "PCF");
    EXPECT_EQ(hs->attribute("outputcontrolpoints")->argument, "3");
    EXPECT_EQ(hs->params[0].patch, "InputPatch");
    EXPECT_EQ(hs->params[0].patchSize, 3);
    EXPECT_EQ(hs->params[0].type.structName, "V");
    auto compiled = compileEffect(effect, CompileOptions{}, diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    const CompiledPass& pass = compiled->techniques[0].passes[0];
    EXPECT_EQ(pass.patchVertices, 3);
    EXPECT_EQ(pass.hull.stage, ShaderStage::Hull);
    EXPECT_EQ(pass.domain.stage, ShaderStage::Domain);
    EXPECT_NE(pass.hull.glsl.find("layout(vertices = 3) out;"), std::string::npos) << pass.hull.glsl;
    EXPECT_NE(pass.hull.glsl.find("gl_TessLevelOuter[2]"), std::string::npos) << pass.hull.glsl;
    EXPECT_NE(pass.domain.glsl.find("layout(triangles, ccw, fractional_odd_spacing) in;"), std::string::npos)
        << pass.domain.glsl;
    EXPECT_EQ(pass.hull.uniformBlockBinding, 3);
    EXPECT_EQ(pass.domain.uniformBlockBinding, 4);
    ASSERT_FALSE(pass.hull.uniforms.empty());
    EXPECT_EQ(pass.hull.uniforms[0].name, "Factor");
}

// A geometry shader's input primitive decides what the pass's draws feed it.
TEST(D3d10Syntax, GeometryShaderInputPrimitiveChoosesTheDrawPrimitive) {
    for (const auto& [input, primitive] :
         {std::pair{"point V v[1]", CompiledPass::DrawPrimitive::Points},
          std::pair{"line V v[2]", CompiledPass::DrawPrimitive::Lines},
          std::pair{"triangle V v[3]", CompiledPass::DrawPrimitive::Triangles},
          std::pair{"triangleadj V v[6]", CompiledPass::DrawPrimitive::TrianglesAdjacency}}) {
        DiagnosticList diagnostics;
        auto compiled = compile(std::string(R"(
struct V { float4 p : SV_Position; };
V VS(float3 p : POSITION) { V v; v.p = float4(p, 1); return v; }
[maxvertexcount(1)]
void GS()") + input + R"(, inout PointStream<V> s) { s.Append(v[0]); }
float4 PS() : SV_Target { return 1; }
technique11 T { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetGeometryShader(CompileShader(gs_5_0, GS()));
                       SetPixelShader(CompileShader(ps_5_0, PS())); } }
)",
                                diagnostics);
        ASSERT_TRUE(compiled) << input << "\n" << diagnostics.str();
        EXPECT_EQ(compiled->techniques[0].passes[0].primitive, primitive) << input;
    }
}

TEST(D3d10Syntax, DynamicLinkageIsRefusedWhereItIsDeclared) {
    DiagnosticList diagnostics;
    auto effect = parseEffectSource("interface ILight { float3 Light(); };\n" + withTechniques(""),
                                    "d3d10.fx", ParseOptions{}, diagnostics);
    EXPECT_FALSE(effect);
    const Diagnostic* d = find(diagnostics, DiagId::DynamicShaderLinkage);
    ASSERT_TRUE(d) << diagnostics.str();
    EXPECT_EQ(d->loc.line, 1);
    EXPECT_EQ(d->loc.column, 1);
    EXPECT_NE(str(*d).find("dynamic shader linkage ('interface')"), std::string::npos);
}

// [SECTION] State objects and defaults

TEST(D3d10Syntax, PassesStartFromD3d10DefaultsWhichDifferFromD3d9s) {
    DiagnosticList diagnostics;
    auto compiled = compile(withTechniques(R"(
technique11 Modern { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
technique Classic { pass { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)"),
                            diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    const CompiledPass& modern = compiled->techniques[0].passes[0];
    const CompiledPass& classic = compiled->techniques[1].passes[0];
    EXPECT_EQ(stateOf(modern, RenderStateId::ZFunc), 2.0);  // LESS (D3D9: LESSEQUAL)
    EXPECT_EQ(stateOf(modern, RenderStateId::StencilMask), 255.0);
    EXPECT_EQ(stateOf(modern, RenderStateId::StencilWriteMask), 255.0);
    EXPECT_EQ(stateOf(modern, RenderStateId::MultiSampleAntialias), 0.0);
    EXPECT_EQ(stateOf(modern, RenderStateId::CullMode), 3.0);  // BACK with clockwise front faces
    EXPECT_EQ(stateOf(modern, RenderStateId::DepthBiasClamp), 0.0);
    EXPECT_TRUE(classic.states.empty());  // D3D9's defaults come from the state table
    EXPECT_EQ(renderStateInfo(RenderStateId::ZFunc).defaultValue, 4.0);
    EXPECT_EQ(renderStateInfo(RenderStateId::StencilMask).defaultValue, 4294967295.0);
}

TEST(D3d10Syntax, StateObjectsSetEveryFieldTheyNameAndDefaultTheRest) {
    DiagnosticList diagnostics;
    auto compiled = compile(withTechniques(R"(
RasterizerState FrontCcw { CullMode = Back; FrontCounterClockwise = TRUE; DepthBias = 4; SlopeScaledDepthBias = 1.5; DepthClipEnable = FALSE; }
RasterizerState CullFront { CullMode = FRONT; FillMode = WIREFRAME; };
DepthStencilState Stencilled { DepthEnable = FALSE; DepthWriteMask = ZERO; StencilEnable = TRUE;
    FrontFaceStencilPass = INCR_SAT; BackFaceStencilFunc = NOT_EQUAL; StencilReadMask = 0x0F; };
BlendState Additive { BlendEnable[0] = TRUE; SrcBlend = SRC_ALPHA; DestBlend = ONE; BlendOpAlpha = REV_SUBTRACT;
    RenderTargetWriteMask[0] = 0x07; RenderTargetWriteMask[1] = 0; };
technique11 T
{
    pass A { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS()));
             SetRasterizerState(FrontCcw); SetDepthStencilState(Stencilled, 7);
             SetBlendState(Additive, float4(1, 0, 0, 1), 0xFFFFFFFF); }
    pass B { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS()));
             SetRasterizerState(CullFront); }
}
)"),
                            diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    const CompiledPass& a = compiled->techniques[0].passes[0];
    EXPECT_EQ(stateOf(a, RenderStateId::CullMode), 2.0);  // back faces are clockwise ones here
    EXPECT_EQ(stateOf(a, RenderStateId::DepthBiasUnits), 4.0);
    EXPECT_EQ(stateOf(a, RenderStateId::SlopeScaleDepthBias), 1.5);
    EXPECT_EQ(stateOf(a, RenderStateId::DepthClipEnable), 0.0);
    EXPECT_EQ(stateOf(a, RenderStateId::FillMode), 3.0);  // defaulted: SOLID
    EXPECT_EQ(stateOf(a, RenderStateId::ZEnable), 0.0);
    EXPECT_EQ(stateOf(a, RenderStateId::ZWriteEnable), 0.0);
    EXPECT_EQ(stateOf(a, RenderStateId::ZFunc), 2.0);  // defaulted: LESS
    EXPECT_EQ(stateOf(a, RenderStateId::StencilPass), 4.0);
    EXPECT_EQ(stateOf(a, RenderStateId::CCW_StencilFunc), 6.0);
    EXPECT_EQ(stateOf(a, RenderStateId::StencilMask), 15.0);
    EXPECT_EQ(stateOf(a, RenderStateId::StencilRef), 7.0);
    EXPECT_EQ(stateOf(a, RenderStateId::TwoSidedStencilMode), 1.0);
    EXPECT_EQ(stateOf(a, RenderStateId::AlphaBlendEnable), 1.0);
    EXPECT_EQ(stateOf(a, RenderStateId::SrcBlend), 5.0);
    EXPECT_EQ(stateOf(a, RenderStateId::DestBlend), 2.0);
    EXPECT_EQ(stateOf(a, RenderStateId::BlendOpAlpha), 3.0);
    EXPECT_EQ(stateOf(a, RenderStateId::ColorWriteEnable), 7.0);
    EXPECT_EQ(stateOf(a, RenderStateId::ColorWriteEnable1), 0.0);
    EXPECT_EQ(stateOf(a, RenderStateId::BlendFactor), static_cast<double>(0xFFFF0000u));
    const CompiledPass& b = compiled->techniques[0].passes[1];
    EXPECT_EQ(stateOf(b, RenderStateId::CullMode), 2.0);  // FRONT: the clockwise ones
    EXPECT_EQ(stateOf(b, RenderStateId::FillMode), 2.0);
    EXPECT_EQ(stateOf(b, RenderStateId::ZFunc), 2.0);  // no depth-stencil object: D3D10's default
    EXPECT_EQ(stateOf(b, RenderStateId::AlphaBlendEnable), 0.0);
}

TEST(D3d10Syntax, ABareVectorInAPassFunctionIsAFloat4) {
    // Game projects' shared state headers pass `vector(1.f, 1.f, 1.f, 1.f)` as the blend factor: HLSL's
    // bare `vector` is float4, and fxc evaluated it on the host as it evaluates float4(...).
    DiagnosticList diagnostics;
    auto compiled = compile(withTechniques(R"(
BlendState BS_None { BlendEnable[0] = FALSE; };
technique11 T
{
    pass P { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS()));
             SetBlendState(BS_None, vector(0.f, 1.f, 0.f, 1.f), 0xffffffff); }
    pass Q { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS()));
             SetBlendState(BS_None, mul(vector(1, 0, 0, 1), matrix(0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0,
                                                                     0, 0, 0, 1)), 0xffffffff); }
}
)"),
                            diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    EXPECT_EQ(stateOf(compiled->techniques[0].passes[0], RenderStateId::BlendFactor),
              static_cast<double>(0xFF00FF00u));
    // The row vector (1, 0, 0, 1) times the matrix that swaps x and z: blue, a program that reads nothing.
    const std::vector<RenderStateSetting>& states = compiled->techniques[0].passes[1].states;
    const auto factor = std::find_if(states.begin(), states.end(), [](const RenderStateSetting& s) {
        return s.id == RenderStateId::BlendFactor;
    });
    ASSERT_NE(factor, states.end());
    ASSERT_TRUE(factor->value.isConstant());
    EXPECT_EQ(factor->value.constant().data, (std::vector<float>{0, 0, 1, 1}));
}

TEST(D3d10Syntax, BlendStatesBlendEachRenderTargetByItsOwnFields) {
    DiagnosticList diagnostics;
    auto compiled = compile(withTechniques(R"(
BlendState PerTarget { BlendEnable[0] = TRUE; SrcBlend = ONE; DestBlend = ONE; BlendEnable[2] = TRUE;
    SrcBlend[2] = ZERO; DestBlend[2] = SRC1_COLOR; BlendOp[2] = MAX; DestBlendAlpha[3] = INV_SRC1_ALPHA; };
technique11 T { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS()));
    SetBlendState(PerTarget, float4(0, 0, 0, 0), 0xFFFFFFFF); } }
)"),
                            diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    const CompiledPass& pass = compiled->techniques[0].passes[0];
    EXPECT_EQ(stateOf(pass, RenderStateId::IndependentBlendEnable), 1.0);
    EXPECT_EQ(stateOf(pass, RenderStateId::AlphaBlendEnable), 1.0);
    EXPECT_EQ(stateOf(pass, RenderStateId::AlphaBlendEnable1), 0.0);  // D3D10: FALSE unless set
    EXPECT_EQ(stateOf(pass, RenderStateId::SrcBlend1), 2.0);          // target 0's ONE
    EXPECT_EQ(stateOf(pass, RenderStateId::AlphaBlendEnable2), 1.0);
    EXPECT_EQ(stateOf(pass, RenderStateId::SrcBlend2), 1.0);    // ZERO
    EXPECT_EQ(stateOf(pass, RenderStateId::DestBlend2), 16.0);  // SRC1_COLOR
    EXPECT_EQ(stateOf(pass, RenderStateId::BlendOp2), 5.0);     // MAX
    EXPECT_EQ(stateOf(pass, RenderStateId::DestBlendAlpha3), 19.0);
    EXPECT_EQ(stateOf(pass, RenderStateId::DestBlend7), 2.0);  // target 0's ONE
}

TEST(D3d10Syntax, StateObjectErrorsAreLocated) {
    struct Case {
        const char* source;
        int line, column;
        const char* message;
    };
    const Case cases[] = {
        {"RasterizerState R { CullMod = NONE; };", 1, 21, "unknown state 'CullMod'"},
        {"RasterizerState R { CullMode = CCW; };", 1, 32, "'CCW' is not a value of state 'CullMode'"},
        {"BlendState B { BlendEnable[0] = TRUE; RenderTargetWriteMask[5] = 0; };\ntechnique11 T { pass { "
         "SetBlendState(B, "
         "float4(0,0,0,0), 0xFFFFFFFF); } }",
         1, 39, "RenderTargetWriteMask[5] masks a render target the runtime never binds"},
        {"BlendState B { AlphaToCoverageEnable[1] = TRUE; };\ntechnique11 T { pass { SetBlendState(B, "
         "float4(0,0,0,0), 0xFFFFFFFF); } }",
         1, 16, "AlphaToCoverageEnable takes no render-target index"},
        {"DepthStencilState D { DepthEnable = FALSE; };\ntechnique11 T { pass { SetRasterizerState(D); } }",
         2, 43, "'D' is not a RasterizerState"},
        {"technique11 T { pass { SetDepthStencilState(Nowhere, 0); } }", 1, 45,
         "unknown identifier 'Nowhere'"},
        {"BlendState B { };\ntechnique11 T { pass { SetBlendState(B); } }", 2, 24,
         "expected 3 argument(s), found 1"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.source);
        DiagnosticList diagnostics;
        auto effect = parseEffectSource(c.source, "d3d10.fx", ParseOptions{}, diagnostics);
        EXPECT_FALSE(effect);
        ASSERT_TRUE(diagnostics.hasErrors());
        const Diagnostic& first = diagnostics.items().front();
        EXPECT_EQ(first.loc.line, c.line) << diagnostics.str();
        EXPECT_EQ(first.loc.column, c.column) << diagnostics.str();
        EXPECT_NE(str(first).find(c.message), std::string::npos) << diagnostics.str();
    }
}

// [SECTION] Resources

TEST(D3d10Syntax, SamplerObjectsTakeD3d10DefaultsAndD3d9SamplersKeepTheirs) {
    DiagnosticList diagnostics;
    auto compiled = compile(withTechniques(R"(
Texture2D Albedo;
texture2D OldAlbedo;
SamplerState Plain { };
SamplerState Bordered { Filter = MIN_MAG_MIP_POINT; AddressU = BORDER; BorderColor = float4(0, 0, 0, 0); MaxLOD = 2; MinLOD = 1; };
SamplerComparisonState Compare { Filter = COMPARISON_MIN_MAG_LINEAR_MIP_POINT; };
sampler2D OldSampler = sampler_state { Texture = <OldAlbedo>; };
float4 SamplePS(VsOut i) : SV_Target
{
    return Albedo.Sample(Plain, i.Uv) + Albedo.SampleLevel(Bordered, i.Uv, 0) + tex2D(OldSampler, i.Uv);
}
technique11 T { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, SamplePS())); } }
)"),
                            diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    auto sampler = [&](const char* name) -> const SamplerDesc& {
        for (const SamplerDesc& s : compiled->samplers)
            if (compiled->parameters[s.parameter].name == name) return s;
        ADD_FAILURE() << name;
        return compiled->samplers.front();
    };
    const SamplerDesc& plain = sampler("Plain");
    EXPECT_EQ(plain.minFilter, 2);
    EXPECT_EQ(plain.mipFilter, 2);
    EXPECT_EQ(plain.addressU, 3);  // CLAMP
    EXPECT_EQ(plain.borderColor[0], 1.0f);
    EXPECT_EQ(plain.comparisonFunc, 0);
    const SamplerDesc& bordered = sampler("Bordered");
    EXPECT_EQ(bordered.minFilter, 1);
    EXPECT_EQ(bordered.addressU, 4);
    EXPECT_EQ(bordered.addressV, 3);
    EXPECT_EQ(bordered.borderColor[0], 0.0f);
    EXPECT_EQ(bordered.minLod, 1.0f);
    EXPECT_EQ(bordered.maxLod, 2.0f);
    EXPECT_EQ(sampler("Compare").comparisonFunc, 1);  // NEVER, D3D11's default, until told otherwise
    const SamplerDesc& old = sampler("OldSampler");
    EXPECT_EQ(old.minFilter, 1);  // D3D9: POINT, WRAP
    EXPECT_EQ(old.addressU, 1);

    // Each (texture, sampler) pair the code samples is one GL sampler with the pair's texture, on a unit
    // after the D3D9 samplers', which its GLSL declares: the runtime sets no unit by name.
    const CompiledPass& pass = compiled->techniques[0].passes[0];
    std::vector<const SamplerBinding*> pairs;
    for (const SamplerBinding& s : pass.fragment.samplers)
        if (!s.pairTexture.empty()) pairs.push_back(&s);
    ASSERT_EQ(pairs.size(), 2u) << pass.fragment.glsl;
    for (const SamplerBinding* s : pairs) {
        EXPECT_EQ(s->pairTexture, "Albedo");
        ASSERT_TRUE(s->textureParameter);
        EXPECT_EQ(compiled->parameters[*s->textureParameter].name, "Albedo");
        EXPECT_GE(s->unit, 1);
        EXPECT_TRUE(s->read);
        const std::string declaration =
            "layout(binding = " + std::to_string(s->unit) + ") uniform sampler2D " + s->glslName + ";\n";
        EXPECT_NE(pass.fragment.glsl.find(declaration), std::string::npos)
            << declaration << pass.fragment.glsl;
    }
    EXPECT_NE(pairs[0]->unit, pairs[1]->unit);
}

// A texture and sampler handed down through user functions (two calls deep) still pair the effect's
// texture and sampler: glslang copies such arguments into temporaries, which the unit is legalized to
// forward (the pair was "param"/"param" and bound to no texture before).
TEST(D3d10Syntax, PairsPassedThroughFunctionsNameTheEffectsTextureAndSampler) {
    DiagnosticList diagnostics;
    auto compiled = compile(R"(
Texture2D Albedo;
SamplerState Point { Filter = MIN_MAG_MIP_POINT; };
float Inner(Texture2D t, SamplerState s, float2 uv) { return t.Sample(s, uv).x; }
float Outer(Texture2D t, SamplerState s, float2 uv) { return Inner(t, s, uv) + Inner(t, s, uv * 2); }
float4 VS(float4 p : POSITION) : SV_Position { return p; }
float4 PS(float4 p : SV_Position) : SV_Target { return Outer(Albedo, Point, p.xy).xxxx; }
technique11 T { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
)",
                            diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    const CompiledPass& pass = compiled->techniques[0].passes[0];
    ASSERT_EQ(pass.fragment.samplers.size(), 1u) << pass.fragment.glsl;
    const SamplerBinding& pair = pass.fragment.samplers[0];
    EXPECT_EQ(pair.pairTexture, "Albedo") << pass.fragment.glsl;
    EXPECT_EQ(pair.pairSampler, "Point");
    ASSERT_TRUE(pair.textureParameter);
    EXPECT_EQ(compiled->parameters[*pair.textureParameter].name, "Albedo");
}

// An array of textures handed on from a function that takes a texture of its own: the callee is declared
// again with the effect's array in place of its parameter, so the pair is the array's, declared and
// indexed as one (a single unnamed sampler indexed [0] before, which the GL driver refused to link).
TEST(D3d10Syntax, TextureArraysPassedThroughFunctionsKeepTheirArrayShape) {
    DiagnosticList diagnostics;
    auto compiled = compile(R"(
Texture2D Albedo;
Texture2D GBuffer[3];
SamplerState Point { Filter = MIN_MAG_MIP_POINT; };
float4 Pick(Texture2D g[3], float2 uv, int i) { return g[0].Sample(Point, uv) + g[i].Sample(Point, uv); }
float4 Outer(Texture2D t, float2 uv) { return t.Sample(Point, uv) * Pick(GBuffer, uv, int(uv.x)).z; }
float4 VS(float4 p : POSITION) : SV_Position { return p; }
float4 PS(float4 p : SV_Position) : SV_Target { return Outer(Albedo, p.xy); }
technique11 T { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
)",
                            diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    const CompiledPass& pass = compiled->techniques[0].passes[0];
    std::set<std::string> textures;
    for (const SamplerBinding& s : pass.fragment.samplers) textures.insert(s.pairTexture);
    EXPECT_EQ(textures, (std::set<std::string>{"Albedo", "GBuffer"})) << pass.fragment.glsl;
    EXPECT_NE(pass.fragment.glsl.find("uniform sampler2D fx_pair_GBuffer_Point[3];"), std::string::npos)
        << pass.fragment.glsl;
    EXPECT_NE(pass.fragment.glsl.find("fx_pair_GBuffer_Point[0]"), std::string::npos) << pass.fragment.glsl;
}

TEST(D3d10Syntax, ConstantBufferMembersAreParametersWithSemanticsAndAnnotations) {
    DiagnosticList diagnostics;
    std::shared_ptr<Effect> effect =
        parseEffectSource(withTechniques(""), "d3d10.fx", ParseOptions{}, diagnostics);
    ASSERT_TRUE(effect) << diagnostics.str();
    const Parameter* wvp = effect->findParameter("Wvp");
    ASSERT_TRUE(wvp);
    EXPECT_EQ(wvp->semantic, "WorldViewProjection");
    const Parameter* tint = effect->findParameter("Tint");
    ASSERT_TRUE(tint);
    ASSERT_TRUE(tint->annotation("UIName"));
    ASSERT_TRUE(tint->initializer);

    // FX10's shared constant buffers (shared with other effects of a pool) and tbuffers read the same.
    auto pooled =
        parseEffectSource("shared cbuffer Pool { float4x4 View : View; };\ntbuffer Lights { float3 Dir; };",
                          "pool.fx", ParseOptions{}, diagnostics);
    ASSERT_TRUE(pooled) << diagnostics.str();
    ASSERT_TRUE(pooled->findParameter("View"));
    EXPECT_EQ(pooled->findParameter("View")->semantic, "View");
    EXPECT_TRUE(pooled->findParameter("Dir"));
}

TEST(D3d10Syntax, CustomVaryingSemanticsLinkAcrossStages) {
    DiagnosticList diagnostics;
    auto compiled = compile(withTechniques(R"(
technique11 T { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
)"),
                            diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    const CompiledPass& pass = compiled->techniques[0].passes[0];
    EXPECT_NE(pass.vertex.glsl.find("layout(location = 24) out"), std::string::npos) << pass.vertex.glsl;
    EXPECT_NE(pass.fragment.glsl.find("layout(location = 24) in"), std::string::npos) << pass.fragment.glsl;
}

}  // namespace
}  // namespace fx::test_d3d10_syntax
