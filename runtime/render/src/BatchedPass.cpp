// BatchedPass: see BatchedPass.h.
#include "BatchedPass.h"

#include <algorithm>
#include <cstring>

namespace runtime {

std::unique_ptr<BatchedPass> BatchedPass::create(const fx::CompiledPass& pass,
                                                 const std::vector<bool>& perObjectParameter,
                                                 const std::vector<bool>& perObjectArgument,
                                                 const std::vector<bool>& viewParameter) {
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
    for (const fx::UniformBinding& field : batched->mVariant.record) {
        const bool view = field.source == fx::UniformBinding::Source::CompileArgument ||
                          (field.index < viewParameter.size() && viewParameter[field.index]);
        if (!view) continue;
        batched->mViewFields.push_back(&field);
        batched->mViewSpans.push_back(Span{field.offset, field.size});
    }
    std::vector<Span>& spans = batched->mViewSpans;
    std::sort(spans.begin(), spans.end(), [](const Span& a, const Span& b) { return a.offset < b.offset; });
    size_t merged = 0;
    for (const Span& span : spans) {
        if (merged > 0 && spans[merged - 1].offset + spans[merged - 1].size >= span.offset) {
            Span& last = spans[merged - 1];
            last.size = std::max(last.size, span.offset + span.size - last.offset);
        } else {
            spans[merged++] = span;
        }
    }
    spans.resize(merged);
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
        mStamps.assign(objectCount, RecordStamps{});
        mRecords.assign(objectCount * mVariant.recordSize, 0);
        mDirtyBegin = mDirtyEnd = 0;
    }
}

BatchedPass::RecordNeed BatchedPass::recordNeed(size_t index, const SceneObject& object) {
    RecordStamps& stamps = mStamps[index];
    if (stamps.contextGeneration == 0) return RecordNeed::Whole;
    if (stamps.sceneStamp != mSceneStamp) {  // some object changed since this one was last compared
        const RecordKey& key = mKeys[index];
        if (key.world != object.world || key.color != object.color || key.id != object.id)
            return RecordNeed::Whole;
        stamps.sceneStamp = mSceneStamp;
    }
    return stamps.contextGeneration == mContextGeneration ? RecordNeed::Nothing : RecordNeed::ViewPart;
}

void BatchedPass::prefetchRecord(size_t index) const {
    if (index >= mStamps.size()) return;
    __builtin_prefetch(&mStamps[index]);
    const uint8_t* record = mRecords.data() + index * mVariant.recordSize;
    for (const Span& span : mViewSpans) {  // its first and last bytes: a span may straddle cache lines
        __builtin_prefetch(record + span.offset);
        __builtin_prefetch(record + span.offset + span.size - 1);
    }
}

namespace {

const fx::Value* fieldValue(const fx::UniformBinding& field, const std::vector<fx::Value>& parameters,
                            const std::vector<fx::Value>& arguments) {
    const std::vector<fx::Value>& source =
        field.source == fx::UniformBinding::Source::Parameter ? parameters : arguments;
    return field.index < source.size() ? &source[field.index] : nullptr;
}

}  // namespace

void BatchedPass::packRecord(size_t index, const SceneObject& object,
                             const std::vector<fx::Value>& parameters,
                             const std::vector<fx::Value>& arguments) {
    mStamps[index] = RecordStamps{mContextGeneration, mSceneStamp};
    mKeys[index] = RecordKey{object.world, object.color, object.id};
    const size_t size = mVariant.recordSize;
    if (size == 0) return;
    mScratch.assign(size, 0);
    for (const fx::UniformBinding& field : mVariant.record)
        if (const fx::Value* value = fieldValue(field, parameters, arguments))
            UniformPacker::pack(field, *value, mScratch);
    uint8_t* record = mRecords.data() + index * size;
    if (std::memcmp(record, mScratch.data(), size) == 0) return;
    std::memcpy(record, mScratch.data(), size);
    markDirty(index);
}

void BatchedPass::packViewPart(size_t index, const std::vector<fx::Value>& parameters,
                               const std::vector<fx::Value>& arguments) {
    mStamps[index].contextGeneration = mContextGeneration;
    const size_t size = mVariant.recordSize;
    if (size == 0 || mViewFields.empty()) return;
    // The scratch record's bytes outside the view part's members are left as they are: only the spans are
    // compared and copied, and the members' padding, never written, stays zero as the whole pack left it.
    mScratch.resize(size, 0);
    for (const fx::UniformBinding* field : mViewFields)
        if (const fx::Value* value = fieldValue(*field, parameters, arguments))
            UniformPacker::pack(*field, *value, mScratch);
    uint8_t* record = mRecords.data() + index * size;
    bool changed = false;
    for (const Span& span : mViewSpans) {
        if (std::memcmp(record + span.offset, mScratch.data() + span.offset, span.size) == 0) continue;
        std::memcpy(record + span.offset, mScratch.data() + span.offset, span.size);
        changed = true;
    }
    if (changed) markDirty(index);
}

void BatchedPass::markDirty(size_t index) {
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
