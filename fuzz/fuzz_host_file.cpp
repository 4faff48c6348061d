// Fuzz target 8: the host file reader (runtime::parseHostJson) and its location index: any text is a
// host file or located errors, never a crash.
#include "FuzzSupport.h"

#include <runtime/HostFileReader.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size > (256u << 10)) return 0;
    fx::DiagnosticList diagnostics;
    std::shared_ptr<const fx::HostFile> host =
        runtime::parseHostJson(fuzz::text(data, size), "fuzz/host.json", diagnostics);
    if ((host != nullptr) == diagnostics.hasErrors()) __builtin_trap();
    (void)diagnostics.str();
    return 0;
}
