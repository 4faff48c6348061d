// VisibleSamplePass: see VisibleSamplePass.h.
#include "VisibleSamplePass.h"

#include <runtime/GlStateSnapshot.h>
#include <runtime/GpuMesh.h>
#include <runtime/GpuProgram.h>
#include <runtime/IntersectionBody.h>
#include <runtime/RenderStateApplier.h>

#include <glm/gtc/type_ptr.hpp>

#include <vector>

namespace runtime {

namespace {

constexpr const char* kVertexShader = R"(#version 450
layout(location = 0) in vec3 inPosition;
uniform mat4 uWorld;
uniform mat4 uViewProjection;
out vec3 vWorld;
void main() {
    vec4 world = uWorld * vec4(inPosition, 1.0);
    vWorld = world.xyz;
    gl_Position = uViewProjection * world;
}
)";

// w = 1 marks a pixel that saw a surface; the clear leaves 0 (background).
constexpr const char* kFragmentShader = R"(#version 450
in vec3 vWorld;
layout(location = 0) out vec4 outPosition;
void main() {
    outPosition = vec4(vWorld, 1.0);
}
)";

}  // namespace

VisibleSamplePass::~VisibleSamplePass() {
    if (mProgram) gl::DeleteProgram(mProgram);
    if (mFramebuffer) gl::DeleteFramebuffers(1, &mFramebuffer);
    if (mPositions) gl::DeleteTextures(1, &mPositions);
    if (mDepth) gl::DeleteRenderbuffers(1, &mDepth);
}

bool VisibleSamplePass::ready(int width, int height) {
    if (!mProgram && !mFailed) {
        mProgram = linkRuntimeProgram(kVertexShader, kFragmentShader);
        mFailed = mProgram == 0;
        if (mProgram) {
            mViewProjectionLocation = gl::GetUniformLocation(mProgram, "uViewProjection");
            mWorldLocation = gl::GetUniformLocation(mProgram, "uWorld");
        }
    }
    if (!mProgram) return false;
    if (mFramebuffer && width == mWidth && height == mHeight) return true;
    if (!mFramebuffer) {
        gl::GenFramebuffers(1, &mFramebuffer);
        gl::GenTextures(1, &mPositions);
        gl::GenRenderbuffers(1, &mDepth);
    }
    gl::BindTexture(GL_TEXTURE_2D, mPositions);
    gl::TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl::BindTexture(GL_TEXTURE_2D, 0);
    gl::BindRenderbuffer(GL_RENDERBUFFER, mDepth);
    gl::RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
    gl::BindRenderbuffer(GL_RENDERBUFFER, 0);
    gl::BindFramebuffer(GL_FRAMEBUFFER, mFramebuffer);
    gl::FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, mPositions, 0);
    gl::FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, mDepth);
    const bool complete = gl::CheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    mWidth = width;
    mHeight = height;
    return complete;
}

std::optional<VisibleSamples> VisibleSamplePass::run(
    const Scene& scene, const InstanceBvh& bvh, int width, int height,
    const std::function<GpuMesh&(const SceneObject&)>& meshOf) {
    GlStateMask mask;
    mask.program = mask.renderStates = mask.framebuffer = true;
    const GlStateSnapshot saved = GlStateSnapshot::capture(mask);
    std::optional<VisibleSamples> samples;
    if (width > 0 && height > 0 && ready(width, height)) {
        gl::BindFramebuffer(GL_FRAMEBUFFER, mFramebuffer);
        gl::Viewport(0, 0, width, height);
        gl::ColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        gl::Disablei(GL_BLEND, 0);
        gl::Disable(GL_STENCIL_TEST);
        gl::Disable(GL_SCISSOR_TEST);
        gl::Disable(GL_DEPTH_CLAMP);
        gl::Disable(GL_POLYGON_OFFSET_FILL);
        gl::PolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        // D3D's default CullMode = CCW, as the effects' scene passes and the ground truth's G-buffer draw:
        // with both faces, a camera inside a closed occluder would see its inner faces and miss the
        // receivers beyond them that the scene pass shows.
        gl::FrontFace(kD3dFrontFace);
        gl::Enable(GL_CULL_FACE);
        gl::CullFace(GL_BACK);
        gl::Enable(GL_DEPTH_TEST);
        gl::DepthMask(GL_TRUE);
        gl::DepthFunc(GL_LESS);
        const GLfloat zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        gl::ClearBufferfv(GL_COLOR, 0, zero);
        const GLfloat farDepth = 1.0f;
        gl::ClearBufferfv(GL_DEPTH, 0, &farDepth);

        const float aspect = static_cast<float>(width) / static_cast<float>(height);
        const glm::mat4 viewProjection = scene.camera.projection(aspect) * scene.camera.view();
        gl::UseProgram(mProgram);
        gl::UniformMatrix4fv(mViewProjectionLocation, 1, GL_FALSE, glm::value_ptr(viewProjection));
        std::vector<uint32_t> inFrustum;
        if (bvh.empty()) {
            for (size_t i = 0; i < scene.objects.size(); ++i) inFrustum.push_back(static_cast<uint32_t>(i));
        } else {
            const ConvexVolume frustum = frustumPlanes(viewProjection);
            bvh.query([&](const Aabb& box) { return overlapVolume(frustum, box); }, inFrustum);
        }
        static const std::vector<fx::VertexInput> kInputs = {{"POSITION0", 0, 3, {}}};
        for (uint32_t index : inFrustum) {
            const SceneObject& object = scene.objects[index];
            if (!object.mesh) continue;
            gl::UniformMatrix4fv(mWorldLocation, 1, GL_FALSE, glm::value_ptr(object.world));
            meshOf(object).draw(kInputs);
        }
        std::vector<float> positions(static_cast<size_t>(width) * static_cast<size_t>(height) * 4);
        gl::ReadBuffer(GL_COLOR_ATTACHMENT0);
        gl::PixelStorei(GL_PACK_ALIGNMENT, 4);
        gl::ReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, positions.data());
        samples = reduceVisibleSamples(positions, scene.camera);
    }
    saved.restore();
    return samples;
}

}  // namespace runtime
