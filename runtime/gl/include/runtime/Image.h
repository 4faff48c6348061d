// Image: pixels on the CPU, read back from render targets or loaded from files, written as PNG.
// Row 0 is the top row everywhere (render targets under the runtime's upper-left clip control, stb's
// files), so nothing is ever flipped.
#pragma once

#include <runtime/GpuTexture.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace runtime {

struct Image {
    int width = 0;
    int height = 0;
    int channels = 4;      // 1..4
    bool isFloat = false;  // float32 samples in `floats`, else 8-bit samples in `bytes`
    std::vector<uint8_t> bytes;
    std::vector<float> floats;

    static Image makeBytes(int width, int height, int channels);
    static Image makeFloats(int width, int height, int channels);

    bool empty() const { return width == 0 || height == 0; }
    // One sample, normalized (bytes / 255) for 8-bit images.
    float sample(int x, int y, int channel) const;
    // The pixel as RGBA: missing colour channels read 0, a missing alpha 1.
    glm::vec4 pixel(int x, int y) const;
    // 8-bit RGBA (floats clamped to [0, 1] and rounded), for PNG output and comparisons.
    Image toRGBA8() const;
    // Writes a PNG (8-bit; float images are clamped first). Returns false and sets `error` on failure.
    bool writePng(const std::string& path, std::string& error) const;
};

// Reads a colour texture level (2D, or a cube face) in its own channel count: 8-bit for RGBA8, float for
// float formats. For depth textures, one float channel of depth in [0, 1].
Image readColorTarget(const GpuTexture& texture, int level = 0, int face = 0);
// Same, always as floats (depth textures included).
Image readFloatTexture(const GpuTexture& texture, int level = 0, int face = 0);
// A level's size and channels, where its samples went to a buffer of the caller's.
struct ImageShape {
    int width = 0;
    int height = 0;
    int channels = 0;
};
// Same, the samples into `floats`, resized, its allocation reused where large enough: a scan over many
// large textures reads them all through one buffer instead of allocating and zeroing one for each.
ImageShape readFloatTexture(const GpuTexture& texture, std::vector<float>& floats, int level = 0,
                            int face = 0);
// Reads colour attachment `index` of the bound read framebuffer: RGBA floats, width × height from (0, 0).
Image readFramebufferColor(int index, int width, int height);
// Reads the stencil values of the bound read framebuffer as 8-bit, one channel.
Image readFramebufferStencil(int width, int height);

// PNG, TGA, JPG, BMP, ... through stb_image, as 8-bit RGBA (HDR files as float RGBA). nullopt, with
// stb_image's reason in `error`, if the file cannot be read.
std::optional<Image> loadImageFile(const std::string& path, std::string& error);

}  // namespace runtime
