// ImageCompare: see runtime/ImageCompare.h for the algorithm.
#include <runtime/ImageCompare.h>

#include <runtime/Image.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace runtime {
namespace {

struct Rgb {
    float r, g, b;
};

Rgb texel(const FrameImage& image, int x, int y) {
    x = std::clamp(x, 0, image.width - 1);
    y = std::clamp(y, 0, image.height - 1);
    const uint8_t* p = image.pixel(x, y);
    return {p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f};
}

// Bilinear sample at (x, y) in pixel units, pixel centres at integer coordinates, clamped at the edges.
Rgb bilinear(const FrameImage& image, float x, float y) {
    const int x0 = static_cast<int>(std::floor(x));
    const int y0 = static_cast<int>(std::floor(y));
    const float fx = x - static_cast<float>(x0);
    const float fy = y - static_cast<float>(y0);
    const Rgb a = texel(image, x0, y0), b = texel(image, x0 + 1, y0);
    const Rgb c = texel(image, x0, y0 + 1), d = texel(image, x0 + 1, y0 + 1);
    auto mix = [&](float pa, float pb, float pc, float pd) {
        return (pa * (1 - fx) + pb * fx) * (1 - fy) + (pc * (1 - fx) + pd * fx) * fy;
    };
    return {mix(a.r, b.r, c.r, d.r), mix(a.g, b.g, c.g, d.g), mix(a.b, b.b, c.b, d.b)};
}

float distance(const Rgb& a, const Rgb& b) {
    return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

// The smallest distance between `colour` and `other` near (x, y): the 3x3 neighbourhood's pixels, then
// the bilinear samples at `offsets` (sub-pixel positions relative to (x, y)).
float closest(const Rgb& colour, const FrameImage& other, int x, int y,
              const std::vector<std::array<float, 2>>& offsets) {
    float best = 1.0f;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            best = std::min(best, distance(colour, texel(other, x + dx, y + dy)));
    for (const auto& offset : offsets) {
        if (best == 0.0f) break;
        best = std::min(best, distance(colour, bilinear(other, static_cast<float>(x) + offset[0],
                                                        static_cast<float>(y) + offset[1])));
    }
    return best;
}

}  // namespace

FuzzyCompareResult fuzzyCompare(const FrameImage& reference, const FrameImage& result,
                                const FuzzyCompareOptions& options) {
    FuzzyCompareResult out;
    out.pixels = static_cast<size_t>(result.width) * static_cast<size_t>(result.height);
    out.sameSize = reference.width == result.width && reference.height == result.height &&
                   reference.rgba.size() == out.pixels * 4 && result.rgba.size() == out.pixels * 4;
    if (!out.sameSize || out.pixels == 0) {
        out.sameSize = out.sameSize && out.pixels > 0;
        out.failingPixels = out.pixels;
        out.failingFraction = 1.0;
        out.maxError = 1.0f;
        return out;
    }

    // One generator for the whole image, seeded once: mt19937's sequence is fixed by the standard (its
    // distributions are not, hence the explicit conversion to [-1, 1)).
    std::mt19937 generator(options.seed);
    auto unit = [&] { return static_cast<float>(generator() >> 8) * (2.0f / 16777216.0f) - 1.0f; };
    std::vector<std::array<float, 2>> offsets(static_cast<size_t>(std::max(options.bilinearSamples, 0)));

    out.errorMask.width = result.width;
    out.errorMask.height = result.height;
    out.errorMask.rgba.resize(out.pixels * 4);
    for (int y = 0; y < result.height; ++y) {
        for (int x = 0; x < result.width; ++x) {
            for (auto& offset : offsets) offset = {unit(), unit()};
            const float forward = closest(texel(result, x, y), reference, x, y, offsets);
            const float backward = closest(texel(reference, x, y), result, x, y, offsets);
            const float error = std::max(forward, backward);
            out.maxError = std::max(out.maxError, error);
            uint8_t* mask = &out.errorMask.rgba[(static_cast<size_t>(y) * result.width + x) * 4];
            if (error > options.deadZone) {
                ++out.failingPixels;
                mask[0] = static_cast<uint8_t>(std::lround(128.0f + 127.0f * std::min(error, 1.0f)));
                mask[1] = 0;
                mask[2] = 0;
            } else {
                const uint8_t* p = result.pixel(x, y);
                const uint8_t grey = static_cast<uint8_t>((p[0] + p[1] + p[2]) / 9);  // a third, dimmed
                mask[0] = mask[1] = mask[2] = grey;
            }
            mask[3] = 255;
        }
    }
    out.failingFraction = static_cast<double>(out.failingPixels) / static_cast<double>(out.pixels);
    out.matches = out.failingFraction <= options.threshold;
    return out;
}

std::optional<FrameImage> readPng(const std::string& path, std::string& error) {
    std::optional<Image> image = loadImageFile(path, error);
    if (!image) {
        error = path + ": " + error;
        return std::nullopt;
    }
    const Image rgba = image->toRGBA8();
    FrameImage frame;
    frame.width = rgba.width;
    frame.height = rgba.height;
    frame.rgba = rgba.bytes;
    return frame;
}

}  // namespace runtime
