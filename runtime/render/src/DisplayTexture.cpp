// DisplayTexture: uploads for the viewer's window.
#include <runtime/DisplayTexture.h>

#include <runtime/GlApi.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace runtime {

DisplayTexture::~DisplayTexture() {
    if (mTexture != 0) gl::DeleteTextures(1, &mTexture);
}

void DisplayTexture::upload(const FrameImage& image) {
    if (image.width <= 0 || image.height <= 0) return;
    if (mTexture == 0) {
        gl::GenTextures(1, &mTexture);
        gl::BindTexture(GL_TEXTURE_2D, mTexture);
        gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    gl::BindTexture(GL_TEXTURE_2D, mTexture);
    gl::PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl::PixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    if (image.width != mWidth || image.height != mHeight) {
        gl::TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                       image.rgba.data());
        mWidth = image.width;
        mHeight = image.height;
    } else {
        gl::TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                          image.rgba.data());
    }
    gl::BindTexture(GL_TEXTURE_2D, 0);
}

void DisplayTexture::uploadNormalized(const std::vector<float>& texels, int width, int height, int channels) {
    upload(normalizeForDisplay(texels, width, height, channels));
}

FrameImage normalizeForDisplay(const std::vector<float>& texels, int width, int height, int channels) {
    FrameImage image;
    if (width <= 0 || height <= 0 || channels <= 0 ||
        texels.size() < static_cast<size_t>(width) * height * channels) {
        return image;
    }
    image.width = width;
    image.height = height;
    image.rgba.assign(static_cast<size_t>(width) * height * 4, 255);
    const size_t count = static_cast<size_t>(width) * height;
    const int shown = std::min(channels, 3);
    for (int c = 0; c < shown; ++c) {
        float lo = std::numeric_limits<float>::max();
        float hi = std::numeric_limits<float>::lowest();
        size_t atHi = 0;
        for (size_t i = 0; i < count; ++i) {
            const float v = texels[i * channels + c];
            if (!std::isfinite(v)) continue;
            lo = std::min(lo, v);
            if (v > hi) {
                hi = v;
                atHi = 0;
            }
            if (v == hi) ++atHi;
        }
        if (lo > hi) continue;  // no finite texel: leave white
        // A clear value covering many texels: range over the rest (see the header).
        float rangeHi = hi;
        if (atHi > count / 100) {
            float below = std::numeric_limits<float>::lowest();
            for (size_t i = 0; i < count; ++i) {
                const float v = texels[i * channels + c];
                if (std::isfinite(v) && v < hi) below = std::max(below, v);
            }
            if (below >= lo) rangeHi = below;
        }
        const float scale = rangeHi > lo ? 1.0f / (rangeHi - lo) : 0.0f;
        for (size_t i = 0; i < count; ++i) {
            const float v = texels[i * channels + c];
            const float t = !std::isfinite(v) || v > rangeHi ? 1.0f : (v - lo) * scale;
            const auto byte = static_cast<uint8_t>(std::clamp(t, 0.0f, 1.0f) * 255.0f + 0.5f);
            if (shown == 1) {
                image.rgba[i * 4 + 0] = image.rgba[i * 4 + 1] = image.rgba[i * 4 + 2] = byte;
            } else {
                image.rgba[i * 4 + c] = byte;
            }
        }
    }
    if (shown == 2) {
        for (size_t i = 0; i < count; ++i) image.rgba[i * 4 + 2] = 0;
    }
    return image;
}

}  // namespace runtime
