// Reading back what a compute shader computed: the tests that write words into the frame and compare them
// with the CPU's bit for bit.
#pragma once

#include "EffectHarness.h"

#include <runtime/BuiltinScenes.h>
#include <runtime/FrameImage.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <ios>
#include <optional>
#include <string>

namespace shadowfx::test {

// The frame of the effect at `path` (relative to the source tree), whose compute passes write their words
// into it: the teapot is the scene, not drawn. Fails the current test and returns nothing on any error.
inline std::optional<runtime::FrameImage> computedFrame(const std::string& path, int width, int height) {
    auto renderer = loadEffect(sourcePath(path), true);
    auto teapot = runtime::makeBuiltinScene("teapot", nullptr);
    if (!renderer || !teapot) {
        ADD_FAILURE() << path << ": the effect or the teapot could not be loaded";
        return std::nullopt;
    }
    if (!render(*renderer, *teapot, width, height)) return std::nullopt;
    return renderer->readFrame();
}

// Words a compute shader wrote into the frame, one RGBA8 pixel each (R the low byte), `wordsPerThread` a
// thread in thread order, compared with the CPU's `expectedWords(thread)` (its first `wordsCompared`): the
// words that differ, the first eight reported as failures, and the words that are not zero (a blank frame
// has none).
struct ComputedWords {
    int wrong = 0;
    int nonZero = 0;
};
template <typename ExpectedWords>
ComputedWords compareComputedWords(const runtime::FrameImage& frame, int width, int threads,
                                   int wordsPerThread, int wordsCompared, ExpectedWords expectedWords) {
    ComputedWords words;
    for (int thread = 0; thread < threads; ++thread) {
        const auto expected = expectedWords(static_cast<uint32_t>(thread));
        for (int k = 0; k < wordsCompared; ++k) {
            const int index = thread * wordsPerThread + k;
            const uint8_t* p = frame.pixel(index % width, index / width);
            const uint32_t word = p[0] | p[1] << 8 | p[2] << 16 | static_cast<uint32_t>(p[3]) << 24;
            words.nonZero += word != 0;
            if (word == expected[k]) continue;
            if (++words.wrong <= 8)
                ADD_FAILURE() << "thread " << thread << ", word " << k << ": GL computed 0x" << std::hex
                              << word << ", the CPU 0x" << expected[k] << std::dec;
        }
    }
    return words;
}

// The words the effect at `path` computed for `threads` threads (the first `wordsCompared` of each) equal
// the CPU's `expectedWords(thread)` bit for bit, and the frame is no blank one: more than half of them are
// not zero.
template <typename ExpectedWords>
void expectComputedWords(const std::string& path, int width, int height, int threads, int wordsPerThread,
                         int wordsCompared, ExpectedWords expectedWords) {
    const std::optional<runtime::FrameImage> frame = computedFrame(path, width, height);
    ASSERT_TRUE(frame);
    const ComputedWords words =
        compareComputedWords(*frame, width, threads, wordsPerThread, wordsCompared, expectedWords);
    EXPECT_EQ(words.wrong, 0);
    EXPECT_GT(words.nonZero, threads * wordsCompared / 2);
}

}  // namespace shadowfx::test
