// ConformanceRun: the measurement of `shadowfx check`: every technique of every effect compiled once, then
// per backend rendered headlessly on each of its scenes and checked: compile, link, GL errors, non-finite
// render targets, a blank or constant frame, its Expect* annotations against the ray-cast ground truth
// (docs/scoring.md) and its golden images (written instead with `update`). The rows go to
// report/ConformanceReport.h; the images of a failure are written under `outDir` as it runs.
// Where goldens live per renderer: docs/measurement.md, "shadowfx check".
#pragma once

#include <fx/HostFile.h>
#include <fx/EffectParser.h>
#include <report/ConformanceReport.h>
#include <runtime/GlContext.h>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace runtime {

struct ConformanceOptions {
    std::vector<std::string> effects;     // effect source files
    std::vector<std::string> techniques;  // only these (empty: all)
    std::vector<Backend> backends{Backend::EGL, Backend::OSMesa};
    bool backendsNamed = false;       // a backend that creates no context FAILs instead of NOT_SUPPORTED
    std::vector<std::string> scenes;  // for every technique, over its ExpectScenes (empty: ExpectScenes)
    std::optional<float> areaRadius;  // the penumbra checks' light size, over ExpectAreaRadius
    int width = 320, height = 240;    // the size goldens are made at
    int areaSamples = 256;            // ground-truth light samples per pixel for area lights
    std::string truthCacheDir;        // TruthCache.h; empty: cast every truth
    bool update = false;              // write this renderer's goldens instead of comparing
    bool requireGoldens = false;      // a renderer without goldens FAILs instead of NOT_SUPPORTED
    bool batching = true;
    std::filesystem::path outDir = "out/check";  // EFFECT/TECHNIQUE/SCENE.{result,reference,errormask}.png
    fx::ParseOptions parseOptions;               // -I and -D
    // --host: every technique drawn as the host file's application drew it (docs/host-files.md).
    std::shared_ptr<const fx::HostFile> host;
};

struct ConformanceLog {
    std::function<void(const std::string&)> note;        // a line for the user (the renderer, images written)
    std::function<void(const std::string&)> diagnostic;  // each distinct diagnostic once (DiagnosticLog)
};

struct ConformanceResult {
    bool noTechniqueMatches = false;  // `techniques` named none of the effects' techniques: nothing checked
    bool anyContext = false;          // some backend created a context (else nothing was rendered)
    std::vector<report::CheckRow> rows;
};

ConformanceResult runConformance(const ConformanceOptions& options, const ConformanceLog& log);

}  // namespace runtime
