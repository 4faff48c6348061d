// HostScene: the host's part of an FX Composer frame, which effects written for FX Composer and the
// DirectX 9 SDK expect and never do themselves:
// - the background: before a technique whose scripts do not clear the frame's colour target, the host
//   clears colour to kHostBackground, depth to 1 and stencil to 0 (FX Composer cleared its viewport
//   before drawing "object" class materials); before a "scene" class effect only in a frame that starts a
//   picture, since FX Composer handed such an effect the frame it left (fx::CompiledEffect::sceneClass);
// - `ScriptExternal=color`: where a scene or post-process script says so, the host draws the scene into
//   the current targets with its default material (HostScenePainter).
// docs/fxcomposer.md documents both for effect authors.
#pragma once

#include <fx/CompiledEffect.h>
#include <glm/glm.hpp>
#include <runtime/Scene.h>

#include <array>

namespace runtime {

class GpuMesh;

// The host background: a dark grey-blue, (64, 72, 96) of 255, that neither a black nor a white blank
// frame can be mistaken for.
constexpr glm::vec4 kHostBackground{64.0f / 255.0f, 72.0f / 255.0f, 96.0f / 255.0f, 1.0f};

// Draws scene objects with the host's default material: the object's diffuse colour (SceneObject::color)
// lit by the scene's first light, Lambert with an ambient term of 0.2, D3D's default render states
// (depth test LessEqual with writes, counter-clockwise triangles culled, no blending). Without a light, a
// headlight from the camera.
class HostScenePainter {
public:
    HostScenePainter() = default;
    ~HostScenePainter();
    HostScenePainter(const HostScenePainter&) = delete;
    HostScenePainter& operator=(const HostScenePainter&) = delete;

    // Compiles the program on first use; false if the driver refuses it (never expected).
    bool ready();
    // Draws one object; `view` and `projection` are the current port's (glm column-vector form).
    void draw(const Scene& scene, const SceneObject& object, const glm::mat4& view,
              const glm::mat4& projection, GpuMesh& mesh);

private:
    unsigned int mProgram = 0;  // GLuint
    // uWorld, uViewProjection, uColor, uLightColor, uLightDirection, uLightPosition: found once, at link.
    std::array<int, 6> mLocations{};
    bool mFailed = false;
};

}  // namespace runtime
