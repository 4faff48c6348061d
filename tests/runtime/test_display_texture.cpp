// normalizeForDisplay: how the viewer makes float render targets (R32F shadow maps) visible.
#include <runtime/DisplayTexture.h>

#include <gtest/gtest.h>

#include <vector>

namespace test_display_texture {

namespace {

TEST(DisplayTexture, ShadowMapDepthsSpanBlackToWhiteAndTheClearValueIsWhite) {
    // A 4x1 R32F shadow map: two depths and two texels still at the thesis effect's clear value.
    const std::vector<float> texels = {0.25f, 0.75f, 8184.0f, 8184.0f};
    const runtime::FrameImage image = runtime::normalizeForDisplay(texels, 4, 1, 1);
    ASSERT_EQ(image.width, 4);
    EXPECT_EQ(image.pixel(0, 0)[0], 0);    // nearest depth: black
    EXPECT_EQ(image.pixel(1, 0)[0], 255);  // farthest real depth: white, not squashed by the clear value
    EXPECT_EQ(image.pixel(2, 0)[0], 255);
    EXPECT_EQ(image.pixel(1, 0)[1], image.pixel(1, 0)[0]);  // one channel shows as grey
    EXPECT_EQ(image.pixel(0, 0)[3], 255);
}

TEST(DisplayTexture, TwoChannelMomentsShowAsRedAndGreen) {
    const std::vector<float> texels = {0.0f, 0.0f, 1.0f, 2.0f};
    const runtime::FrameImage image = runtime::normalizeForDisplay(texels, 2, 1, 2);
    EXPECT_EQ(image.pixel(0, 0)[0], 0);
    EXPECT_EQ(image.pixel(1, 0)[0], 255);
    EXPECT_EQ(image.pixel(1, 0)[1], 255);
    EXPECT_EQ(image.pixel(1, 0)[2], 0);
}

TEST(DisplayTexture, TooFewTexelsGiveAnEmptyImage) {
    EXPECT_EQ(runtime::normalizeForDisplay({1.0f}, 2, 2, 1).width, 0);
}

}  // namespace
}  // namespace test_display_texture
