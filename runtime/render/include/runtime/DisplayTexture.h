// DisplayTexture: an RGBA8 GL texture holding an image to show in a window: the frame, or a render
// target made viewable (a float shadow map normalised to grey). The viewer hands id() to Dear ImGui
// (ImGui::Image, draw lists); the runtime's GL functions stay private to the runtime.
//
// Needs a current GL context for its whole life.
#pragma once

#include <runtime/FrameImage.h>

#include <cstdint>
#include <vector>

namespace runtime {

class DisplayTexture {
public:
    DisplayTexture() = default;
    ~DisplayTexture();
    DisplayTexture(const DisplayTexture&) = delete;
    DisplayTexture& operator=(const DisplayTexture&) = delete;

    // Uploads `image` (rows top to bottom); row 0 ends up at texture v = 0, as ImGui expects.
    void upload(const FrameImage& image);
    // Uploads float texels (rows top to bottom, `channels` per texel) scaled to [0, 1] for display; see
    // normalizeForDisplay.
    void uploadNormalized(const std::vector<float>& texels, int width, int height, int channels);

    // The GL texture name (0 before the first upload).
    uint32_t id() const { return mTexture; }
    int width() const { return mWidth; }
    int height() const { return mHeight; }

private:
    uint32_t mTexture = 0;
    int mWidth = 0;
    int mHeight = 0;
};

// Float texels -> an RGBA8 image a person can read. Each channel (up to three) is mapped linearly from
// the range of the values to [0, 255]. A shadow map is cleared to a huge "far" value (the thesis effect
// clears to 8184) that would squash every real depth to black, so when the largest value is also the
// most frequent clear value, the range is taken over the other texels and cleared texels show white.
FrameImage normalizeForDisplay(const std::vector<float>& texels, int width, int height, int channels);

}  // namespace runtime
