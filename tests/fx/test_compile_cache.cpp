// CompileCache: a second compile of the same effect is all hits; editing one function recompiles only
// the passes that use it.
#include <fx/CompileCache.h>
#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>

#include <gtest/gtest.h>

namespace fx::test_compile_cache {
namespace {

const char* kEffect = R"(float4 Tint = {1, 1, 1, 1};
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PSA() : COLOR { return Tint; }
float4 PSB() : COLOR { return Tint * 0.5; }
technique t {
    pass a { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PSA(); }
    pass b { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PSB(); }
}
)";

std::unique_ptr<CompiledEffect> build(const std::string& src, CompileCache& cache) {
    DiagnosticList diags;
    auto effect = parseEffectSource(src, "cache.fx", ParseOptions{}, diags);
    EXPECT_TRUE(effect) << diags.str();
    if (!effect) return nullptr;
    CompileOptions options;
    options.cache = &cache;
    auto fx = compileEffect(effect, options, diags);
    EXPECT_TRUE(fx) << diags.str();
    return fx;
}

TEST(CompileCache, SecondCompileIsAllHits) {
    CompileCache cache;
    auto first = build(kEffect, cache);
    ASSERT_TRUE(first);
    EXPECT_EQ(cache.hits(), 1u);  // pass b's vertex unit equals pass a's
    EXPECT_EQ(cache.misses(), 3u);
    cache.resetCounters();
    auto second = build(kEffect, cache);
    ASSERT_TRUE(second);
    EXPECT_EQ(cache.hits(), 4u);
    EXPECT_EQ(cache.misses(), 0u);
    EXPECT_EQ(second->techniques[0].passes[1].fragment.glsl, first->techniques[0].passes[1].fragment.glsl);
}

TEST(CompileCache, EditingOneFunctionRecompilesOnlyItsPasses) {
    CompileCache cache;
    ASSERT_TRUE(build(kEffect, cache));
    cache.resetCounters();
    std::string edited = kEffect;
    edited.replace(edited.find("Tint * 0.5"), 10, "Tint * 0.7");
    auto fx = build(edited, cache);
    ASSERT_TRUE(fx);
    EXPECT_EQ(cache.misses(), 1u);  // only PSB's unit
    EXPECT_EQ(cache.hits(), 3u);
    EXPECT_NE(fx->techniques[0].passes[1].fragment.hlsl.find("0.7"), std::string::npos);
}

TEST(CompileCache, HashSeparatesStageAndOptions) {
    EXPECT_NE(CompileCache::hash("x", ShaderStage::Vertex, "o"),
              CompileCache::hash("x", ShaderStage::Fragment, "o"));
    EXPECT_NE(CompileCache::hash("ab", ShaderStage::Vertex, "c"),
              CompileCache::hash("a", ShaderStage::Vertex, "bc"));
}

}  // namespace
}  // namespace fx::test_compile_cache
