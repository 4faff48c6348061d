// The runtime runs a pass's preshader programs (its expression-valued render states and compile
// arguments) only when a parameter they read has changed: the dry run evaluates the states once per pass
// for the executor, and a frame that changes nothing runs none (FrameStats::preshaderRuns).
#include "runtime/LeaveOutFrames.h"

#include <runtime/BuiltinScenes.h>
#include <runtime/Scene.h>

namespace shadowfx::test::test_preshader_runs {
namespace {

const char* kEffect = R"(
float4x4 WorldViewProjection : WorldViewProjection;
float Scale = 1.0;
bool DepthOn = true;
struct Out { float4 Position : POSITION; };
Out VS(float4 position : POSITION, uniform float scale)
{
    Out o;
    o.Position = mul(float4(position.xyz * scale, 1), WorldViewProjection);
    return o;
}
float4 PS() : COLOR { return float4(1, 1, 1, 1); }
float4 Black = {0, 0, 0, 1};
technique t
{
    pass p < string Script = "ClearSetColor=Black; Clear=Color; Clear=Depth; Draw=Geometry;"; >
    {
        ZEnable = DepthOn;
        VertexShader = compile vs_3_0 VS(Scale * 0.5);
        PixelShader = compile ps_3_0 PS();
    }
}
)";

TEST(PreshaderRuns, OnlyWhenAnInputChanged) {
    auto renderer = loadEffect(kEffect, false);
    ASSERT_TRUE(renderer);
    const runtime::Scene scene = *runtime::makeBuiltinScene("boxes");
    ASSERT_GT(scene.objects.size(), 2u);

    const StatsFrame first = renderWithStats(*renderer, scene, "", true);
    EXPECT_TRUE(notConstant(first.image));
    EXPECT_EQ(first.stats.preshaderRuns, 2u);  // the state, once for every draw; the argument, once
    const StatsFrame same = renderWithStats(*renderer, scene, "", true);
    EXPECT_EQ(same.stats.preshaderRuns, 0u);
    EXPECT_EQ(differingPixels(first.image, same.image), 0u);

    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(renderer->setParameterFromText("Scale", "0.5", diagnostics));
    const StatsFrame scaled = renderWithStats(*renderer, scene, "", true);
    EXPECT_EQ(scaled.stats.preshaderRuns, 1u);  // the argument that reads Scale
    EXPECT_GT(differingPixels(first.image, scaled.image), 0u);

    ASSERT_TRUE(renderer->setParameterFromText("DepthOn", "false", diagnostics));
    EXPECT_EQ(renderWithStats(*renderer, scene, "", true).stats.preshaderRuns, 1u);  // the state
}

}  // namespace
}  // namespace shadowfx::test::test_preshader_runs
