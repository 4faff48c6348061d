// PeerProgram: see PeerProgram.h. The build's path of the peer is compiled into the CLI
// (samples/shadowfx/CMakeLists.txt), not into the measurement library.
#include "PeerProgram.h"

#include <algorithm>
#include <filesystem>
#include <iostream>

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

std::vector<runtime::Peer> selectPeers(const std::string& command, const std::vector<std::string>& names,
                                       const std::vector<std::string>& filter, int& status) {
    std::vector<runtime::Peer> peers;
    const auto fail = [&](int code) {
        status = code;
        return std::vector<runtime::Peer>{};
    };
    for (const std::string& name : names) {
        runtime::Peer peer{name, findPeerProgram(name), {}};
        if (name != "osg") {
            std::cerr << "shadowfx " << command << ": --peers: unknown peer '" << name << "' (known: osg)\n";
            return fail(2);
        }
        if (peer.program.empty()) {
            std::cerr << "shadowfx " << command << ": --peers " << name << ": shadowfx-" << name
                      << "-peer was not built (OpenSceneGraph was not found when configuring; "
                         "scripts/install-deps.sh installs libopenscenegraph-dev)\n";
            return fail(2);
        }
        const std::vector<std::string> offered = runtime::peerTechniques(peer.program);
        if (offered.empty()) {
            std::cerr << "shadowfx " << command << ": --peers " << name << ": " << peer.program
                      << " does not run\n";
            return fail(1);
        }
        for (const std::string& technique : offered)
            if (filter.empty() || std::find(filter.begin(), filter.end(), technique) != filter.end())
                peer.techniques.push_back(technique);
        peers.push_back(std::move(peer));
    }
    for (const std::string& technique : filter) {
        const bool offered = std::any_of(peers.begin(), peers.end(), [&](const runtime::Peer& peer) {
            return std::find(peer.techniques.begin(), peer.techniques.end(), technique) !=
                   peer.techniques.end();
        });
        if (!offered) {
            std::cerr << "shadowfx " << command << ": --peer-techniques: no peer offers '" << technique
                      << "'\n";
            return fail(2);
        }
    }
    return peers;
}

}  // namespace shadowfx::cli
