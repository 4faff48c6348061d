// GpuBuffer: a GL buffer object holding a D3D10 buffer resource, owned RAII: the storage of a
// StructuredBuffer or ByteAddressBuffer (a shader storage block), or of a Buffer<T> together with the
// buffer texture that reads it as texels of T (samplerBuffer).
#pragma once

#include <runtime/GlApi.h>

#include <cstddef>
#include <cstdint>

namespace runtime {

class GpuBuffer {
public:
    // `size` bytes of `data` (zeros where data is null). With `texelFormat` (GL_R32F, GL_RGBA32UI, ...),
    // also a buffer texture over the whole buffer.
    static GpuBuffer create(const void* data, size_t size, GLenum texelFormat = 0);

    GpuBuffer() = default;
    ~GpuBuffer();
    GpuBuffer(GpuBuffer&& other) noexcept;
    GpuBuffer& operator=(GpuBuffer&& other) noexcept;
    GpuBuffer(const GpuBuffer&) = delete;
    GpuBuffer& operator=(const GpuBuffer&) = delete;

    GLuint id() const { return mBuffer; }
    GLuint texture() const { return mTexture; }          // the buffer texture; 0 for a storage buffer
    GLenum texelFormat() const { return mTexelFormat; }  // the buffer texture's; 0 for a storage buffer
    size_t size() const { return mSize; }

private:
    GLuint mBuffer = 0;
    GLuint mTexture = 0;
    GLenum mTexelFormat = 0;
    size_t mSize = 0;
};

}  // namespace runtime
