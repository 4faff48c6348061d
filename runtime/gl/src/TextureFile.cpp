// TextureFile: the DDS reader (see TextureFile.h). Block-compressed formats are decoded by libsquish;
// everything else here. Layout after Microsoft's "DDS" programming guide: "DDS ", the 124-byte DDS_HEADER
// with its 32-byte DDS_PIXELFORMAT, the 20-byte DDS_HEADER_DXT10 when the FourCC is "DX10", then the data:
// per array element, per cube face, per mip level, that level's depth slices, rows top first, no padding.
//
// [SECTION] Reading bytes
// [SECTION] Texel formats (D3D9 pixel formats, D3D9 FourCC codes, DXGI formats)
// [SECTION] Header
// [SECTION] Decoding
#include <runtime/TextureFile.h>

#include <squish.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

namespace runtime {

namespace {

// [SECTION] Reading bytes

uint32_t readU32(const uint8_t* at) {
    return uint32_t(at[0]) | uint32_t(at[1]) << 8 | uint32_t(at[2]) << 16 | uint32_t(at[3]) << 24;
}

float halfToFloat(uint16_t h) {
    const uint32_t sign = uint32_t(h >> 15) << 31;
    const int exponent = (h >> 10) & 0x1f;
    const uint32_t mantissa = h & 0x3ffu;
    float value;
    if (exponent == 0)
        value = std::ldexp(static_cast<float>(mantissa), -24);
    else if (exponent == 31)
        value = mantissa ? std::numeric_limits<float>::quiet_NaN() : std::numeric_limits<float>::infinity();
    else
        value = std::ldexp(static_cast<float>(mantissa | 0x400u), exponent - 25);
    return sign ? -value : value;
}

// [SECTION] Texel formats
// Three families cover what D3D9 and D3D10 wrote to DDS files:
// - bit masks over a texel of at most 32 bits (every D3D9 pixel format with masks, and the DXGI formats
//   that are such a texel: R8G8B8A8, B8G8R8A8, R10G10B10A2, R8G8, R8, A8);
// - whole components of 16 or 32 bits (the float formats, and 16-bit UNORM);
// - 4x4 blocks: DXT1-5 (BC1-3) decoded by libsquish; ATI1/ATI2 (BC4/BC5) here, since Debian's libsquish
//   1.15 decodes their blocks as colour blocks.
// A channel a format lacks reads as Direct3D reads it: D3D9's formats 1 in every missing channel (its
// "Texture Formats" page: "the default value for formats that do not contain all channels" is 1), DXGI's
// 0 in a missing colour channel and 1 in a missing alpha.

enum class Component { Unorm16, Half, Float };

struct TexelFormat {
    enum class Family { Masks, Components, Blocks };
    Family family = Family::Masks;
    int bytes = 0;  // per texel; per 4x4 block for Blocks
    // Masks: the R, G, B, A masks (0: channel absent); `luminance` replicates R into G and B.
    std::array<uint32_t, 4> masks{};
    bool luminance = false;
    // Components: the type and, for R, G, B, A, the stored component it reads (-1: absent).
    Component component = Component::Float;
    std::array<int, 4> swizzle{-1, -1, -1, -1};
    // Blocks: libsquish's flag for BC1-3, else BC4 (1 channel) or BC5 (2) decoded here.
    int squishFlags = 0;
    int blockChannels = 4;
    float missingColour = 0.0f;  // what an absent R, G or B reads
};

TexelFormat masks(int bits, uint32_t r, uint32_t g, uint32_t b, uint32_t a, float missingColour,
                  bool luminance = false) {
    TexelFormat f;
    f.family = TexelFormat::Family::Masks;
    f.bytes = bits / 8;
    f.masks = {r, g, b, a};
    f.luminance = luminance;
    f.missingColour = missingColour;
    return f;
}

TexelFormat components(Component component, int count, std::array<int, 4> swizzle, float missingColour) {
    TexelFormat f;
    f.family = TexelFormat::Family::Components;
    f.component = component;
    f.bytes = count * (component == Component::Float ? 4 : 2);
    f.swizzle = swizzle;
    f.missingColour = missingColour;
    return f;
}

TexelFormat blocks(int squishFlags, int bytes, int channels = 4) {
    TexelFormat f;
    f.family = TexelFormat::Family::Blocks;
    f.bytes = bytes;
    f.squishFlags = squishFlags;
    f.blockChannels = channels;
    return f;
}

constexpr std::array<int, 4> kR = {0, -1, -1, -1}, kRG = {0, 1, -1, -1}, kRGBA = {0, 1, 2, 3};

std::optional<TexelFormat> fourCCFormat(uint32_t fourCC) {
    auto code = [](const char* s) { return readU32(reinterpret_cast<const uint8_t*>(s)); };
    // DXT2 and DXT4 hold premultiplied alpha; D3D9 sampled their texels as stored, as here.
    if (fourCC == code("DXT1")) return blocks(squish::kDxt1, 8);
    if (fourCC == code("DXT2") || fourCC == code("DXT3")) return blocks(squish::kDxt3, 16);
    if (fourCC == code("DXT4") || fourCC == code("DXT5")) return blocks(squish::kDxt5, 16);
    if (fourCC == code("ATI1") || fourCC == code("BC4U")) return blocks(0, 8, 1);
    if (fourCC == code("ATI2") || fourCC == code("BC5U")) return blocks(0, 16, 2);
    // D3DFORMAT values stored as the FourCC.
    switch (fourCC) {
        case 36:  // D3DFMT_A16B16G16R16
            return components(Component::Unorm16, 4, kRGBA, 1.0f);
        case 111:  // D3DFMT_R16F
            return components(Component::Half, 1, kR, 1.0f);
        case 112:  // D3DFMT_G16R16F
            return components(Component::Half, 2, kRG, 1.0f);
        case 113:  // D3DFMT_A16B16G16R16F
            return components(Component::Half, 4, kRGBA, 1.0f);
        case 114:  // D3DFMT_R32F
            return components(Component::Float, 1, kR, 1.0f);
        case 115:  // D3DFMT_G32R32F
            return components(Component::Float, 2, kRG, 1.0f);
        case 116:  // D3DFMT_A32B32G32R32F
            return components(Component::Float, 4, kRGBA, 1.0f);
        default:
            return std::nullopt;
    }
}

std::optional<TexelFormat> dxgiFormat(uint32_t format) {
    switch (format) {
        case 2:  // R32G32B32A32_FLOAT
            return components(Component::Float, 4, kRGBA, 0.0f);
        case 10:  // R16G16B16A16_FLOAT
            return components(Component::Half, 4, kRGBA, 0.0f);
        case 11:  // R16G16B16A16_UNORM
            return components(Component::Unorm16, 4, kRGBA, 0.0f);
        case 16:  // R32G32_FLOAT
            return components(Component::Float, 2, kRG, 0.0f);
        case 24:  // R10G10B10A2_UNORM
            return masks(32, 0x3ffu, 0xffc00u, 0x3ff00000u, 0xc0000000u, 0.0f);
        case 28:  // R8G8B8A8_UNORM(_SRGB): the bytes as stored; the effect's sampler decides on sRGB
        case 29:
            return masks(32, 0xffu, 0xff00u, 0xff0000u, 0xff000000u, 0.0f);
        case 34:  // R16G16_FLOAT
            return components(Component::Half, 2, kRG, 0.0f);
        case 41:  // R32_FLOAT
            return components(Component::Float, 1, kR, 0.0f);
        case 49:  // R8G8_UNORM
            return masks(16, 0xffu, 0xff00u, 0, 0, 0.0f);
        case 54:  // R16_FLOAT
            return components(Component::Half, 1, kR, 0.0f);
        case 56:  // R16_UNORM
            return components(Component::Unorm16, 1, kR, 0.0f);
        case 61:  // R8_UNORM
            return masks(8, 0xffu, 0, 0, 0, 0.0f);
        case 65:  // A8_UNORM
            return masks(8, 0, 0, 0, 0xffu, 0.0f);
        case 71:  // BC1_UNORM(_SRGB)
        case 72:
            return blocks(squish::kDxt1, 8);
        case 74:  // BC2
        case 75:
            return blocks(squish::kDxt3, 16);
        case 77:  // BC3
        case 78:
            return blocks(squish::kDxt5, 16);
        case 80:  // BC4_UNORM
            return blocks(0, 8, 1);
        case 83:  // BC5_UNORM
            return blocks(0, 16, 2);
        case 87:  // B8G8R8A8_UNORM(_SRGB)
        case 91:
            return masks(32, 0xff0000u, 0xff00u, 0xffu, 0xff000000u, 0.0f);
        case 88:  // B8G8R8X8_UNORM(_SRGB)
        case 93:
            return masks(32, 0xff0000u, 0xff00u, 0xffu, 0, 0.0f);
        default:
            return std::nullopt;
    }
}

// [SECTION] Header

// DDS_PIXELFORMAT flags, DDS_HEADER caps2 flags and DX10 header fields the reader looks at.
constexpr uint32_t kAlphaPixels = 0x1, kAlpha = 0x2, kFourCC = 0x4, kRgb = 0x40, kLuminance = 0x20000;
constexpr uint32_t kCaps2Cube = 0x200, kCaps2AllFaces = 0xfc00, kCaps2Volume = 0x200000;
constexpr uint32_t kMipMapCountFlag = 0x20000;
constexpr uint32_t kDx10Texture1D = 2, kDx10Texture2D = 3, kDx10Texture3D = 4, kDx10MiscCube = 0x4;
// Direct3D 11's resource limits: what a DDS file may hold (and what is checked before allocating).
constexpr uint32_t kMaxSide2D = 16384, kMaxSide3D = 2048, kMaxElements = 2048;

struct Layout {
    TextureFile::Kind kind = TextureFile::Kind::Flat;
    uint32_t width = 0, height = 0, depth = 1, levels = 1, elements = 1;
    TexelFormat format;
    size_t dataOffset = 0;
};

// The bytes one mip level of one face takes in the file.
size_t levelBytes(const Layout& layout, uint32_t level) {
    const size_t w = std::max(layout.width >> level, 1u), h = std::max(layout.height >> level, 1u);
    const size_t d = std::max(layout.depth >> level, 1u);
    if (layout.format.family == TexelFormat::Family::Blocks)
        return ((w + 3) / 4) * ((h + 3) / 4) * size_t(layout.format.bytes) * d;
    return w * h * d * size_t(layout.format.bytes);
}

std::optional<TexelFormat> legacyFormat(const uint8_t* pf, std::optional<TextureFileFault>& fault) {
    const uint32_t flags = readU32(pf + 4);
    if (flags & kFourCC) {
        const uint32_t fourCC = readU32(pf + 8);
        if (std::optional<TexelFormat> format = fourCCFormat(fourCC)) return format;
        std::string name;
        for (int i = 0; i < 4; ++i) {
            const char c = static_cast<char>(fourCC >> (8 * i));
            name += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
        }
        fault = {fx::DiagId::TextureFileFourCCUnsupported, {name, std::to_string(fourCC)}};
        return std::nullopt;
    }
    const uint32_t bits = readU32(pf + 12);
    if (!(flags & (kRgb | kLuminance | kAlpha)) || (bits != 8 && bits != 16 && bits != 24 && bits != 32)) {
        fault = {fx::DiagId::TextureFilePixelFormatUnsupported,
                 {std::to_string(flags), std::to_string(bits)}};
        return std::nullopt;
    }
    const uint32_t alphaMask = (flags & (kAlphaPixels | kAlpha)) ? readU32(pf + 28) : 0;
    if (flags & kAlpha && !(flags & (kRgb | kLuminance))) return masks(int(bits), 0, 0, 0, alphaMask, 0.0f);
    if (flags & kLuminance) return masks(int(bits), readU32(pf + 16), 0, 0, alphaMask, 1.0f, true);
    return masks(int(bits), readU32(pf + 16), readU32(pf + 20), readU32(pf + 24), alphaMask, 1.0f);
}

std::optional<Layout> readLayout(std::span<const uint8_t> bytes, std::optional<TextureFileFault>& fault) {
    if (bytes.size() < 128 || std::memcmp(bytes.data(), "DDS ", 4) != 0 || readU32(&bytes[4]) != 124) {
        fault = {fx::DiagId::TextureFileNotDds, {}};
        return std::nullopt;
    }
    const uint8_t* header = bytes.data() + 4;  // DDS_HEADER
    const uint8_t* pf = header + 72;           // DDS_PIXELFORMAT
    Layout layout;
    layout.height = readU32(header + 8);
    layout.width = readU32(header + 12);
    const uint32_t depth = readU32(header + 20);
    const uint32_t mipCount = readU32(header + 24);
    layout.levels = (readU32(header + 4) & kMipMapCountFlag) || mipCount > 1 ? std::max(mipCount, 1u) : 1u;
    const uint32_t caps2 = readU32(header + 108);
    layout.dataOffset = 128;
    const bool dx10 = (readU32(pf + 4) & kFourCC) && std::memcmp(pf + 8, "DX10", 4) == 0;
    if (dx10) {
        if (bytes.size() < 148) {
            fault = {fx::DiagId::TextureFileDx10HeaderTruncated, {}};
            return std::nullopt;
        }
        const uint8_t* ext = bytes.data() + 128;
        const uint32_t dxgi = readU32(ext);
        std::optional<TexelFormat> format = dxgiFormat(dxgi);
        if (!format) {
            fault = {fx::DiagId::TextureFileDxgiFormatUnsupported, {std::to_string(dxgi)}};
            return std::nullopt;
        }
        layout.format = *format;
        const uint32_t dimension = readU32(ext + 4);
        if (dimension != kDx10Texture1D && dimension != kDx10Texture2D && dimension != kDx10Texture3D) {
            fault = {fx::DiagId::TextureFileDimensionNotTexture, {std::to_string(dimension)}};
            return std::nullopt;
        }
        if (dimension == kDx10Texture1D) layout.height = 1;
        layout.kind = dimension == kDx10Texture3D          ? TextureFile::Kind::Volume
                      : (readU32(ext + 8) & kDx10MiscCube) ? TextureFile::Kind::Cube
                                                           : TextureFile::Kind::Flat;
        layout.elements = std::max(readU32(ext + 12), 1u);
        layout.dataOffset = 148;
    } else {
        std::optional<TexelFormat> format = legacyFormat(pf, fault);
        if (!format) return std::nullopt;
        layout.format = *format;
        if (caps2 & kCaps2Cube) {
            // D3D9 allowed cube maps with some faces left out; a cube texture needs all six.
            if ((caps2 & kCaps2AllFaces) != kCaps2AllFaces) {
                fault = {fx::DiagId::TextureFileCubeFacesMissing, {}};
                return std::nullopt;
            }
            layout.kind = TextureFile::Kind::Cube;
        } else if (caps2 & kCaps2Volume) {
            layout.kind = TextureFile::Kind::Volume;
        }
    }
    if (layout.kind == TextureFile::Kind::Volume) layout.depth = std::max(depth, 1u);
    const uint32_t maxSide = layout.kind == TextureFile::Kind::Volume ? kMaxSide3D : kMaxSide2D;
    if (layout.width == 0 || layout.height == 0 || layout.width > maxSide || layout.height > maxSide ||
        layout.depth > kMaxSide3D || layout.elements > kMaxElements ||
        (layout.kind == TextureFile::Kind::Volume && layout.elements > 1) ||
        (layout.kind == TextureFile::Kind::Cube && layout.width != layout.height)) {
        fault = {fx::DiagId::TextureFileHeaderMalformed,
                 {std::to_string(layout.width), std::to_string(layout.height), std::to_string(layout.depth),
                  std::to_string(layout.elements), std::to_string(maxSide)}};
        return std::nullopt;
    }
    // A mip chain ends at 1x1x1; a count beyond that is the writer's mistake, not more data.
    const uint32_t fullChain =
        uint32_t(std::bit_width(std::max({layout.width, layout.height, layout.depth})));
    layout.levels = std::min(layout.levels, fullChain);
    return layout;
}

// [SECTION] Decoding

// One texel of a Masks or Components format as RGBA.
void decodeTexel(const TexelFormat& f, const uint8_t* in, float* out) {
    if (f.family == TexelFormat::Family::Masks) {
        uint32_t texel = 0;
        for (int i = 0; i < f.bytes; ++i) texel |= uint32_t(in[i]) << (8 * i);
        for (int c = 0; c < 4; ++c) {
            const uint32_t mask = f.masks[size_t(c)];
            if (!mask) {
                out[c] = c == 3 ? 1.0f : f.missingColour;
                continue;
            }
            const int shift = std::countr_zero(mask);
            out[c] = float((texel & mask) >> shift) / float(mask >> shift);
        }
        if (f.luminance) out[1] = out[2] = out[0];
        return;
    }
    const int size = f.component == Component::Float ? 4 : 2;
    for (int c = 0; c < 4; ++c) {
        const int stored = f.swizzle[size_t(c)];
        if (stored < 0) {
            out[c] = c == 3 ? 1.0f : f.missingColour;
            continue;
        }
        const uint8_t* at = in + stored * size;
        if (f.component == Component::Float) {
            std::memcpy(&out[c], at, 4);
        } else {
            const uint16_t v = uint16_t(at[0] | at[1] << 8);
            out[c] = f.component == Component::Half ? halfToFloat(v) : float(v) / 65535.0f;
        }
    }
}

// One channel of a 4x4 BC4 block (also each half of a BC5 block, and BC3's alpha): two 8-bit endpoints
// and sixteen 3-bit indices into the 8 (or, with e0 <= e1, 6 plus 0 and 1) values between them
// (Direct3D 10's "Block Compression" documentation, BC4).
void decodeBc4Channel(const uint8_t* block, int w, int h, int bx, int by, int channel, float* out) {
    const float e0 = block[0] / 255.0f, e1 = block[1] / 255.0f;
    float values[8] = {e0, e1};
    if (block[0] > block[1]) {
        for (int i = 1; i < 7; ++i) values[i + 1] = (float(7 - i) * e0 + float(i) * e1) / 7.0f;
    } else {
        for (int i = 1; i < 5; ++i) values[i + 1] = (float(5 - i) * e0 + float(i) * e1) / 5.0f;
        values[6] = 0.0f;
        values[7] = 1.0f;
    }
    uint64_t indices = 0;
    for (int i = 0; i < 6; ++i) indices |= uint64_t(block[2 + i]) << (8 * i);
    for (int i = 0; i < 16; ++i) {
        const int x = bx * 4 + i % 4, y = by * 4 + i / 4;
        if (x < w && y < h)
            out[(size_t(y) * size_t(w) + size_t(x)) * 4 + size_t(channel)] = values[(indices >> (3 * i)) & 7];
    }
}

// One face's level (every depth slice) from `in` into `out` as RGBA floats.
void decodeSurface(const Layout& layout, uint32_t level, const uint8_t* in, float* out) {
    const int w = int(std::max(layout.width >> level, 1u)), h = int(std::max(layout.height >> level, 1u));
    const int d = int(std::max(layout.depth >> level, 1u));
    const size_t texels = size_t(w) * size_t(h);
    const TexelFormat& f = layout.format;
    if (f.family != TexelFormat::Family::Blocks) {
        for (size_t t = 0; t < texels * size_t(d); ++t) decodeTexel(f, in + t * size_t(f.bytes), out + t * 4);
        return;
    }
    const int blocksX = (w + 3) / 4, blocksY = (h + 3) / 4;
    const size_t sliceBytes = size_t(blocksX) * size_t(blocksY) * size_t(f.bytes);
    std::vector<uint8_t> rgba(f.squishFlags ? texels * 4 : 0);
    for (int z = 0; z < d; ++z) {
        const uint8_t* slice = in + size_t(z) * sliceBytes;
        float* target = out + size_t(z) * texels * 4;
        if (f.squishFlags) {
            squish::DecompressImage(rgba.data(), w, h, slice, f.squishFlags);
            for (size_t i = 0; i < texels * 4; ++i) target[i] = rgba[i] / 255.0f;
            continue;
        }
        // BC4 and BC5: the channels a block holds; the rest read as DXGI defines (colour 0, alpha 1).
        for (size_t t = 0; t < texels; ++t) {
            target[t * 4 + 1] = target[t * 4 + 2] = 0.0f;
            target[t * 4 + 3] = 1.0f;
        }
        for (int by = 0; by < blocksY; ++by)
            for (int bx = 0; bx < blocksX; ++bx) {
                const uint8_t* block = slice + (size_t(by) * size_t(blocksX) + size_t(bx)) * size_t(f.bytes);
                for (int channel = 0; channel < f.blockChannels; ++channel)
                    decodeBc4Channel(block + 8 * channel, w, h, bx, by, channel, target);
            }
    }
}

}  // namespace

bool isTextureFile(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension == ".dds";
}

std::optional<TextureFile> loadTextureFile(const std::string& path, std::optional<TextureFileFault>& fault) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        fault = {fx::DiagId::TextureFileUnopenable, {}};
        return std::nullopt;
    }
    const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return decodeTextureFile(bytes, fault);
}

std::optional<TextureFile> decodeTextureFile(std::span<const uint8_t> bytes,
                                             std::optional<TextureFileFault>& fault) {
    const std::optional<Layout> layout = readLayout(bytes, fault);
    if (!layout) return std::nullopt;

    // The data's size is checked before any allocation: a header may claim 2048 elements of 16384² texels.
    const size_t faces = layout->kind == TextureFile::Kind::Cube ? 6 : 1;
    size_t chainBytes = 0;
    for (uint32_t level = 0; level < layout->levels; ++level) chainBytes += levelBytes(*layout, level);
    const size_t elementBytes = chainBytes * faces;
    const size_t available = bytes.size() - layout->dataOffset;
    if (available / elementBytes < layout->elements) {
        const size_t complete = available / elementBytes;
        fault = layout->elements > 1
                    ? TextureFileFault{fx::DiagId::TextureFileElementTruncated, {std::to_string(complete)}}
                    : TextureFileFault{fx::DiagId::TextureFileTexelsTruncated,
                                       {std::to_string(available), std::to_string(elementBytes)}};
        return std::nullopt;
    }

    TextureFile file;
    file.kind = layout->kind;
    file.width = int(layout->width);
    file.height = int(layout->height);
    file.depth = int(layout->depth);
    file.elements = int(layout->elements);
    const size_t layers = faces * layout->elements;
    file.levels.resize(layout->levels);
    std::vector<size_t> layerFloats(layout->levels);
    for (uint32_t level = 0; level < layout->levels; ++level) {
        layerFloats[level] = size_t(std::max(layout->width >> level, 1u)) *
                             std::max(layout->height >> level, 1u) * std::max(layout->depth >> level, 1u) * 4;
        file.levels[level].resize(layerFloats[level] * layers);
    }
    // The file holds each layer's whole chain in turn; TextureFile holds each level's layers in turn.
    const uint8_t* at = bytes.data() + layout->dataOffset;
    for (size_t layer = 0; layer < layers; ++layer)
        for (uint32_t level = 0; level < layout->levels; ++level) {
            decodeSurface(*layout, level, at, file.levels[level].data() + layer * layerFloats[level]);
            at += levelBytes(*layout, level);
        }
    return file;
}

}  // namespace runtime
