// The fuzzy image comparison (runtime/ImageCompare.h) on a real rendered frame: the shipped golden of the
// thesis effect on dual-l (a render of llvmpipe, made by `shadowfx check --update`), against copies of it
// moved, blurred, blanked or touched in one pixel.
#include <runtime/ImageCompare.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace test_image_compare {

namespace {

runtime::FrameImage loadGolden() {
    std::string error;
    std::optional<runtime::FrameImage> image =
        runtime::readPng("effects/golden/thesis_fxcomposer/main/dual-l.png", error);
    EXPECT_TRUE(image) << error;
    return image.value_or(runtime::FrameImage{});
}

// The image moved right by `dx` pixels (the left columns repeat the first one).
runtime::FrameImage shifted(const runtime::FrameImage& image, int dx) {
    runtime::FrameImage out = image;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            std::copy_n(image.pixel(std::max(x - dx, 0), y), 4,
                        &out.rgba[(static_cast<size_t>(y) * image.width + x) * 4]);
    return out;
}

// The image resampled half a pixel to the right (each pixel the mean of itself and its left neighbour): a
// sub-pixel move of every edge, which the bilinear search must accept.
runtime::FrameImage halfPixelShifted(const runtime::FrameImage& image) {
    runtime::FrameImage out = image;
    for (int y = 0; y < image.height; ++y)
        for (int x = 1; x < image.width; ++x)
            for (int c = 0; c < 3; ++c)
                out.rgba[(static_cast<size_t>(y) * image.width + x) * 4 + c] =
                    static_cast<uint8_t>((image.pixel(x, y)[c] + image.pixel(x - 1, y)[c] + 1) / 2);
    return out;
}

TEST(ImageCompare, AnImageMatchesItself) {
    const runtime::FrameImage golden = loadGolden();
    ASSERT_EQ(golden.width, 320);
    const runtime::FuzzyCompareResult result = runtime::fuzzyCompare(golden, golden);
    EXPECT_TRUE(result.matches);
    EXPECT_EQ(result.failingPixels, 0u);
    EXPECT_EQ(result.maxError, 0.0f);
}

TEST(ImageCompare, AShiftByAFewPixelsFails) {
    const runtime::FrameImage golden = loadGolden();
    for (int dx : {2, 3, 5}) {
        const runtime::FuzzyCompareResult result = runtime::fuzzyCompare(golden, shifted(golden, dx));
        EXPECT_FALSE(result.matches) << dx << " px: " << result.failingPixels << " failing pixels";
        EXPECT_GT(result.failingFraction, 0.001) << dx;
    }
}

TEST(ImageCompare, AOnePixelShiftAndAHalfPixelResampleMatch) {
    const runtime::FrameImage golden = loadGolden();
    EXPECT_TRUE(runtime::fuzzyCompare(golden, shifted(golden, 1)).matches);  // the 3x3 neighbourhood
    const runtime::FuzzyCompareResult half = runtime::fuzzyCompare(golden, halfPixelShifted(golden));
    EXPECT_TRUE(half.matches) << half.failingPixels;
}

TEST(ImageCompare, OneDifferentPixelIsCountedButWithinTolerance) {
    const runtime::FrameImage golden = loadGolden();
    runtime::FrameImage touched = golden;
    uint8_t* p = &touched.rgba[(static_cast<size_t>(120) * touched.width + 160) * 4];
    p[0] = 255, p[1] = 0, p[2] = 255;
    const runtime::FuzzyCompareResult result = runtime::fuzzyCompare(golden, touched);
    EXPECT_TRUE(result.matches);
    EXPECT_EQ(result.failingPixels, 1u);
    EXPECT_GT(result.maxError, 0.5f);
    // The error mask marks exactly that pixel red.
    const uint8_t* mask = result.errorMask.pixel(160, 120);
    EXPECT_GT(mask[0], 128);
    EXPECT_EQ(mask[1], 0);
}

TEST(ImageCompare, ASmallColourChangeInsideTheDeadZoneIsNoError) {
    const runtime::FrameImage golden = loadGolden();
    runtime::FrameImage brighter = golden;
    for (size_t i = 0; i < brighter.rgba.size(); i += 4)
        for (int c = 0; c < 3; ++c)
            brighter.rgba[i + c] = static_cast<uint8_t>(std::min(255, brighter.rgba[i + c] + 8));
    EXPECT_EQ(runtime::fuzzyCompare(golden, brighter).failingPixels, 0u);
    runtime::FrameImage darker = golden;  // 40 of 255: far outside it
    for (size_t i = 0; i < darker.rgba.size(); i += 4)
        for (int c = 0; c < 3; ++c)
            darker.rgba[i + c] = static_cast<uint8_t>(std::max(0, darker.rgba[i + c] - 40));
    EXPECT_FALSE(runtime::fuzzyCompare(golden, darker).matches);
}

TEST(ImageCompare, ABlankImageFails) {
    const runtime::FrameImage golden = loadGolden();
    runtime::FrameImage blank = golden;
    for (size_t i = 0; i < blank.rgba.size(); i += 4) std::copy_n(golden.pixel(0, 0), 4, &blank.rgba[i]);
    const runtime::FuzzyCompareResult result = runtime::fuzzyCompare(golden, blank);
    EXPECT_FALSE(result.matches);
    EXPECT_GT(result.failingFraction, 0.3);  // the L and the plane cover most of the frame
}

TEST(ImageCompare, AFeatureMissingFromTheResultIsFound) {
    // The search runs both ways: a thin dark line in the reference, absent from the result, must fail even
    // though every result pixel finds its own colour next to the line.
    const runtime::FrameImage golden = loadGolden();
    runtime::FrameImage lined = golden;
    for (int y = 0; y < lined.height; ++y) {
        uint8_t* p = &lined.rgba[(static_cast<size_t>(y) * lined.width + 40) * 4];
        p[0] = p[1] = p[2] = 0;
    }
    EXPECT_FALSE(runtime::fuzzyCompare(lined, golden).matches);
    EXPECT_FALSE(runtime::fuzzyCompare(golden, lined).matches);
}

TEST(ImageCompare, DifferentSizesNeverMatchAndTheResultIsDeterministic) {
    const runtime::FrameImage golden = loadGolden();
    runtime::FrameImage smaller;
    smaller.width = golden.width - 1;
    smaller.height = golden.height;
    smaller.rgba.assign(static_cast<size_t>(smaller.width) * smaller.height * 4, 128);
    const runtime::FuzzyCompareResult sizes = runtime::fuzzyCompare(golden, smaller);
    EXPECT_FALSE(sizes.sameSize);
    EXPECT_FALSE(sizes.matches);

    const runtime::FrameImage moved = halfPixelShifted(shifted(golden, 2));
    const runtime::FuzzyCompareResult a = runtime::fuzzyCompare(golden, moved);
    const runtime::FuzzyCompareResult b = runtime::fuzzyCompare(golden, moved);
    EXPECT_EQ(a.failingPixels, b.failingPixels);
    EXPECT_EQ(a.errorMask.rgba, b.errorMask.rgba);
}

TEST(ImageCompare, ReadPngReportsAMissingFile) {
    std::string error;
    EXPECT_FALSE(runtime::readPng("effects/golden/no/such.png", error));
    EXPECT_NE(error.find("no/such.png"), std::string::npos) << error;
}

}  // namespace
}  // namespace test_image_compare
