// DdsWriter: writes DirectDraw Surface files for texture tests, so that no binary file is checked in:
// uncompressed A8R8G8B8 (2D, cube, volume, with mip chains), DXT1/DXT3/DXT5 blocks of one colour, and
// single surfaces of any pixel format whose bytes the test encodes.
// Layout after Microsoft's DDS_HEADER documentation: "DDS ", a 124-byte header with a 32-byte pixel
// format; cube maps store each face's mip chain in turn (+X -X +Y -Y +Z -Z), volumes each level's slices.
#pragma once

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace shadowfx::test {

struct DdsColor {
    uint8_t r = 0, g = 0, b = 0, a = 255;
};

class DdsWriter {
public:
    enum class Layout { Flat, Cube, Volume };
    enum class Compression { None, Dxt1, Dxt3, Dxt5 };

    // `texel(face, level, x, y, z)` gives each texel; faces are 0..5 for cubes, else 0.
    using Texels = std::function<DdsColor(int face, int level, int x, int y, int z)>;

    static bool write(const std::string& path, Layout layout, Compression compression, int width, int height,
                      int depth, int levels, const Texels& texel) {
        std::vector<uint8_t> out;
        auto u32 = [&](uint32_t v) {
            for (int i = 0; i < 4; ++i) out.push_back(static_cast<uint8_t>(v >> (8 * i)));
        };
        const bool compressed = compression != Compression::None;
        out.insert(out.end(), {'D', 'D', 'S', ' '});
        u32(124);
        u32(0x1 | 0x2 | 0x4 | 0x1000 | (levels > 1 ? 0x20000 : 0) | (compressed ? 0x80000 : 0x8) |
            (layout == Layout::Volume ? 0x800000 : 0));
        u32(static_cast<uint32_t>(height));
        u32(static_cast<uint32_t>(width));
        u32(compressed ? static_cast<uint32_t>(((width + 3) / 4) * ((height + 3) / 4) *
                                               (compression == Compression::Dxt1 ? 8 : 16))
                       : static_cast<uint32_t>(width * 4));
        u32(layout == Layout::Volume ? static_cast<uint32_t>(depth) : 0);
        u32(static_cast<uint32_t>(levels));
        for (int i = 0; i < 11; ++i) u32(0);
        // DDS_PIXELFORMAT
        u32(32);
        if (compressed) {
            u32(0x4);  // DDPF_FOURCC
            const char* fourCC = compression == Compression::Dxt1   ? "DXT1"
                                 : compression == Compression::Dxt3 ? "DXT3"
                                                                    : "DXT5";
            out.insert(out.end(), fourCC, fourCC + 4);
            for (int i = 0; i < 5; ++i) u32(0);
        } else {
            u32(0x40 | 0x1);  // DDPF_RGB | DDPF_ALPHAPIXELS
            u32(0);
            u32(32);
            u32(0x00ff0000);
            u32(0x0000ff00);
            u32(0x000000ff);
            u32(0xff000000);
        }
        u32(0x1000 | (levels > 1 ? 0x400000 : 0) | (layout != Layout::Flat || levels > 1 ? 0x8 : 0));
        u32(layout == Layout::Cube ? 0x200 | 0xFC00 : layout == Layout::Volume ? 0x200000 : 0);
        u32(0);
        u32(0);
        u32(0);

        const int faces = layout == Layout::Cube ? 6 : 1;
        for (int face = 0; face < faces; ++face) {
            for (int level = 0; level < levels; ++level) {
                const int w = std::max(width >> level, 1), h = std::max(height >> level, 1);
                const int d = layout == Layout::Volume ? std::max(depth >> level, 1) : 1;
                for (int z = 0; z < d; ++z) {
                    if (!compressed) {
                        for (int y = 0; y < h; ++y) {
                            for (int x = 0; x < w; ++x) {
                                const DdsColor c = texel(face, level, x, y, z);
                                out.insert(out.end(), {c.b, c.g, c.r, c.a});
                            }
                        }
                        continue;
                    }
                    // One colour per 4x4 block (its top-left texel's): colour0 with every index 0.
                    for (int by = 0; by < (h + 3) / 4; ++by) {
                        for (int bx = 0; bx < (w + 3) / 4; ++bx) {
                            const DdsColor c = texel(face, level, bx * 4, by * 4, z);
                            if (compression == Compression::Dxt3) {
                                const uint8_t a4 = static_cast<uint8_t>((c.a >> 4) * 0x11);
                                for (int i = 0; i < 8; ++i) out.push_back(a4);
                            } else if (compression == Compression::Dxt5) {
                                out.insert(out.end(), {c.a, c.a, 0, 0, 0, 0, 0, 0});
                            }
                            const uint16_t c565 =
                                static_cast<uint16_t>(((c.r >> 3) << 11) | ((c.g >> 2) << 5) | (c.b >> 3));
                            // colour0 > colour1 selects the four-colour mode in DXT1 (index 0 = colour0).
                            const uint16_t other = c565 == 0 ? 0 : static_cast<uint16_t>(c565 - 1);
                            out.insert(out.end(),
                                       {static_cast<uint8_t>(c565), static_cast<uint8_t>(c565 >> 8),
                                        static_cast<uint8_t>(other), static_cast<uint8_t>(other >> 8)});
                            u32(0);
                        }
                    }
                }
            }
        }
        std::ofstream file(path, std::ios::binary);
        file.write(reinterpret_cast<const char*>(out.data()), static_cast<std::streamsize>(out.size()));
        return static_cast<bool>(file);
    }

    // D3D9's DDS_PIXELFORMAT: flags (DDPF_*), FourCC, bits per texel and the R, G, B, A masks.
    struct PixelFormat {
        uint32_t flags = 0, fourCC = 0, bits = 0, r = 0, g = 0, b = 0, a = 0;
    };

    // One 2D level whose bytes the caller encoded: in `format`, or with a DX10 header naming `dxgiFormat`
    // when that is not 0.
    static bool writeSurface(const std::string& path, int width, int height, PixelFormat format,
                             const std::vector<uint8_t>& data, uint32_t dxgiFormat = 0) {
        std::vector<uint8_t> out;
        auto u32 = [&](uint32_t v) {
            for (int i = 0; i < 4; ++i) out.push_back(static_cast<uint8_t>(v >> (8 * i)));
        };
        out.insert(out.end(), {'D', 'D', 'S', ' '});
        u32(124);
        u32(0x1 | 0x2 | 0x4 | 0x1000);
        u32(static_cast<uint32_t>(height));
        u32(static_cast<uint32_t>(width));
        u32(0);
        u32(0);
        u32(1);
        for (int i = 0; i < 11; ++i) u32(0);
        u32(32);
        if (dxgiFormat != 0) format = PixelFormat{0x4, 0x30315844};  // DDPF_FOURCC, "DX10"
        for (uint32_t v : {format.flags, format.fourCC, format.bits, format.r, format.g, format.b, format.a})
            u32(v);
        u32(0x1000);
        for (int i = 0; i < 4; ++i) u32(0);
        if (dxgiFormat != 0) {
            u32(dxgiFormat);
            u32(3);  // D3D10_RESOURCE_DIMENSION_TEXTURE2D
            u32(0);
            u32(1);
            u32(0);
        }
        out.insert(out.end(), data.begin(), data.end());
        std::ofstream file(path, std::ios::binary);
        file.write(reinterpret_cast<const char*>(out.data()), static_cast<std::streamsize>(out.size()));
        return static_cast<bool>(file);
    }

    // A Direct3D 10 array (DDS_HEADER_DXT10, DXGI_FORMAT_R8G8B8A8_UNORM, one level): `elements` 2D
    // textures, or cubes with `cube` (`texel(face, 0, x, y, element)`), each element's faces in turn.
    // `truncateBy` drops bytes off the end, for the error test.
    static bool writeDx10Array(const std::string& path, int width, int height, int elements, bool cube,
                               const Texels& texel, size_t truncateBy = 0) {
        std::vector<uint8_t> out;
        auto u32 = [&](uint32_t v) {
            for (int i = 0; i < 4; ++i) out.push_back(static_cast<uint8_t>(v >> (8 * i)));
        };
        out.insert(out.end(), {'D', 'D', 'S', ' '});
        u32(124);
        u32(0x1 | 0x2 | 0x4 | 0x1000 | 0x8);
        u32(static_cast<uint32_t>(height));
        u32(static_cast<uint32_t>(width));
        u32(static_cast<uint32_t>(width * 4));
        u32(0);
        u32(1);
        for (int i = 0; i < 11; ++i) u32(0);
        u32(32);
        u32(0x4);  // DDPF_FOURCC
        out.insert(out.end(), {'D', 'X', '1', '0'});
        for (int i = 0; i < 5; ++i) u32(0);
        u32(0x1000 | (cube ? 0x8 : 0));
        u32(cube ? 0x200 | 0xFC00 : 0);
        for (int i = 0; i < 3; ++i) u32(0);
        // DDS_HEADER_DXT10
        u32(28);  // DXGI_FORMAT_R8G8B8A8_UNORM
        u32(3);   // D3D10_RESOURCE_DIMENSION_TEXTURE2D
        u32(cube ? 0x4 : 0);
        u32(static_cast<uint32_t>(elements));
        u32(0);
        for (int element = 0; element < elements; ++element)
            for (int face = 0; face < (cube ? 6 : 1); ++face)
                for (int y = 0; y < height; ++y)
                    for (int x = 0; x < width; ++x) {
                        const DdsColor c = texel(face, 0, x, y, element);
                        out.insert(out.end(), {c.r, c.g, c.b, c.a});
                    }
        out.erase(out.end() - static_cast<std::ptrdiff_t>(std::min(truncateBy, out.size())), out.end());
        std::ofstream file(path, std::ios::binary);
        file.write(reinterpret_cast<const char*>(out.data()), static_cast<std::streamsize>(out.size()));
        return static_cast<bool>(file);
    }
};

}  // namespace shadowfx::test
