// Writes through swizzles through the real pipeline (docs/legalization.md): tests/data/d3d10/
// matrix_swizzle_writes.fx writes several matrix elements through a swizzle of a matrix swizzle, passes
// whole matrix swizzles and a vector swizzle to `out` and `inout` parameters, on a float4x4 and an int2x3,
// in a compute shader on Mesa's GL; this file computes the same words on the CPU, as HLSL copies an
// argument in and out through its swizzle, and compares them bit for bit. A blank frame fails.
#include "ComputedWords.h"
#include "EffectHarness.h"

#include <runtime/BuiltinScenes.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

namespace shadowfx::test::test_matrix_swizzle_writes {
namespace {

constexpr int kWidth = 128;
constexpr int kHeight = 4;
constexpr int kThreads = 16;
constexpr int kWordsPerThread = 32;
constexpr int kWordsWritten = 26;

uint32_t bitsOf(float value) {
    uint32_t bits = 0;
    std::memcpy(&bits, &value, 4);
    return bits;
}

std::array<uint32_t, kWordsWritten> threadWords(uint32_t i) {
    const float fi = static_cast<float>(i);
    float m[4][4];
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m[r][c] = static_cast<float>(r * 4 + c + 1) + fi;
    // m._m00_m11.yx = float2(i, 2 * i): .yx of (m00, m11) is (m11, m00).
    m[1][1] = fi;
    m[0][0] = 2 * fi;
    // m._m22_m23_m32.zx += float2(10, 20): .zx of (m22, m23, m32) is (m32, m22).
    m[3][2] += 10;
    m[2][2] += 20;
    // Twice(m._m01_m02)
    m[0][1] = m[0][1] * 2 + 1;
    m[0][2] = m[0][2] * 2 + 3;
    // Fill(m._m30_m31_m33)
    m[3][0] = 70;
    m[3][1] = 80;
    m[3][3] = 90;
    // Rotate(m._m10_m12_m13): v = v.zxy, then v.x + 100.
    const float m10 = m[1][0], m12 = m[1][2], m13 = m[1][3];
    m[1][0] = m13;
    m[1][2] = m10;
    m[1][3] = m12;
    const float rotated = m13 + 100;
    // Twice(v.zx) of v = (i, i + 1, i + 2).
    const float v[3] = {fi * 2 + 3, fi + 1, (fi + 2) * 2 + 1};
    int32_t e[2][3];
    for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 3; ++c) e[r][c] = static_cast<int32_t>(i) * (r * 3 + c + 1);
    // Bump(e._m02_m10), then e._m11_m00_m12.zy = int2(-1, -2): .zy of (m11, m00, m12) is (m12, m00).
    e[0][2] += 5;
    e[1][0] -= 3;
    e[1][2] = -1;
    e[0][0] = -2;

    std::array<uint32_t, kWordsWritten> words{};
    for (int k = 0; k < 16; ++k) words[k] = bitsOf(m[k / 4][k % 4]);
    words[16] = bitsOf(rotated);
    for (int k = 0; k < 3; ++k) words[17 + k] = bitsOf(v[k]);
    for (int n = 0; n < 6; ++n) words[20 + n] = static_cast<uint32_t>(e[n / 3][n % 3]);
    return words;
}

TEST(MatrixSwizzleWrites, WritesThroughSwizzlesAndOutArgumentsReachTheElementsHlslNames) {
    expectComputedWords("tests/data/d3d10/matrix_swizzle_writes.fx", kWidth, kHeight, kThreads,
                        kWordsPerThread, kWordsWritten, threadWords);
}

}  // namespace
}  // namespace shadowfx::test::test_matrix_swizzle_writes
