// StorageResources: the GL storage behind an effect's buffer parameters (Buffer<T>, StructuredBuffer,
// ByteAddressBuffer and their read-write, append and consume forms), its read-write textures and
// RWBuffers, and the parameters that view them (`string ViewOf`). Made at load, as an FX11 application
// creates the resources and views it binds, and kept between frames and dispatches: compute passes write
// them, later passes and frames read what they wrote. Invariants its mutators keep:
// - every buffer parameter has its buffer from load on, zeros until the application sets it;
// - every RWStructuredBuffer, AppendStructuredBuffer and ConsumeStructuredBuffer has its hidden counter
//   (one uint), zero at load and set to the number of elements the application gives, and its buffer
//   keeps room for its ElementCount, where the shaders append;
// - a view names a read-write resource, and what is set through a view is its resource's.
#pragma once

#include <fx/CompiledEffect.h>
#include <fx/Diagnostics.h>
#include <runtime/GpuBuffer.h>
#include <runtime/GpuTexture.h>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>

namespace runtime {

class StorageResources {
public:
    // Every buffer at its declared size and every image a pass uses at its annotated size, in the format
    // its code declares, a Buffer<T> in its texels' format, and the views: what the compiler resolved
    // (ParameterInfo::elementCount, imageSize, imageFormat, bufferTexel, viewOf).
    static std::unique_ptr<StorageResources> create(const fx::CompiledEffect& effect);

    // The buffer, counter or image of a parameter (not of the resource it views: see viewedResource), or
    // null where it has none.
    const GpuBuffer* buffer(size_t parameter) const;
    const GpuBuffer* counter(size_t parameter) const;
    const GpuTexture* image(size_t parameter) const;
    // The resource `parameter` reads: the one it is a view of, else its own.
    size_t viewedResource(size_t parameter) const;

    // EffectRenderer::setBuffer: `elements` elements of `elementBytes` each, in D3D's packing, repacked for
    // the GL block. False, with a diagnostic, for a parameter that is no buffer or elements of the wrong
    // size.
    bool set(size_t index, const void* bytes, size_t elements, size_t elementBytes,
             fx::DiagnosticSink& diagnostics);

    // Compute dispatches so far: what a pass reading storage buffers or images reads changes with them,
    // which the frame plan's signatures take in (PlanRecorder::draw) so that leave-out never keeps such a
    // pass's last result.
    uint64_t dispatches() const { return mDispatches; }
    void countDispatch() { ++mDispatches; }

private:
    explicit StorageResources(const fx::CompiledEffect& effect) : mEffect(&effect) {}
    void createDefaultBuffers();
    // StorageImages.cpp.
    void createImages();

    const fx::CompiledEffect* mEffect;
    std::map<size_t, GpuBuffer> mBuffers;  // by parameter index; an RWBuffer's with its buffer texture
    std::map<size_t, GpuBuffer> mCounters;
    std::map<size_t, GpuTexture> mImages;
    std::map<size_t, size_t> mResourceViews;  // view parameter -> the resource it reads
    uint64_t mDispatches = 0;
};

}  // namespace runtime
