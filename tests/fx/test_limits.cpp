// The configurable limits of fx::CompileOptions: a limit is an error with the id, line and column of the
// offending annotation or script command, never an allocation or a hang, and the limit itself is accepted.
// (The fixed limits of the parser and the preprocessor are in the malformed corpus, tests/data/malformed/.)
#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>

#include <gtest/gtest.h>

#include <string>

namespace fx::test_limits {
namespace {

struct Result {
    bool compiled = false;
    int maxScriptLoopCount = 0;  // the compiled effect's, which the runtime's LoopByCount obeys
    DiagnosticList diagnostics;
};

Result compile(const std::string& source, const CompileOptions& options) {
    Result result;
    ParseOptions parseOptions;
    auto effect = parseEffectSource(source, "limits.fx", parseOptions, result.diagnostics);
    if (!effect) return result;
    if (auto compiled = compileEffect(effect, options, result.diagnostics)) {
        result.compiled = true;
        result.maxScriptLoopCount = compiled->maxScriptLoopCount;
    }
    return result;
}

::testing::AssertionResult reports(const Result& result, DiagId id, int line, int column) {
    for (const Diagnostic& d : result.diagnostics.items())
        if (d.id == id && d.loc.line == line && d.loc.column == column) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "expected " << diagnosticName(id) << " at " << line << ":" << column << ", got:\n"
           << result.diagnostics.str();
}

const char* kShaders = R"(float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
)";

std::string withTarget(int size) {
    return "texture Map : RENDERCOLORTARGET < float2 Dimensions = {" + std::to_string(size) + ", " +
           std::to_string(size) + "}; >;\n" + kShaders +
           "technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } "
           "}\n";
}

std::string withLoop(int count) {
    return std::string(kShaders) + "technique t < string Script = \"LoopByCount=" + std::to_string(count) +
           "; Pass=p; LoopEnd=;\"; >\n{ pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile "
           "ps_3_0 PS(); } }\n";
}

TEST(Limits, RenderTargetSizeDefaultsTo16384) {
    CompileOptions options;
    EXPECT_EQ(options.maxRenderTargetSize, 16384);
    EXPECT_TRUE(compile(withTarget(16384), options).compiled);
    Result tooLarge = compile(withTarget(16385), options);
    EXPECT_FALSE(tooLarge.compiled);
    EXPECT_TRUE(reports(tooLarge, DiagId::RenderTargetSizeOutOfRange, 1, 42));
}

TEST(Limits, RenderTargetSizeIsConfigurable) {
    CompileOptions options;
    options.maxRenderTargetSize = 1024;
    EXPECT_TRUE(compile(withTarget(1024), options).compiled);
    Result tooLarge = compile(withTarget(2048), options);
    EXPECT_FALSE(tooLarge.compiled);
    EXPECT_TRUE(reports(tooLarge, DiagId::RenderTargetSizeOutOfRange, 1, 42));
    EXPECT_NE(tooLarge.diagnostics.str().find("1..1024"), std::string::npos) << tooLarge.diagnostics.str();
}

TEST(Limits, LiteralLoopCountIsCheckedAtCompileTime) {
    CompileOptions options;
    EXPECT_EQ(options.maxScriptLoopCount, 1024);
    EXPECT_TRUE(compile(withLoop(1024), options).compiled);
    EXPECT_EQ(compile(withLoop(1024), options).maxScriptLoopCount, 1024);
    Result tooMany = compile(withLoop(1025), options);
    EXPECT_FALSE(tooMany.compiled);
    EXPECT_TRUE(reports(tooMany, DiagId::ScriptLoopCountTooLarge, 3, 32));

    options.maxScriptLoopCount = 8;
    EXPECT_TRUE(compile(withLoop(8), options).compiled);
    EXPECT_EQ(compile(withLoop(8), options).maxScriptLoopCount, 8);  // parameter counts: the same limit
    EXPECT_TRUE(reports(compile(withLoop(9), options), DiagId::ScriptLoopCountTooLarge, 3, 32));
}

TEST(Limits, IncludeDepthAndSourceSizeAreOptions) {
    ParseOptions options;
    EXPECT_EQ(options.maxIncludeDepth, 32);
    EXPECT_EQ(options.maxSourceBytes, size_t{16} << 20);
    // Exactly at the depth limit is accepted: a chain of maxIncludeDepth distinct files.
    options.maxIncludeDepth = 3;
    options.readFile = [](const std::string& path) -> std::optional<std::string> {
        if (path == "chain0.fx") return std::string("#include \"chain1.fxh\"\n");
        const int level = path[5] - '0';
        return level < 3 ? "#include \"chain" + std::to_string(level + 1) + ".fxh\"\n"
                         : std::string("float Leaf;\n");
    };
    DiagnosticList atLimit;
    EXPECT_TRUE(parseEffectFile("chain0.fx", options, atLimit)) << atLimit.str();
    options.maxIncludeDepth = 2;
    DiagnosticList beyond;
    EXPECT_FALSE(parseEffectFile("chain0.fx", options, beyond));
    ASSERT_EQ(beyond.items().size(), 1u) << beyond.str();
    EXPECT_EQ(beyond.items()[0].loc.file, "chain2.fxh");
    EXPECT_EQ(beyond.items()[0].loc.line, 1);
    EXPECT_EQ(beyond.items()[0].loc.column, 10);
}

}  // namespace
}  // namespace fx::test_limits
