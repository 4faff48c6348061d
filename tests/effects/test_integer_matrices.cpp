// Integer and bool matrices through the real pipeline (docs/legalization.md, "Integer and bool
// matrices"; its static table lists rows in braces, "Static initializers", and it writes |= on a bool):
// tests/data/d3d10/integer_matrices.fx computes with int2x3, uint2x4, bool2x3 and uint4x4 in a compute
// shader on Mesa's GL, and this file computes the same words on the CPU, as HLSL defines each operation
// (element by element, two's-complement wrap, arithmetic right shift of ints), and compares them bit for
// bit. A blank frame (every word zero) fails.
#include "ComputedWords.h"
#include "EffectHarness.h"

#include <runtime/BuiltinScenes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace shadowfx::test::test_integer_matrices {
namespace {

constexpr int kWidth = 128;
constexpr int kHeight = 4;
constexpr int kThreads = 64;
constexpr int kWordsPerThread = 8;

// An HLSL matrix: rows of columns.
template <typename T, size_t Rows, size_t Columns>
using Matrix = std::array<std::array<T, Columns>, Rows>;
using Int2x3 = Matrix<int32_t, 2, 3>;
using Uint2x3 = Matrix<uint32_t, 2, 3>;
using Bool2x3 = Matrix<bool, 2, 3>;
using Uint2x4 = Matrix<uint32_t, 2, 4>;
using Uint4x4 = Matrix<uint32_t, 4, 4>;

// What the effect's parameters and its static table hold.
constexpr Int2x3 kOffsets = {{{1, -2, 3}, {4, 5, -6}}};
constexpr uint32_t kPrecision = 5;
constexpr std::array<Uint4x4, 2> kRotations = {{
    {{{1, 2, 3, 4}, {5, 6, 7, 8}, {9, 10, 11, 12}, {13, 14, 15, 16}}},
    {{{0x100, 0x2000, 0x30000, 0x400000}, {17, 19, 23, 29}, {31, 37, 41, 43}, {47, 53, 59, 61}}},
}};

// Two's-complement arithmetic, as HLSL's ints wrap.
int32_t wrap(uint32_t bits) {
    return static_cast<int32_t>(bits);
}
uint32_t bits(int32_t value) {
    return static_cast<uint32_t>(value);
}

template <typename T, size_t R, size_t C, typename F>
auto elementWise(const std::array<std::array<T, C>, R>& m, F f) {
    Matrix<decltype(f(m[0][0], 0, 0)), R, C> out{};
    for (size_t r = 0; r < R; ++r)
        for (size_t c = 0; c < C; ++c) out[r][c] = f(m[r][c], static_cast<int>(r), static_cast<int>(c));
    return out;
}

uint32_t rowSum(const std::array<int32_t, 3>& row) {
    return bits(row[0]) + 3 * bits(row[1]) + 5 * bits(row[2]);
}

std::array<uint32_t, kWordsPerThread> threadWords(uint32_t i) {
    const int32_t si = static_cast<int32_t>(i);
    Int2x3 e = {{{si, -si, static_cast<int32_t>(3 * i)}, {static_cast<int32_t>(i ^ 5), 7 - si, si - 31}}};
    e = elementWise(e, [](int32_t v, int r, int c) { return wrap(bits(v) + bits(kOffsets[r][c])); });
    // Quantize: (shift >= 15 | e == 0) ? e : ((e << shift) + 0x40) >> 7, element by element.
    const int32_t shift = static_cast<int32_t>(kPrecision);
    e = elementWise(e, [&](int32_t v, int, int) {
        return shift >= 15 || v == 0 ? v : wrap((bits(v) << shift) + 0x40) >> 7;
    });
    const Bool2x3 negative = elementWise(e, [](int32_t v, int, int) { return v < 0; });
    Int2x3 a = elementWise(e, [](int32_t v, int, int) { return wrap(bits(v < 0 ? -v : v)) & 0x3f; });
    const Int2x3 n = elementWise(a, [&](int32_t v, int r, int c) { return negative[r][c] ? -v : ~v; });
    Uint2x4 m = {kRotations[i & 1][i % 4], kRotations[(i + 1) & 1][(i >> 2) % 4]};
    m = elementWise(m, [&](uint32_t v, int, int) { return (v ^ (v << (i % 7))) + 3; });
    const uint32_t first = m[0][0];  // HLSL reads m._m00 once, before it writes a row
    m = elementWise(m, [&](uint32_t v, int, int) { return v ^ first; });
    const Uint2x3 s = elementWise(e, [](int32_t v, int, int) { return v >= 0 ? 0u : 1u; });
    const Uint2x3 c = elementWise(a, [&](int32_t v, int r, int col) {
        const uint32_t u = bits(v);
        return std::clamp(u, 2u, 40u) + (std::min(s[r][col], 1u) << 4) + std::max(u, 9u);
    });
    const Int2x3 mirrored = {e[1], e[0]};

    uint32_t flags = 0;
    bool anyNegative = false, allNonZero = true, anyOffset = false;
    for (int k = 0; k < 6; ++k) {
        const int r = k / 3, col = k % 3;
        flags |= (negative[r][col] ? 1u : 0u) << k;
        anyNegative |= negative[r][col];
        allNonZero &= n[r][col] != 0;
        anyOffset |= e[r][col] == kOffsets[r][col];
    }
    flags |= (anyNegative ? 1u : 0u) << 6 | (allNonZero ? 1u : 0u) << 7 | (anyOffset ? 1u : 0u) << 8;
    const bool big = ((e[0][0] > 8 || e[1][1] > 1) && i > 3) != ((i & 4) != 0);
    flags |= (big ? 1u : 0u) << 9;
    const auto mixed = [](const std::array<uint32_t, 4>& row) {
        return row[0] ^ (row[1] * 7) ^ (row[2] * 13) ^ (row[3] * 17);
    };
    const auto asInts = [](const std::array<uint32_t, 3>& row) {
        return std::array<int32_t, 3>{wrap(row[0]), wrap(row[1]), wrap(row[2])};
    };
    return {rowSum(e[0]),
            rowSum(e[1]),
            flags,
            rowSum(n[0]) ^ (rowSum(n[1]) << 3),
            mixed(m[0]),
            mixed(m[1]),
            s[0][0] + 2 * s[0][1] + 4 * s[0][2] + 8 * s[1][0] + 16 * s[1][1] + 32 * s[1][2] +
                (bits(e[i & 1][i % 3]) << 8),
            rowSum(asInts(c[0])) + 7 * rowSum(asInts(c[1])) + 11 * rowSum(mirrored[0])};
}

TEST(IntegerMatrices, ElementWiseOperationsOnIntegerMatricesMatchTheCpuBitForBit) {
    expectComputedWords("tests/data/d3d10/integer_matrices.fx", kWidth, kHeight, kThreads, kWordsPerThread,
                        kWordsPerThread, threadWords);
}

}  // namespace
}  // namespace shadowfx::test::test_integer_matrices
