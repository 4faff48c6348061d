// Arrays of D3D10 state objects through the real pipeline (docs/d3d10.md, "State objects"): an element
// chosen by a constant index blends as its block says, and one chosen by a parameter follows the
// parameter's value from frame to frame.
#include "EffectHarness.h"

#include <runtime/BuiltinScenes.h>

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace shadowfx::test::test_d3d10_state_arrays {
namespace {

constexpr int kWidth = 96;
constexpr int kHeight = 64;

runtime::Scene scene(const char* name) {
    auto s = runtime::makeBuiltinScene(name, nullptr);
    if (!s) throw std::runtime_error(std::string("no scene ") + name);
    return std::move(*s);
}

int litPixels(const runtime::FrameImage& frame) {
    int lit = 0;
    for (size_t i = 0; i + 3 < frame.rgba.size(); i += 4) lit += frame.rgba[i] == 255;
    return lit;
}

// Blends[0] replaces the dark red clear by 0.25 grey, Blends[1] adds another 0.25: 0.5 grey everywhere
// (Blends[0] twice leaves 0.25; Blends[1] twice keeps the red, 1.0).
TEST(D3d10StateArrays, AConstantIndexTakesThatElementsBlock) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/state_object_arrays.fx"), true);
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, scene("boxes"), kWidth, kHeight, "Blended"));
    const runtime::FrameImage frame = renderer->readFrame();
    for (const auto& [x, y] :
         {std::pair{0, 0}, std::pair{kWidth / 2, kHeight / 2}, std::pair{kWidth - 1, kHeight - 1}}) {
        const uint8_t* p = frame.pixel(x, y);
        EXPECT_NEAR(p[0], 128, 1) << x << "," << y;
        EXPECT_NEAR(p[1], 128, 1) << x << "," << y;
        EXPECT_NEAR(p[2], 128, 1) << x << "," << y;
    }
}

// Fills[FillChoice]: FillChoice 0 fills the middle quarter of the frame, 1 draws its outline and diagonal
// only; back to 0, filled again.
TEST(D3d10StateArrays, AParameterIndexChoosesTheElementWhenThePassIsApplied) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/state_object_arrays.fx"), true);
    ASSERT_TRUE(renderer);
    const runtime::Scene boxes = scene("boxes");
    const int quarter = kWidth * kHeight / 4;
    ASSERT_TRUE(render(*renderer, boxes, kWidth, kHeight, "Filled"));
    EXPECT_NEAR(litPixels(renderer->readFrame()), quarter, kWidth + kHeight);
    EXPECT_EQ(renderer->readFrame().pixel(kWidth / 2 + 5, kHeight / 2 - 9)[0], 255);
    ASSERT_TRUE(renderer->variable("FillChoice").setInt(1));
    ASSERT_TRUE(render(*renderer, boxes, kWidth, kHeight, "Filled"));
    const runtime::FrameImage wire = renderer->readFrame();
    EXPECT_GT(litPixels(wire), kWidth / 2);
    EXPECT_LT(litPixels(wire), 4 * (kWidth + kHeight));
    EXPECT_EQ(wire.pixel(kWidth / 2 + 5, kHeight / 2 - 9)[0], 0);  // inside the quad, off its diagonal
    ASSERT_TRUE(renderer->variable("FillChoice").setInt(0));
    ASSERT_TRUE(render(*renderer, boxes, kWidth, kHeight, "Filled"));
    EXPECT_NEAR(litPixels(renderer->readFrame()), quarter, kWidth + kHeight);
}

}  // namespace
}  // namespace shadowfx::test::test_d3d10_state_arrays
