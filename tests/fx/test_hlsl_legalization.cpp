// HlslLegalization: fxc's HLSL that glslang refuses, rewritten on the lexer's tokens before glslang reads
// it; each rewrite checked in the text glslang gets and through glslang itself (the frames: the effects
// tests' FxcFrontEnd.ImplicitConversions).
#include "Glsl450.h"

#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <utility>
#include <vector>

namespace fx::test_hlsl_legalization {
namespace {

std::shared_ptr<Effect> parse(const std::string& source, DiagnosticList& diags) {
    return parseEffectSource(source, "legal.fx", ParseOptions{}, diags);
}

const FunctionDecl& function(const Effect& effect, const std::string& name) {
    const std::vector<const FunctionDecl*> found = effect.findFunctions(name);
    EXPECT_EQ(found.size(), 1u) << name;
    return *found.front();
}

// Whether `text` holds `part`, blanks aside: the preprocessor respaces tokens (`Tex . Sample`, `- 1`).
bool contains(const std::string& text, const std::string& part) {
    auto squeezed = [](std::string s) {
        s.erase(std::remove_if(s.begin(), s.end(), [](unsigned char c) { return std::isspace(c); }), s.end());
        return s;
    };
    return squeezed(text).find(squeezed(part)) != std::string::npos;
}

// Every pass compiles through glslang and SPIRV-Cross with no error and no warning.
::testing::AssertionResult compilesClean(const std::shared_ptr<Effect>& effect) {
    DiagnosticList diags;
    auto compiled = compileEffect(effect, CompileOptions{}, diags);
    if (!compiled || !diags.items().empty()) return ::testing::AssertionFailure() << diags.str();
    return ::testing::AssertionSuccess();
}

// The effect compiles with exactly one diagnostic: a warning `id` at legal.fx's `line` whose message holds
// `text`. Returns it for the checks a test adds.
Diagnostic compilesWithOneWarning(const std::shared_ptr<Effect>& effect, DiagId id, int line,
                                  const std::string& text) {
    DiagnosticList diags;
    EXPECT_TRUE(compileEffect(effect, CompileOptions{}, diags)) << diags.str();
    EXPECT_EQ(diags.items().size(), 1u) << diags.str();
    if (diags.items().empty()) return {};
    const Diagnostic& warning = diags.items().front();
    EXPECT_EQ(warning.id, id) << diags.str();
    EXPECT_EQ(warning.severity, Severity::Warning);
    EXPECT_EQ(warning.loc.file, "legal.fx");
    EXPECT_EQ(warning.loc.line, line);
    EXPECT_NE(warning.message.find(text), std::string::npos) << warning.message;
    return warning;
}

const char* kSkinning = R"(float4 Weights = {0.25, 0.25, 0.5, 0};
float4x4 Bones[4];
struct VIn { float4 Pos : POSITION; float4 Indices : BLENDINDICES; float3 Normal : NORMAL; };
float4 VS(VIn i) : POSITION {
    float w[4] = (float[4])Weights;
    int idx[4] = (int[4])i.Indices;
    float three[3] = (float[ 3 ]) mul(i.Pos, Bones[0]);
    float4 p = 0;
    for (unsigned int k = 0; k < 3; k++) p += w[k] * three[k] * mul(i.Pos, Bones[idx[k]]);
    unsigned last = 3;
    float4 sums[2] = { 0, 0, 0, 0, 1, -1, 1, w[0] };
    return p + w[last] * i.Pos + sums[1];
}
float4 PS() : COLOR { return 1; }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)";

TEST(HlslLegalization, VectorsCastToArraysFlatInitializersAndUnsigned) {
    DiagnosticList diags;
    auto effect = parse(kSkinning, diags);
    ASSERT_TRUE(effect) << diags.str();
    const std::string& vs = function(*effect, "VS").hlslText;
    EXPECT_TRUE(contains(vs, "float w[4] = fx_to_array_float_4(Weights);")) << vs;
    EXPECT_TRUE(contains(vs, "int idx[4] = fx_to_array_int_4(i.Indices);")) << vs;
    EXPECT_TRUE(contains(vs, "fx_to_array_float_3(mul(i.Pos, Bones[0]));")) << vs;
    EXPECT_TRUE(contains(vs, "for (uint k = 0;")) << vs;
    EXPECT_TRUE(contains(vs, "uint last = 3;")) << vs;
    EXPECT_FALSE(contains(vs, "unsigned")) << vs;
    EXPECT_TRUE(contains(vs, "float4 sums[2] = { float4(0, 0, 0, 0), float4(1, -1, 1, w[0]) };")) << vs;
    EXPECT_TRUE(compilesClean(effect));
}

TEST(HlslLegalization, LvalueConstructorAndKeywordsAsNames) {
    DiagnosticList diags;
    auto effect = parse(R"(float4 PS(float2 uv : TEXCOORD0, linear float4 c : COLOR0) : COLOR {
    float2 dxSize, dx;
    float dyScale; float3 dy;
    float4( dxSize, dx ) = ddx( float4( uv, uv * 2 ) );
    float4(dyScale, dy) = ddy(c);
    float line = dxSize.x;
    float point = dyScale;
    return float4(dx, line, point) + dy.xyzz;
}
float4 VS(float4 p : POSITION) : POSITION { return p; }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)",
                        diags);
    ASSERT_TRUE(effect) << diags.str();
    const std::string& ps = function(*effect, "PS").hlslText;
    EXPECT_TRUE(contains(ps, "fx_assign_float4( dxSize, dx , ddx( float4( uv, uv * 2 ) ));")) << ps;
    EXPECT_TRUE(contains(ps, "fx_assign_float4(dyScale, dy , ddy(c));")) << ps;
    EXPECT_TRUE(contains(ps, "linear float4 c")) << ps;  // the modifier stays
    EXPECT_TRUE(contains(ps, "float fx_line = dxSize.x;")) << ps;
    EXPECT_TRUE(contains(ps, "float4(dx, fx_line, fx_point)")) << ps;
    EXPECT_TRUE(compilesClean(effect));
}

// C++'s brace initialization of locals (FX11 games' `float rim{};`): zero for `{}`, a constructor for a
// numeric type's list, an initializer list for a struct's; the frame of each value:
// D3d10Effects.BraceInitializedLocalsTakeTheirValues.
TEST(HlslLegalization, BraceInitializedLocalsAreZeroOrTheirList) {
    DiagnosticList diags;
    auto effect = parse(R"(struct Pair { float a; float b; };
float4 PS() : SV_Target {
    float rim{};
    int2 n{};
    float3 v{1, 2,
             3};
    Pair p{rim, v.y};
    return float4(rim + n.x, v.x, p.b, 1);
}
float4 VS(float4 p : POSITION) : SV_Position { return p; }
technique10 t { pass p { SetVertexShader(CompileShader(vs_4_0, VS())); SetPixelShader(CompileShader(ps_4_0, PS())); } }
)",
                        diags);
    ASSERT_TRUE(effect) << diags.str();
    const std::string& ps = function(*effect, "PS").hlslText;
    EXPECT_TRUE(contains(ps, "float rim = (float)0;")) << ps;
    EXPECT_TRUE(contains(ps, "int2 n = (int2)0;")) << ps;
    EXPECT_TRUE(contains(ps, "float3 v = float3(1, 2, 3);")) << ps;
    EXPECT_TRUE(contains(ps, "Pair p = {rim, v.y};")) << ps;
    // The list's line break stays: what follows keeps its line.
    const size_t list = ps.find("float3 v"), after = ps.find("Pair p");
    ASSERT_LT(list, after) << ps;
    EXPECT_EQ(std::count(ps.begin() + static_cast<std::ptrdiff_t>(list),
                         ps.begin() + static_cast<std::ptrdiff_t>(after), '\n'),
              2)
        << ps;
    EXPECT_TRUE(compilesClean(effect));
}

// fxc's backward-compatibility mode, which D3DX9 compiled effects in, let a shader write a uniform: each
// shader works on its own copy, read by every function it calls.
TEST(HlslLegalization, AShaderWritingAUniformWorksOnItsOwnCopy) {
    DiagnosticList diags;
    auto effect = parse(R"(struct Wave { float freq; float amp; };
Wave wave[2] = { {1, 2}, {3, 4} };
float Speed = 1;
float Scale = 2;
float Height() { return wave[0].amp * wave[1].freq; }
float4 VS(float4 p : POSITION) : POSITION {
    wave[0].freq = Speed;
    wave[1].amp *= 2;
    float Scale = 3;  // a local of the same name: the uniform is not written
    Scale += 1;
    return p * Height() * Scale;
}
float4 PS() : COLOR { return wave[0].freq; }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)",
                        diags);
    ASSERT_TRUE(effect) << diags.str();
    EXPECT_TRUE(contains(function(*effect, "VS").hlslText, "fx_mutable_wave[0].freq = Speed;"));
    EXPECT_TRUE(
        contains(function(*effect, "Height").hlslText, "fx_mutable_wave[0].amp * fx_mutable_wave[1].freq"));
    EXPECT_TRUE(contains(function(*effect, "PS").hlslText, "return fx_mutable_wave[0].freq;"));
    EXPECT_TRUE(contains(function(*effect, "VS").hlslText, "Scale += 1;"));
    bool copied = false;
    for (const VerbatimDecl& v : effect->verbatim) {
        copied = copied || v.hlslText == "static Wave fx_mutable_wave[2] = wave;";
        EXPECT_FALSE(contains(v.hlslText, "Speed") || contains(v.hlslText, "Scale")) << v.hlslText;
    }
    EXPECT_TRUE(copied);
    EXPECT_TRUE(compilesClean(effect));
}

// GLSL takes constant texel offsets only (the driver refused to link `textureOffset` with a variable):
// an offset from a variable is added to the coordinate in texels of the texture's size (to Load's texel
// location), moved next to the coordinate with the line breaks it spanned left in place; a constant one,
// or one made of static consts, stays an offset.
TEST(HlslLegalization, SampleOffsetsFromVariablesMoveTheCoordinate) {
    DiagnosticList diags;
    auto effect = parse(R"(Texture2D Tex;
Texture3D Volume;
SamplerState Point;
static const int2 kStep = int2(1, 0);
float4 PS(float2 uv : TEXCOORD0) : SV_Target {
    float4 c = Tex.Sample(Point, uv, int2(1, -1)) + Tex.Sample(Point, uv, kStep);
    for (int y = -1; y < 1; y++)
        for (int x = -1; x < 1; x++)
            c += Tex.Sample(Point, uv, int2(x, y)) + Volume.Sample(Point, uv.xyx, int3(x, y, 0));
    c += Tex.SampleLevel(Point, uv, 0,
                         int2(c.x, 0)) + Tex.Load(int3(uv, 0), int2(c.y, 0));
    return c;
}
float4 VS(float4 p : POSITION) : SV_Position { return p * 2; }
technique10 t { pass p { SetVertexShader(CompileShader(vs_4_0, VS())); SetPixelShader(CompileShader(ps_4_0, PS())); } }
)",
                        diags);
    ASSERT_TRUE(effect) << diags.str();
    const std::string& ps = function(*effect, "PS").hlslText;
    EXPECT_TRUE(contains(ps, "Tex.Sample(Point, uv, int2(1, -1)) + Tex.Sample(Point, uv, kStep);")) << ps;
    EXPECT_TRUE(contains(ps, "c += Tex.Sample(Point, fx_offset_uv_Tex(uv, int2(x, y)))")) << ps;
    EXPECT_TRUE(contains(ps, "Volume.Sample(Point, fx_offset_uv_Volume(uv.xyx, int3(x, y, 0)))")) << ps;
    EXPECT_TRUE(contains(ps, "Tex.SampleLevel(Point, fx_offset_uv_Tex(uv, int2(c.x, 0)), 0)")) << ps;
    EXPECT_TRUE(contains(ps, "Tex.Load(fx_offset_texel_int3_int2(int3(uv, 0), int2(c.y, 0)))")) << ps;
    EXPECT_EQ(std::count(ps.begin(), ps.end(), '\n'), 8) << ps;  // the function's lines, as written
    EXPECT_TRUE(compilesClean(effect));
}

// `T.Length` of every object fxc defined it for compiles through glslang as a helper of the object's
// shape (the pixels of the shapes read by a pixel shader: test_d3d10_effects); a local named `Length` and
// a struct member of that name are left alone.
TEST(HlslLegalization, LengthOfTexturesAndBuffersIsAGetDimensionsHelper) {
    DiagnosticList diags;
    auto effect = parse(R"(Texture1D Line;
Texture3D Volume;
RWTexture1D<float4> OutLine;
RWTexture2D<float4> Out;
RWTexture2DArray<float4> OutLayers;
RWTexture3D<float4> OutVolume;
RWBuffer<float> OutItems;
struct Sized { uint Length; };
[numthreads(1, 1, 1)]
void CS(uint3 id : SV_DispatchThreadID) {
    Sized s; s.Length = Line.Length;
    uint Length = Volume.Length.z + s.Length;
    Out[id.xy] = float4(Out.Length, OutLayers.Length.z, Length + OutVolume.Length.x);
    OutLine[OutLine.Length - 1] = OutItems.Length;
}
technique11 t { pass p { SetComputeShader(CompileShader(cs_5_0, CS())); } }
)",
                        diags);
    ASSERT_TRUE(effect) << diags.str();
    const std::string& cs = function(*effect, "CS").hlslText;
    EXPECT_TRUE(contains(cs, "s.Length = fx_length_Line();")) << cs;
    EXPECT_TRUE(contains(cs, "uint Length = fx_length_Volume().z + s.Length;")) << cs;
    EXPECT_TRUE(
        contains(cs, "float4(fx_length_Out(), fx_length_OutLayers().z, Length + fx_length_OutVolume().x)"))
        << cs;
    EXPECT_TRUE(contains(cs, "OutLine[fx_length_OutLine() - 1] = fx_length_OutItems();")) << cs;
    EXPECT_TRUE(compilesClean(effect));
}

// A rewrite leaves the columns before it on its line alone, and every line where it was: glslang's
// message about what follows is at the user's line.
TEST(HlslLegalization, GlslangMessagesAfterARewriteKeepTheirLine) {
    DiagnosticList diags;
    auto effect = parse(R"(float4 V;
float4 VS(float4 p : POSITION) : POSITION {
    float w[4] = (float[4])V; unsigned int n = 2;
    return p * w[n] * undeclared;
}
float4 PS() : COLOR { return 1; }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)",
                        diags);
    ASSERT_TRUE(effect) << diags.str();
    EXPECT_FALSE(compileEffect(effect, CompileOptions{}, diags));
    ASSERT_TRUE(diags.hasErrors());
    const Diagnostic& error = diags.items().front();
    EXPECT_EQ(error.id, DiagId::HlslError) << diags.str();
    EXPECT_EQ(error.loc.file, "legal.fx");
    EXPECT_EQ(error.loc.line, 4) << diags.str();
    EXPECT_EQ(error.loc.column, 23) << diags.str();
}

// mul(float3, float4x4): glslang reads the matrix's first three rows as fxc did, and says so as fxc did
// (X3206), at the line of the call.
TEST(HlslLegalization, MulOfMismatchedSizesWarnsAsFxc) {
    DiagnosticList diags;
    auto effect = parse(R"(float4x4 M;
float4 VS(float4 p : POSITION) : POSITION {
    float4 r = mul(p.xyz, M);
    return r;
}
float4 PS() : COLOR { return 1; }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)",
                        diags);
    ASSERT_TRUE(effect) << diags.str();
    const Diagnostic warning = compilesWithOneWarning(effect, DiagId::ImplicitTruncation, 3, "X3206");
    EXPECT_EQ(warning.loc.column, 5);  // glslang gives no column: the statement's
}

// A vector where a smaller one or a scalar is expected (initialized, passed, returned): glslang keeps the
// first components without a word, fxc warned X3206 at the value; a constructor or cast the code spells is
// no implicit conversion.
TEST(HlslLegalization, VectorTruncationWarnsAsFxc) {
    DiagnosticList diags;
    auto effect = parse(R"(float4 Colour = {1, 0.5, 0.25, 1};
float3 shade(float3 c) { return c * 0.5; }
float4 PS() : COLOR {
    float3 rgb = Colour;
    float alpha = Colour;
    float3 spelled = float3(Colour.xyz) + (float3)Colour;
    return float4(shade(Colour) + rgb + spelled, alpha);
}
float3 narrow(float4 v) { return v; }
float4 VS(float4 p : POSITION) : POSITION { return float4(narrow(p), 1); }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)",
                        diags);
    ASSERT_TRUE(effect) << diags.str();
    ASSERT_TRUE(compileEffect(effect, CompileOptions{}, diags)) << diags.str();
    std::vector<std::pair<int, int>> at;
    for (const Diagnostic& d : diags.items()) {
        EXPECT_EQ(d.id, DiagId::ImplicitVectorTruncation) << diags.str();
        EXPECT_EQ(d.severity, Severity::Warning);
        EXPECT_EQ(d.loc.file, "legal.fx");
        EXPECT_NE(d.message.find("X3206"), std::string::npos) << d.message;
        at.emplace_back(d.loc.line, d.loc.column);
    }
    std::sort(at.begin(), at.end());
    const std::vector<std::pair<int, int>> expected = {{4, 18}, {5, 19}, {7, 25}, {9, 34}};
    EXPECT_EQ(at, expected) << diags.str();
    EXPECT_NE(diags.str().find("'float4' to 'float3'"), std::string::npos) << diags.str();
    EXPECT_NE(diags.str().find("'float4' to 'float'"), std::string::npos) << diags.str();
}

// A vector where the effect's own function takes a scalar is truncated only where the argument is
// evidently a vector; scalars (also one a closed block's vector shadowed), overloaded functions, `out`
// parameters, struct members and the function's own declaration are left as written (glslang's overload
// resolution takes them).
TEST(HlslLegalization, OnlyEvidentVectorsArePassedTruncated) {
    DiagnosticList diags;
    auto effect = parse(R"(struct S { float4 v; };
float one(float x) { return x; }
float two(float x) { return x; }
float2 two(float2 x) { return x; }
void put(out float x, float4 v) { x = v.y; }
float4 PS(float4 c : COLOR0) : COLOR {
    S s; s.v = c; float k = 2; float4 v = c; float got;
    for (int i = 0; i < 2; i++) { float4 k = c; got = k.x; }
    put(got, v);
    return float4(one(k), two(v.xy).x, one(s.v), got) * one(v);
}
technique t { pass p { PixelShader = compile ps_3_0 PS(); } }
)",
                        diags);
    ASSERT_TRUE(effect) << diags.str();
    ASSERT_EQ(diags.items().size(), 1u) << diags.str();
    EXPECT_EQ(diags.items().front().id, DiagId::ImplicitVectorTruncation);
    EXPECT_EQ(diags.items().front().loc.line, 10);
    EXPECT_EQ(diags.items().front().loc.column, 61);
    const std::string& text = function(*effect, "PS").hlslText;
    EXPECT_TRUE(contains(text, "one(v.x)")) << text;
    EXPECT_TRUE(contains(text, "one(k)")) << text;
    EXPECT_TRUE(contains(text, "two(v.xy)")) << text;
    EXPECT_TRUE(contains(text, "put(got, v)")) << text;
}

// A swizzle of several matrix elements (`M._11_22`) compiles under fxc; glslang's SPIR-V back end writes
// a constant in its place unless the swizzle is rewritten into its elements: every read compiles clean,
// of a matrix whose evaluation has no side effects (a parameter, an array element, a member, a product)
// and of one evaluated once into a temporary (a call's result), in a function or a static's initializer
// (the frames: the runtime tests' MatrixSwizzles).
TEST(HlslLegalization, AMatrixSwizzleReadCompilesClean) {
    DiagnosticList diags;
    auto effect = parse(R"(float4x4 M;
float4x4 Bones[2];
int Bone = 1;
struct Frame { float3x3 basis; };
float4x4 twice() { return M * 2; }
static float2 Scale = twice()._11_22;
float4 PS() : COLOR {
    Frame f;
    f.basis = (float3x3)M;
    float2 diagonal = M._11_22 + M._m01_m10.yx + twice()._21_12 * Scale;
    float3 picked = Bones[Bone]._12_23_34 + f.basis._m02_m11_m20 + mul(M, M)._41_42_43;
    return float4(diagonal, M._m01 + M[2].y, dot(picked, Bones[(int)M._44]._14_24_34)) + Bones[0]._11_22_33_44;
}
float4 VS(float4 p : POSITION) : POSITION { return p; }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)",
                        diags);
    ASSERT_TRUE(effect) << diags.str();
    EXPECT_TRUE(compilesClean(effect));
}

// A swizzle of several elements incremented still compiles to glslang's constant, with a warning at it
// (an error would refuse effects whose swizzle feeds nothing, such as a function D3DX ran on the host).
TEST(HlslLegalization, AMatrixSwizzleIncrementedIsAWarningAtIt) {
    DiagnosticList diags;
    auto written = parse(R"(float4x4 M;
float4 PS() : COLOR {
    float4x4 w = M;
    w._11_22_33++;
    return w[0];
}
float4 VS(float4 p : POSITION) : POSITION { return p; }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)",
                         diags);
    ASSERT_TRUE(written) << diags.str();
    const Diagnostic warning =
        compilesWithOneWarning(written, DiagId::HlslWarning, 4, "swizzle of 3 matrix elements written here");
    EXPECT_NE(warning.message.find("float3 v = m._11_22_33; v++; m._11_22_33 = v;"), std::string::npos)
        << warning.message;
}

// Elements of the swizzle written (`w._11_22.x = e;`, `[1]`, an `out` argument, `++`), several of them
// through a vector swizzle (`w._11_22_33.zx = e;`, compound too) or whole through an `out` argument: those
// elements are written (their values: MatrixSwizzles in tests/runtime/, MatrixSwizzleWrites in
// tests/effects/), no warning; glslang alone crashed on each or wrote a constant.
TEST(HlslLegalization, AWriteThroughAMatrixSwizzleCompilesClean) {
    for (const char* write : {"w._11_22.x = 0.5;", "w._11_22[1] = 0.5;", "halve(w._11_22.y);",
                              "w._11_22.x++;", "w._11_22_33.zx = 0.25;", "w._11_22_33.zx *= float2(2, 3);",
                              "halve3(w._11_22_33);", "halve3(w._m00_m01_m02.zxy);"}) {
        DiagnosticList diags;
        auto written = parse(std::string(R"(float4x4 M;
void halve(out float v) { v = 0.5; }
void halve3(out float3 v) { v = 0.5; }
float4 PS() : COLOR {
    float4x4 w = M;
    )") + write + R"(
    return w[0];
}
float4 VS(float4 p : POSITION) : POSITION { return p; }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)",
                             diags);
        ASSERT_TRUE(written) << write << "\n" << diags.str();
        DiagnosticList compileDiags;
        EXPECT_TRUE(compileEffect(written, CompileOptions{}, compileDiags)) << write << "\n"
                                                                            << compileDiags.str();
        EXPECT_TRUE(compileDiags.items().empty()) << write << "\n" << compileDiags.str();
    }
}

// Integer and bool matrices (docs/legalization.md, "Integer and bool matrices"): element-wise operations,
// comparisons and an int2x3 parameter compile into arrays of rows, which GLSL has (their values:
// IntegerMatrices in tests/effects/); what cannot be computed row by row is an error where it stands.
TEST(HlslLegalization, IntegerMatricesCompileIntoArraysOfRows) {
    DiagnosticList diags;
    auto effect = parse(R"(RWByteAddressBuffer Words;
int2x3 Offsets = { 1, -2, 3, 4, 5, -6 };
[numthreads(4, 1, 1)]
void CS(uint i : SV_GroupIndex) {
    int2x3 e = int2x3(i, 2, 3, 4, 5, 6) + Offsets;
    e = (e == 0) ? e : (e << 2) ^ 1;
    const bool2x3 negative = e < 0;
    Words.Store(i * 4, e[1].z + (any(negative) ? 1u : 0u));
}
technique11 t { pass p { SetComputeShader(CompileShader(cs_5_0, CS())); } }
)",
                        diags);
    ASSERT_TRUE(effect) << diags.str();
    DiagnosticList compileDiags;
    auto compiled = compileEffect(effect, CompileOptions{}, compileDiags);
    ASSERT_TRUE(compiled && compileDiags.items().empty()) << compileDiags.str();
    const std::string& glsl = compiled->techniques[0].passes[0].compute.glsl;
    EXPECT_NE(glsl.find("ivec3 Offsets[2];"), std::string::npos) << glsl;
    EXPECT_EQ(glsl.find("imat"), std::string::npos) << glsl;
    EXPECT_EQ(glsl.find("bmat"), std::string::npos) << glsl;
}

// A matrix built from vectors that are not its rows (a float2x3 from a float4 and a float2) is compared
// element by element from its elements, not from those vectors taken as rows (which wrote invalid SPIR-V).
TEST(HlslLegalization, AMatrixBuiltFromVectorsOfOtherSizesComparesByElement) {
    DiagnosticList diags;
    auto effect = parse(R"(float2x3 M;
float4 PS(float2 uv : TEXCOORD0) : COLOR {
    const bool2x3 equal = float2x3(float4(uv, 1, 2), float2(3, 4)) == M;
    return equal[1].z ? 1 : 0;
}
float4 VS(float4 p : POSITION) : POSITION { return p; }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)",
                        diags);
    ASSERT_TRUE(effect) << diags.str();
    DiagnosticList compileDiags;
    const std::unique_ptr<CompiledEffect> compiled = compileEffect(effect, CompileOptions{}, compileDiags);
    ASSERT_TRUE(compiled) << compileDiags.str();
    EXPECT_TRUE(test::compilesAsGlsl450(compiled->techniques[0].passes[0].fragment));
}

// Parses and compiles `source`, which must parse and must not compile: its first diagnostic, an error in
// legal.fx.
Diagnostic firstCompileError(const std::string& source) {
    DiagnosticList diags;
    auto effect = parse(source, diags);
    EXPECT_TRUE(effect) << diags.str();
    if (!effect) return {};
    DiagnosticList compileDiags;
    EXPECT_FALSE(compileEffect(effect, CompileOptions{}, compileDiags) && !compileDiags.hasErrors())
        << source;
    EXPECT_FALSE(compileDiags.items().empty()) << source;
    if (compileDiags.items().empty()) return {};
    const Diagnostic error = compileDiags.items().front();
    EXPECT_EQ(error.severity, Severity::Error) << compileDiags.str();
    EXPECT_EQ(error.loc.file, "legal.fx") << compileDiags.str();
    return error;
}

// HLSL's `*` multiplies matrices element by element; one of matrices of different shapes, or of a vector
// and a matrix, which glslang reads as a product and fxc truncated first, is an error at the operator.
TEST(HlslLegalization, AStarProductOfDifferentShapesIsAnErrorAtTheOperator) {
    for (const char* statement :
         {"float2x2 m = M23 * M32;", "float3 v = V * M33;", "float2x3 m = M23; m *= M22;",
          // Constants, whose product glslang computes while it parses.
          "float2x2 m = C23 * float3x2(1, 2, 3, 4, 5, 6);", "float3 v = float3(1, 2, 3) * C33;"}) {
        const Diagnostic error =
            firstCompileError(std::string(R"(float2x3 M23; float3x2 M32; float3x3 M33; float2x2 M22; float3 V;
static const float2x3 C23 = {1, 2, 3, 4, 5, 6}; static const float3x3 C33 = {1, 2, 3, 4, 5, 6, 7, 8, 9};
float4 PS() : SV_Target {
    )") + statement + R"(
    return 1;
}
technique10 t { pass p { SetPixelShader(CompileShader(ps_4_0, PS())); } }
)");
        EXPECT_EQ(error.id, DiagId::HlslError) << error.message;
        EXPECT_EQ(error.loc.line, 4) << error.message;
        EXPECT_EQ(error.loc.column, static_cast<int>(std::string(statement).find('*')) + 5) << error.message;
        EXPECT_NE(error.message.find("element by element"), std::string::npos) << error.message;
    }
}

TEST(HlslLegalization, IntegerMatrixOperationsThatCannotBeSplitAreLocatedErrors) {
    struct Case {
        const char* declarations;
        const char* statement;
        DiagId id;
        int column;  // 0: not checked (SPIRV-Cross's message stands at the pass's CompileShader)
        const char* text;
    };
    for (const Case& c : {
             Case{"RWByteAddressBuffer Words;", "Words.Store(0, transpose(int2x2(i, 1, 2, 3))[0].y);",
                  DiagId::HlslError, 48, "transpose() of an integer or bool matrix is not supported"},
             Case{"RWByteAddressBuffer Words;", "Words.Store(0, ((int3x3)int2x2(i, 1, 2, 3))[2].z);",
                  DiagId::HlslError, 0, "a matrix made from a smaller matrix is not supported"},
             Case{"struct E { uint2x2 m; }; RWStructuredBuffer<E> Words;",
                  "Words[i].m = uint2x2(i, 2, 3, 4);", DiagId::CrossCompileError, 0,
                  "an integer or bool matrix in a structured buffer's element"},
             Case{"RWByteAddressBuffer Words; struct S { int3x2 m; }; cbuffer Params { S s; }",
                  "Words.Store(0, s.m[2].y + i);", DiagId::CrossCompileError, 0, "declare it row_major"},
         }) {
        const Diagnostic error = firstCompileError(std::string(c.declarations) + R"(
[numthreads(1, 1, 1)]
void CS(uint i : SV_GroupIndex) {
    )" + c.statement + R"(
}
technique11 t { pass p { SetComputeShader(CompileShader(cs_5_0, CS())); } }
)");
        EXPECT_EQ(error.id, c.id) << error.message;
        // glslang places the call at its closing parenthesis; SPIRV-Cross's refusal is the shader's, at the
        // technique's CompileShader.
        EXPECT_EQ(error.loc.line, c.id == DiagId::HlslError ? 4 : 6) << error.message;
        if (c.column) {
            EXPECT_EQ(error.loc.column, c.column) << error.message;
        }
        EXPECT_NE(error.message.find(c.text), std::string::npos) << error.message;
    }
}

}  // namespace
}  // namespace fx::test_hlsl_legalization
