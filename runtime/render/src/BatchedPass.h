// BatchedPass: one pass drawn as instanced draws, one per mesh (FrameOptions::batching). Holds the pass's
// instanced variant (fx/InstancedPass.h) linked as GL programs, the per-object records in a shader storage
// buffer (one record per scene object, packed when the object or what its values derive from changed, and
// uploaded only then) and the instance lists (the culled objects of each mesh, uploaded per pass when
// they differ from the last ones).
#pragma once

#include <runtime/GlApi.h>
#include <runtime/GpuProgram.h>
#include <runtime/Scene.h>

#include <fx/CompiledEffect.h>
#include <fx/InstancedPass.h>
#include <fx/Value.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace runtime {

class BatchedPass {
public:
    // The variant for these per-object flags (one per effect parameter, one per compile argument of the
    // pass), or nullopt where the pass cannot be drawn instanced (InstancedPass.h) or the variant does not
    // link: the pass is then drawn object by object, as with batching off.
    static std::unique_ptr<BatchedPass> create(const fx::CompiledPass& pass,
                                               const std::vector<bool>& perObjectParameter,
                                               const std::vector<bool>& perObjectArgument);
    ~BatchedPass();
    BatchedPass(const BatchedPass&) = delete;
    BatchedPass& operator=(const BatchedPass&) = delete;

    bool sameFlags(const std::vector<bool>& perObjectParameter,
                   const std::vector<bool>& perObjectArgument) const {
        return perObjectParameter == mPerObjectParameter && perObjectArgument == mPerObjectArgument;
    }
    // The linked variant: with the pixel stage, or the vertex stage alone (GpuProgram::Stages::DepthOnly,
    // linked on first use; null if it does not link).
    GpuProgram* program(bool depthOnly);
    const fx::CompiledPass& pass() const { return mVariant.pass; }

    // [SECTION] Per-object records
    // Starts a pass's records: `context` is what the objects' values derive from besides the objects
    // (SemanticBinder::objectContext, the stamps of the per-pass inputs of per-object compile arguments);
    // when it differs from the last pass's, every record is stale. `sceneStamp` is leave-out's stamp of the
    // scene's objects (EffectResources::SceneCache): while it stays, no object changed.
    void beginRecords(const std::vector<uint32_t>& context, size_t objectCount, uint64_t sceneStamp);
    // True if object `index`'s record was packed in this context from an object equal to `object`.
    bool recordCurrent(size_t index, const SceneObject& object);
    // Packs object `index`'s record from the bound values and the evaluated compile arguments.
    void packRecord(size_t index, const SceneObject& object, const std::vector<fx::Value>& parameters,
                    const std::vector<fx::Value>& arguments);
    // Uploads the records packed since the last upload and binds the record buffer.
    void bindRecords();

    // [SECTION] Instance lists
    // The offset a batch's list must start at, in entries (storage-buffer offset alignment).
    size_t listAlignment() const { return mListAlignment; }
    // Uploads `instances` (object indices, each batch's run starting at a multiple of listAlignment())
    // unless it equals the last list this pass uploaded.
    void setInstances(const std::vector<uint32_t>& instances);
    void bindInstances(size_t first, size_t count);

private:
    BatchedPass() = default;

    // What an object's record was packed from, besides the context (mKeyContexts).
    struct RecordKey {
        uint64_t sceneStamp = 0;  // of the scene in which the object was last seen equal
        glm::mat4 world{1.0f};
        glm::vec3 color{0.0f};
        uint32_t id = 0;
    };

    fx::InstancedPass mVariant;
    std::vector<bool> mPerObjectParameter;
    std::vector<bool> mPerObjectArgument;
    std::unique_ptr<GpuProgram> mProgram;
    std::optional<std::unique_ptr<GpuProgram>> mDepthOnly;  // nullopt until first asked for

    std::vector<uint32_t> mContext;
    uint64_t mContextGeneration = 1;
    uint64_t mSceneStamp = 0;
    std::vector<RecordKey> mKeys;  // per scene object
    // Per scene object: the context generation its record was packed in, 0 for none. Apart from mKeys
    // because every visible object's is read when the context changed (a moving camera: every frame),
    // and 8 bytes an object stay in the CPU's caches where a whole key, fetched from memory, stalls.
    std::vector<uint64_t> mKeyContexts;
    std::vector<uint8_t> mRecords;
    std::vector<uint8_t> mScratch;
    size_t mDirtyBegin = 0, mDirtyEnd = 0;  // records packed since the last upload, in objects
    GLuint mRecordBuffer = 0;
    size_t mRecordBufferSize = 0;

    std::vector<uint32_t> mInstances;
    GLuint mInstanceBuffer = 0;
    size_t mListAlignment = 1;
};

}  // namespace runtime
