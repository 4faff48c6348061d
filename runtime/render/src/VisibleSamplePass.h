// VisibleSamplePass: the host's depth pre-pass for fits to what the camera sees (sample distribution shadow
// maps, Lauritzen, Salvi & Lefohn 2011). Before the lights of an effect that asks for it
// (SemanticBinder::wantsVisibleSamples) are fitted, it draws the objects in the view frustum from the camera
// into a float target holding each pixel's world position (counter-clockwise triangles culled, D3D's
// default CullMode, as the scene passes and the ground truth draw), reads it back and reduces it
// (runtime/VisibleSamples.h): the fits of the same frame then see this frame's samples, with no frame of
// latency, at the cost of one depth-tested draw of the visible objects and a read-back of the frame
// (docs/techniques/light-space-parameterizations.md, "Fits from what the camera sees").
#pragma once

#include <runtime/GlApi.h>
#include <runtime/InstanceBvh.h>
#include <runtime/Scene.h>
#include <runtime/VisibleSamples.h>

#include <functional>
#include <optional>

namespace runtime {

class GpuMesh;

class VisibleSamplePass {
public:
    VisibleSamplePass() = default;
    ~VisibleSamplePass();
    VisibleSamplePass(const VisibleSamplePass&) = delete;
    VisibleSamplePass& operator=(const VisibleSamplePass&) = delete;

    // Draws `scene`'s objects that `bvh` (over the scene's objects; may be empty: every object) finds in
    // the camera's frustum at width x height, reads the positions back and reduces them. GL state it
    // changes (program, render states, framebuffer and viewport) is restored. nullopt when no pixel sees a
    // surface or the program or target cannot be made.
    std::optional<VisibleSamples> run(const Scene& scene, const InstanceBvh& bvh, int width, int height,
                                      const std::function<GpuMesh&(const SceneObject&)>& meshOf);

private:
    bool ready(int width, int height);

    GLuint mProgram = 0;
    GLint mViewProjectionLocation = -1, mWorldLocation = -1;  // found once, when the program links
    bool mFailed = false;
    GLuint mFramebuffer = 0;
    GLuint mPositions = 0;  // RGBA32F: world position, coverage in w
    GLuint mDepth = 0;      // depth renderbuffer
    int mWidth = 0, mHeight = 0;
};

}  // namespace runtime
