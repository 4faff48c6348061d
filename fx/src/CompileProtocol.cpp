// CompileProtocol: see CompileProtocol.h.
#include "CompileProtocol.h"

#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <thread>

namespace fx {

namespace {

class Writer {
public:
    void u32(uint32_t v) {
        char b[4];
        std::memcpy(b, &v, 4);
        mOut.append(b, 4);
    }
    void str(const std::string& s) {
        u32(static_cast<uint32_t>(s.size()));
        mOut += s;
    }
    std::string take() { return std::move(mOut); }

private:
    std::string mOut;
};

// Every read is bounds-checked: a short or garbled payload fails the decode instead of reading past it.
class Reader {
public:
    explicit Reader(const std::string& in) : mIn(in) {}
    uint32_t u32() {
        if (mPos + 4 > mIn.size()) return fail();
        uint32_t v;
        std::memcpy(&v, mIn.data() + mPos, 4);
        mPos += 4;
        return v;
    }
    int i32() { return static_cast<int>(u32()); }
    std::string str() {
        uint32_t n = u32();
        if (!mOk || n > mIn.size() - mPos) {
            fail();
            return {};
        }
        std::string s = mIn.substr(mPos, n);
        mPos += n;
        return s;
    }
    // A count of items that each take at least `minBytes`: bounded by what is left.
    uint32_t count(size_t minBytes) {
        uint32_t n = u32();
        if (n > (mIn.size() - mPos) / minBytes) return fail();
        return n;
    }
    bool done() const { return mOk && mPos == mIn.size(); }

private:
    uint32_t fail() {
        mOk = false;
        mPos = mIn.size();
        return 0;
    }
    const std::string& mIn;
    size_t mPos = 0;
    bool mOk = true;
};

void writeProgram(Writer& w, const StageProgram& p) {
    w.str(p.glsl);
    w.str(p.uniformBlockName);
    w.u32(static_cast<uint32_t>(p.uniformBlockBinding));
    w.u32(p.uniformBlockSize);
    w.u32(static_cast<uint32_t>(p.uniforms.size()));
    for (const UniformBinding& u : p.uniforms) {
        w.str(u.name);
        w.u32(u.offset);
        w.u32(u.size);
        w.u32(u.arrayStride);
        w.u32(u.matrixStride);
        w.u32((u.hlslColumnsContiguous ? 1u : 0u) | (u.active ? 2u : 0u));
        // Reflection only: the types and components of the fields follow from the parameter's type.
        w.u32(static_cast<uint32_t>(u.fields.size()));
        for (const UniformField& field : u.fields) {
            w.str(field.path);
            w.u32(field.offset);
            w.u32(field.arrayStride);
            w.u32(field.matrixStride);
            w.u32(field.hlslColumnsContiguous ? 1u : 0u);
        }
    }
    w.u32(static_cast<uint32_t>(p.samplers.size()));
    for (const SamplerBinding& s : p.samplers) {
        w.str(s.glslName);
        w.u32(static_cast<uint32_t>(s.unit));
        w.u32((s.depthCompare ? 1u : 0u) | (s.read ? 2u : 0u));
        w.str(s.pairTexture);
        w.str(s.pairSampler);
    }
    w.u32(static_cast<uint32_t>(p.storageBuffers.size()));
    for (const StorageBufferBinding& b : p.storageBuffers) {
        w.str(b.glslName);
        w.u32(static_cast<uint32_t>(b.binding));
        w.u32(b.glStride);
        w.u32(b.d3dStride);
        w.u32(static_cast<uint32_t>(b.runs.size()));
        for (const StorageBufferBinding::Run& run : b.runs) {
            w.u32(run.d3dOffset);
            w.u32(run.glOffset);
            w.u32(run.bytes);
        }
        w.u32(static_cast<uint32_t>(b.counterBinding));
    }
    w.u32(static_cast<uint32_t>(p.images.size()));
    for (const ImageBinding& image : p.images) {
        w.str(image.glslName);
        w.str(image.format);
    }
    w.u32(static_cast<uint32_t>(p.inputs.size()));
    for (const VertexInput& i : p.inputs) {
        w.str(i.semantic);
        w.u32(static_cast<uint32_t>(i.location));
        w.u32(static_cast<uint32_t>(i.components));
        w.u32(static_cast<uint32_t>(i.stream.stream));
        w.u32(static_cast<uint32_t>(i.stream.index));
    }
    const StageEffects& e = p.effects;
    w.u32((e.discards ? 1u : 0u) | (e.writesDepth ? 2u : 0u) | (e.writesSampleMask ? 4u : 0u) |
          (e.writesImages ? 8u : 0u) | (e.writesBuffers ? 16u : 0u) | (e.atomics ? 32u : 0u) |
          (e.writesPointSize ? 64u : 0u) | (e.writesDiffuse ? 128u : 0u));
    w.u32(static_cast<uint32_t>(e.clipDistances));
}

void readProgram(Reader& r, StageProgram& p) {
    p.glsl = r.str();
    p.uniformBlockName = r.str();
    p.uniformBlockBinding = r.i32();
    p.uniformBlockSize = r.u32();
    p.uniforms.resize(r.count(28));
    for (UniformBinding& u : p.uniforms) {
        u.name = r.str();
        u.offset = r.u32();
        u.size = r.u32();
        u.arrayStride = r.u32();
        u.matrixStride = r.u32();
        uint32_t flags = r.u32();
        u.hlslColumnsContiguous = flags & 1u;
        u.active = flags & 2u;
        u.fields.resize(r.count(20));
        for (UniformField& field : u.fields) {
            field.path = r.str();
            field.offset = r.u32();
            field.arrayStride = r.u32();
            field.matrixStride = r.u32();
            field.hlslColumnsContiguous = r.u32() != 0;
        }
    }
    p.samplers.resize(r.count(20));
    for (SamplerBinding& s : p.samplers) {
        s.glslName = r.str();
        s.unit = r.i32();
        const uint32_t flags = r.u32();
        s.depthCompare = flags & 1u;
        s.read = flags & 2u;
        s.pairTexture = r.str();
        s.pairSampler = r.str();
    }
    p.storageBuffers.resize(r.count(16));
    for (StorageBufferBinding& b : p.storageBuffers) {
        b.glslName = r.str();
        b.binding = r.i32();
        b.glStride = r.u32();
        b.d3dStride = r.u32();
        b.runs.resize(r.count(12));
        for (StorageBufferBinding::Run& run : b.runs) {
            run.d3dOffset = r.u32();
            run.glOffset = r.u32();
            run.bytes = r.u32();
        }
        b.counterBinding = r.i32();
    }
    p.images.resize(r.count(8));
    for (ImageBinding& image : p.images) {
        image.glslName = r.str();
        image.format = r.str();
    }
    p.inputs.resize(r.count(20));
    for (VertexInput& i : p.inputs) {
        i.semantic = r.str();
        i.location = r.i32();
        i.components = r.i32();
        i.stream.stream = static_cast<VertexStream>(
            std::min<uint32_t>(r.u32(), static_cast<uint32_t>(VertexStream::BlendIndices)));
        i.stream.index = r.i32();
    }
    StageEffects& e = p.effects;
    const uint32_t effects = r.u32();
    e.discards = effects & 1u;
    e.writesDepth = effects & 2u;
    e.writesSampleMask = effects & 4u;
    e.writesImages = effects & 8u;
    e.writesBuffers = effects & 16u;
    e.atomics = effects & 32u;
    e.writesPointSize = effects & 64u;
    e.writesDiffuse = effects & 128u;
    e.clipDistances = std::clamp(r.i32(), 0, 8);
}

}  // namespace

std::string encodeJob(const StageJob& job) {
    Writer w;
    w.str(job.hlsl);
    w.u32(static_cast<uint32_t>(job.stage));
    w.str(job.entryPoint);
    w.str(job.cross.uniformBlockName);
    w.u32(static_cast<uint32_t>(job.cross.uniformBlockBinding));
    w.u32(static_cast<uint32_t>(job.cross.samplerUnits.size()));
    for (const auto& [name, unit] : job.cross.samplerUnits) {
        w.str(name);
        w.u32(static_cast<uint32_t>(unit));
    }
    for (const std::map<std::string, int>* bindings :
         {&job.cross.storageBindings, &job.cross.counterBindings}) {
        w.u32(static_cast<uint32_t>(bindings->size()));
        for (const auto& [name, binding] : *bindings) {
            w.str(name);
            w.u32(static_cast<uint32_t>(binding));
        }
    }
    w.u32(static_cast<uint32_t>(job.cross.depthSamplers.size()));
    for (const std::string& s : job.cross.depthSamplers) w.str(s);
    return w.take();
}

std::optional<StageJob> decodeJob(const std::string& payload) {
    Reader r(payload);
    StageJob job;
    job.hlsl = r.str();
    uint32_t stage = r.u32();
    job.stage =
        static_cast<ShaderStage>(std::min<uint32_t>(stage, static_cast<uint32_t>(ShaderStage::Compute)));
    job.entryPoint = r.str();
    job.cross.uniformBlockName = r.str();
    job.cross.uniformBlockBinding = r.i32();
    for (uint32_t i = 0, n = r.count(8); i < n; ++i) {
        std::string name = r.str();
        job.cross.samplerUnits[name] = r.i32();
    }
    for (std::map<std::string, int>* bindings : {&job.cross.storageBindings, &job.cross.counterBindings})
        for (uint32_t i = 0, n = r.count(8); i < n; ++i) {
            std::string name = r.str();
            (*bindings)[name] = r.i32();
        }
    job.cross.depthSamplers.resize(r.count(4));
    for (std::string& s : job.cross.depthSamplers) s = r.str();
    if (!r.done() || stage > static_cast<uint32_t>(ShaderStage::Compute)) return std::nullopt;
    return job;
}

std::string encodeOutcome(const StageOutcome& outcome) {
    Writer w;
    w.u32(static_cast<uint32_t>(outcome.status));
    w.u32(static_cast<uint32_t>(outcome.messages.size()));
    for (const HlslMessage& m : outcome.messages) {
        w.u32(m.error ? 1u : 0u);
        w.str(m.file);
        w.u32(static_cast<uint32_t>(m.line));
        w.u32(static_cast<uint32_t>(m.column));
        w.str(m.text);
    }
    w.str(outcome.crossError);
    writeProgram(w, outcome.program);
    return w.take();
}

std::optional<StageOutcome> decodeOutcome(const std::string& payload) {
    Reader r(payload);
    StageOutcome outcome;
    uint32_t status = r.u32();
    outcome.messages.resize(r.count(20));
    for (HlslMessage& m : outcome.messages) {
        m.error = r.u32() != 0;
        m.file = r.str();
        m.line = r.i32();
        m.column = r.i32();
        m.text = r.str();
    }
    outcome.crossError = r.str();
    readProgram(r, outcome.program);
    if (!r.done() || status > static_cast<uint32_t>(StageOutcome::Status::SanitizerReport))
        return std::nullopt;
    outcome.status = static_cast<StageOutcome::Status>(status);
    return outcome;
}

std::string frame(FrameKind kind, const std::string& payload) {
    Writer w;
    w.u32(kProtocolMagic);
    w.u32(kProtocolVersion);
    w.u32(static_cast<uint32_t>(kind));
    w.u32(static_cast<uint32_t>(payload.size()));
    return w.take() + payload;
}

std::optional<FrameHeader> parseFrameHeader(const char* header) {
    uint32_t v[4];
    std::memcpy(v, header, sizeof v);
    if (v[0] != kProtocolMagic || v[1] != kProtocolVersion || v[3] > kMaxFramePayload) return std::nullopt;
    if (v[2] != static_cast<uint32_t>(FrameKind::Request) && v[2] != static_cast<uint32_t>(FrameKind::Reply))
        return std::nullopt;
    return FrameHeader{static_cast<FrameKind>(v[2]), v[3]};
}

bool sendAll(int fd, const char* data, size_t size) {
    while (size > 0) {
        ssize_t n = send(fd, data, size, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        data += n;
        size -= static_cast<size_t>(n);
    }
    return true;
}

bool receiveAll(int fd, char* data, size_t size) {
    while (size > 0) {
        ssize_t n = read(fd, data, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        data += n;
        size -= static_cast<size_t>(n);
    }
    return true;
}

int serveCompileRequests(int fd, bool (*jobLeftNoFinding)()) {
    // For the tests of the time limit and of a worker killed mid-request only: a unit containing this
    // marker makes the worker hang instead of compiling.
    const char* hangMarker = std::getenv("SHADOWFX_COMPILE_WORKER_TEST_HANG");
    // For the tests of a crash of the HLSL compiler only: a unit containing this marker makes the worker
    // die of SIGSEGV, as glslang does on text it crashes on (the compiler refuses every such text it
    // knows before glslang sees it, so no real one is left to test with).
    const char* crashMarker = std::getenv("SHADOWFX_COMPILE_WORKER_TEST_CRASH");
    for (;;) {
        char header[kFrameHeaderBytes];
        if (!receiveAll(fd, header, sizeof header)) return 0;  // the compiler closed the stream: done
        std::optional<FrameHeader> h = parseFrameHeader(header);
        if (!h || h->kind != FrameKind::Request) return 2;
        std::string payload(h->payloadBytes, '\0');
        if (!receiveAll(fd, payload.data(), payload.size())) return 2;
        std::optional<StageJob> job = decodeJob(payload);
        if (!job) return 2;
        if (hangMarker && *hangMarker && job->hlsl.find(hangMarker) != std::string::npos)
            for (;;) std::this_thread::sleep_for(std::chrono::hours(1));
        if (crashMarker && *crashMarker && job->hlsl.find(crashMarker) != std::string::npos)
            std::raise(SIGSEGV);
        std::string reply = frame(FrameKind::Reply, encodeOutcome(compileStageInProcess(*job)));
        if (jobLeftNoFinding && !jobLeftNoFinding()) return kWorkerSanitizerExitStatus;
        if (!sendAll(fd, reply.data(), reply.size())) return 2;
    }
}

}  // namespace fx
