// Load/unload cycles must not leak: every effect in effects/ goes through parse -> compile ->
// runtime::EffectRenderer::create -> destroy, at least 1,000 cycles in all (200 under AddressSanitizer, see
// kTotalCycles), and after a warm-up neither the process's resident memory (/proc/self/statm) nor the number
// of live GL objects (probed with glIs* over the first names) may grow. Heap leaks in our own code are found
// more precisely by scripts/test-sanitized.sh (LeakSanitizer); this test also catches GL objects that are
// never deleted and growth that LeakSanitizer cannot see (objects still referenced from a cache, driver-side
// memory).
#include "GlTestSupport.h"
#include "LiveGlObjects.h"

#include <fx/CompileCache.h>
#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>
#include <runtime/EffectRenderer.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <malloc.h>
#include <unistd.h>

namespace {

// Mesa hands out program and shader names in increasing order without reuse, so the names in use climb
// with every cycle: the probe must reach past all of them (12 effects' warm-up alone passed 4096).
constexpr GLuint kProbedNames = 65536;

// Under AddressSanitizer freed memory sits in its quarantine (up to 256 MB) instead of returning to the
// allocator, so RSS grows by design; there LeakSanitizer checks the heap instead (scripts/test-sanitized.sh).
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kRssIsMeaningful = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kRssIsMeaningful = false;
#else
constexpr bool kRssIsMeaningful = true;
#endif
#else
constexpr bool kRssIsMeaningful = true;
#endif

// Where RSS is not checked, the cycles only count GL objects, and one object leaked a cycle shows in the
// first cycles: a fifth of them keeps the sanitized suite's time down without weakening that check.
constexpr int kTotalCycles = kRssIsMeaningful ? 1000 : 200;  // over all effects together
constexpr int kWarmUpCycles =
    kRssIsMeaningful ? 20 : 5;  // per effect: caches, driver pools and allocator arenas fill up

// Resident set size in kB.
long residentKb() {
    long pages = 0, resident = 0;
    if (FILE* f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
        std::fclose(f);
    }
    return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

std::vector<std::string> effectFiles() {
    std::vector<std::string> files;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::string(SHADOWFX_SOURCE_DIR) + "/effects"))
        if (entry.path().extension() == ".fx") files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

// One cycle: parse, compile (through `cache`, as hot reload does), create the renderer, destroy it all.
void cycle(const std::string& path, fx::CompileCache* cache) {
    fx::DiagnosticList diagnostics;
    fx::ParseOptions parseOptions;
    std::shared_ptr<fx::Effect> effect = fx::parseEffectFile(path, parseOptions, diagnostics);
    ASSERT_TRUE(effect) << diagnostics.str();
    fx::CompileOptions compileOptions;
    compileOptions.cache = cache;
    std::shared_ptr<const fx::CompiledEffect> compiled =
        fx::compileEffect(effect, compileOptions, diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    std::unique_ptr<runtime::EffectRenderer> renderer =
        runtime::EffectRenderer::create(compiled, diagnostics);
    ASSERT_TRUE(renderer) << path << ": " << diagnostics.str();
}

TEST(LoadUnload, ThousandCyclesKeepMemoryAndGlObjectsFlat) {
    // glibc raises its mmap threshold to the size of each large block freed (up to 32 MiB), after which
    // blocks of that size come from the heap and their memory stays resident when freed: an effect's
    // 16 MiB storage buffer, zeroed and handed to the driver on every load, would read as RSS growth
    // without a byte leaked. A fixed threshold keeps such blocks mapped and returned at free.
    mallopt(M_MMAP_THRESHOLD, 4 << 20);
    testsupport::sharedContext();
    const std::vector<std::string> files = effectFiles();
    ASSERT_FALSE(files.empty());
    const int perEffect =
        (kTotalCycles + static_cast<int>(files.size()) - 1) / static_cast<int>(files.size());

    // Compiling through glslang costs tens of milliseconds a stage; the cache keeps 1,000 cycles within
    // the time budget. Every tenth cycle compiles from scratch (a fresh cache) so that glslang and
    // SPIRV-Cross run often enough for a per-compile leak to show.
    fx::CompileCache cache;
    for (const std::string& file : files)
        for (int i = 0; i < kWarmUpCycles; ++i) {
            fx::CompileCache fresh;
            ASSERT_NO_FATAL_FAILURE(cycle(file, i % 10 == 0 ? &fresh : &cache));
        }
    {  // The probe must see what a live renderer holds, or a flat count would prove nothing.
        const shadowfx::test::LiveGlObjects idle = shadowfx::test::countLiveGlObjects(kProbedNames);
        fx::DiagnosticList diagnostics;
        fx::ParseOptions parseOptions;
        std::shared_ptr<fx::Effect> effect = fx::parseEffectFile(files.front(), parseOptions, diagnostics);
        ASSERT_TRUE(effect) << diagnostics.str();
        fx::CompileOptions compileOptions;
        compileOptions.cache = &cache;
        std::shared_ptr<const fx::CompiledEffect> compiled =
            fx::compileEffect(effect, compileOptions, diagnostics);
        ASSERT_TRUE(compiled) << diagnostics.str();
        auto renderer = runtime::EffectRenderer::create(compiled, diagnostics);
        ASSERT_TRUE(renderer) << diagnostics.str();
        const shadowfx::test::LiveGlObjects live = shadowfx::test::countLiveGlObjects(kProbedNames);
        EXPECT_GT(live.programs, idle.programs) << "the glIs* probe does not see the renderer's programs";
    }
    gl::Finish();
    const long rssBefore = residentKb();
    const shadowfx::test::LiveGlObjects objectsBefore = shadowfx::test::countLiveGlObjects(kProbedNames);

    const auto start = std::chrono::steady_clock::now();
    int cycles = 0;
    for (const std::string& file : files)
        for (int i = 0; i < perEffect; ++i, ++cycles) {
            fx::CompileCache fresh;
            ASSERT_NO_FATAL_FAILURE(cycle(file, i % 10 == 0 ? &fresh : &cache));
        }
    gl::Finish();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const long rssAfter = residentKb();
    const shadowfx::test::LiveGlObjects objectsAfter = shadowfx::test::countLiveGlObjects(kProbedNames);

    EXPECT_GE(cycles, kTotalCycles);
    EXPECT_EQ(objectsAfter, objectsBefore) << "GL objects leaked over " << cycles << " cycles";
    // Allocator arenas and Mesa's pools fluctuate by a few MB; a leak of even 4 kB a cycle exceeds this.
    const long growthKb = rssAfter - rssBefore;
    if (kRssIsMeaningful) {
        EXPECT_LT(growthKb, 4 * 1024)
            << "RSS grew from " << rssBefore << " kB to " << rssAfter << " kB over " << cycles << " cycles";
    }
    std::printf(
        "[ leaks    ] %d cycles over %zu effects in %.1f s; RSS %ld -> %ld kB; GL objects %d textures, %d "
        "programs\n",
        cycles, files.size(), seconds, rssBefore, rssAfter, objectsAfter.textures, objectsAfter.programs);
}

}  // namespace
