// HostScene: the default material of `ScriptExternal=color` (see HostScene.h).
#include "HostScene.h"

#include <runtime/GlApi.h>
#include <runtime/GpuMesh.h>
#include <runtime/GpuProgram.h>

#include <glm/gtc/type_ptr.hpp>

namespace runtime {

namespace {

constexpr const char* kVertexShader = R"(#version 450
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
uniform mat4 uWorld;
uniform mat4 uViewProjection;
out vec3 vNormal;
out vec3 vWorld;
void main() {
    vec4 world = uWorld * vec4(inPosition, 1.0);
    vWorld = world.xyz;
    vNormal = mat3(transpose(inverse(uWorld))) * inNormal;
    gl_Position = uViewProjection * world;
}
)";

constexpr const char* kFragmentShader = R"(#version 450
in vec3 vNormal;
in vec3 vWorld;
uniform vec3 uColor;
uniform vec3 uLightColor;
uniform vec3 uLightDirection;  // from the light into the scene; zero: a point light at uLightPosition
uniform vec3 uLightPosition;
layout(location = 0) out vec4 outColor;
void main() {
    vec3 toLight = dot(uLightDirection, uLightDirection) > 0.0 ? -uLightDirection : uLightPosition - vWorld;
    float lambert = abs(dot(normalize(vNormal), normalize(toLight)));
    outColor = vec4(uColor * (0.2 + 0.8 * lambert * uLightColor), 1.0);
}
)";

}  // namespace

HostScenePainter::~HostScenePainter() {
    if (mProgram) gl::DeleteProgram(mProgram);
}

bool HostScenePainter::ready() {
    if (mProgram || mFailed) return mProgram != 0;
    mProgram = linkRuntimeProgram(kVertexShader, kFragmentShader);
    mFailed = mProgram == 0;
    if (mFailed) return false;
    const char* const names[] = {"uWorld",      "uViewProjection", "uColor",
                                 "uLightColor", "uLightDirection", "uLightPosition"};
    for (size_t i = 0; i < mLocations.size(); ++i) mLocations[i] = gl::GetUniformLocation(mProgram, names[i]);
    return true;
}

void HostScenePainter::draw(const Scene& scene, const SceneObject& object, const glm::mat4& view,
                            const glm::mat4& projection, GpuMesh& mesh) {
    if (!ready()) return;
    gl::UseProgram(mProgram);
    // The last pass's program may have enabled clip distances, which this program does not write (GL
    // leaves such a clip undefined); GpuProgram::bind sets them again for the next pass.
    for (GLenum i = 0; i < 8; ++i) gl::Disable(GL_CLIP_DISTANCE0 + i);
    const glm::mat4 viewProjection = projection * view;
    gl::UniformMatrix4fv(mLocations[0], 1, GL_FALSE, glm::value_ptr(object.world));
    gl::UniformMatrix4fv(mLocations[1], 1, GL_FALSE, glm::value_ptr(viewProjection));
    gl::Uniform3fv(mLocations[2], 1, glm::value_ptr(object.color));
    glm::vec3 color(1.0f), direction(0.0f), position = scene.camera.position;
    if (!scene.lights.empty()) {
        const Light& light = scene.lights.front();
        color = light.color;
        position = light.position;
        if (light.type != Light::Type::Point) direction = light.direction;
    }
    gl::Uniform3fv(mLocations[3], 1, glm::value_ptr(color));
    gl::Uniform3fv(mLocations[4], 1, glm::value_ptr(direction));
    gl::Uniform3fv(mLocations[5], 1, glm::value_ptr(position));
    static const std::vector<fx::VertexInput> kInputs = {{"POSITION0", 0, 3, {fx::VertexStream::Position, 0}},
                                                         {"NORMAL0", 1, 3, {fx::VertexStream::Normal, 0}}};
    mesh.draw(kInputs);
}

}  // namespace runtime
