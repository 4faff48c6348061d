// StreamOutBuffers: one stream-output pass's capture on the GPU (D3D10's stream-output buffers as GL
// transform feedback): two sets of buffers, one per fx::StreamOutput slot each, used in turn, so that a
// pass can draw what it captured last while it captures anew (a particle system advancing itself), and a
// vertex array per set whose attribute k reads element k of the capture, for the passes that draw it
// (DrawAuto's role: glDrawTransformFeedback).
#pragma once

#include <runtime/GlApi.h>

#include <fx/CompiledEffect.h>

#include <cstdint>
#include <memory>

namespace runtime {

// What a stream-output pass captured last: the GL objects an application draws or reads back.
struct StreamOutCapture {
    // For glDrawTransformFeedback(primitive, transformFeedback); 0 while nothing was captured yet.
    GLuint transformFeedback = 0;
    GLuint buffers[4] = {0, 0, 0, 0};  // per slot of the declaration; 0 where the slot is unused
    uint32_t strides[4] = {0, 0, 0, 0};
    GLuint vertexArray = 0;  // attribute k reads fx::StreamOutput::elements[k] (converted to float)
    GLenum primitive = GL_POINTS;
    // Vertices captured (a query of the primitives written; counting them waits for the capture). Before
    // the first capture: the seed, one vertex whose every element is 0.
    uint64_t vertices = 0;
    bool seed = true;
};

class StreamOutBuffers {
public:
    // Buffers of `output.capacity` vertices per slot, both sets holding the seed vertex.
    explicit StreamOutBuffers(const fx::StreamOutput& output);
    ~StreamOutBuffers();
    StreamOutBuffers(const StreamOutBuffers&) = delete;
    StreamOutBuffers& operator=(const StreamOutBuffers&) = delete;

    // Captures the draws between begin() and end() into the set that does not hold the last capture.
    void begin();
    void end();
    // Draws the last capture (the seed before any) as `mode`, with its vertex array bound; the caller's
    // program reads it. Leaves vertex array 0 bound.
    void drawLast(GLenum mode) const;
    // The last capture; counting its vertices waits for the GPU to finish it.
    StreamOutCapture last() const;
    GLenum primitive() const { return mPrimitive; }
    // GL's primitive mode for a captured primitive type.
    static GLenum mode(fx::StreamOutput::Primitive primitive);

private:
    struct Set {
        GLuint feedback = 0;
        GLuint buffers[4] = {0, 0, 0, 0};
        GLuint vertexArray = 0;
        GLuint query = 0;  // GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN of its last capture
    };
    Set mSets[2];
    uint32_t mStrides[4] = {0, 0, 0, 0};
    GLenum mPrimitive = GL_POINTS;
    int mLast = 1;      // the set holding the last capture (or the seed)
    bool mSeed = true;  // nothing captured yet
    bool mCapturing = false;
};

}  // namespace runtime
