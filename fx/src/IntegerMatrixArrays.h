// IntegerMatrixArrays: the integer and bool matrices of a SPIR-V module made arrays of their rows, before
// SPIRV-Cross reads it. glslang writes an HLSL `int2x3` as a SPIR-V matrix of two int vectors (glslang's
// columns are HLSL's rows), which SPIR-V allows for floats only and GLSL has no type for (`imat2x3`).
// Once IntegerMatrixSplitting has rewritten every element-wise operation into one per row, an integer
// matrix is only declared, built from rows (OpCompositeConstruct), indexed (OpAccessChain,
// OpCompositeExtract/Insert), loaded, stored and passed, which an array of the same vectors supports
// alike: each such OpTypeMatrix becomes an OpTypeArray of its vectors, `ivec3[2]` in GLSL. In a buffer, a
// matrix whose vectors are HLSL's rows (row_major, as shadowfx declares its parameters of these types)
// keeps its place and stride; one laid out column_major, or one in a structured buffer's element (whose
// bytes the application writes in D3D's order), is refused. Private to fx.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace fx::detail {

// A block member that was an integer or bool matrix (or an array of them) and is now an array of its rows.
struct LoweredMatrixMember {
    uint32_t rowStride = 0;  // bytes between its rows (the matrix's MatrixStride)
};

struct IntegerMatrixLowering {
    // By (struct type id, member index).
    std::map<std::pair<uint32_t, uint32_t>, LoweredMatrixMember> members;
    std::string error;  // non-empty: a matrix the lowering refuses, and why
};

// Rewrites `spirv` in place (see above).
IntegerMatrixLowering lowerIntegerMatrices(std::vector<uint32_t>& spirv);

}  // namespace fx::detail
