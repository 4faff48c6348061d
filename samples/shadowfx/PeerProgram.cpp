// PeerProgram: see PeerProgram.h. The build's path of the peer is compiled into the CLI
// (samples/shadowfx/CMakeLists.txt), not into the measurement library.
#include "PeerProgram.h"

#include <filesystem>

namespace shadowfx::cli {

namespace {

std::filesystem::path ownDirectory() {
    std::error_code ignored;
    return std::filesystem::read_symlink("/proc/self/exe", ignored).parent_path();
}

}  // namespace

std::string findPeerProgram(const std::string& name) {
    const std::string program = "shadowfx-" + name + "-peer";
#ifdef SHADOWFX_OSG_PEER_PATH
    if (name == "osg" && std::filesystem::exists(SHADOWFX_OSG_PEER_PATH)) return SHADOWFX_OSG_PEER_PATH;
#endif
    const std::filesystem::path installed = ownDirectory() / program;
    if (std::filesystem::exists(installed)) return installed.string();
    return "";
}

}  // namespace shadowfx::cli
