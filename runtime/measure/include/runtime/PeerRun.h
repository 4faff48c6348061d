// PeerRun: one run of another library's shadow technique on a shadowfx scene (`shadowfx bench --peers`):
// the peer program renders the scene (or a stress case) with the technique, times its frames and writes a
// visibility frame (lit 1, shadowed 0), which is scored against the same ray-cast ground truth as shadowfx's
// effects. docs/peers.md describes the peers and how their frames are made comparable.
#pragma once

#include <runtime/ShadowMeasurement.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace runtime {

// Another library's shadow techniques run beside the effects (`bench`, `stress`), its program already found.
struct Peer {
    std::string name;                     // "osg"
    std::string program;                  // its executable
    std::vector<std::string> techniques;  // the ones to run, in the peer's order
};

struct PeerRequest {
    std::string program;    // the peer's executable
    std::string scene;      // as --scenes named it: a built-in name or a scene file; or a stress case's name
    std::string technique;  // the peer's name for it ("ShadowMap", "VDSM-persp-2", ...)
    int mapSize = 1024;
    int width = 640;
    int height = 480;
    int frames = 10;
    int warmup = 2;
};

struct PeerResult {
    std::vector<double> frameMs;    // the timed frames, wall time until the GPU finished
    std::vector<float> visibility;  // per pixel, rows top to bottom (the G-buffer's order)
    std::string glRenderer;
    std::string libraryVersion;
    bool mapSizeHonoured = false;  // every shadow map the peer made has the requested size (it reports)
};

// The techniques the peer program offers (it lists them), in its order; empty if it cannot be run.
std::vector<std::string> peerTechniques(const std::string& program);

// Runs the peer for `request` on the scene of `truth` (its light's direction is passed on, so that a light
// turned by --light-angle-to-view is the peer's light too). Its JSON and log are left in `workDir`.
// nullopt, with why in `error`, if the program fails or its frame is not the G-buffer's size.
std::optional<PeerResult> runPeer(const PeerRequest& request, const SceneTruth& truth,
                                  const std::filesystem::path& workDir, std::string& error);

// Runs the peer on the case `request.scene` of `shadowfx stress` (runtime/StressCases.h), which it builds
// by name: one visibility frame per camera of the case (`cameras`: its path's length, or 1), each
// request.width x request.height, rows top to bottom. nullopt, with why in `error`, if the peer fails there.
std::optional<std::vector<std::vector<float>>> runPeerOnStressCase(const PeerRequest& request, size_t cameras,
                                                                   const std::filesystem::path& workDir,
                                                                   std::string& error);

}  // namespace runtime
