#pragma once
// The largest buffers and read-write textures shadowfx makes (docs/d3d10.md, "Compute shaders and
// read-write resources"), in one place: the compiler refuses an annotation beyond them, a compiled effect
// file that holds one is corrupt, and the runtime refuses an application's data beyond them.

#include <fx/CompiledEffect.h>

#include <cstdint>

namespace fx {

// A storage buffer's or RWBuffer's elements (`int ElementCount`).
inline constexpr uint32_t kMostStorageElements = 1u << 28;
// A read-write texture's width and height.
inline constexpr int kMostImageSide = 16384;
// Each side of an RWTexture3D, and an RWTexture2DArray's layers.
inline constexpr int kMostVolumeImageSide = 2048;

// The texel formats a read-write texture or RWBuffer can have: those the compiler maps from the format
// glslang declares for its element type (no depth and no 16-bit normalized format).
inline bool isImageFormat(TextureFormat format) {
    switch (format) {
        case TextureFormat::RGBA8:
        case TextureFormat::RGBA16F:
        case TextureFormat::RGBA32F:
        case TextureFormat::R16F:
        case TextureFormat::R32F:
        case TextureFormat::RG16F:
        case TextureFormat::RG32F:
            return true;
        default:
            return false;
    }
}

}  // namespace fx
