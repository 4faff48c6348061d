// `shadowfx view` in a real window: starts its own Xvfb on a free display, runs the viewer for a few
// frames with --screenshot, and checks the image. Skipped where Xvfb is not installed
// (scripts/install-deps.sh installs it, so CI runs it).
#include "WorkerCrashHook.h"

#include <gtest/gtest.h>

#include <stb/stb_image.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
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

// Xvfb is one of the packages scripts/install-deps.sh installs: without it the viewer's tests fail rather
// than skip, since CTest counts a skipped test as passed.
bool xvfbInstalled() {
    return std::system("command -v Xvfb >/dev/null 2>&1") == 0;
}

// Runs `view ARGUMENTS --frames 3 --width 320 --height 240 --screenshot PNG` on `display` and returns the
// number of distinct colours of the screenshot (-1 if the viewer failed or wrote none).
int viewScreenshotColours(const std::string& display, const std::string& arguments) {
    const fs::path out = fs::temp_directory_path() / ("shadowfx_view_" + std::to_string(getpid()) + ".png");
    fs::remove(out);
    const std::string command = "DISPLAY=" + display + " LP_NUM_THREADS=2 " + kTool + " view " + arguments +
                                " --frames 3 --width 320 --height 240 --screenshot " + out.string() + " 2>&1";
    const int status = std::system(command.c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << command;
    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(out.c_str(), &width, &height, &channels, 4);
    if (!pixels) return -1;
    EXPECT_EQ(width, 320);
    EXPECT_EQ(height, 240);
    std::set<unsigned> colours;
    for (int i = 0; i < width * height; ++i) {
        const unsigned char* p = pixels + i * 4;
        colours.insert((p[0] << 16) | (p[1] << 8) | p[2]);
    }
    stbi_image_free(pixels);
    fs::remove(out);
    return static_cast<int>(colours.size());
}

TEST(ViewCommand, RendersFramesInAWindowAndWritesTheScreenshot) {
    ASSERT_TRUE(xvfbInstalled()) << "Xvfb is not installed (xvfb, which scripts/install-deps.sh installs)";
    XvfbServer server;
    ASSERT_FALSE(server.display().empty()) << "could not start Xvfb";
    // Not blank and not constant: the thesis scene has lit, shadowed and background pixels.
    EXPECT_GT(viewScreenshotColours(server.display(), "effects/thesis_fxcomposer.fx"), 20);
}

// A compiled effect file views as its source does.
TEST(ViewCommand, ViewsACompiledEffectFile) {
    ASSERT_TRUE(xvfbInstalled()) << "Xvfb is not installed (xvfb, which scripts/install-deps.sh installs)";
    XvfbServer server;
    ASSERT_FALSE(server.display().empty()) << "could not start Xvfb";
    const fs::path file = fs::temp_directory_path() / ("shadowfx_view_" + std::to_string(getpid()) + ".sfxo");
    const std::string compile =
        kTool + " compile effects/thesis_fxcomposer.fx --out " + file.string() + " 2>&1";
    ASSERT_EQ(std::system(compile.c_str()), 0) << compile;
    EXPECT_GT(viewScreenshotColours(server.display(), file.string()), 20);
    fs::remove(file);
}

// --host: the viewer draws the application's frame of an effect without SAS scripts (lit objects: many
// colours); a host file that cannot be read is an error (exit status 1).
TEST(ViewCommand, DrawsTheFrameOfAHostFile) {
    ASSERT_TRUE(xvfbInstalled()) << "Xvfb is not installed (xvfb, which scripts/install-deps.sh installs)";
    XvfbServer server;
    ASSERT_FALSE(server.display().empty()) << "could not start Xvfb";
    EXPECT_GT(viewScreenshotColours(server.display(),
                                    "tests/data/host/app_shadow.fx --host tests/data/host/app_shadow.json"),
              20);
    const int badHost = std::system(("DISPLAY=" + server.display() + " " + kTool +
                                     " view tests/data/host/app_shadow.fx --host no_such_host.json --frames 1"
                                     " >/dev/null 2>&1")
                                        .c_str());
    EXPECT_TRUE(WIFEXITED(badHost) && WEXITSTATUS(badHost) == 1);
}

// [SECTION] A save that crashes the HLSL compiler

// One pass drawing the scene in a constant colour; `body` is the pixel shader's body.
std::string colourEffect(const std::string& body) {
    return "float4x4 WorldViewProj : WorldViewProjection;\n"
           "struct VSOut { float4 Pos : POSITION; float3 WorldNorm : TEXCOORD0; };\n"
           "VSOut VS(float4 P : POSITION, float3 N : NORMAL) {\n"
           "    VSOut OUT; OUT.Pos = mul(P, WorldViewProj); OUT.WorldNorm = N; return OUT;\n"
           "}\n"
           "float4 PS(const VSOut IN) : COLOR {\n" +
           body +
           "\n}\n"
           "float4 ClearColor = {0, 0, 0, 1};\n"
           "technique Main < string Script = \"ClearSetColor=ClearColor; Clear=Color; Clear=Depth; "
           "Pass=P0;\"; > {\n"
           "    pass P0 { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); }\n"
           "}\n";
}
const std::string kRed = colourEffect("    return float4(1, 0, 0, 1);");
const std::string kGreen = colourEffect("    return float4(0, 1, 0, 1);");
// The worker dies of SIGSEGV on its pixel shader under the crash hook, as glslang does on text it crashes on.
const std::string kCrashes = colourEffect(std::string("    float ") + shadowfx::test::kWorkerCrashMarker +
                                          " = 1;\n    return float4(0, 0, 1, 1);");

void saveLikeAnEditor(const fs::path& path, const std::string& text) {
    const fs::path temporary = path.string() + ".tmp~";
    std::ofstream(temporary) << text;
    fs::rename(temporary, path);
}

std::string readText(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// `shadowfx view` in the background, its output in a file.
class ViewProcess {
public:
    ViewProcess(const std::string& display, const fs::path& effect, const fs::path& screenshot, int frames,
                const fs::path& log)
        : mLog(log) {
        const std::string framesText = std::to_string(frames);
        mPid = fork();
        if (mPid == 0) {
            const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            dup2(fd, 1);
            dup2(fd, 2);
            setenv("DISPLAY", display.c_str(), 1);
            setenv("LP_NUM_THREADS", "2", 1);
            execl(kTool.c_str(), kTool.c_str(), "view", effect.c_str(), "--frames", framesText.c_str(),
                  "--width", "160", "--height", "120", "--screenshot", screenshot.c_str(), nullptr);
            _exit(127);
        }
    }
    ~ViewProcess() {
        if (mPid > 0 && !mExited) {
            kill(mPid, SIGKILL);
            waitpid(mPid, nullptr, 0);
        }
    }
    // Waits up to `seconds` for `text` in the output; false if it never came or the viewer ended.
    bool waitFor(const std::string& text, double seconds) {
        const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        while (std::chrono::steady_clock::now() < end) {
            if (readText(mLog).find(text) != std::string::npos) return true;
            if (exited()) return readText(mLog).find(text) != std::string::npos;
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        return false;
    }
    // The exit status once the frames have run out (-1 after `seconds`, or if a signal ended it).
    int wait(double seconds) {
        const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        while (!exited() && std::chrono::steady_clock::now() < end)
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        return mExited && WIFEXITED(mStatus) ? WEXITSTATUS(mStatus) : -1;
    }
    bool killedBySignal() const { return mExited && WIFSIGNALED(mStatus); }
    std::string output() const { return readText(mLog); }

private:
    bool exited() {
        if (!mExited && waitpid(mPid, &mStatus, WNOHANG) == mPid) mExited = true;
        return mExited;
    }
    pid_t mPid = -1;
    fs::path mLog;
    bool mExited = false;
    int mStatus = 0;
};

// Pixels of the screenshot that are mostly red and mostly green.
std::pair<int, int> redAndGreenPixels(const fs::path& png) {
    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(png.c_str(), &width, &height, &channels, 4);
    if (!pixels) return {-1, -1};
    int red = 0, green = 0;
    for (int i = 0; i < width * height; ++i) {
        const unsigned char* p = pixels + i * 4;
        red += p[0] > 200 && p[1] < 60 && p[2] < 60;
        green += p[1] > 200 && p[0] < 60 && p[2] < 60;
    }
    stbi_image_free(pixels);
    return {red, green};
}

// The viewer's frame limit: long enough for the edits below on a loaded machine (a frame of this effect
// at 160x120 takes a few milliseconds on llvmpipe), short enough to end on its own.
constexpr int kFrames = 3000;

TEST(ViewCommand, ASaveThatCrashesTheHlslCompilerKeepsTheLastGoodEffectAndAFixReloads) {
    ASSERT_TRUE(xvfbInstalled()) << "Xvfb is not installed (xvfb, which scripts/install-deps.sh installs)";
    XvfbServer server;
    ASSERT_FALSE(server.display().empty()) << "could not start Xvfb";
    const shadowfx::test::WorkerCrashHook hook;  // the viewers started below inherit it
    const fs::path dir = fs::temp_directory_path() / ("shadowfx_view_crash_" + std::to_string(getpid()));
    fs::create_directories(dir);
    const fs::path effect = dir / "edit.fx";

    // Red, then the crashing save: the viewer reports the located error and keeps drawing red.
    {
        saveLikeAnEditor(effect, kRed);
        ViewProcess view(server.display(), effect, dir / "kept.png", kFrames, dir / "kept.log");
        ASSERT_TRUE(view.waitFor("shadowfx view: loaded", 60)) << view.output();
        saveLikeAnEditor(effect, kCrashes);
        ASSERT_TRUE(
            view.waitFor("edit.fx:6:8: error: the HLSL compiler crashed on this shader (signal 11)", 60))
            << view.output();
        ASSERT_EQ(view.wait(300), 0) << view.output();
        EXPECT_FALSE(view.killedBySignal());
        const auto [red, green] = redAndGreenPixels(dir / "kept.png");
        EXPECT_GT(red, 200) << "the last good (red) effect is not on screen";
        EXPECT_EQ(green, 0);
    }
    // Red, the crashing save, then a fix (green): the fix reloads.
    {
        saveLikeAnEditor(effect, kRed);
        ViewProcess view(server.display(), effect, dir / "fixed.png", kFrames, dir / "fixed.log");
        ASSERT_TRUE(view.waitFor("shadowfx view: loaded", 60)) << view.output();
        saveLikeAnEditor(effect, kCrashes);
        ASSERT_TRUE(view.waitFor("crashed on this shader", 60)) << view.output();
        saveLikeAnEditor(effect, kGreen);
        ASSERT_TRUE(view.waitFor("shadowfx view: reloaded", 60)) << view.output();
        ASSERT_EQ(view.wait(300), 0) << view.output();
        const auto [red, green] = redAndGreenPixels(dir / "fixed.png");
        EXPECT_GT(green, 200) << "the fixed (green) effect is not on screen";
        EXPECT_EQ(red, 0);
    }
    fs::remove_all(dir);
}

}  // namespace
