// BatchedPass: see BatchedPass.h.
#include "BatchedPass.h"

#include <algorithm>
#include <cstring>

namespace runtime {

std::unique_ptr<BatchedPass> BatchedPass::create(const fx::CompiledPass& pass,
                                                 const std::vector<bool>& perObjectParameter,
                                                 const std::vector<bool>& perObjectArgument) {
    GLint vertexBlocks = 0;
    gl::GetIntegerv(GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS, &vertexBlocks);
    if (vertexBlocks < 2) return nullptr;  // GL 4.5 allows vertex stages without storage buffers
    std::string whyNot;
    std::optional<fx::InstancedPass> variant =
        fx::instancedPass(pass, perObjectParameter, perObjectArgument, whyNot);
    if (!variant) return nullptr;
    std::unique_ptr<BatchedPass> batched(new BatchedPass());
    batched->mVariant = std::move(*variant);
    batched->mPerObjectParameter = perObjectParameter;
    batched->mPerObjectArgument = perObjectArgument;
    // An optimization, not the effect's program: a driver that refuses it costs speed, not the frame.
    fx::DiagnosticList ignored;
    batched->mProgram = GpuProgram::create(batched->mVariant.pass, ignored);
    if (!batched->mProgram || !batched->mProgram->hasShaders()) return nullptr;
    GLint alignment = 0;
    gl::GetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &alignment);
    batched->mListAlignment = std::max<size_t>(1, static_cast<size_t>(std::max(alignment, 4)) / 4);
    gl::GenBuffers(1, &batched->mInstanceBuffer);
    if (batched->mVariant.recordSize > 0) gl::GenBuffers(1, &batched->mRecordBuffer);
    return batched;
}

BatchedPass::~BatchedPass() {
    if (mRecordBuffer) gl::DeleteBuffers(1, &mRecordBuffer);
    if (mInstanceBuffer) gl::DeleteBuffers(1, &mInstanceBuffer);
}

GpuProgram* BatchedPass::program(bool depthOnly) {
    if (!depthOnly) return mProgram.get();
    if (!mDepthOnly) {
        fx::DiagnosticList ignored;
        mDepthOnly = GpuProgram::create(mVariant.pass, ignored, GpuProgram::Stages::DepthOnly);
    }
    return mDepthOnly->get();
}

// [SECTION] Per-object records

void BatchedPass::beginRecords(const std::vector<uint32_t>& context, size_t objectCount,
                               uint64_t sceneStamp) {
    mSceneStamp = sceneStamp;
    if (context != mContext) {
        mContext = context;
        ++mContextGeneration;
    }
    if (mKeys.size() != objectCount) {
        mKeys.assign(objectCount, RecordKey{});
        mKeyContexts.assign(objectCount, 0);
        mRecords.assign(objectCount * mVariant.recordSize, 0);
        mDirtyBegin = mDirtyEnd = 0;
    }
}

bool BatchedPass::recordCurrent(size_t index, const SceneObject& object) {
    if (mKeyContexts[index] != mContextGeneration) return false;
    RecordKey& key = mKeys[index];
    if (key.sceneStamp == mSceneStamp) return true;  // no object changed since it was last compared
    if (key.world != object.world || key.color != object.color || key.id != object.id) return false;
    key.sceneStamp = mSceneStamp;
    return true;
}

void BatchedPass::packRecord(size_t index, const SceneObject& object,
                             const std::vector<fx::Value>& parameters,
                             const std::vector<fx::Value>& arguments) {
    mKeyContexts[index] = mContextGeneration;
    mKeys[index] = RecordKey{mSceneStamp, object.world, object.color, object.id};
    const size_t size = mVariant.recordSize;
    if (size == 0) return;
    mScratch.assign(size, 0);
    for (const fx::UniformBinding& field : mVariant.record) {
        const std::vector<fx::Value>& source =
            field.source == fx::UniformBinding::Source::Parameter ? parameters : arguments;
        if (field.index < source.size()) UniformPacker::pack(field, source[field.index], mScratch);
    }
    uint8_t* record = mRecords.data() + index * size;
    if (std::memcmp(record, mScratch.data(), size) == 0) return;
    std::memcpy(record, mScratch.data(), size);
    if (mDirtyBegin == mDirtyEnd) {
        mDirtyBegin = index;
        mDirtyEnd = index + 1;
    } else {
        mDirtyBegin = std::min(mDirtyBegin, index);
        mDirtyEnd = std::max(mDirtyEnd, index + 1);
    }
}

void BatchedPass::bindRecords() {
    if (!mRecordBuffer || mRecords.empty()) return;
    gl::BindBuffer(GL_SHADER_STORAGE_BUFFER, mRecordBuffer);
    if (mRecordBufferSize != mRecords.size()) {
        gl::BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(mRecords.size()), mRecords.data(),
                       GL_DYNAMIC_DRAW);
        mRecordBufferSize = mRecords.size();
    } else if (mDirtyBegin != mDirtyEnd) {
        const size_t size = mVariant.recordSize;
        gl::BufferSubData(GL_SHADER_STORAGE_BUFFER, static_cast<GLintptr>(mDirtyBegin * size),
                          static_cast<GLsizeiptr>((mDirtyEnd - mDirtyBegin) * size),
                          mRecords.data() + mDirtyBegin * size);
    }
    mDirtyBegin = mDirtyEnd = 0;
    gl::BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    gl::BindBufferBase(GL_SHADER_STORAGE_BUFFER, fx::kObjectBufferBinding, mRecordBuffer);
}

// [SECTION] Instance lists

void BatchedPass::setInstances(const std::vector<uint32_t>& instances) {
    if (instances == mInstances) return;
    // Grown geometrically, not to each list's length: lists that vary with the view stop allocating once
    // the longest has been seen.
    if (instances.size() > mInstances.capacity())
        mInstances.reserve(std::max(instances.size(), 2 * mInstances.capacity()));
    mInstances = instances;
    gl::BindBuffer(GL_SHADER_STORAGE_BUFFER, mInstanceBuffer);
    // A fresh allocation each time: the draws still queued read the old list.
    gl::BufferData(GL_SHADER_STORAGE_BUFFER,
                   static_cast<GLsizeiptr>(std::max<size_t>(instances.size(), 1) * 4),
                   instances.empty() ? nullptr : instances.data(), GL_STREAM_DRAW);
    gl::BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

void BatchedPass::bindInstances(size_t first, size_t count) {
    gl::BindBufferRange(GL_SHADER_STORAGE_BUFFER, fx::kInstanceBufferBinding, mInstanceBuffer,
                        static_cast<GLintptr>(first * 4), static_cast<GLsizeiptr>(count * 4));
}

}  // namespace runtime
