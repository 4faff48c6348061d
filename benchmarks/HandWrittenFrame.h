// HandWrittenFrame: the thesis effect's `main` frame (effects/thesis_fxcomposer.fx) written directly
// against OpenGL 4.5, the baseline that says what the effect layer costs: clear the R32F map to ZMaxValue,
// draw the casters into it from light0 with BlendOp=min, clear the frame and draw the scene with the
// shadow test. It takes the GLSL, block layouts and sampler units of the compiled effect (the text
// `shadowfx compile` prints), so both draw the same shaders; everything else is written out by hand, the
// way a careful GL programmer would: one VAO per mesh and pass set up once, the culled lists from the same
// BVH and receiver region as the runtime's leave-out, every draw's uniform blocks written straight into
// a persistently mapped buffer (a region per frame in flight) and bound by range, states set once per
// pass.
//
// Needs a current GL 4.5 context for its whole life. Knows the thesis effect's parameters by name: a
// changed effect fails create() with the member it does not know, rather than drawing something else.
#pragma once

#include <fx/CompiledEffect.h>
#include <runtime/FrameImage.h>
#include <runtime/InstanceBvh.h>
#include <runtime/Scene.h>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace shadowfx::baseline {

class HandWrittenFrame {
public:
    // The scene's objects and meshes are uploaded and indexed here; render() may move the camera only.
    static std::unique_ptr<HandWrittenFrame> create(const fx::CompiledEffect& effect,
                                                    const runtime::Scene& scene, int width, int height,
                                                    std::string& error);
    ~HandWrittenFrame();
    HandWrittenFrame(const HandWrittenFrame&) = delete;
    HandWrittenFrame& operator=(const HandWrittenFrame&) = delete;

    // Issues one frame (does not wait for it).
    void render(const runtime::Scene& scene);
    runtime::FrameImage readFrame() const;
    int shadowDraws() const { return mShadowDraws; }
    int sceneDraws() const { return mSceneDraws; }

    struct Member;
    struct Block;
    struct Pass;
    struct FrameValues;

private:
    HandWrittenFrame() = default;
    bool setUp(const fx::CompiledEffect& effect, const runtime::Scene& scene, std::string& error);
    void drawPass(Pass& pass, const std::vector<uint32_t>& objects, const FrameValues& frame);

    int mWidth = 0, mHeight = 0, mMapSize = 0;
    std::vector<float> mShadowClear;  // ShadowClearColor
    std::vector<float> mFrameClear;   // ClearColor
    float mClearDepth = 1.0f;
    float mPadTexels = 8.0f;  // the runtime's receiver padding for a pass without FilterReachTexels
    std::unique_ptr<Pass> mShadowPass, mScenePass;
    std::vector<const runtime::SceneObject*> mObjects;  // index = the BVH's object index
    std::vector<size_t> mObjectMesh;                    // per object, its index in mMeshes
    std::map<const runtime::Mesh*, size_t> mMeshIndex;
    struct MeshBuffers {
        uint32_t positions = 0, normals = 0, texcoords = 0, indices = 0;
        int indexCount = 0;
    };
    std::vector<MeshBuffers> mMeshes;
    runtime::InstanceBvh mBvh;
    runtime::Bounds mBounds;
    std::vector<uint32_t> mCasters, mVisible;
    uint32_t mShadowMap = 0, mFrameColor = 0, mFrameDepth = 0, mNoise = 0;
    uint32_t mShadowFbo = 0, mFrameFbo = 0;
    uint32_t mPointClamp = 0, mLinearWrap = 0;
    int mUniformAlignment = 256;
    int mShadowDraws = 0, mSceneDraws = 0;
};

}  // namespace shadowfx::baseline
