// CliRunner: runs the built shadowfx tool from the source root, as users script against it, and captures
// its exit status and output (stdout and stderr together). Shared by the command-line tests.
#pragma once

#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace shadowfx::test {

inline const std::string kTool = std::string(SHADOWFX_BINARY_DIR) + "/samples/shadowfx/shadowfx";
inline const std::string kSource = SHADOWFX_SOURCE_DIR;

struct RunResult {
    int exitCode = -1;
    bool crashed = false;  // killed by a signal, or an exit status >= 128 (the shell's report of one)
    std::string output;
};

inline RunResult run(const std::string& arguments) {
    RunResult result;
    const std::string command = "cd '" + kSource + "' && '" + kTool + "' " + arguments + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return result;
    std::array<char, 4096> buffer{};
    size_t n = 0;
    while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), n);
    const int status = pclose(pipe);
    result.crashed = WIFSIGNALED(status) || (WIFEXITED(status) && WEXITSTATUS(status) >= 128);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

}  // namespace shadowfx::test
