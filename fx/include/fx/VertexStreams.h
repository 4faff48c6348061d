// VertexStreams: which mesh stream feeds a vertex shader's input, decided once by the compiler and carried
// in each CompiledPass's VertexInput, so that the runtime binds buffers without reading semantic names.
//
// Every stream has a fixed attribute location, the same in every program:
//   POSITION 0, NORMAL 1, TEXCOORD0..7 2..9, COLOR0..1 10..11, TANGENT 12, BINORMAL 13, BLENDWEIGHT 14,
//   BLENDINDICES 15.
// D3D9 names the streams exactly (vertexInputLocation). D3D10/11 input layouts bind free names that each
// application chose ("POS", "TEXTURE0", "UV", "NORM"); vertexStreamByName() matches them to the streams
// by the prefixes applications used.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace fx {

enum class VertexStream : uint8_t {
    Position,
    Normal,
    Texcoord,
    Color,
    Tangent,
    Binormal,
    BlendWeight,
    BlendIndices
};

struct VertexStreamSlot {
    VertexStream stream = VertexStream::Position;
    int index = 0;  // TEXCOORD3 -> 3
};

// The attribute location of a D3D9 vertex semantic ("POSITION", "TEXCOORD3", any case); nullopt for names
// outside the table above.
std::optional<int> vertexInputLocation(const std::string& semantic);
// The semantic a location carries ("TEXCOORD0"); "" outside the table.
std::string vertexInputSemantic(int location);
// The stream at a location of the table.
std::optional<VertexStreamSlot> vertexStreamAt(int location);
// A D3D10 input-layout name matched to a stream by its prefix, with its trailing digits as the index:
// POS* -> position, NORM* -> normal, TEX* and UV* -> texture coordinates, BINORM* and BITAN* ->
// binormal, TAN* -> tangent, COL* -> colour, BLENDIND* -> blend indices, other BLEND* -> blend weights.
// The location it gets, or nullopt where no stream fits (the input then reads a constant).
std::optional<int> vertexStreamByName(const std::string& semantic);

}  // namespace fx
