#include <runtime/Image.h>

// Debian's libstb already contains the stb implementations (stbi_write_png, stbi_load): define no
// STB_*_IMPLEMENTATION here, or the symbols would be duplicated.
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>

namespace runtime {

Image Image::makeBytes(int width, int height, int channels) {
    Image image;
    image.width = width;
    image.height = height;
    image.channels = channels;
    image.isFloat = false;
    image.bytes.assign(size_t(width) * size_t(height) * size_t(channels), 0);
    return image;
}

Image Image::makeFloats(int width, int height, int channels) {
    Image image = makeBytes(0, 0, channels);
    image.width = width;
    image.height = height;
    image.isFloat = true;
    image.floats.assign(size_t(width) * size_t(height) * size_t(channels), 0.0f);
    return image;
}

float Image::sample(int x, int y, int channel) const {
    size_t index = (size_t(y) * size_t(width) + size_t(x)) * size_t(channels) + size_t(channel);
    return isFloat ? floats[index] : float(bytes[index]) / 255.0f;
}

glm::vec4 Image::pixel(int x, int y) const {
    glm::vec4 result(0.0f, 0.0f, 0.0f, 1.0f);
    for (int c = 0; c < channels && c < 4; ++c) result[c] = sample(x, y, c);
    return result;
}

Image Image::toRGBA8() const {
    Image result = makeBytes(width, height, 4);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            glm::vec4 value = pixel(x, y);
            for (int c = 0; c < 4; ++c) {
                float clamped = std::clamp(std::isnan(value[c]) ? 0.0f : value[c], 0.0f, 1.0f);
                result.bytes[(size_t(y) * size_t(width) + size_t(x)) * 4 + size_t(c)] =
                    uint8_t(std::lround(clamped * 255.0f));
            }
        }
    }
    return result;
}

bool Image::writePng(const std::string& path, std::string& error) const {
    if (empty()) {
        error = "cannot write an empty image to " + path;
        return false;
    }
    Image rgba = isFloat || channels != 4 ? toRGBA8() : *this;
    if (stbi_write_png(path.c_str(), rgba.width, rgba.height, 4, rgba.bytes.data(), rgba.width * 4) == 0) {
        error = "cannot write " + path;
        return false;
    }
    return true;
}

namespace {

// `floatStorage`: where float samples go instead of the image (null: into the image).
Image readTexture(const GpuTexture& texture, int level, int face, bool asFloat,
                  std::vector<float>* floatStorage = nullptr) {
    const GlTextureFormat& format = texture.glFormat();
    int width = std::max(texture.width() >> level, 1);
    int height = std::max(texture.height() >> level, 1);
    int channels = format.isDepth ? 1 : format.channels;
    bool floatOutput = asFloat || format.isFloat || format.isDepth;
    Image image;
    image.width = width;
    image.height = height;
    image.channels = channels;
    image.isFloat = floatOutput;
    const size_t samples = size_t(width) * size_t(height) * size_t(channels);
    std::vector<float>& floats = floatStorage ? *floatStorage : image.floats;
    if (floatOutput)
        floats.resize(samples);
    else
        image.bytes.assign(samples, 0);
    GLenum pixelFormat = format.isDepth ? GL_DEPTH_COMPONENT : format.pixelFormat;
    GLenum type = floatOutput ? GL_FLOAT : GL_UNSIGNED_BYTE;
    void* data = floatOutput ? static_cast<void*>(floats.data()) : static_cast<void*>(image.bytes.data());
    size_t bufferSize = floatOutput ? floats.size() * sizeof(float) : image.bytes.size();
    // glGetTextureSubImage reads a single cube face; glGetTexImage would need the face target bound.
    gl::GetTextureSubImage(texture.id(), level, 0, 0, texture.isCube() ? face : 0, width, height, 1,
                           pixelFormat, type, GLsizei(bufferSize), data);
    return image;
}

}  // namespace

Image readColorTarget(const GpuTexture& texture, int level, int face) {
    return readTexture(texture, level, face, false);
}

Image readFloatTexture(const GpuTexture& texture, int level, int face) {
    return readTexture(texture, level, face, true);
}

ImageShape readFloatTexture(const GpuTexture& texture, std::vector<float>& floats, int level, int face) {
    const Image image = readTexture(texture, level, face, true, &floats);
    return {image.width, image.height, image.channels};
}

Image readFramebufferColor(int index, int width, int height) {
    Image image = Image::makeFloats(width, height, 4);
    GLint savedReadBuffer = 0;
    gl::GetIntegerv(GL_READ_BUFFER, &savedReadBuffer);
    gl::ReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + index));
    gl::ReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, image.floats.data());
    gl::ReadBuffer(GLenum(savedReadBuffer));
    return image;
}

Image readFramebufferStencil(int width, int height) {
    Image image = Image::makeBytes(width, height, 1);
    gl::ReadPixels(0, 0, width, height, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, image.bytes.data());
    return image;
}

std::optional<Image> loadImageFile(const std::string& path, std::string& error) {
    int width = 0, height = 0, fileChannels = 0;
    if (stbi_is_hdr(path.c_str())) {
        float* pixels = stbi_loadf(path.c_str(), &width, &height, &fileChannels, 4);
        if (pixels == nullptr) {
            error = stbi_failure_reason() ? stbi_failure_reason() : "cannot load";
            return std::nullopt;
        }
        Image image = Image::makeFloats(width, height, 4);
        std::copy(pixels, pixels + image.floats.size(), image.floats.begin());
        stbi_image_free(pixels);
        return image;
    }
    uint8_t* pixels = stbi_load(path.c_str(), &width, &height, &fileChannels, 4);
    if (pixels == nullptr) {
        error = stbi_failure_reason() ? stbi_failure_reason() : "cannot load";
        return std::nullopt;
    }
    Image image = Image::makeBytes(width, height, 4);
    std::copy(pixels, pixels + image.bytes.size(), image.bytes.begin());
    stbi_image_free(pixels);
    return image;
}

}  // namespace runtime
