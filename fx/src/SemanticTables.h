// SemanticTables: D3D9's and D3D10's semantics as the lowering reads them: canonical spellings, the
// varying location of each, the value a vertex input reads when no mesh stream feeds it. Private to fx.
#pragma once

#include <fx/Effect.h>

#include <optional>
#include <set>
#include <string>
#include <utility>

namespace fx {

// Vertex attribute locations: fx/VertexStreams.h (vertexInputLocation, vertexInputSemantic).
// Varying locations shared by both stages: TEXCOORDn -> n, COLORn -> 8+n, NORMAL 10, TANGENT 11,
// BINORMAL 12, FOG 13. Returns nullopt for semantics that are not varyings (POSITION, PSIZE, VPOS...).
std::optional<int> varyingLocation(const std::string& semantic);
// The semantic a POSITION member takes where its struct also has an SV_Position one (the parser's
// positionBesideSvPosition): a free name, so a varying in every stage.
constexpr const char* kPositionBesideSvPosition = "FX_POSITION";
// "texcoord" -> "TEXCOORD0", "COLOR" -> "COLOR0", "SV_Position" -> "SV_POSITION".
std::string canonicalSemantic(const std::string& semantic);
// Splits "TEXCOORD3" into ("TEXCOORD", 3); no trailing digits -> index 0.
std::pair<std::string, int> splitSemantic(const std::string& canonical);
// Vertex inputs D3D9 declared that no mesh here supplies (a second tangent frame, more blend weights,
// point size, fog): they read a constant, as an unbound D3D9 stream reads its default.
std::optional<std::string> vertexInputDefault(const std::string& semantic);
// D3D10 lets a varying carry any semantic name ("WORLDPOS", "LIGHTDIR", the SDK's "TEXTURE0".."TEXTURE8").
// Such names get the locations above the D3D9 table's (24..31), then the table's locations no semantic of
// the effect uses, in the order of their sorted names over the whole effect, so that every stage of every
// pass agrees. An array or a matrix takes one name per element; a name that only ever stands as a vertex
// shader's input (an attribute) takes none.
std::optional<int> customVaryingLocation(const Effect& effect, const std::string& semantic);
// The structs some vertex shader of the effect takes as an input (a pass's or a shader variable's compile
// expression with a vs_ profile).
std::set<std::string> vertexInputStructs(const Effect& effect);

}  // namespace fx
