// `shadowfx view` in a real window: starts its own Xvfb on a free display, runs the viewer for a few
// frames with --screenshot, and checks the image. Skipped where Xvfb is not installed
// (scripts/install-deps.sh installs it, so CI runs it).
#include <gtest/gtest.h>

#include <stb/stb_image.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <thread>

namespace {

namespace fs = std::filesystem;

const std::string kTool = std::string(SHADOWFX_BINARY_DIR) + "/samples/shadowfx/shadowfx";

// An Xvfb server on the first display number with neither a lock file nor a socket; stopped (by its pid)
// when the object goes.
class XvfbServer {
public:
    XvfbServer() {
        for (int display = 90; display < 190; ++display) {
            const std::string lock = "/tmp/.X" + std::to_string(display) + "-lock";
            const std::string socket = "/tmp/.X11-unix/X" + std::to_string(display);
            if (fs::exists(lock) || fs::exists(socket)) continue;
            const pid_t pid = fork();
            if (pid == 0) {
                const std::string name = ":" + std::to_string(display);
                execlp("Xvfb", "Xvfb", name.c_str(), "-screen", "0", "1024x768x24", "-nolisten", "tcp",
                       nullptr);
                _exit(127);
            }
            if (pid < 0) return;
            // The socket appears once the server accepts clients; give it ten seconds.
            for (int i = 0; i < 200 && !fs::exists(socket); ++i) {
                int status = 0;
                if (waitpid(pid, &status, WNOHANG) == pid) break;  // died: display taken after all
                std::this_thread::sleep_for(std::chrono::milliseconds(50));
            }
            if (fs::exists(socket)) {
                mPid = pid;
                mDisplay = ":" + std::to_string(display);
                return;
            }
            kill(pid, SIGTERM);
            waitpid(pid, nullptr, 0);
        }
    }
    ~XvfbServer() {
        if (mPid > 0) {
            kill(mPid, SIGTERM);
            waitpid(mPid, nullptr, 0);
        }
    }
    XvfbServer(const XvfbServer&) = delete;
    XvfbServer& operator=(const XvfbServer&) = delete;

    const std::string& display() const { return mDisplay; }  // "" if none started

private:
    pid_t mPid = -1;
    std::string mDisplay;
};

TEST(ViewCommand, RendersFramesInAWindowAndWritesTheScreenshot) {
    if (std::system("command -v Xvfb >/dev/null 2>&1") != 0) GTEST_SKIP() << "Xvfb is not installed";
    XvfbServer server;
    ASSERT_FALSE(server.display().empty()) << "could not start Xvfb";

    const fs::path out = fs::temp_directory_path() / ("shadowfx_view_" + std::to_string(getpid()) + ".png");
    fs::remove(out);
    const std::string command =
        "DISPLAY=" + server.display() + " LP_NUM_THREADS=2 " + kTool +
        " view effects/thesis_fxcomposer.fx --frames 3 --width 320 --height 240 --screenshot " +
        out.string() + " 2>&1";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status)) << command;
    ASSERT_EQ(WEXITSTATUS(status), 0) << command;

    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(out.c_str(), &width, &height, &channels, 4);
    ASSERT_NE(pixels, nullptr) << "no image at " << out;
    EXPECT_EQ(width, 320);
    EXPECT_EQ(height, 240);
    // Not blank and not constant: the thesis scene has lit, shadowed and background pixels.
    std::set<unsigned> colours;
    for (int i = 0; i < width * height; ++i) {
        const unsigned char* p = pixels + i * 4;
        colours.insert((p[0] << 16) | (p[1] << 8) | p[2]);
    }
    stbi_image_free(pixels);
    fs::remove(out);
    EXPECT_GT(colours.size(), 20u);
}

}  // namespace
