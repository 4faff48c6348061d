// ViewCommand: the `shadowfx view` window loop (see ViewCommand.h).
//
// [SECTION] Orbit camera and light
// [SECTION] Render-target viewer
// [SECTION] Panels
// [SECTION] Main loop
#include "ViewCommand.h"
#include "HostOption.h"

#include "ParameterPanel.h"

#include <fx/Diagnostics.h>
#include <runtime/DisplayTexture.h>
#include <runtime/EffectRenderer.h>
#include <runtime/GlContext.h>
#include <runtime/ReloadableEffect.h>
#include <runtime/Scene.h>
#include <runtime/SceneFile.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace shadowfx::cli {

const char* const kViewUsage =
    "usage: shadowfx view EFFECT.fx [options]\n"
    "  --scene NAME|FILE     built-in scene or scene file (.json), as for render (default boxes)\n"
    "  --technique NAME      technique to start with (switch in the panel)\n"
    "  --width W, --height H window size (default 1280x800)\n"
    "  --frames N            render N frames, then exit (tests, CI under Xvfb)\n"
    "  --screenshot FILE.png write the last frame (the effect's image, without the panel) on exit\n"
    "Saving the effect or a file it includes reloads it; a broken save keeps the last good effect.\n"
    "Mouse: left drag orbits, wheel zooms, right drag moves the light. Keys: arrows move the light,\n"
    "R reloads, F12 or P writes a screenshot (shadowfx_view_N.png), Esc quits.\n" SHADOWFX_HOST_OPTION_HELP;

namespace {

using Clock = std::chrono::steady_clock;

// [SECTION] Orbit camera and light

// Spherical coordinates around the scene's centre, initialised from the scene's own camera so the first
// frame matches `shadowfx render`.
struct Orbit {
    glm::vec3 target{0.0f};
    float yaw = 0.0f;    // radians around +Y
    float pitch = 0.3f;  // radians above the horizon
    float distance = 10.0f;

    static Orbit around(const runtime::Camera& camera) {
        Orbit orbit;
        orbit.target = camera.target;
        const glm::vec3 offset = camera.position - camera.target;
        orbit.distance = std::max(0.01f, glm::length(offset));
        orbit.yaw = std::atan2(offset.x, offset.z);
        orbit.pitch = std::asin(std::clamp(offset.y / orbit.distance, -1.0f, 1.0f));
        return orbit;
    }
    glm::vec3 offset() const {
        return distance *
               glm::vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
    }
    void clampPitch() { pitch = std::clamp(pitch, -1.55f, 1.55f); }
};

// Turns the scene's first light around the scene's centre by (yaw, pitch) from where the scene put it:
// the direction for directional lights, position and direction for spot and point lights.
void aimLight(const runtime::Light& original, float yaw, float pitch, const glm::vec3& centre,
              runtime::Light& light) {
    glm::mat4 rotation = glm::rotate(glm::mat4(1.0f), yaw, glm::vec3(0, 1, 0));
    const glm::vec3 side = glm::cross(original.direction, glm::vec3(0, 1, 0));
    if (glm::length(side) > 1e-4f)
        rotation = rotation * glm::rotate(glm::mat4(1.0f), pitch, glm::normalize(side));
    light.direction = glm::normalize(glm::vec3(rotation * glm::vec4(original.direction, 0.0f)));
    light.position = centre + glm::vec3(rotation * glm::vec4(original.position - centre, 0.0f));
}

// [SECTION] Render-target viewer

// The effect's render targets, by parameter name, in declaration order.
std::vector<std::string> renderTargetNames(const runtime::EffectRenderer& renderer) {
    std::vector<std::string> names;
    const fx::CompiledEffect& compiled = renderer.effect();
    for (const fx::TextureDesc& texture : compiled.textures) {
        if (texture.kind == fx::TextureDesc::Kind::RenderColorTarget ||
            texture.kind == fx::TextureDesc::Kind::RenderDepthStencilTarget) {
            names.push_back(compiled.parameters[texture.parameter].name);
        }
    }
    return names;
}

struct TargetView {
    int selected = 0;
    runtime::DisplayTexture texture;
    std::string status;
};

void drawTargetView(runtime::EffectRenderer& renderer, TargetView& view) {
    const std::vector<std::string> names = renderTargetNames(renderer);
    if (names.empty()) {
        ImGui::TextUnformatted("(no render targets)");
        return;
    }
    view.selected = std::clamp(view.selected, 0, static_cast<int>(names.size()) - 1);
    if (ImGui::BeginCombo("target", names[view.selected].c_str())) {
        for (int i = 0; i < static_cast<int>(names.size()); ++i) {
            if (ImGui::Selectable(names[i].c_str(), i == view.selected)) view.selected = i;
        }
        ImGui::EndCombo();
    }
    int width = 0, height = 0, channels = 0;
    const std::optional<std::vector<float>> texels =
        renderer.readTarget(names[view.selected], &width, &height, &channels);
    if (!texels || width <= 0 || height <= 0) {
        ImGui::TextUnformatted("not readable (not allocated yet, or a depth-stencil format)");
        return;
    }
    // Float targets (R32F shadow maps, moments) are normalised to their range of values for display.
    view.texture.uploadNormalized(*texels, width, height, channels);
    ImGui::Text("%d x %d, %d channel%s, normalised", width, height, channels, channels == 1 ? "" : "s");
    const float shown = std::min(ImGui::GetContentRegionAvail().x, 360.0f);
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(view.texture.id())),
                 ImVec2(shown, shown * height / width));
}

// [SECTION] Panels

struct FrameClock {
    double frameMs = 0.0;   // wall time between frames, smoothed
    double renderMs = 0.0;  // EffectRenderer::render, smoothed
    void add(double& average, double sample) {
        average = average == 0.0 ? sample : average * 0.9 + sample * 0.1;
    }
};

void drawErrorOverlay(const runtime::ReloadableEffect& effect) {
    if (!effect.lastReloadFailed()) return;
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x + 10, viewport->Pos.y + viewport->Size.y - 10),
                            ImGuiCond_Always, ImVec2(0, 1));
    ImGui::SetNextWindowSizeConstraints(ImVec2(300, 0),
                                        ImVec2(viewport->Size.x - 20, viewport->Size.y * 0.4f));
    ImGui::PushStyleColor(ImGuiCol_WindowBg, IM_COL32(110, 10, 10, 235));
    ImGui::PushStyleColor(ImGuiCol_TitleBg, IM_COL32(170, 20, 20, 255));
    ImGui::PushStyleColor(ImGuiCol_TitleBgActive, IM_COL32(170, 20, 20, 255));
    ImGui::Begin(effect.renderer() ? "Reload failed: showing the last good effect" : "Effect failed to load",
                 nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoFocusOnAppearing);
    ImGui::TextUnformatted(effect.errorText().c_str());
    ImGui::End();
    ImGui::PopStyleColor(3);
}

}  // namespace

// [SECTION] Main loop

int viewCommand(const Arguments& args) {
    const std::string path = args.positional(0);
    const int width = args.intValue("--width", 1280);
    const int height = args.intValue("--height", 800);
    const int frameLimit = args.intValue("--frames", 0);
    const std::string screenshot = args.value("--screenshot");
    if (width <= 0 || height <= 0 || width > 16384 || height > 16384 || frameLimit < 0) {
        std::cerr << "shadowfx view: --width/--height must be 1..16384 and --frames not negative\n";
        return 2;
    }

    fx::DiagnosticList sceneDiagnostics;
    std::optional<runtime::Scene> loadedScene =
        runtime::loadScene(args.value("--scene", "boxes"), sceneDiagnostics);
    for (const fx::Diagnostic& diagnostic : sceneDiagnostics.items())
        std::cerr << fx::renderDiagnostic(diagnostic) << "\n";
    if (!loadedScene) return 2;
    runtime::Scene scene = *loadedScene;
    const runtime::Scene original = scene;

    runtime::ContextOptions contextOptions;
    contextOptions.backend = runtime::Backend::GLFW;
    contextOptions.width = width;
    contextOptions.height = height;
    contextOptions.windowTitle = "shadowfx view - " + std::filesystem::path(path).filename().string();
    std::string contextError;
    std::unique_ptr<runtime::GlContext> context = runtime::createContext(contextOptions, contextError);
    if (!context) {
        std::cerr << "shadowfx view: " << contextError << "\n";
        return 1;
    }
    auto* window = static_cast<GLFWwindow*>(context->nativeWindow());

    const fx::ParseOptions parseOptions = effectParseOptions(args);
    runtime::ReloadableEffect effect(path, parseOptions);
    fx::DiagnosticList hostDiagnostics;
    bool hostRead = true;
    const std::shared_ptr<const fx::HostFile> host = readHostOption(args, hostDiagnostics, hostRead);
    if (!hostRead) {
        std::cerr << hostDiagnostics.str();
        return 1;
    }
    // Every renderer a reload makes draws the host file's frame too.
    const auto hostEffect = [&] {
        fx::DiagnosticList diagnostics;
        if (effect.renderer() && !useHostFile(*effect.renderer(), host, diagnostics))
            std::cerr << diagnostics.str();
    };
    // On failure the window stays open: the next save may fix it. Scripts and tests wait for "loaded".
    if (!effect.reload()) {
        std::cerr << effect.errorText();
    } else {
        hostEffect();
        std::cerr << "shadowfx view: loaded " << path << "\n";
    }

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini next to the user's effects
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 450");

    std::string technique = args.value("--technique");
    Orbit orbit = Orbit::around(scene.camera);
    float lightYaw = 0.0f, lightPitch = 0.0f;
    const glm::vec3 centre = scene.bounds().center();
    bool timePasses = true;
    runtime::DisplayTexture frameTexture;
    TargetView targetView;
    FrameClock clock;
    runtime::FrameStats stats;
    int screenshotCount = 0;
    std::string lastReload;
    bool renderFailed = false;
    Clock::time_point previous = Clock::now();

    for (int frame = 0; !context->shouldClose() && (frameLimit == 0 || frame < frameLimit); ++frame) {
        glfwPollEvents();
        const ImGuiIO& io = ImGui::GetIO();

        // Hot reload: poll the watcher; a save is picked up within one frame plus the debounce.
        bool forceReload = !io.WantCaptureKeyboard && ImGui::IsKeyPressed(GLFW_KEY_R, false);
        const runtime::ReloadableEffect::Result result =
            forceReload ? (effect.reload() ? runtime::ReloadableEffect::Result::Reloaded
                                           : runtime::ReloadableEffect::Result::Failed)
                        : effect.reloadIfChanged();
        if (result == runtime::ReloadableEffect::Result::Failed) {
            std::cerr << effect.errorText();
        } else if (result == runtime::ReloadableEffect::Result::Reloaded) {
            const runtime::ReloadableEffect::ReloadStats& s = effect.lastStats();
            char line[200];
            std::snprintf(
                line, sizeof line,
                "reloaded in %.0f ms (parse %.0f, compile %.0f, link %.0f; %zu stages compiled, %zu cached)",
                s.parseMs + s.compileMs + s.createMs, s.parseMs, s.compileMs, s.createMs, s.cacheMisses,
                s.cacheHits);
            lastReload = line;
            hostEffect();
            std::cerr << "shadowfx view: " << lastReload << "\n";
            renderFailed = false;
        }

        // Camera and light from the mouse, unless ImGui has it.
        if (!io.WantCaptureMouse) {
            if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
                orbit.yaw -= io.MouseDelta.x * 0.01f;
                orbit.pitch += io.MouseDelta.y * 0.01f;
                orbit.clampPitch();
            }
            if (ImGui::IsMouseDragging(ImGuiMouseButton_Right)) {
                lightYaw += io.MouseDelta.x * 0.01f;
                lightPitch += io.MouseDelta.y * 0.01f;
            }
            if (io.MouseWheel != 0.0f)
                orbit.distance = std::max(0.05f, orbit.distance * std::pow(0.9f, io.MouseWheel));
        }
        if (!io.WantCaptureKeyboard) {
            const float step = 1.5f * io.DeltaTime;
            if (ImGui::IsKeyDown(GLFW_KEY_LEFT)) lightYaw -= step;
            if (ImGui::IsKeyDown(GLFW_KEY_RIGHT)) lightYaw += step;
            if (ImGui::IsKeyDown(GLFW_KEY_UP)) lightPitch -= step;
            if (ImGui::IsKeyDown(GLFW_KEY_DOWN)) lightPitch += step;
            if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) glfwSetWindowShouldClose(window, GLFW_TRUE);
        }
        lightPitch = std::clamp(lightPitch, -1.4f, 1.4f);
        scene.camera.target = orbit.target;
        scene.camera.position = orbit.target + orbit.offset();
        if (!scene.lights.empty())
            aimLight(original.lights[0], lightYaw, lightPitch, centre, scene.lights[0]);

        // The effect's frame, at the window's framebuffer size.
        int fbWidth = 0, fbHeight = 0;
        glfwGetFramebufferSize(window, &fbWidth, &fbHeight);
        runtime::EffectRenderer* renderer = effect.renderer();
        if (renderer && fbWidth > 0 && fbHeight > 0) {
            runtime::FrameOptions options;
            options.width = fbWidth;
            options.height = fbHeight;
            options.technique = technique;
            options.time = static_cast<float>(glfwGetTime());
            options.timePasses = timePasses;
            fx::DiagnosticList diagnostics;
            const Clock::time_point start = Clock::now();
            stats = {};
            if (!renderer->render(scene, options, diagnostics, &stats)) {
                if (!renderFailed) std::cerr << diagnostics.str();  // once, not every frame
                renderFailed = true;
            }
            clock.add(clock.renderMs,
                      std::chrono::duration<double, std::milli>(Clock::now() - start).count());
            frameTexture.upload(renderer->readFrame());
        }
        const Clock::time_point now = Clock::now();
        clock.add(clock.frameMs, std::chrono::duration<double, std::milli>(now - previous).count());
        previous = now;

        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        if (frameTexture.id() != 0) {
            ImGui::GetBackgroundDrawList()->AddImage(
                reinterpret_cast<ImTextureID>(static_cast<intptr_t>(frameTexture.id())), ImVec2(0, 0),
                ImVec2(io.DisplaySize.x, io.DisplaySize.y));
        }

        ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowSize(ImVec2(380, 0), ImGuiCond_FirstUseEver);
        ImGui::Begin(std::filesystem::path(path).filename().c_str());
        ImGui::Text("frame %.2f ms (%.0f fps), render %.2f ms", clock.frameMs,
                    clock.frameMs > 0 ? 1000.0 / clock.frameMs : 0.0, clock.renderMs);
        if (!lastReload.empty()) ImGui::TextWrapped("%s", lastReload.c_str());
        if (renderer) {
            const fx::CompiledEffect& compiled = renderer->effect();
            const std::string shown = technique.empty() ? "(effect's choice)" : technique;
            if (ImGui::BeginCombo("technique", shown.c_str())) {
                if (ImGui::Selectable("(effect's choice)", technique.empty())) technique.clear();
                for (const fx::CompiledTechnique& t : compiled.techniques) {
                    if (ImGui::Selectable(t.name.c_str(), t.name == technique)) technique = t.name;
                }
                ImGui::EndCombo();
            }
            if (ImGui::CollapsingHeader("Passes", ImGuiTreeNodeFlags_DefaultOpen)) {
                ImGui::Checkbox("GPU pass times", &timePasses);
                if (timePasses && ImGui::BeginTable("passes", 3, ImGuiTableFlags_SizingStretchProp)) {
                    ImGui::TableSetupColumn("pass");
                    ImGui::TableSetupColumn("GPU ms");
                    ImGui::TableSetupColumn("draws");
                    ImGui::TableHeadersRow();
                    for (const runtime::PassTiming& pass : stats.passTimings) {
                        ImGui::TableNextRow();
                        ImGui::TableNextColumn();
                        ImGui::TextUnformatted(pass.pass.c_str());
                        ImGui::TableNextColumn();
                        ImGui::Text("%.3f", pass.gpuNs / 1e6);
                        ImGui::TableNextColumn();
                        ImGui::Text("%d", pass.draws);
                    }
                    ImGui::EndTable();
                }
                ImGui::Text("%d passes, %d draws, %llu triangles", stats.passesRun, stats.draws,
                            static_cast<unsigned long long>(stats.triangles));
            }
            if (ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen))
                ParameterPanel::draw(*renderer);
            if (ImGui::CollapsingHeader("Render targets", ImGuiTreeNodeFlags_DefaultOpen))
                drawTargetView(*renderer, targetView);
        }
        if (ImGui::CollapsingHeader("Scene")) {
            ImGui::Text("%s: %zu objects, %zu triangles", scene.name.c_str(), scene.objects.size(),
                        scene.triangleCount());
            ImGui::TextUnformatted("left drag: orbit, wheel: zoom, right drag / arrows: light");
            if (ImGui::Button("reset view")) {
                orbit = Orbit::around(original.camera);
                lightYaw = lightPitch = 0.0f;
            }
        }
        ImGui::End();
        drawErrorOverlay(effect);
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

        const bool screenshotKey = !io.WantCaptureKeyboard && (ImGui::IsKeyPressed(GLFW_KEY_F12, false) ||
                                                               ImGui::IsKeyPressed(GLFW_KEY_P, false));
        if (screenshotKey && renderer) {
            const std::string file = "shadowfx_view_" + std::to_string(screenshotCount++) + ".png";
            std::string error;
            if (runtime::writePng(renderer->readFrame(), file, error)) {
                std::cerr << "shadowfx view: wrote " << file << "\n";
            } else {
                std::cerr << "shadowfx view: " << error << "\n";
            }
        }
        context->swapBuffers();
    }

    int status = effect.renderer() ? 0 : 1;
    if (!screenshot.empty()) {
        removeStaleOutput(screenshot);
        std::string error;
        if (!effect.renderer()) {
            std::cerr << "shadowfx view: no screenshot: the effect never loaded\n";
        } else if (!runtime::writePng(effect.renderer()->readFrame(), screenshot, error)) {
            std::cerr << "shadowfx view: " << error << "\n";
            status = 1;
        } else {
            std::cout << screenshot << "\n";
        }
    }
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    return status;
}

}  // namespace shadowfx::cli
