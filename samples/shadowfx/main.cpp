// shadowfx: the command-line tool. Thin by design: parse arguments, call the fx and runtime libraries,
// print. Subcommands are one table (kCommands); each has --help.
//
//   shadowfx render EFFECT.fx --out FILE.png [options]   render one frame headlessly
//   shadowfx compile EFFECT.fx [--technique NAME]        print the generated GLSL, or the diagnostics
//   shadowfx info EFFECT.fx                              list techniques, passes and parameters
//   shadowfx bench --effects A.fx,B.fx --out DIR [...]   shadow error and frame time (BenchCommand)
//   shadowfx bench merge OUT DIR...                      join --shard outputs (BenchMergeCommand)
//   shadowfx check EFFECT.fx [...]                       expectations, goldens, JUnit (CheckCommand)
//   shadowfx stress [EFFECT.fx ...] [--reduced]          extreme configurations (StressCommand)
//   shadowfx tune EFFECT.fx --technique T --scenes ...   best tweakables within a time budget (TuneCommand)
//   shadowfx view EFFECT.fx [...]                        window, hot reload, parameters (ViewCommand)
//   shadowfx new NAME [--from pcf|vsm|minimal]           a technique skeleton NAME.fx (NewCommand)
#include "BenchCommand.h"
#include "BenchMergeCommand.h"
#include "CheckCommand.h"
#include "CommandLine.h"
#include "HostOption.h"
#include "NewCommand.h"
#include "StressCommand.h"
#include "TuneCommand.h"
#include "ViewCommand.h"

#include <fx/CompiledEffectFile.h>
#include <fx/EffectFile.h>
#include <runtime/EffectRenderer.h>
#include <runtime/GlContext.h>
#include <runtime/Scene.h>
#include <runtime/SceneFile.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace {

using shadowfx::cli::Arguments;
using shadowfx::cli::removeStaleOutput;

// Prints every diagnostic as "path:line:column: severity: message" with the source line and a caret;
// notes with --verbose, the GL driver's words on the generated GLSL with --driver-log only (their line
// numbers are the GLSL's, not the effect's).
class StderrSink : public fx::DiagnosticSink {
public:
    using fx::DiagnosticSink::report;
    explicit StderrSink(bool verbose, bool driverLog = false) : mVerbose(verbose), mDriverLog(driverLog) {}
    void report(const fx::Diagnostic& diagnostic) override {
        const bool driverLog = diagnostic.id == fx::DiagId::DriverShaderLog ||
                               diagnostic.id == fx::DiagId::DriverFixedFunctionLog ||
                               diagnostic.id == fx::DiagId::DriverLinkLog;
        if (driverLog ? !mDriverLog : diagnostic.severity == fx::Severity::Note && !mVerbose) return;
        if (diagnostic.severity == fx::Severity::Error) ++mErrors;
        std::cerr << fx::renderDiagnostic(diagnostic) << "\n";
    }
    int errors() const { return mErrors; }

private:
    bool mVerbose;
    bool mDriverLog;
    int mErrors = 0;
};

// An effect source (.fx) or a compiled effect file (.sfxo), told apart by its first bytes.
std::shared_ptr<fx::CompiledEffect> loadEffect(const Arguments& args, const std::string& technique,
                                               fx::DiagnosticSink& sink) {
    fx::CompileOptions options;
    options.technique = technique;
    return fx::loadEffectFile(args.positional(0), shadowfx::cli::effectParseOptions(args), options, sink);
}

// [SECTION] render
int renderCommand(const Arguments& args) {
    const std::string out = args.value("--out");
    const bool verbose = args.flag("--verbose");
    StderrSink sink(verbose, args.flag("--driver-log"));
    removeStaleOutput(out);

    const int width = args.intValue("--width", 800);
    const int height = args.intValue("--height", 600);
    if (width <= 0 || height <= 0 || width > 16384 || height > 16384) {
        std::cerr << "shadowfx render: --width and --height must be between 1 and 16384\n";
        return 2;
    }
    std::optional<runtime::Scene> scene = runtime::loadScene(args.value("--scene", "boxes"), sink);
    if (!scene) return 2;
    const std::optional<runtime::Backend> backend = runtime::parseBackend(args.value("--backend", "auto"));
    if (!backend || *backend == runtime::Backend::GLFW) {
        std::cerr << "shadowfx render: --backend must be auto, osmesa or egl\n";
        return 2;
    }

    std::shared_ptr<fx::CompiledEffect> compiled = loadEffect(args, args.value("--technique"), sink);
    if (!compiled || sink.errors() > 0) return 1;
    bool hostRead = true;
    const std::shared_ptr<const fx::HostFile> host = shadowfx::cli::readHostOption(args, sink, hostRead);
    if (!hostRead) return 1;

    runtime::ContextOptions contextOptions;
    contextOptions.backend = *backend;
    contextOptions.debug = verbose;
    // Mesa's on-disk shader cache skips compiling a shader it has seen before, and leaves its info log
    // empty then: the driver's words would come only on a shader's first run on this machine.
    if (args.flag("--driver-log")) setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
    std::string contextError;
    std::unique_ptr<runtime::GlContext> context = runtime::createContext(contextOptions, contextError);
    if (!context) {
        std::cerr << "shadowfx render: " << contextError << "\n";
        return 1;
    }
    if (verbose) {
        std::cerr << "shadowfx: backend " << runtime::backendName(context->backend()) << ": "
                  << context->renderer() << "\n";
    }

    std::unique_ptr<runtime::EffectRenderer> renderer = runtime::EffectRenderer::create(compiled, sink);
    if (!renderer || !shadowfx::cli::useHostFile(*renderer, host, sink)) return 1;
    for (const std::string& assignment : args.all("--set")) {
        const size_t eq = assignment.find('=');
        if (eq == std::string::npos) {
            std::cerr << "shadowfx render: --set expects PARAM=VALUE, got '" << assignment << "'\n";
            return 2;
        }
        if (!renderer->setParameterFromText(assignment.substr(0, eq), assignment.substr(eq + 1), sink))
            return 1;
    }

    runtime::FrameOptions frame;
    frame.width = width;
    frame.height = height;
    frame.technique = args.value("--technique");
    frame.leaveOut = !args.flag("--no-leave-out");
    frame.batching = !args.flag("--no-batching");
    frame.countTexels = args.flag("--stats");
    runtime::FrameStats stats;
    if (!renderer->render(*scene, frame, sink, &stats) || sink.errors() > 0) return 1;

    runtime::FrameImage image = renderer->readFrame();
    // FX Composer's viewport showed a frame's colour alone: an effect that writes alpha 0 (its edge
    // detectors' lines) stays visible in an image written so.
    if (args.flag("--opaque"))
        for (size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255;
    std::string writeError;
    if (!runtime::writePng(image, out, writeError)) {
        std::cerr << "shadowfx render: " << writeError << "\n";
        removeStaleOutput(out);
        return 1;
    }
    if (args.flag("--stats") || verbose) {
        std::cerr << "shadowfx: " << stats.passesRun << " passes, " << stats.draws << " draws ("
                  << stats.objects << " objects), " << stats.triangles << " triangles, " << stats.clears
                  << " clears";
        std::cerr << " (leave-out " << (frame.leaveOut ? "on" : "off") << ": " << stats.passesLeftOut
                  << " passes left out, " << stats.culled << " objects culled)\n";
    }
    if (args.flag("--stats")) {
        for (const runtime::PassStats& pass : stats.passes) {
            std::cerr << "  pass " << pass.pass << ": "
                      << (pass.leftOut.empty() ? std::string("ran") : "left out (" + pass.leftOut + ")")
                      << ", " << pass.draws << " draws (" << pass.objects << " objects), " << pass.culled
                      << " culled, " << pass.triangles << " triangles, " << pass.clears << " clears, "
                      << pass.texelsWritten << " texels written\n";
        }
    }
    std::cout << out << "\n";
    return 0;
}

// [SECTION] compile
int compileCommand(const Arguments& args) {
    StderrSink sink(args.flag("--verbose"));
    const std::string out = args.value("--out");
    if (!out.empty()) removeStaleOutput(out);
    std::shared_ptr<fx::CompiledEffect> compiled = loadEffect(args, args.value("--technique"), sink);
    if (!compiled || sink.errors() > 0) return 1;
    // The compiled effect file (docs/compiled-effect.md) instead of the listing.
    if (!out.empty()) return fx::writeCompiledEffectFile(*compiled, out, sink) ? 0 : 1;
    const bool showHlsl = args.flag("--hlsl");
    for (const fx::CompiledTechnique& technique : compiled->techniques) {
        for (const fx::CompiledPass& pass : technique.passes) {
            for (const fx::StageProgram* stage :
                 {&pass.vertex, &pass.hull, &pass.domain, &pass.geometry, &pass.fragment, &pass.compute}) {
                if (stage->entryPoint.empty()) continue;
                std::cout << "// technique " << technique.name << ", pass " << pass.name << ", "
                          << fx::shaderStageName(stage->stage) << " shader " << stage->entryPoint << " ("
                          << stage->profile << ")\n";
                if (showHlsl) std::cout << "// generated HLSL:\n" << stage->hlsl << "\n// GLSL:\n";
                std::cout << stage->glsl << "\n";
            }
        }
    }
    return 0;
}

// [SECTION] info
int infoCommand(const Arguments& args) {
    StderrSink sink(args.flag("--verbose"));
    std::shared_ptr<fx::CompiledEffect> compiled = loadEffect(args, "", sink);
    if (!compiled || sink.errors() > 0) return 1;
    if (fx::isCompiledEffectFile(args.positional(0))) {
        const fx::EffectProvenance& from = compiled->provenance;
        std::cout << "compiled from " << from.sourcePath << " by " << from.compilerVersion << "\n";
        for (const auto& [name, value] : from.defines) std::cout << "  -D " << name << "=" << value << "\n";
        for (const std::string& dir : from.includeDirs) std::cout << "  -I " << dir << "\n";
    }
    std::cout << "techniques:\n";
    for (const fx::CompiledTechnique& technique : compiled->techniques) {
        std::cout << "  " << technique.name << ":";
        for (const fx::CompiledPass& pass : technique.passes) std::cout << " " << pass.name;
        std::cout << "\n";
    }
    std::cout << "parameters:\n";
    for (const fx::ParameterInfo& p : compiled->parameters) {
        if (p.isStatic) continue;
        std::cout << "  " << p.type.hlslName() << " " << p.name;
        for (int dimension : p.type.arrayDims) std::cout << "[" << dimension << "]";
        if (!p.semantic.empty()) std::cout << " : " << p.semantic;
        if (!p.semantic.empty() && p.type.isNumeric() && p.standard.kind == fx::SemanticKind::None)
            std::cout << "  (not bound by shadowfx: keeps its default value)";
        if (p.standard.byName) {
            const int light = p.standard.light;
            std::cout << "  (bound by its name as "
                      << fx::semanticBindingName(
                             p.standard,
                             light >= 0 ? compiled->lights[static_cast<size_t>(light)] : std::string())
                      << ")";
        }
        for (const fx::MemberBinding& member : p.memberBindings) {
            const int light = member.standard.light;
            std::cout << "\n    ." << member.member << " bound by its name as "
                      << fx::semanticBindingName(
                             member.standard,
                             light >= 0 ? compiled->lights[static_cast<size_t>(light)] : std::string());
        }
        std::cout << "\n";
    }
    std::cout << "semantics shadowfx binds (case-insensitive; docs/effect-format.md):\n ";
    for (const std::string& name : runtime::EffectRenderer::boundSemantics()) std::cout << " " << name;
    std::cout << "\n";
    return 0;
}

const shadowfx::cli::Command kCommands[] = {
    {"render",
     "render one frame of an effect headlessly and write a PNG",
     "usage: shadowfx render EFFECT.fx --out FILE.png [options]\n"
     "  --out FILE.png        where to write the image (required; removed if rendering fails)\n"
     "  --width W, --height H image size (default 800x600)\n"
     "  --technique NAME      technique to run (default: the effect's STANDARDSGLOBAL choice, else the "
     "first)\n"
     "  --scene NAME|FILE     built-in scene (boxes, torus, teapot, dual-l, double-torus, forest, "
     "forest-fifth, behind,\n"
     "                        bunny, horse, spider, engine; default boxes) or a scene file (.json)\n"
     "  --set PARAM=VALUE     set a parameter (repeatable): --set PCF=true --set Bias=0.002\n"
     "  --backend NAME        auto, osmesa or egl (default auto)\n"
     "  --stats               print passes, draws, culled objects, triangles and texels written, per pass\n"
     "  --no-leave-out        draw every object in every pass, run every pass (the image is the same)\n"
     "  --no-batching         draw every object alone, not one instanced draw per mesh (the same image)\n"
     "  --opaque              write the frame's colour with alpha 1, as FX Composer's viewport showed it\n"
     "  --verbose             print the GL renderer and notes\n"
     "  --driver-log          print what the GL driver said compiling each pass's generated GLSL (its\n"
     "                        lines are the GLSL's, which `shadowfx compile` prints), at the "
     "pass\n" SHADOWFX_HOST_OPTION_HELP,
     {"--out"},
     {"--width", "--height", "--technique", "--scene", "--set", "--backend", "--host", "-I", "-D"},
     {"--stats", "--verbose", "--driver-log", "--no-leave-out", "--no-batching", "--opaque"},
     renderCommand},
    {"compile",
     "print the generated GLSL of every pass, or write a compiled effect file",
     "usage: shadowfx compile EFFECT.fx [--technique NAME] [--hlsl] [--out EFFECT.sfxo]\n"
     "  --technique NAME      only this technique\n"
     "  --hlsl                also print the HLSL unit generated for each stage\n"
     "  --out EFFECT.sfxo     write the compiled effect file (docs/compiled-effect.md) instead of printing;\n"
     "                        every command loads it like the source, without compiling\n",
     {},
     {"--technique", "--out", "-I", "-D"},
     {"--hlsl", "--verbose"},
     compileCommand},
    {"info",
     "list an effect's techniques, passes and parameters",
     "usage: shadowfx info EFFECT.fx\n",
     {},
     {"-I", "-D"},
     {"--verbose"},
     infoCommand},
    {"bench",
     "measure effects: shadow error against the ray-cast ground truth, and frame time",
     shadowfx::cli::kBenchUsage,
     {"--out"},
     {"--effects",
      "--scenes",
      "--map-sizes",
      "--techniques",
      "--frames",
      "--warmup",
      "--width",
      "--height",
      "--area-samples",
      "--area-radius",
      "--light-angle-to-view",
      "--camera-orbit",
      "--backend",
      "--set",
      "-I",
      "-D",
      "--leave-out",
      "--time",
      "--peers",
      "--peer-techniques",
      "--shard",
      "--truth-cache",
      "--host"},
     {"--no-leave-out", "--no-batching"},
     shadowfx::cli::benchCommand,
     -1},
    {"bench merge",
     "join the outputs of `bench --shard K/N` into one results.json, report and plot",
     shadowfx::cli::kBenchMergeUsage,
     {},
     {},
     {},
     shadowfx::cli::benchMergeCommand,
     -1},
    {"check",
     "conformance: render every technique headlessly, check its expectations and golden images",
     shadowfx::cli::kCheckUsage,
     {},
     {"--technique", "--scenes", "--backend", "--junit", "--out", "--width", "--height", "--area-samples",
      "--area-radius", "--truth-cache", "--host", "-I", "-D"},
     {"--update", "--require-goldens", "--list-techniques", "--no-batching"},
     shadowfx::cli::checkCommand,
     -1},
    {"stress",
     "run effects through extreme configurations: finite values, light coverage, error, shimmer",
     shadowfx::cli::kStressUsage,
     {},
     {"--effects", "--cases", "--techniques", "--width", "--height", "--map-size", "--uniform", "--backend",
      "--out", "--truth-cache", "--peers", "--peer-techniques", "-I", "-D"},
     {"--reduced", "--list", "--strict"},
     shadowfx::cli::stressCommand,
     -1},
    {"tune",
     "search a technique's tweakables for the least shadow error within a frame-time budget",
     shadowfx::cli::kTuneUsage,
     {"--technique", "--scenes", "--out"},
     {"--budget-ms", "--evaluations", "--grid", "--map-size", "--frames", "--warmup", "--width", "--height",
      "--backend", "--area-samples", "--area-radius", "--light-angle-to-view", "--truth-cache", "-I", "-D"},
     {},
     shadowfx::cli::tuneCommand},
    {"view",
     "open an effect in a window: hot reload, error overlay, parameters, render targets",
     shadowfx::cli::kViewUsage,
     {},
     {"--scene", "--technique", "--width", "--height", "--frames", "--screenshot", "--host", "-I", "-D"},
     {},
     shadowfx::cli::viewCommand},
    {"new",
     "write a technique skeleton NAME.fx in the current folder, ready for render, check, bench, stress",
     shadowfx::cli::kNewUsage,
     {},
     {"--from"},
     {},
     shadowfx::cli::newCommand,
     1,
     "name, NAME"},
};

}  // namespace

int main(int argc, char** argv) {
    return shadowfx::cli::dispatch(argc, argv, kCommands);
}
