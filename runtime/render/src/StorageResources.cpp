// StorageResources: see StorageResources.h. The images are made in StorageImages.cpp.
#include "StorageResources.h"

#include <fx/StorageLimits.h>

#include <algorithm>
#include <cstring>

namespace runtime {

namespace {

// A Buffer<T>'s texel, as the compiler resolved T (fx::BufferTexel): its GL buffer-texture format and
// size. The compiled effect's checks let through 32-bit float, int and uint texels of 1 to 4 components.
struct TexelFormat {
    GLenum format;
    size_t bytes;
};
TexelFormat bufferTexelFormat(const fx::BufferTexel& texel) {
    static constexpr GLenum kFloat[4] = {GL_R32F, GL_RG32F, GL_RGB32F, GL_RGBA32F};
    static constexpr GLenum kInt[4] = {GL_R32I, GL_RG32I, GL_RGB32I, GL_RGBA32I};
    static constexpr GLenum kUInt[4] = {GL_R32UI, GL_RG32UI, GL_RGB32UI, GL_RGBA32UI};
    const GLenum* formats = texel.component == fx::BaseType::Int    ? kInt
                            : texel.component == fx::BaseType::UInt ? kUInt
                                                                    : kFloat;
    const size_t components = static_cast<size_t>(std::clamp(texel.components, 1, 4));
    return TexelFormat{formats[components - 1], components * 4};
}

// The storage layout a pass's code gives a StructuredBuffer or ByteAddressBuffer (the first found; every
// unit declares the same type the same way); null if no pass reads it.
const fx::StorageBufferBinding* storageLayout(const fx::CompiledEffect& effect, size_t parameter) {
    for (const fx::CompiledTechnique& technique : effect.techniques)
        for (const fx::CompiledPass& pass : technique.passes)
            for (const fx::StageProgram* stage :
                 {&pass.vertex, &pass.hull, &pass.domain, &pass.geometry, &pass.fragment, &pass.compute})
                for (const fx::StorageBufferBinding& b : stage->storageBuffers)
                    if (b.parameter == parameter) return &b;
    return nullptr;
}

}  // namespace

std::unique_ptr<StorageResources> StorageResources::create(const fx::CompiledEffect& effect) {
    auto storage = std::unique_ptr<StorageResources>(new StorageResources(effect));
    storage->createDefaultBuffers();
    storage->createImages();
    return storage;
}

const GpuBuffer* StorageResources::buffer(size_t parameter) const {
    auto found = mBuffers.find(parameter);
    return found == mBuffers.end() ? nullptr : &found->second;
}

const GpuBuffer* StorageResources::counter(size_t parameter) const {
    auto found = mCounters.find(parameter);
    return found == mCounters.end() ? nullptr : &found->second;
}

const GpuTexture* StorageResources::image(size_t parameter) const {
    auto found = mImages.find(parameter);
    return found == mImages.end() ? nullptr : &found->second;
}

size_t StorageResources::viewedResource(size_t parameter) const {
    auto view = mResourceViews.find(parameter);
    return view == mResourceViews.end() ? parameter : view->second;
}

// Zeros until the application sets them: what D3D10 reads from a resource slot with nothing bound.
void StorageResources::createDefaultBuffers() {
    for (size_t i = 0; i < mEffect->parameters.size(); ++i) {
        const fx::TypeDesc& type = mEffect->parameters[i].type;
        if (!type.isBuffer()) continue;
        if (type.base == fx::BaseType::Buffer) {
            const TexelFormat texel = bufferTexelFormat(mEffect->parameters[i].bufferTexel);
            mBuffers[i] = GpuBuffer::create(nullptr, texel.bytes, texel.format);
            continue;
        }
        const fx::StorageBufferBinding* layout = storageLayout(*mEffect, i);
        const size_t elements = mEffect->parameters[i].elementCount;
        mBuffers[i] =
            GpuBuffer::create(nullptr, elements * (layout ? std::max<size_t>(layout->glStride, 4) : 16));
        if (type.base == fx::BaseType::RWStructuredBuffer ||
            type.base == fx::BaseType::AppendStructuredBuffer ||
            type.base == fx::BaseType::ConsumeStructuredBuffer) {
            const uint32_t zero = 0;
            mCounters[i] = GpuBuffer::create(&zero, sizeof zero);
        }
    }
}

bool StorageResources::set(size_t index, const void* bytes, size_t elements, size_t elementBytes,
                           fx::DiagnosticSink& diagnostics) {
    index = viewedResource(index);  // a view's contents are its resource's
    const bool isBuffer = index < mEffect->parameters.size() && mEffect->parameters[index].type.isBuffer();
    auto refuse = [&](fx::DiagId id, const std::vector<std::string>& args) {
        const fx::SourceLoc where = index < mEffect->parameters.size() ? mEffect->parameters[index].loc
                                                                       : fx::SourceLoc{mEffect->path, 0, 0};
        diagnostics.report(id, where, args);
        return false;
    };
    if (!isBuffer) return refuse(fx::DiagId::SetBufferNotBuffer, {std::to_string(index)});
    const fx::TypeDesc& type = mEffect->parameters[index].type;
    const std::vector<std::string> what = {mEffect->parameters[index].name, type.hlslName()};
    const auto withSize = [&](size_t elementSize) {
        std::vector<std::string> args = what;
        args.push_back(std::to_string(elementSize));
        return args;
    };
    if ((bytes == nullptr && elements > 0) || elements > fx::kMostStorageElements || elementBytes > 65536)
        return refuse(fx::DiagId::SetBufferByteCount, what);
    const size_t total = elements * elementBytes;
    if (type.base == fx::BaseType::Buffer) {
        const TexelFormat texel = bufferTexelFormat(mEffect->parameters[index].bufferTexel);
        if (elementBytes != texel.bytes)
            return refuse(fx::DiagId::SetBufferElementSize, withSize(texel.bytes));
        mBuffers[index] = GpuBuffer::create(bytes, total, texel.format);
    } else if (type.base == fx::BaseType::ByteAddressBuffer) {
        if (total % 4 != 0) return refuse(fx::DiagId::SetBufferWholeWords, what);
        mBuffers[index] = GpuBuffer::create(bytes, total);
    } else if (const fx::StorageBufferBinding* layout = storageLayout(*mEffect, index)) {
        if (elementBytes != layout->d3dStride)
            return refuse(fx::DiagId::SetBufferPackedElementSize, withSize(layout->d3dStride));
        // From D3D's packing to the GL block's (std430 aligns vectors and pads elements). A buffer with a
        // counter keeps room for its ElementCount, where the shaders append.
        auto counter = mCounters.find(index);
        const size_t room = counter == mCounters.end()
                                ? elements
                                : std::max(elements, size_t{mEffect->parameters[index].elementCount});
        std::vector<uint8_t> packed(room * layout->glStride, 0);
        const auto* in = static_cast<const uint8_t*>(bytes);
        for (size_t e = 0; e < elements; ++e)
            for (const fx::StorageBufferBinding::Run& run : layout->runs)
                std::memcpy(packed.data() + e * layout->glStride + run.glOffset,
                            in + e * layout->d3dStride + run.d3dOffset, run.bytes);
        mBuffers[index] = GpuBuffer::create(packed.data(), packed.size());
        // D3D11's initial count of the view an application binds the elements it filled through: a consume
        // buffer holds them to consume, an append buffer appends after them.
        if (counter != mCounters.end()) {
            const auto count = static_cast<uint32_t>(elements);
            counter->second = GpuBuffer::create(&count, sizeof count);
        }
    } else {
        mBuffers[index] = GpuBuffer::create(bytes, total);  // no pass reads it
    }
    return true;
}

}  // namespace runtime
