// SemanticIndex: a semantic's name and register index, the one reading of it for vertex inputs
// (VertexStreams.cpp, in the contract library) and varyings (SemanticTables.cpp, in the compiler).
#pragma once

#include <cctype>
#include <string>
#include <utility>

namespace fx {

// An index of more than nine digits is no register's: it reads as this, which every table and limit refuses,
// rather than overflowing an int (an effect may spell `TEXCOORD99999999999`).
inline constexpr int kSemanticIndexTooLarge = 1 << 30;

// "TEXCOORD3" -> ("TEXCOORD", 3); no trailing digits -> index 0. The name keeps its case.
inline std::pair<std::string, int> splitSemanticIndex(const std::string& semantic) {
    size_t end = semantic.size();
    while (end > 0 && std::isdigit(static_cast<unsigned char>(semantic[end - 1]))) --end;
    if (end == semantic.size()) return {semantic, 0};
    if (semantic.size() - end > 9) return {semantic.substr(0, end), kSemanticIndexTooLarge};
    return {semantic.substr(0, end), std::stoi(semantic.substr(end))};
}

}  // namespace fx
