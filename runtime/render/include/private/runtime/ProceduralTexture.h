// ProceduralTexture: texels of the textures an effect asks the runtime to generate
// (`string Procedural = "noise"; int Seed = 7;` on a texture parameter; docs/effect-format.md, "What the
// runtime provides").
//
// The noise is uniform white noise, independent per texel and channel, from PCG32 (O'Neill, "PCG: A
// Family of Simple Fast Space-Efficient Statistically Good Algorithms for Random Number Generation",
// 2014; the reference pcg32_srandom_r/pcg32_random_r), so that every machine generates the same texture:
// no std:: distribution, whose algorithms differ between standard libraries.
#pragma once

#include <cstdint>
#include <vector>

namespace runtime {

// pcg32_random_r with the state initialised as pcg32_srandom_r(seed, sequence) does.
class Pcg32 {
public:
    Pcg32(uint64_t seed, uint64_t sequence);
    uint32_t next();

private:
    uint64_t mState = 0;
    uint64_t mIncrement = 0;
};

// The sequence every noise texture uses (PCG's demo default): the Seed annotation alone picks the stream.
constexpr uint64_t kNoiseSequence = 54;

// RGBA floats, rows top to bottom, texels left to right, channels R, G, B, A: each the next PCG32 output
// of Pcg32(seed, kNoiseSequence) mapped to [0, 1) as (x >> 8) * 2^-24 (24 bits: exact in a float).
// Mean 1/2, variance 1/12 per channel.
std::vector<float> whiteNoiseTexels(int width, int height, uint32_t seed);

}  // namespace runtime
