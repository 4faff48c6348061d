#include <runtime/StreamOutBuffers.h>

#include <algorithm>
#include <vector>

namespace runtime {

namespace {

GLenum componentType(fx::StreamOutElement::Component component) {
    switch (component) {
        case fx::StreamOutElement::Component::Int:
            return GL_INT;
        case fx::StreamOutElement::Component::UInt:
            return GL_UNSIGNED_INT;
        case fx::StreamOutElement::Component::Float:
            break;
    }
    return GL_FLOAT;
}

}  // namespace

GLenum StreamOutBuffers::mode(fx::StreamOutput::Primitive primitive) {
    switch (primitive) {
        case fx::StreamOutput::Primitive::Lines:
            return GL_LINES;
        case fx::StreamOutput::Primitive::Triangles:
            return GL_TRIANGLES;
        case fx::StreamOutput::Primitive::Points:
            break;
    }
    return GL_POINTS;
}

StreamOutBuffers::StreamOutBuffers(const fx::StreamOutput& output) : mPrimitive(mode(output.primitive)) {
    const GLsizeiptr capacity = std::max(output.capacity, 1);
    for (Set& set : mSets) {
        gl::CreateTransformFeedbacks(1, &set.feedback);
        gl::CreateVertexArrays(1, &set.vertexArray);
        gl::GenQueries(1, &set.query);
        for (int slot = 0; slot < 4; ++slot) {
            const uint32_t stride = output.strides[slot];
            mStrides[slot] = stride;
            if (stride == 0) continue;
            gl::CreateBuffers(1, &set.buffers[slot]);
            gl::NamedBufferStorage(set.buffers[slot], capacity * stride, nullptr, GL_DYNAMIC_STORAGE_BIT);
            // The seed: one vertex whose every element is 0, drawn until the first capture.
            const std::vector<uint8_t> zero(stride, 0);
            gl::NamedBufferSubData(set.buffers[slot], 0, stride, zero.data());
            gl::TransformFeedbackBufferBase(set.feedback, static_cast<GLuint>(slot), set.buffers[slot]);
            gl::VertexArrayVertexBuffer(set.vertexArray, static_cast<GLuint>(slot), set.buffers[slot], 0,
                                        static_cast<GLsizei>(stride));
        }
        for (size_t k = 0; k < output.elements.size(); ++k) {
            const fx::StreamOutElement& e = output.elements[k];
            const GLuint attribute = static_cast<GLuint>(k);
            gl::EnableVertexArrayAttrib(set.vertexArray, attribute);
            // Not the I-variant: integer elements arrive converted to float, as every attribute of the
            // effect's vertex shaders is declared (fx's lowering converts them back).
            gl::VertexArrayAttribFormat(set.vertexArray, attribute, e.components, componentType(e.component),
                                        GL_FALSE, e.offset);
            gl::VertexArrayAttribBinding(set.vertexArray, attribute, static_cast<GLuint>(e.slot));
        }
    }
}

StreamOutBuffers::~StreamOutBuffers() {
    for (Set& set : mSets) {
        gl::DeleteTransformFeedbacks(1, &set.feedback);
        gl::DeleteVertexArrays(1, &set.vertexArray);
        gl::DeleteQueries(1, &set.query);
        for (GLuint buffer : set.buffers)
            if (buffer) gl::DeleteBuffers(1, &buffer);
    }
}

void StreamOutBuffers::begin() {
    const Set& set = mSets[1 - mLast];
    gl::BindTransformFeedback(GL_TRANSFORM_FEEDBACK, set.feedback);
    gl::BeginQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, set.query);
    gl::BeginTransformFeedback(mPrimitive);
    mCapturing = true;
}

void StreamOutBuffers::end() {
    if (!mCapturing) return;
    gl::EndTransformFeedback();
    gl::EndQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
    gl::BindTransformFeedback(GL_TRANSFORM_FEEDBACK, 0);
    mCapturing = false;
    mLast = 1 - mLast;
    mSeed = false;
}

void StreamOutBuffers::drawLast(GLenum mode) const {
    const Set& set = mSets[mLast];
    gl::BindVertexArray(set.vertexArray);
    if (mSeed)
        gl::DrawArrays(mode, 0, 1);
    else
        gl::DrawTransformFeedback(mode, set.feedback);
    gl::BindVertexArray(0);
}

StreamOutCapture StreamOutBuffers::last() const {
    const Set& set = mSets[mLast];
    StreamOutCapture capture;
    capture.seed = mSeed;
    capture.transformFeedback = mSeed ? 0 : set.feedback;
    for (int slot = 0; slot < 4; ++slot) {
        capture.buffers[slot] = set.buffers[slot];
        capture.strides[slot] = mStrides[slot];
    }
    capture.vertexArray = set.vertexArray;
    capture.primitive = mPrimitive;
    if (mSeed) {
        capture.vertices = 1;
    } else {
        GLuint64 primitives = 0;
        gl::GetQueryObjectui64v(set.query, GL_QUERY_RESULT, &primitives);
        const uint64_t perPrimitive = mPrimitive == GL_TRIANGLES ? 3 : mPrimitive == GL_LINES ? 2 : 1;
        capture.vertices = primitives * perPrimitive;
    }
    return capture;
}

}  // namespace runtime
