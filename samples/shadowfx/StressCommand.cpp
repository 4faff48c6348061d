// StressCommand: `shadowfx stress`: its options read into runtime::StressOptions, the run
// (runtime/StressRun.h), the table printed and stress.json, report.md and the failures' error images written
// (report/StressReport.h).
#include "StressCommand.h"
#include "EffectLibrary.h"
#include "PeerProgram.h"

#include <report/StressReport.h>
#include <runtime/EffectRenderer.h>
#include <runtime/StressCases.h>
#include <runtime/StressRun.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>

namespace shadowfx::cli {

const char* const kStressUsage =
    "usage: shadowfx stress [EFFECT.fx ...] [options]\n"
    "  EFFECT.fx ...         effects to stress (default: every effects/*.fx); a compiled EFFECT.sfxo\n"
    "                        is stressed as compiled, its error scored only where it was compiled\n"
    "                        with -D SHADOWFX_VISIBILITY=1\n"
    "  --effects LIST        the same, comma-separated\n"
    "  --cases LIST          cases to run, comma-separated (default: all; see --list)\n"
    "  --reduced             the reduced set (a quick look; CI runs every case)\n"
    "  --strict              a declared limitation that passes (xpass) fails the run too\n"
    "  --techniques LIST     only these techniques\n"
    "  --list                print the cases and exit\n"
    "  --width W, --height H frame size (default 320x240)\n"
    "  --map-size N          -D SHADOWFX_SHADOW_MAP_SIZE=N (default 1024)\n"
    "  --uniform FILE:TECH   the uniform shadow map every method is held to (default: the effect\n"
    "                        library's thesis_fxcomposer.fx:main, wherever stress runs from)\n"
    "  --backend NAME        auto, osmesa or egl (default auto)\n"
    "  --truth-cache DIR     read each case's ray-cast ground truth from DIR when it was cast before for\n"
    "                        the same inputs, else cast and store it there (docs/sharding.md)\n"
    "  --peers LIST          also run other libraries' shadow techniques through the same cases, held to\n"
    "                        the same criteria (osg: OpenSceneGraph's osgShadow; docs/peers.md); their\n"
    "                        failures show where they break and do not fail the run\n"
    "  --peer-techniques LIST  only these of the peers' techniques (default: all)\n"
    "  --out DIR             stress.json, report.md and errors/*.png (failed runs) go here\n"
    "                        (default out/stress)\n"
    "exit status: 0 if every run passes or fails only where declared, 1 if one fails (or, with\n"
    "  --strict, passes where a failure is declared), 2 for usage errors\n";

int stressCommand(const Arguments& args) {
    if (args.flag("--list")) {
        for (const std::string& name : runtime::stressCaseNames()) {
            const runtime::StressCase c = *runtime::makeStressCase(name);
            std::cout << std::left << std::setw(24) << name << (c.reduced ? "[reduced] " : "          ")
                      << c.description << "\n";
        }
        return 0;
    }
    std::vector<std::string> effects;
    for (size_t i = 0; i < args.positionalCount(); ++i) effects.push_back(args.positional(i));
    for (const std::string& list : args.all("--effects"))
        for (const std::string& path : splitList(list)) effects.push_back(path);
    if (effects.empty()) {
        std::error_code error;
        for (const auto& entry : std::filesystem::directory_iterator("effects", error))
            if (entry.path().extension() == ".fx") effects.push_back(entry.path().string());
        std::sort(effects.begin(), effects.end());
        if (effects.empty()) {
            std::cerr << "shadowfx stress: no effects given and no effects/*.fx here\n";
            return 2;
        }
    }

    std::vector<std::string> caseNames =
        args.flag("--reduced") ? runtime::reducedStressCaseNames() : runtime::stressCaseNames();
    if (args.value("--cases") != "") caseNames = splitList(args.value("--cases"));
    for (const std::string& name : caseNames) {
        if (!runtime::makeStressCase(name)) {
            std::cerr << "shadowfx stress: no case '" << name << "' (shadowfx stress --list)\n";
            return 2;
        }
    }
    const int width = args.intValue("--width", 320), height = args.intValue("--height", 240);
    const int mapSize = args.intValue("--map-size", 1024);
    if (width <= 0 || height <= 0 || width > 4096 || height > 4096 || mapSize <= 0 || mapSize > 16384) {
        std::cerr << "shadowfx stress: --width/--height must be in 1..4096 and --map-size in 1..16384\n";
        return 2;
    }
    // The reference comes from the effect library, not the working directory: a rule whose reference is
    // missing cannot be evaluated, and that is an error, never a pass.
    const std::filesystem::path library = effectLibraryDir();
    const std::string uniformSpec =
        args.value("--uniform", library.empty() ? "" : (library / "thesis_fxcomposer.fx").string() + ":main");
    if (uniformSpec.empty()) {
        std::cerr << "shadowfx stress: no effect library found for the default --uniform: give --uniform "
                     "FILE:TECHNIQUE\n";
        return 2;
    }
    const size_t colon = uniformSpec.rfind(':');
    if (colon == std::string::npos) {
        std::cerr << "shadowfx stress: --uniform wants FILE:TECHNIQUE\n";
        return 2;
    }
    const std::string uniformPath = uniformSpec.substr(0, colon),
                      uniformTechnique = uniformSpec.substr(colon + 1);
    if (!std::filesystem::is_regular_file(uniformPath)) {
        std::cerr << "shadowfx stress: the uniform reference " << uniformPath << " does not exist\n";
        return 2;
    }
    const std::optional<runtime::Backend> backend = runtime::parseBackend(args.value("--backend", "auto"));
    if (!backend) {
        std::cerr << "shadowfx stress: --backend must be auto, osmesa or egl\n";
        return 2;
    }

    const std::filesystem::path outDir = args.value("--out", "out/stress");
    std::error_code fsError;
    std::filesystem::remove_all(outDir / "errors", fsError);
    std::filesystem::create_directories(outDir, fsError);
    if (fsError) {
        std::cerr << "shadowfx stress: cannot create " << outDir.string() << ": " << fsError.message()
                  << "\n";
        return 1;
    }

    int peerStatus = 0;
    std::vector<runtime::Peer> peers = selectPeers("stress", splitList(args.value("--peers")),
                                                   splitList(args.value("--peer-techniques")), peerStatus);
    if (peerStatus != 0) return peerStatus;

    runtime::StressOptions options;
    options.effects = effects;
    options.cases = caseNames;
    options.techniques = splitList(args.value("--techniques"));
    options.strict = args.flag("--strict");
    options.width = width;
    options.height = height;
    options.mapSize = mapSize;
    options.uniformPath = uniformPath;
    options.uniformTechnique = uniformTechnique;
    options.backend = *backend;
    options.parseOptions = effectParseOptions(args);
    options.truthCacheDir = args.value("--truth-cache");
    options.peers = std::move(peers);
    options.peerWorkDir = outDir / "peers";
    runtime::StressLog log;
    log.note = [](const std::string& text) { std::cerr << "stress: " << text << "\n"; };
    log.problem = [](const std::string& text) { std::cerr << text << "\n"; };
    const runtime::StressRun run = runtime::runStress(options, log);
    if (!run.measured) {
        std::cerr << "shadowfx stress: " << run.error << "\n";
        return 1;
    }
    for (const runtime::StressErrorImage& failure : run.errorImages) {
        const std::filesystem::path image =
            outDir / "errors" /
            (failure.effectStem + "." + failure.technique + "." + failure.caseName + ".png");
        std::error_code ignored;
        std::filesystem::create_directories(image.parent_path(), ignored);
        std::string error;
        if (!runtime::writePng(failure.image, image.string(), error))
            std::cerr << "shadowfx stress: " << error << "\n";
    }

    report::writeStressTable(std::cout, run.result, false);
    std::ofstream(outDir / "stress.json") << report::stressJson(run.result).dump(2) << "\n";
    std::ofstream markdown(outDir / "report.md");
    report::writeStressMarkdown(markdown, run.result);
    std::cerr << "stress: " << (outDir / "stress.json").string() << ", " << (outDir / "report.md").string()
              << "\n";
    return run.failed ? 1 : 0;
}

}  // namespace shadowfx::cli
