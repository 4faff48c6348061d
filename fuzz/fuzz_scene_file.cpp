// Fuzz target 4: the JSON scene loader (runtime::parseSceneJson). Mesh file names in the input resolve
// against "fuzz/" under the working directory, which scripts/fuzz.sh makes an empty temporary folder, so
// that the loader cannot read project files.
#include "FuzzSupport.h"

#include <runtime/SceneFile.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size > (256u << 10)) return 0;
    fx::DiagnosticList diagnostics;
    std::optional<runtime::Scene> scene =
        runtime::parseSceneJson(fuzz::text(data, size), "fuzz/scene.json", diagnostics);
    if (scene.has_value() == diagnostics.hasErrors()) __builtin_trap();
    (void)diagnostics.str();
    return 0;
}
