// PeerProgram: where `bench --peers NAME` finds the peer program of this build.
#pragma once

#include <string>

namespace shadowfx::cli {

// Where the built peer `name` ("osg") is: next to this build's shadowfx, or next to the installed one;
// empty if it was not built (its library was not found when configuring).
std::string findPeerProgram(const std::string& name);

}  // namespace shadowfx::cli
