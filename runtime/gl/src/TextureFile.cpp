// TextureFile: DDS through OpenImageIO (see TextureFile.h).
#include <runtime/TextureFile.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
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

// Widens `channels` samples per texel to RGBA: one channel is luminance (L8), two luminance and alpha.
std::vector<float> toRGBA(const std::vector<float>& samples, int channels) {
    const size_t texels = samples.size() / static_cast<size_t>(channels);
    std::vector<float> rgba(texels * 4);
    for (size_t i = 0; i < texels; ++i) {
        const float* in = &samples[i * static_cast<size_t>(channels)];
        float* out = &rgba[i * 4];
        if (channels <= 2) {
            out[0] = out[1] = out[2] = in[0];
            out[3] = channels == 2 ? in[1] : 1.0f;
        } else {
            out[0] = in[0];
            out[1] = in[1];
            out[2] = in[2];
            out[3] = channels >= 4 ? in[3] : 1.0f;
        }
    }
    return rgba;
}

// [SECTION] DX10-header arrays
// Layout after Microsoft's "DDS_HEADER_DXT10" documentation: "DDS ", the 124-byte DDS_HEADER, the
// 20-byte DX10 header (dxgiFormat, resourceDimension, miscFlag, arraySize, miscFlags2), then per element
// (per face of a cube) its whole mip chain.

uint32_t readU32(const std::vector<uint8_t>& bytes, size_t at) {
    return uint32_t(bytes[at]) | uint32_t(bytes[at + 1]) << 8 | uint32_t(bytes[at + 2]) << 16 |
           uint32_t(bytes[at + 3]) << 24;
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

// One texel of the DXGI formats read here, as RGBA (channels a format lacks read as D3D does: 0, alpha 1).
struct DxgiLayout {
    uint32_t format;
    int bytes;
};
constexpr DxgiLayout kDxgiFormats[] = {{2, 16}, {10, 8}, {28, 4}, {29, 4},
                                       {41, 4}, {61, 1}, {87, 4}, {91, 4}};

void decodeTexel(uint32_t format, const uint8_t* in, float* out) {
    out[0] = out[1] = out[2] = 0.0f;
    out[3] = 1.0f;
    switch (format) {
        case 2:  // R32G32B32A32_FLOAT
            std::memcpy(out, in, 16);
            break;
        case 10:  // R16G16B16A16_FLOAT
            for (int c = 0; c < 4; ++c) out[c] = halfToFloat(uint16_t(in[2 * c] | in[2 * c + 1] << 8));
            break;
        case 28:  // R8G8B8A8_UNORM (_SRGB: the bytes as stored, like the 8-bit files above)
        case 29:
            for (int c = 0; c < 4; ++c) out[c] = in[c] / 255.0f;
            break;
        case 41:  // R32_FLOAT
            std::memcpy(out, in, 4);
            break;
        case 61:  // R8_UNORM
            out[0] = in[0] / 255.0f;
            break;
        default:  // 87, 91: B8G8R8A8_UNORM(_SRGB)
            out[0] = in[2] / 255.0f;
            out[1] = in[1] / 255.0f;
            out[2] = in[0] / 255.0f;
            out[3] = in[3] / 255.0f;
            break;
    }
}

// nullopt when the file is not a DX10-header array (OpenImageIO reads it); otherwise the array, or an
// error in `error` (and an empty TextureFile).
std::optional<TextureFile> readDx10Array(const std::string& path, std::string& error) {
    std::ifstream in(path, std::ios::binary);
    std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.size() < 148 || std::memcmp(bytes.data(), "DDS ", 4) != 0 ||
        std::memcmp(bytes.data() + 84, "DX10", 4) != 0 || readU32(bytes, 140) <= 1)
        return std::nullopt;
    TextureFile file;
    const uint32_t format = readU32(bytes, 128);
    const uint32_t dimension = readU32(bytes, 132);
    const bool cube = (readU32(bytes, 136) & 0x4u) != 0;
    const uint32_t elements = readU32(bytes, 140);
    const uint32_t width = readU32(bytes, 16);
    const uint32_t height = dimension == 2 ? 1 : readU32(bytes, 12);
    const uint32_t levels = std::max(readU32(bytes, 28), 1u);
    const DxgiLayout* layout = nullptr;
    for (const DxgiLayout& l : kDxgiFormats)
        if (l.format == format) layout = &l;
    if (!layout) {
        error = "DXGI format " + std::to_string(format) +
                " is not read in DDS arrays (the uncompressed R8G8B8A8, B8G8R8A8, R16G16B16A16_FLOAT, "
                "R32G32B32A32_FLOAT, R8_UNORM and R32_FLOAT are)";
        return TextureFile{};
    }
    if ((dimension != 2 && dimension != 3) || width == 0 || height == 0 || width > 16384 || height > 16384 ||
        elements > 2048 || levels > 15 || (cube && (dimension != 3 || width != height))) {
        error = "malformed DX10 array header";
        return TextureFile{};
    }
    file.kind = cube ? TextureFile::Kind::Cube : TextureFile::Kind::Flat;
    file.width = static_cast<int>(width);
    file.height = static_cast<int>(height);
    file.elements = static_cast<int>(elements);
    const size_t layers = size_t(elements) * (cube ? 6 : 1);
    // The data's size is checked before any allocation: a header may claim 2048 elements of 16384² texels.
    size_t chainBytes = 0;
    for (uint32_t level = 0; level < levels; ++level)
        chainBytes +=
            size_t(std::max(width >> level, 1u)) * std::max(height >> level, 1u) * size_t(layout->bytes);
    const size_t elementBytes = chainBytes * (cube ? 6 : 1);
    if ((bytes.size() - 148) / elementBytes < elements) {
        error =
            "the file ends inside element " + std::to_string((bytes.size() - 148) / elementBytes) + "'s data";
        return TextureFile{};
    }
    file.levels.resize(levels);
    for (uint32_t level = 0; level < levels; ++level)
        file.levels[level].resize(size_t(std::max(width >> level, 1u)) * std::max(height >> level, 1u) *
                                  layers * 4);
    size_t at = 148;
    for (size_t layer = 0; layer < layers; ++layer) {
        for (uint32_t level = 0; level < levels; ++level) {
            const size_t texels = size_t(std::max(width >> level, 1u)) * std::max(height >> level, 1u);
            float* out = file.levels[level].data() + layer * texels * 4;
            for (size_t t = 0; t < texels; ++t, at += size_t(layout->bytes))
                decodeTexel(format, bytes.data() + at, out + t * 4);
        }
    }
    return file;
}

}  // namespace

bool isTextureFile(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension == ".dds";
}

std::optional<TextureFile> loadTextureFile(const std::string& path, std::string& error) {
    std::string arrayError;
    if (std::optional<TextureFile> array = readDx10Array(path, arrayError)) {
        if (arrayError.empty()) return array;
        error = arrayError;
        return std::nullopt;
    }
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) {
        error = OIIO::geterror();
        if (error.empty()) error = "not a readable image";
        return std::nullopt;
    }
    TextureFile file;
    const std::string format = in->spec().get_string_attribute("textureformat");
    file.kind = format == "CubeFace Environment" ? TextureFile::Kind::Cube
                : format == "Volume Texture"     ? TextureFile::Kind::Volume
                                                 : TextureFile::Kind::Flat;
    for (int level = 0; in->seek_subimage(0, level); ++level) {
        if (file.kind == TextureFile::Kind::Cube && level > 0) break;
        const OIIO::ImageSpec& spec = in->spec();
        if (spec.width <= 0 || spec.height <= 0 || spec.depth <= 0 || spec.nchannels <= 0) {
            error = "empty image";
            return std::nullopt;
        }
        std::vector<float> samples(static_cast<size_t>(spec.width) * static_cast<size_t>(spec.height) *
                                   static_cast<size_t>(spec.depth) * static_cast<size_t>(spec.nchannels));
        if (!in->read_image(0, level, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, samples.data())) {
            error = in->geterror();
            return std::nullopt;
        }
        if (level == 0) {
            file.width = spec.width;
            // A cube map arrives as its six faces stacked top to bottom.
            file.height = file.kind == TextureFile::Kind::Cube ? spec.height / 6 : spec.height;
            file.depth = spec.depth;
            if (file.kind == TextureFile::Kind::Cube && (file.height != file.width || spec.height % 6 != 0)) {
                error = "cube map faces are not square";
                return std::nullopt;
            }
        }
        file.levels.push_back(toRGBA(samples, spec.nchannels));
    }
    if (file.levels.empty()) {
        error = "no image data";
        return std::nullopt;
    }
    return file;
}

}  // namespace runtime
