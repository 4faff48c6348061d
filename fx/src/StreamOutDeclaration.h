// StreamOutDeclaration: D3D10's stream-output declaration, the string of
// `ConstructGSWithSO(CompileShader(gs_4_0, GS()), "POSITION.xyz; NORMAL.xyz; TIMER.x")`, read into the
// elements a stream-output buffer holds, as D3D10_SO_DECLARATION_ENTRY lists them: per entry
// `[slot:]SEMANTIC[index][.mask]` or `[slot:]$SKIP[.mask]`, entries separated by ';'. A malformed entry
// is a located error at its characters, as fxc refused it. Private to fx.
#pragma once

#include <fx/Diagnostics.h>
#include <fx/Effect.h>

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace fx::detail {

struct StreamOutEntry {
    int slot = 0;            // the output buffer (D3D10: 0..3)
    std::string semantic;    // "$SKIP" for a gap of componentCount components
    int semanticIndex = 0;   // TEXCOORD1 -> 1
    int startComponent = 0;  // .yz -> 1
    int componentCount = 4;  // .yz -> 2; no mask: all four
    std::string text;        // the entry as written, for messages
    SourceLoc loc;
};

using ReportStreamOutError = std::function<void(DiagId, const SourceLoc&, const std::vector<std::string>&)>;

// The elements of the string literal `declaration`; reports each malformed entry and leaves it out.
std::vector<StreamOutEntry> parseStreamOutDeclaration(const Expr& declaration,
                                                      const ReportStreamOutError& error);

// Checks a `ConstructGSWithSO(shader, "declaration")` call, or FX11's
// `ConstructGSWithSO(shader, "stream0", "stream1", "stream2", "stream3", rasterizedStream)` (a stream may
// be NULL): its form, every declaration string, and, where the shader's function and its outputs are known
// (`effect` holds the declarations parsed so far), that each entry names an output of the shader and masks
// components it has, as D3D10 matched the declaration against the output signature.
void validateConstructGSWithSO(const Expr& call, const Effect& effect, const ReportStreamOutError& error);

// What the compiler lowers of a `ConstructGSWithSO` call the parser accepted.
struct StreamOutCall {
    const Expr* shader = nullptr;         // CompileShader(...) or a shader variable
    std::vector<StreamOutEntry> entries;  // stream 0's declaration, stable-sorted by slot
    // FX11's declaration of a stream other than 0: a geometry shader with several output streams, which
    // the pass lowering refuses anyway.
    bool otherStreams = false;
};
std::optional<StreamOutCall> readConstructGSWithSO(const Expr& call);

// (SEMANTIC, index) -> components of each output a shader writes: a geometry shader's stream element, or a
// vertex shader's return value and out parameters; nothing where the function is not one definition whose
// outputs are plain scalars and vectors. `name` is set to the function's name.
using OutputSignature = std::map<std::pair<std::string, int>, int>;
std::optional<OutputSignature> streamOutputSignature(const Expr& shader, const Effect& effect,
                                                     std::string& name);

}  // namespace fx::detail
