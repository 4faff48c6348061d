// Fuzz target 3: the SAS script parser (fx::parseSasScript), the text of a `string Script = "...";`.
#include "FuzzSupport.h"

#include <fx/SasScript.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    fx::DiagnosticList diagnostics;
    std::vector<fx::ScriptCommand> commands =
        fx::parseSasScript(fuzz::text(data, size), fx::SourceLoc{"fuzz/input.fx", 1, 1}, diagnostics);
    for (const fx::ScriptCommand& command : commands) (void)fx::scriptCommandName(command.kind);
    (void)diagnostics.str();
    return 0;
}
