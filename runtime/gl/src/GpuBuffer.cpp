#include <runtime/GpuBuffer.h>

#include <algorithm>
#include <cstring>
#include <utility>
#include <vector>

namespace runtime {

GpuBuffer GpuBuffer::create(const void* data, size_t size, GLenum texelFormat) {
    GpuBuffer buffer;
    buffer.mSize = size;
    buffer.mTexelFormat = texelFormat;
    // GL has no empty buffer storage; an empty D3D buffer still binds (and reads as zeros). Storage is at
    // least 16 bytes, so fewer given bytes (an append buffer's 4-byte counter) are copied and padded with
    // zeros rather than read past their end.
    const size_t storage = std::max<size_t>(size, 16);
    std::vector<uint8_t> padded;
    if (!data || size < storage) {
        padded.assign(storage, 0);
        if (data) std::memcpy(padded.data(), data, size);
    }
    gl::GenBuffers(1, &buffer.mBuffer);
    gl::BindBuffer(GL_COPY_WRITE_BUFFER, buffer.mBuffer);
    gl::BufferStorage(GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(storage),
                      padded.empty() ? data : padded.data(), 0);
    gl::BindBuffer(GL_COPY_WRITE_BUFFER, 0);
    if (texelFormat != 0) {
        gl::GenTextures(1, &buffer.mTexture);
        gl::BindTexture(GL_TEXTURE_BUFFER, buffer.mTexture);
        gl::TexBuffer(GL_TEXTURE_BUFFER, texelFormat, buffer.mBuffer);
        gl::BindTexture(GL_TEXTURE_BUFFER, 0);
    }
    return buffer;
}

GpuBuffer::~GpuBuffer() {
    if (mTexture) gl::DeleteTextures(1, &mTexture);
    if (mBuffer) gl::DeleteBuffers(1, &mBuffer);
}

GpuBuffer::GpuBuffer(GpuBuffer&& other) noexcept {
    *this = std::move(other);
}

GpuBuffer& GpuBuffer::operator=(GpuBuffer&& other) noexcept {
    if (this != &other) {
        if (mTexture) gl::DeleteTextures(1, &mTexture);
        if (mBuffer) gl::DeleteBuffers(1, &mBuffer);
        mBuffer = std::exchange(other.mBuffer, 0);
        mTexture = std::exchange(other.mTexture, 0);
        mTexelFormat = std::exchange(other.mTexelFormat, 0);
        mSize = std::exchange(other.mSize, 0);
    }
    return *this;
}

}  // namespace runtime
