#include <private/runtime/ProceduralTexture.h>

#include <cstddef>

namespace runtime {

Pcg32::Pcg32(uint64_t seed, uint64_t sequence) : mIncrement((sequence << 1u) | 1u) {
    next();
    mState += seed;
    next();
}

uint32_t Pcg32::next() {
    const uint64_t old = mState;
    mState = old * 6364136223846793005ULL + mIncrement;
    const auto xorShifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rotation = static_cast<uint32_t>(old >> 59u);
    return (xorShifted >> rotation) | (xorShifted << ((32u - rotation) & 31u));
}

std::vector<float> whiteNoiseTexels(int width, int height, uint32_t seed) {
    Pcg32 generator(seed, kNoiseSequence);
    std::vector<float> texels(static_cast<size_t>(width) * static_cast<size_t>(height) * 4);
    for (float& value : texels) value = static_cast<float>(generator.next() >> 8) * (1.0f / 16777216.0f);
    return texels;
}

}  // namespace runtime
