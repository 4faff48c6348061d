// VertexStreams: the attribute table and the free-name matching (see VertexStreams.h).
#include <fx/VertexStreams.h>

#include "CaseFolding.h"
#include "SemanticIndex.h"

#include <array>
#include <cctype>

namespace fx {

namespace {

struct StreamRange {
    const char* semantic;  // D3D9's name
    VertexStream stream;
    int firstLocation;
    int count;  // indices 0..count-1
};

constexpr std::array<StreamRange, 8> kStreams = {{
    {"POSITION", VertexStream::Position, 0, 1},
    {"NORMAL", VertexStream::Normal, 1, 1},
    {"TEXCOORD", VertexStream::Texcoord, 2, 8},
    {"COLOR", VertexStream::Color, 10, 2},
    {"TANGENT", VertexStream::Tangent, 12, 1},
    {"BINORMAL", VertexStream::Binormal, 13, 1},
    {"BLENDWEIGHT", VertexStream::BlendWeight, 14, 1},
    {"BLENDINDICES", VertexStream::BlendIndices, 15, 1},
}};

// "TEXCOORD3" -> ("TEXCOORD", 3), upper case.
std::pair<std::string, int> splitUpper(const std::string& semantic) {
    return splitSemanticIndex(upperCase(semantic));
}

std::optional<int> locationOf(VertexStream stream, int index) {
    for (const StreamRange& r : kStreams)
        if (r.stream == stream)
            return index >= 0 && index < r.count ? std::optional<int>(r.firstLocation + index) : std::nullopt;
    return std::nullopt;
}

bool startsWith(const std::string& s, const char* prefix) {
    return s.rfind(prefix, 0) == 0;
}

}  // namespace

std::optional<int> vertexInputLocation(const std::string& semantic) {
    auto [name, index] = splitUpper(semantic);
    if (name == "SV_POSITION") name = "POSITION";
    for (const StreamRange& r : kStreams)
        if (name == r.semantic) return locationOf(r.stream, index);
    return std::nullopt;
}

std::string vertexInputSemantic(int location) {
    for (const StreamRange& r : kStreams)
        if (location >= r.firstLocation && location < r.firstLocation + r.count)
            return r.count == 1 ? std::string(r.semantic)
                                : r.semantic + std::to_string(location - r.firstLocation);
    return "";
}

std::optional<VertexStreamSlot> vertexStreamAt(int location) {
    for (const StreamRange& r : kStreams)
        if (location >= r.firstLocation && location < r.firstLocation + r.count)
            return VertexStreamSlot{r.stream, location - r.firstLocation};
    return std::nullopt;
}

std::optional<int> vertexStreamByName(const std::string& semantic) {
    const auto [name, index] = splitUpper(semantic);
    // BINORMAL before NORMAL's prefix could not matter (BINORM does not start with NORM), but BITANGENT
    // must be tested before TAN*, and BLENDINDICES before BLEND*.
    if (startsWith(name, "POS")) return locationOf(VertexStream::Position, index);
    if (startsWith(name, "NORM")) return locationOf(VertexStream::Normal, index);
    if (startsWith(name, "TEX") || startsWith(name, "UV")) return locationOf(VertexStream::Texcoord, index);
    if (startsWith(name, "BINORM") || startsWith(name, "BITAN"))
        return locationOf(VertexStream::Binormal, index);
    if (startsWith(name, "TAN")) return locationOf(VertexStream::Tangent, index);
    if (startsWith(name, "COL")) return locationOf(VertexStream::Color, index);
    if (startsWith(name, "BLENDIND") || startsWith(name, "BONE") || startsWith(name, "JOINT"))
        return locationOf(VertexStream::BlendIndices, index);
    if (startsWith(name, "BLEND") || startsWith(name, "WEIGHT"))
        return locationOf(VertexStream::BlendWeight, index);
    return std::nullopt;
}

}  // namespace fx
