// TextureFile: DDS through OpenImageIO (see TextureFile.h).
#include <runtime/TextureFile.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

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

}  // namespace

bool isTextureFile(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension == ".dds";
}

std::optional<TextureFile> loadTextureFile(const std::string& path, std::string& error) {
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
