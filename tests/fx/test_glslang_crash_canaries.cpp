// The classes of HLSL that glslang's HLSL front end crashes on and that the compiler keeps from it
// (PostfixOperands.h, MulOperands.h; docs/compile-workers.md, "Crashes of glslang"), given to Debian's
// glslangValidator as they are: each must still crash it. The day one does not, glslang fixed it and its
// guard can go (then this test fails and says which).
#include "ScratchDirectory.h"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <string>

namespace fx::test_glslang_crash_canaries {
namespace {

struct Canary {
    const char* name;
    const char* guard;
    const char* hlsl;
};

const Canary kCanaries[] = {
    {"postfix_of_undeclared_name", "PostfixOperands.h", "float4 PS() : SV_Target { return undeclared++; }\n"},
    {"postfix_of_void_call", "PostfixOperands.h",
     "void v() {}\nfloat4 PS() : SV_Target { return 1 + v()++; }\n"},
    {"mul_of_one_component_vector", "MulOperands.h",
     "float3x3 m;\nfloat4 PS(float1 d : TEXCOORD0) : SV_Target { return mul(d, m).xyzz; }\n"},
    {"mul_of_single_column_matrix", "MulOperands.h",
     "float3x1 a; float4x4 b;\nfloat4 PS() : SV_Target { return mul(a, b)[0].xxxx; }\n"},
};

TEST(GlslangCrashCanaries, GlslangStillCrashesOnEachClassItsGuardKeepsFromIt) {
    const shadowfx::test::ScratchDirectory scratch("glslang_canaries");
    for (const Canary& canary : kCanaries) {
        SCOPED_TRACE(canary.name);
        const std::string path = (scratch / (std::string(canary.name) + ".hlsl")).string();
        std::ofstream(path) << canary.hlsl;
        const std::string command =
            "glslangValidator -D -S frag -e PS -V -o /dev/null '" + path + "' >/dev/null 2>&1";
        const int status = std::system(command.c_str());
        ASSERT_NE(status, -1) << "could not run a shell";
        ASSERT_FALSE(WIFEXITED(status) && WEXITSTATUS(status) == 127)
            << "glslangValidator is not installed (glslang-tools, which scripts/install-deps.sh installs)";
        // The shell reports a child killed by signal N as exit status 128 + N.
        const bool crashed = WIFSIGNALED(status) || (WIFEXITED(status) && WEXITSTATUS(status) > 128);
        EXPECT_TRUE(crashed) << "glslang no longer crashes on " << canary.name << " (exit status "
                             << (WIFEXITED(status) ? WEXITSTATUS(status) : -1) << "): the guard in fx/src/"
                             << canary.guard << " can go";
    }
}

}  // namespace
}  // namespace fx::test_glslang_crash_canaries
