// Runtime modules (runtime/RuntimeModules.h): assimp and Embree are mapped into a process only once it
// imports a mesh file or casts truth rays; the CLI links neither, so `--help` and `compile` never load them;
// the commands that need them still work; a module that cannot be found is an error naming it and the
// folders searched, never a crash.
#include <runtime/BuiltinScenes.h>
#include <runtime/GroundTruth.h>
#include <runtime/MeshImporter.h>
#include <runtime/RuntimeModules.h>
#include <runtime/Scene.h>

#include <fx/Diagnostics.h>

#include "ScratchDirectory.h"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace test_runtime_modules {

namespace {

using shadowfx::test::ScratchDirectory;

const std::string kTool = std::string(SHADOWFX_BINARY_DIR) + "/samples/shadowfx/shadowfx";

// Whether a file whose name starts with `prefix` ("libembree") is mapped into this process.
bool mapped(const std::string& prefix) {
    std::ifstream maps("/proc/self/maps");
    std::string line;
    while (std::getline(maps, line)) {
        const size_t slash = line.rfind('/');
        if (slash != std::string::npos && line.compare(slash + 1, prefix.size(), prefix) == 0) return true;
    }
    return false;
}

struct CommandResult {
    int exitStatus = -1;  // -1: killed by a signal
    std::string output;   // standard output and error
};

CommandResult runCommand(const std::string& command) {
    CommandResult result;
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return result;
    char buffer[4096];
    while (size_t n = fread(buffer, 1, sizeof buffer, pipe)) result.output.append(buffer, n);
    const int status = pclose(pipe);
    if (WIFEXITED(status)) result.exitStatus = WEXITSTATUS(status);
    return result;
}

// In the child process, a failed condition: what it was on standard error, exit status 1.
void require(bool condition, const char* what) {
    if (condition) return;
    std::cerr << "not so: " << what << std::endl;
    std::exit(1);
}

}  // namespace

// In a process of its own (the death test's child, started afresh): neither library at start nor after a
// scene of built-in shapes; assimp once a mesh file is imported, Embree once a ray caster is made.
TEST(RuntimeModules, AssimpAndEmbreeAreMappedOnlyWhenUsed) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    const ScratchDirectory scratch("runtime_modules");
    const std::string obj = (scratch / "triangle.obj").string();
    std::ofstream(obj) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    EXPECT_EXIT(
        {
            require(!mapped("libassimp") && !mapped("libembree"), "neither is mapped at start");
            std::optional<runtime::Scene> scene = runtime::makeBuiltinScene("boxes");
            require(scene.has_value(), "the boxes scene is made");
            require(!mapped("libassimp") && !mapped("libembree"), "built-in shapes map neither");

            fx::DiagnosticList diagnostics;
            require(runtime::importMesh(obj, {}, diagnostics).has_value(), "the OBJ file is imported");
            require(mapped("libshadowfx_meshimport") && mapped("libassimp"), "importing maps assimp");
            require(!mapped("libembree"), "importing does not map Embree");

            runtime::Scene box;
            box.objects.push_back(
                {"box", std::make_shared<const runtime::Mesh>(runtime::makeBox(glm::vec3(1.0f)))});
            const runtime::ShadowRayCaster caster(box);
            require(caster.occluded(glm::vec3(0.0f, 5.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f), 10.0f),
                    "a ray down through the box is occluded");
            require(mapped("libshadowfx_raycast") && mapped("libembree"), "a ray caster maps Embree");
            std::exit(0);
        },
        ::testing::ExitedWithCode(0), "");
}

// The CLI's own dependencies (ldd: direct and indirect) hold neither library, so no command pays for
// loading them before it needs them.
TEST(RuntimeModules, TheCliLinksNeitherAssimpNorEmbree) {
    const CommandResult ldd = runCommand("ldd " + kTool);
    ASSERT_EQ(ldd.exitStatus, 0) << ldd.output;
    EXPECT_NE(ldd.output.find("libc.so"), std::string::npos) << ldd.output;
    EXPECT_EQ(ldd.output.find("libassimp"), std::string::npos) << ldd.output;
    EXPECT_EQ(ldd.output.find("libembree"), std::string::npos) << ldd.output;
}

// The commands that need a module find it in this build tree: a scene file whose mesh comes from a file,
// and the ground truth of bench.
TEST(RuntimeModules, TheCliImportsMeshesAndCastsTruthThroughTheModules) {
    const ScratchDirectory scratch("runtime_modules_cli");
    const CommandResult render = runCommand(
        kTool + " render effects/plain_lit.fx --scene scenes/bunny.json --width 64 --height 48 --out " +
        (scratch / "bunny.png").string());
    EXPECT_EQ(render.exitStatus, 0) << render.output;
    EXPECT_TRUE(std::filesystem::exists(scratch / "bunny.png"));

    const CommandResult bench =
        runCommand(kTool +
                   " bench --effects effects/plain_lit.fx --scenes boxes --map-sizes 256 "
                   "--width 64 --height 48 --frames 1 --warmup 0 --out " +
                   (scratch / "bench").string());
    EXPECT_EQ(bench.exitStatus, 0) << bench.output;
    EXPECT_TRUE(std::filesystem::exists(scratch / "bench" / "results.json")) << bench.output;
}

// SHADOWFX_MODULE_DIR naming an empty folder: the command that needs a module fails with its name and the
// folder it was looked for in; one that needs none is unaffected.
TEST(RuntimeModules, AMissingModuleIsAnErrorNamingItAndTheFolderSearched) {
    const ScratchDirectory scratch("runtime_modules_missing");
    const std::string empty = (scratch / "no_modules").string();
    std::filesystem::create_directories(empty);
    const std::string tool = "SHADOWFX_MODULE_DIR=" + empty + " " + kTool;

    const CommandResult render =
        runCommand(tool + " render effects/plain_lit.fx --scene scenes/bunny.json " +
                   "--width 64 --height 48 --out " + (scratch / "bunny.png").string());
    EXPECT_EQ(render.exitStatus, 2) << render.output;
    EXPECT_NE(render.output.find("cannot import mesh"), std::string::npos) << render.output;
    EXPECT_NE(render.output.find(empty + "/libshadowfx_meshimport.so"), std::string::npos) << render.output;

    const CommandResult bench =
        runCommand(tool +
                   " bench --effects effects/plain_lit.fx --scenes boxes --map-sizes 256 "
                   "--width 64 --height 48 --frames 1 --warmup 0 --out " +
                   (scratch / "bench").string());
    EXPECT_EQ(bench.exitStatus, 1) << bench.output;
    EXPECT_NE(bench.output.find(empty + "/libshadowfx_raycast.so"), std::string::npos) << bench.output;
    EXPECT_NE(bench.output.find("SHADOWFX_MODULE_DIR"), std::string::npos) << bench.output;

    const CommandResult compile = runCommand(tool + " compile effects/plain_lit.fx");
    EXPECT_EQ(compile.exitStatus, 0) << compile.output;
}

// The search list: the environment's folder alone when set, else the install's and this build tree's.
TEST(RuntimeModules, SearchesTheEnvironmentsFolderAloneWhenSet) {
    const char* previous = std::getenv("SHADOWFX_MODULE_DIR");
    const std::string saved = previous ? previous : "";
    setenv("SHADOWFX_MODULE_DIR", "/nowhere/modules", 1);
    EXPECT_EQ(runtime::moduleSearchDirs(), std::vector<std::string>{"/nowhere/modules"});
    unsetenv("SHADOWFX_MODULE_DIR");
    const std::vector<std::string> dirs = runtime::moduleSearchDirs();
    EXPECT_NE(std::find(dirs.begin(), dirs.end(), std::string(SHADOWFX_BINARY_DIR) + "/modules"), dirs.end());
    if (previous) setenv("SHADOWFX_MODULE_DIR", saved.c_str(), 1);
}
}  // namespace test_runtime_modules
