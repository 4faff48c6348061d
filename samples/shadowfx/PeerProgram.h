// PeerProgram: where `bench --peers NAME` and `stress --peers NAME` find the peer program of this build,
// and the peers and techniques those options select.
#pragma once

#include <runtime/PeerRun.h>

#include <string>
#include <vector>

namespace shadowfx::cli {

// Where the built peer `name` ("osg") is: next to this build's shadowfx, or next to the installed one;
// empty if it was not built (its library was not found when configuring).
std::string findPeerProgram(const std::string& name);

// The peers `names` (--peers) with the techniques of `filter` (--peer-techniques; empty: all they offer).
// An unknown or unbuilt peer, or a technique no peer offers, is reported on stderr as `command`'s and sets
// `status` (2 for usage, 1 for a peer that does not run); the result is then empty.
std::vector<runtime::Peer> selectPeers(const std::string& command, const std::vector<std::string>& names,
                                       const std::vector<std::string>& filter, int& status);

}  // namespace shadowfx::cli
