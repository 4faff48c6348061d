// FrameImage: an 8-bit RGBA image read back from a frame, the currency of frame readback, PNG output,
// image comparison and display.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace runtime {

// An RGBA image read back from the frame (8 bits per channel, rows top to bottom).
struct FrameImage {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgba;

    const uint8_t* pixel(int x, int y) const { return &rgba[(static_cast<size_t>(y) * width + x) * 4]; }
};

}  // namespace runtime
