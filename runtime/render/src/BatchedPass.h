// BatchedPass: one pass drawn as instanced draws, one per mesh (FrameOptions::batching). Holds the pass's
// instanced variant (fx/InstancedPass.h) linked as GL programs, the per-object records in a shader storage
// buffer (one record per scene object, packed when the object or what its values derive from changed, and
// uploaded only then) and the instance lists (the culled objects of each mesh, uploaded per pass when
// they differ from the last ones).
//
// A record has two parts. Its object part holds the values that derive from the object alone (World and
// its inverses, the object's colour and id); its view part those that also derive from the port's or a
// light's matrices (World*View*Projection and the like) and the per-object compile arguments. A moving
// camera changes every view part every frame and no object part: only the view parts are bound and
// packed again.
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
    // link: the pass is then drawn object by object, as with batching off. `viewParameter` (one flag per
    // effect parameter, PassUse::viewDerived) marks the per-object parameters of the records' view part.
    static std::unique_ptr<BatchedPass> create(const fx::CompiledPass& pass,
                                               const std::vector<bool>& perObjectParameter,
                                               const std::vector<bool>& perObjectArgument,
                                               const std::vector<bool>& viewParameter);
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
    // Starts a pass's records: `context` is what the view parts derive from besides the objects
    // (SemanticBinder::objectContext, the values of the per-pass inputs of per-object compile arguments);
    // when it differs from the last pass's, every view part is stale. `sceneStamp` is leave-out's stamp of
    // the scene's objects (EffectResources::SceneCache): while it stays, no object changed.
    void beginRecords(const std::vector<uint32_t>& context, size_t objectCount, uint64_t sceneStamp);
    // What object `index`'s record needs: nothing (packed in this context from an object equal to
    // `object`), its view part packed again (packed from an equal object in another context), or packing
    // whole.
    enum class RecordNeed { Nothing, ViewPart, Whole };
    RecordNeed recordNeed(size_t index, const SceneObject& object);
    // Asks the CPU to fetch object `index`'s stamps and record ahead of recordNeed and the packs: a pass
    // reads the records of its visible objects, scattered over every object's, and with a moving camera
    // each compare of a view part otherwise waits on memory.
    void prefetchRecord(size_t index) const;
    // Packs object `index`'s record whole from the bound values and the evaluated compile arguments.
    void packRecord(size_t index, const SceneObject& object, const std::vector<fx::Value>& parameters,
                    const std::vector<fx::Value>& arguments);
    // Packs the view part of object `index`'s record, whose object part stands: the view part's
    // parameters bound for the object, the compile arguments evaluated.
    void packViewPart(size_t index, const std::vector<fx::Value>& parameters,
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

    // The object an object's record was packed from.
    struct RecordKey {
        glm::mat4 world{1.0f};
        glm::vec3 color{0.0f};
        uint32_t id = 0;
    };
    // When an object's record was packed. Apart from mKeys because every visible object's is read when
    // the context changed (a moving camera: every frame), and 16 bytes an object stay in the CPU's caches
    // where a whole key, fetched from memory, stalls.
    struct RecordStamps {
        uint64_t contextGeneration = 0;  // the context its view part was packed in; 0: never packed
        uint64_t sceneStamp = 0;         // of the scene in which the object was last seen equal to its key
    };
    // A byte range of the record (the view part's fields, adjacent ones merged).
    struct Span {
        uint32_t offset = 0;
        uint32_t size = 0;
    };
    void markDirty(size_t index);

    fx::InstancedPass mVariant;
    std::vector<bool> mPerObjectParameter;
    std::vector<bool> mPerObjectArgument;
    std::unique_ptr<GpuProgram> mProgram;
    std::optional<std::unique_ptr<GpuProgram>> mDepthOnly;  // nullopt until first asked for

    std::vector<uint32_t> mContext;
    uint64_t mContextGeneration = 1;
    uint64_t mSceneStamp = 0;
    std::vector<RecordKey> mKeys;                        // per scene object
    std::vector<RecordStamps> mStamps;                   // per scene object
    std::vector<const fx::UniformBinding*> mViewFields;  // the view part's members of mVariant.record
    std::vector<Span> mViewSpans;
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
