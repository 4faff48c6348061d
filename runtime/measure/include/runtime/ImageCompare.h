// ImageCompare: a fuzzy comparison of a rendered frame with a reference image, after the idea of dEQP's
// fuzzy image compare (drawElements Quality Program, tcu::fuzzyCompare): rasterizers may legitimately
// move an edge by a fraction of a pixel or round a colour differently, so a pixel is compared not with
// the one reference pixel at its position but with the closest colour found near it.
//
// For every pixel p of one image, the error is the smallest colour distance between p and
//   - the 9 pixels of the other image's 3x3 neighbourhood around p's position, and
//   - `bilinearSamples` bilinear samples of the other image at sub-pixel positions drawn uniformly from
//     that neighbourhood (centres within one pixel of p's) by a generator with a fixed seed, so two runs
//     on the same images give the same answer.
// The colour distance is the largest absolute difference of the red, green and blue channels, in [0, 1]
// (alpha is ignored: frames are opaque). The search runs both ways (result in reference, reference in
// result) and a pixel's error is the larger one, so that a thin feature missing from either image is
// found. Errors at or below the dead zone count as 0 (8-bit rounding, dithering of gradients). A pixel
// with a non-zero error is a failing pixel; the images match if the failing pixels are at most
// `threshold` of all pixels. Images of different sizes never match.
#pragma once

#include <runtime/FrameImage.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace runtime {

struct FuzzyCompareOptions {
    float deadZone = 0.06f;      // colour distance (0..1) that still counts as equal: about 15 of 255
    double threshold = 0.001;    // largest fraction of failing pixels that matches (0.1%: 77 at 320x240)
    int bilinearSamples = 8;     // random sub-pixel samples per pixel, besides the 9 pixel centres
    uint32_t seed = 0x5eedf00d;  // fixed: the comparison is deterministic
};

struct FuzzyCompareResult {
    bool sameSize = false;
    size_t pixels = 0;
    size_t failingPixels = 0;      // pixels whose error is above the dead zone
    double failingFraction = 0.0;  // failingPixels / pixels (1 when the sizes differ)
    float maxError = 0.0f;         // the largest pixel error (0..1), dead zone not applied
    bool matches = false;          // sameSize and failingFraction <= threshold
    // The result in dimmed grey with failing pixels in red (brighter = larger error); empty when the sizes
    // differ.
    FrameImage errorMask;
};

FuzzyCompareResult fuzzyCompare(const FrameImage& reference, const FrameImage& result,
                                const FuzzyCompareOptions& options = {});

// Reads a PNG (or any image stb_image reads) as 8-bit RGBA; nullopt with `error` set on failure.
std::optional<FrameImage> readPng(const std::string& path, std::string& error);

}  // namespace runtime
