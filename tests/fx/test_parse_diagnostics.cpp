// Diagnostics of the effect front end: one test per bad-input class, naming the id, line and column.
#include <fx/EffectParser.h>

#include <gtest/gtest.h>

#include <map>

namespace test_parse_diagnostics {

using namespace fx;

namespace {

std::shared_ptr<Effect> parse(const std::string& source, DiagnosticList& diags,
                              const std::map<std::string, std::string>& files = {}) {
    ParseOptions options;
    options.readFile = [files](const std::string& path) -> std::optional<std::string> {
        auto found = files.find(path);
        if (found == files.end()) return std::nullopt;
        return found->second;
    };
    return parseEffectSource(source, "bad.fx", options, diags);
}

::testing::AssertionResult hasDiagnostic(const DiagnosticList& diags, DiagId id, int line, int column,
                                         const std::string& fragment = "") {
    for (const Diagnostic& d : diags.items())
        if (d.id == id && d.loc.line == line && d.loc.column == column &&
            d.message.find(fragment) != std::string::npos)
            return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "no " << diagnosticName(id) << " at " << line << ":" << column
                                         << " containing '" << fragment << "'; got:\n"
                                         << diags.str();
}

}  // namespace

TEST(ParseDiagnostics, SyntaxError) {
    DiagnosticList diags;
    EXPECT_FALSE(parse("float a = 1;\nfloat b = 2 3;\n", diags));
    EXPECT_TRUE(hasDiagnostic(diags, DiagId::UnexpectedToken, 2, 13, "found '3'"));
}

TEST(ParseDiagnostics, UnclosedPassNamesItsOpener) {
    DiagnosticList diags;
    EXPECT_FALSE(parse("technique t {\n  pass p0 {\n    CullMode = None;\n", diags));
    EXPECT_TRUE(hasDiagnostic(diags, DiagId::UnclosedBlock, 3, 21, "to close 'pass' at line 2"));
}

TEST(ParseDiagnostics, UnclosedPassBeforeNextPass) {
    DiagnosticList diags;
    EXPECT_FALSE(parse("technique t {\n  pass p0 {\n    CullMode = None;\n  pass p1 { }\n}\n", diags));
    EXPECT_TRUE(
        hasDiagnostic(diags, DiagId::UnclosedBlock, 4, 3, "'}' expected (to close 'pass' at line 2)"));
}

TEST(ParseDiagnostics, UnclosedFunctionBody) {
    DiagnosticList diags;
    EXPECT_FALSE(parse("float4 PS() : COLOR\n{\n  return 1;\n", diags));
    EXPECT_TRUE(hasDiagnostic(diags, DiagId::UnclosedBlock, 3, 12, "at line 2"));
}

TEST(ParseDiagnostics, UnknownState) {
    DiagnosticList diags;
    EXPECT_FALSE(parse("technique t { pass p {\n    CullMood = None;\n} }\n", diags));
    EXPECT_TRUE(hasDiagnostic(diags, DiagId::UnknownState, 2, 5, "'CullMood'"));
}

TEST(ParseDiagnostics, UnknownStateValue) {
    DiagnosticList diags;
    EXPECT_FALSE(parse("technique t { pass p {\n    CullMode    =   Sideways;\n} }\n", diags));
    EXPECT_TRUE(hasDiagnostic(diags, DiagId::UnknownStateValue, 2, 21, "None, CW, CCW"));
}

TEST(ParseDiagnostics, UnknownSamplerStateValue) {
    DiagnosticList diags;
    EXPECT_FALSE(parse("sampler s = sampler_state {\n  AddressU = Repeat;\n};\n", diags));
    EXPECT_TRUE(hasDiagnostic(diags, DiagId::UnknownStateValue, 2, 14, "Wrap"));
}

TEST(ParseDiagnostics, MissingInclude) {
    DiagnosticList diags;
    EXPECT_FALSE(parse("float a;\n  #include \"nothere.fxh\"\n", diags));
    EXPECT_TRUE(hasDiagnostic(diags, DiagId::IncludeNotFound, 2, 12, "nothere.fxh"));
}

TEST(ParseDiagnostics, ErrorInsideIncludedFileNamesThatFile) {
    DiagnosticList diags;
    EXPECT_FALSE(
        parse("#include \"inc/a.fxh\"\nfloat ok;\n", diags, {{"inc/a.fxh", "float x;\nfloat y = ;\n"}}));
    ASSERT_EQ(diags.errorCount(), 1u) << diags.str();
    EXPECT_EQ(diags.items()[0].loc.file, "inc/a.fxh");
    EXPECT_TRUE(hasDiagnostic(diags, DiagId::UnexpectedToken, 2, 11));
}

TEST(ParseDiagnostics, PreprocessorErrorDirective) {
    DiagnosticList diags;
    EXPECT_FALSE(parse("float a;\n#if 1\n  #error stop here\n#endif\n", diags));
    EXPECT_TRUE(hasDiagnostic(diags, DiagId::PreprocessorError, 3, 3, "stop here"));
}

TEST(ParseDiagnostics, UnknownType) {
    DiagnosticList diags;
    EXPECT_FALSE(parse("float a;\nfloat5 b;\n", diags));
    EXPECT_TRUE(hasDiagnostic(diags, DiagId::UnknownType, 2, 1, "float5"));
}

TEST(ParseDiagnostics, Redefinition) {
    DiagnosticList diags;
    EXPECT_FALSE(parse("float a;\nint   a;\n", diags));
    EXPECT_TRUE(hasDiagnostic(diags, DiagId::Redefinition, 2, 7));
}

TEST(ParseDiagnostics, RecoversAndReportsSeveralErrors) {
    DiagnosticList diags;
    EXPECT_FALSE(
        parse("float a = ;\nfloat b;\nfloat c = );\ntechnique t { pass { ZEnable = maybe; } }\n", diags));
    EXPECT_EQ(diags.errorCount(), 3u) << diags.str();
    EXPECT_TRUE(hasDiagnostic(diags, DiagId::UnknownStateValue, 4, 32));
}

TEST(ParseDiagnostics, StopsAfterTwentyErrors) {
    std::string source;
    for (int i = 0; i < 100; ++i) source += "float x" + std::to_string(i) + " = ;\n";
    DiagnosticList diags;
    EXPECT_FALSE(parse(source, diags));
    EXPECT_LE(diags.errorCount(), 20u);
    EXPECT_GE(diags.errorCount(), 10u);
}

TEST(ParseDiagnostics, NeverCrashesOnHostileInput) {
    std::vector<std::string> inputs = {
        "",
        "technique",
        "technique t { pass p { VertexShader = compile",
        "float a = ((((((((",
        "struct S { float a",
        "sampler s = sampler_state { Texture = <",
        "\xff\xfe\x80 float \xc3\x28 x;",
        "float a <",
        "float a < string s = \"abc",
        "}}}}}}",
        "float4 f() { { { {",
        "typedef",
        "cbuffer c {",
        "float a[",
        "[numthreads(1,1,1)",
    };
    std::string deep = "float a = ";
    for (int i = 0; i < 5000; ++i) deep += "(";
    inputs.push_back(deep);
    std::string deepUnary = "float a = ";
    for (int i = 0; i < 5000; ++i) deepUnary += "-";
    inputs.push_back(deepUnary + "1;");
    std::string braces = "float a = ";
    for (int i = 0; i < 5000; ++i) braces += "{";
    inputs.push_back(braces);
    for (const std::string& input : inputs) {
        DiagnosticList diags;
        auto effect = parse(input, diags);
        if (!input.empty()) {
            EXPECT_FALSE(effect) << input.substr(0, 40);
        }
        EXPECT_EQ(effect == nullptr, diags.hasErrors());
    }
}

TEST(ParseDiagnostics, FileNotFound) {
    DiagnosticList diags;
    ParseOptions options;
    EXPECT_FALSE(parseEffectFile("/nonexistent/dir/x.fx", options, diags));
    ASSERT_EQ(diags.items().size(), 1u);
    EXPECT_EQ(diags.items()[0].id, DiagId::FileNotFound);
}
}  // namespace test_parse_diagnostics
