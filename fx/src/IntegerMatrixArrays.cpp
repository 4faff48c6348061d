// IntegerMatrixArrays: see IntegerMatrixArrays.h.
#include "IntegerMatrixArrays.h"

#include <set>

namespace fx::detail {

namespace {

// SPIR-V's numbers for what this file reads and writes (the SPIR-V 1.0 specification, 3.32 and 3.20).
constexpr uint32_t kOpDecorate = 71, kOpMemberDecorate = 72, kOpTypeBool = 20, kOpTypeInt = 21,
                   kOpTypeVector = 23, kOpTypeMatrix = 24, kOpTypeArray = 28, kOpTypeRuntimeArray = 29,
                   kOpTypeStruct = 30, kOpConstant = 43;
constexpr uint32_t kDecorationBufferBlock = 3, kDecorationRowMajor = 4, kDecorationColMajor = 5,
                   kDecorationArrayStride = 6, kDecorationMatrixStride = 7;
constexpr size_t kHeaderWords = 5;

struct Instruction {
    size_t at;  // word offset in the module
    uint32_t opcode;
    uint32_t words;
};

std::vector<Instruction> instructions(const std::vector<uint32_t>& spirv) {
    std::vector<Instruction> out;
    for (size_t at = kHeaderWords; at < spirv.size();) {
        const uint32_t words = spirv[at] >> 16;
        if (words == 0 || at + words > spirv.size()) break;
        out.push_back({at, spirv[at] & 0xffff, words});
        at += words;
    }
    return out;
}

uint32_t word(uint32_t opcode, uint32_t words) {
    return words << 16 | opcode;
}

}  // namespace

IntegerMatrixLowering lowerIntegerMatrices(std::vector<uint32_t>& spirv) {
    IntegerMatrixLowering lowering;
    if (spirv.size() <= kHeaderWords) return lowering;
    const std::vector<Instruction> all = instructions(spirv);

    std::set<uint32_t> integerScalars, integerVectors, integerMatrices, bufferBlocks;
    std::map<uint32_t, uint32_t> arrayElement;                // array type -> element type
    std::map<uint32_t, std::vector<uint32_t>> structMembers;  // struct type -> member types
    for (const Instruction& i : all) {
        const uint32_t* w = &spirv[i.at];
        if (i.opcode == kOpTypeBool || i.opcode == kOpTypeInt) integerScalars.insert(w[1]);
        if (i.opcode == kOpTypeVector && integerScalars.count(w[2])) integerVectors.insert(w[1]);
        if (i.opcode == kOpTypeMatrix && integerVectors.count(w[2])) integerMatrices.insert(w[1]);
        if (i.opcode == kOpTypeArray || i.opcode == kOpTypeRuntimeArray) arrayElement[w[1]] = w[2];
        if (i.opcode == kOpTypeStruct) structMembers[w[1]].assign(w + 2, w + i.words);
        if (i.opcode == kOpDecorate && i.words > 2 && w[2] == kDecorationBufferBlock)
            bufferBlocks.insert(w[1]);
    }
    if (integerMatrices.empty()) return lowering;

    const auto holdsMatrix = [&](uint32_t type) {
        while (arrayElement.count(type)) type = arrayElement[type];
        return integerMatrices.count(type) > 0;
    };
    // The structs a structured buffer's element holds, through arrays and nested structs.
    std::set<uint32_t> inBuffers;
    std::vector<uint32_t> pending(bufferBlocks.begin(), bufferBlocks.end());
    while (!pending.empty()) {
        uint32_t type = pending.back();
        pending.pop_back();
        while (arrayElement.count(type)) type = arrayElement[type];
        if (!structMembers.count(type) || !inBuffers.insert(type).second) continue;
        for (uint32_t member : structMembers[type]) pending.push_back(member);
    }

    // The members that hold a matrix: their layout decorations go (an array has none of a matrix's), their
    // MatrixStride becomes the row array's ArrayStride.
    std::map<uint32_t, uint32_t> arrayStrides;  // matrix type -> its rows' stride in buffers
    std::vector<uint32_t> out(spirv.begin(), spirv.begin() + kHeaderWords);
    std::map<std::pair<uint32_t, uint32_t>, bool> rowMajorMembers;  // true: HLSL's rows contiguous
    for (const Instruction& i : all) {
        const uint32_t* w = &spirv[i.at];
        if (i.opcode != kOpMemberDecorate || i.words < 4) continue;
        const auto members = structMembers.find(w[1]);
        if (members == structMembers.end() || w[2] >= members->second.size() ||
            !holdsMatrix(members->second[w[2]]))
            continue;
        if (inBuffers.count(w[1])) {
            lowering.error =
                "an integer or bool matrix in a structured buffer's element is not supported (shadowfx "
                "stores "
                "these matrices as arrays of their rows): declare the member as an array of int or uint "
                "vectors";
            return lowering;
        }
        // glslang decorates RowMajor an HLSL column_major matrix (its SPIR-V rows are HLSL's columns).
        if (w[3] == kDecorationRowMajor) rowMajorMembers[{w[1], w[2]}] = false;
        if (w[3] == kDecorationColMajor) rowMajorMembers.emplace(std::make_pair(w[1], w[2]), true);
        if (w[3] == kDecorationMatrixStride && i.words > 4) {
            uint32_t type = members->second[w[2]];
            while (arrayElement.count(type)) type = arrayElement[type];
            const auto [stride, added] = arrayStrides.emplace(type, w[4]);
            if (!added && stride->second != w[4]) {
                lowering.error =
                    "integer or bool matrices of one type laid out with two strides in two "
                    "buffers are not supported";
                return lowering;
            }
            lowering.members[{w[1], w[2]}].rowStride = w[4];
        }
    }
    for (const auto& [member, rowsContiguous] : rowMajorMembers) {
        if (rowsContiguous) continue;
        lowering.error =
            "an integer or bool matrix declared column_major in a constant buffer's struct is not supported "
            "(shadowfx stores these matrices as arrays of their rows): declare it row_major";
        return lowering;
    }

    uint32_t bound = spirv[3];
    uint32_t uintType = 0;  // a 32-bit integer type declared so far, for the arrays' lengths
    bool stridesDecorated = false;
    for (const Instruction& i : all) {
        const uint32_t* w = &spirv[i.at];
        // The rows' strides among the module's other decorations, which precede its types.
        if ((i.opcode == kOpDecorate || i.opcode == kOpMemberDecorate) && !stridesDecorated) {
            for (const auto& [matrix, stride] : arrayStrides)
                out.insert(out.end(), {word(kOpDecorate, 4), matrix, kDecorationArrayStride, stride});
            stridesDecorated = true;
        }
        if (i.opcode == kOpMemberDecorate && i.words >= 4 &&
            (w[3] == kDecorationRowMajor || w[3] == kDecorationColMajor || w[3] == kDecorationMatrixStride) &&
            lowering.members.count({w[1], w[2]}) + rowMajorMembers.count({w[1], w[2]}) > 0)
            continue;
        if (i.opcode == kOpTypeInt && w[2] == 32 && !uintType) uintType = w[1];
        if (i.opcode == kOpTypeMatrix && integerMatrices.count(w[1])) {
            if (!uintType) {
                uintType = bound++;
                out.insert(out.end(), {word(kOpTypeInt, 4), uintType, 32, 0});
            }
            const uint32_t length = bound++;
            out.insert(out.end(), {word(kOpConstant, 4), uintType, length, w[3]});
            out.insert(out.end(), {word(kOpTypeArray, 4), w[1], w[2], length});
            continue;
        }
        out.insert(out.end(), w, w + i.words);
    }
    out[3] = bound;
    spirv = std::move(out);
    return lowering;
}

}  // namespace fx::detail
