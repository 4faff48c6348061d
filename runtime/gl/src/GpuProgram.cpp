#include <runtime/GpuProgram.h>

#include <algorithm>
#include <cstring>
#include <string>

namespace runtime {

// [SECTION] UniformPacker

namespace {

void writeScalar(std::vector<uint8_t>& block, size_t offset, fx::BaseType base, float value) {
    if (offset + 4 > block.size()) return;  // reflection and type disagree: never write out of bounds
    // glslang stores HLSL bools in uniform blocks as 32-bit uints, ints as ints.
    if (base == fx::BaseType::Bool || base == fx::BaseType::UInt) {
        const uint32_t bits =
            base == fx::BaseType::Bool ? (value != 0.0f ? 1u : 0u) : static_cast<uint32_t>(value);
        std::memcpy(block.data() + offset, &bits, 4);
    } else if (base == fx::BaseType::Int) {
        const int32_t bits = static_cast<int32_t>(value);
        std::memcpy(block.data() + offset, &bits, 4);
    } else {
        std::memcpy(block.data() + offset, &value, 4);
    }
}

// Packs `type`'s numbers, value.data from `first` on, at `offset` in the block: arrays by `arrayStride`,
// matrices by `matrixStride` in the orientation the block stores them.
void packNumbers(const fx::TypeDesc& type, size_t offset, uint32_t arrayStride, uint32_t matrixStride,
                 bool hlslColumnsContiguous, const fx::Value& value, size_t first,
                 std::vector<uint8_t>& block) {
    const int rows = type.shape == fx::Shape::Matrix ? type.rows : 1;
    const int cols = type.shape == fx::Shape::Scalar ? 1 : type.cols;
    const size_t perElement = static_cast<size_t>(rows * cols);
    int elements = 1;
    for (int dim : type.arrayDims) elements *= dim;

    // Floats whose every component the value holds and the block has room for (the per-object matrices a
    // batched pass packs for every visible object): the same bytes without the per-component checks and
    // conversions below.
    const bool matrix = type.shape == fx::Shape::Matrix;
    const size_t rowStep = !matrix ? 0 : hlslColumnsContiguous ? 4 : matrixStride;
    const size_t colStep = matrix && hlslColumnsContiguous ? matrixStride : 4;
    const size_t extent = rows > 0 && cols > 0 ? static_cast<size_t>(rows - 1) * rowStep +
                                                     static_cast<size_t>(cols - 1) * colStep + 4
                                               : 0;
    if (type.base == fx::BaseType::Float && elements > 0 && extent > 0 &&
        first + static_cast<size_t>(elements) * perElement <= value.data.size() &&
        offset + static_cast<size_t>(elements - 1) * arrayStride + extent <= block.size()) {
        const float* from = value.data.data() + first;
        for (int e = 0; e < elements; ++e) {
            uint8_t* element = block.data() + offset + static_cast<size_t>(e) * arrayStride;
            for (int r = 0; r < rows; ++r)
                for (int c = 0; c < cols; ++c, ++from)
                    std::memcpy(element + static_cast<size_t>(r) * rowStep + static_cast<size_t>(c) * colStep,
                                from, 4);
        }
        return;
    }

    for (int e = 0; e < elements; ++e) {
        const size_t elementOffset = offset + static_cast<size_t>(e) * arrayStride;
        for (int r = 0; r < rows; ++r) {
            for (int c = 0; c < cols; ++c) {
                const size_t source =
                    first + static_cast<size_t>(e) * perElement + static_cast<size_t>(r * cols + c);
                const float component = source < value.data.size() ? value.data[source] : 0.0f;
                size_t at = elementOffset;
                if (type.shape == fx::Shape::Matrix) {
                    at += hlslColumnsContiguous
                              ? static_cast<size_t>(c) * matrixStride + static_cast<size_t>(r) * 4
                              : static_cast<size_t>(r) * matrixStride + static_cast<size_t>(c) * 4;
                } else {
                    at += static_cast<size_t>(c) * 4;
                }
                writeScalar(block, at, type.base, component);
            }
        }
    }
}

}  // namespace

void UniformPacker::pack(const fx::UniformBinding& member, const fx::Value& value,
                         std::vector<uint8_t>& block) {
    if (member.type.base == fx::BaseType::Struct) {
        for (const fx::UniformField& field : member.fields)
            packNumbers(field.type, member.offset + field.offset, field.arrayStride, field.matrixStride,
                        field.hlslColumnsContiguous, value, field.firstComponent, block);
        return;
    }
    packNumbers(member.type, member.offset, member.arrayStride, member.matrixStride,
                member.hlslColumnsContiguous, value, 0, block);
}

// [SECTION] GpuProgram

namespace {

std::string shaderInfoLog(GLuint shader) {
    GLint length = 0;
    gl::GetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    if (length <= 1) return {};
    std::string info(static_cast<size_t>(length), '\0');
    gl::GetShaderInfoLog(shader, length, nullptr, info.data());
    return info.c_str();
}

std::string programInfoLog(GLuint program) {
    GLint length = 0;
    gl::GetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    if (length <= 1) return {};
    std::string info(static_cast<size_t>(length), '\0');
    gl::GetProgramInfoLog(program, length, nullptr, info.data());
    return info.c_str();
}

// What the driver says about a shader that compiled or a program that linked (Mesa's "0:37(42): warning:
// `x' used uninitialized"): one note per line at the pass, naming the shader (`id` and `args`, the line
// last), since its line numbers are the generated GLSL's. The CLI prints them on request only (--driver-log).
void reportDriverLog(const std::string& log, fx::DiagId id, std::vector<std::string> args,
                     const fx::CompiledPass& pass, fx::DiagnosticSink& diagnostics) {
    args.emplace_back();
    size_t start = 0;
    while (start < log.size()) {
        size_t end = log.find('\n', start);
        if (end == std::string::npos) end = log.size();
        std::string line = log.substr(start, end - start);
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
        if (!line.empty()) {
            args.back() = line;
            diagnostics.report(id, pass.loc, args);
        }
        start = end + 1;
    }
}

GLuint compileRuntimeShader(GLenum kind, const char* source) {
    const GLuint shader = gl::CreateShader(kind);
    gl::ShaderSource(shader, 1, &source, nullptr);
    gl::CompileShader(shader);
    GLint ok = GL_FALSE;
    gl::GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        gl::DeleteShader(shader);
        return 0;
    }
    return shader;
}

// `stage` is null for the fixed-function pixel stage's stand-in.
GLuint compileShader(GLenum kind, const std::string& source, const fx::StageProgram* stage,
                     const fx::CompiledPass& pass, std::string& errors, fx::DiagnosticSink& diagnostics) {
    GLuint shader = gl::CreateShader(kind);
    const char* text = source.c_str();
    gl::ShaderSource(shader, 1, &text, nullptr);
    gl::CompileShader(shader);
    GLint ok = GL_FALSE;
    gl::GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    const std::string log = shaderInfoLog(shader);
    if (!ok) {
        errors += log;
        gl::DeleteShader(shader);
        return 0;
    }
    if (stage)
        reportDriverLog(log, fx::DiagId::DriverShaderLog,
                        {std::string(fx::shaderStageName(stage->stage)), stage->entryPoint, pass.name}, pass,
                        diagnostics);
    else
        reportDriverLog(log, fx::DiagId::DriverFixedFunctionLog, {pass.name}, pass, diagnostics);
    return shader;
}

}  // namespace

std::unique_ptr<GpuProgram> GpuProgram::create(const fx::CompiledPass& pass, fx::DiagnosticSink& diagnostics,
                                               Stages stages) {
    if (!pass.compute.glsl.empty() && pass.vertex.glsl.empty()) return createCompute(pass, diagnostics);
    std::unique_ptr<GpuProgram> program(new GpuProgram());
    if (pass.vertex.glsl.empty()) return program;  // a pass of script commands only

    // A vertex shader without a pixel shader (`PixelShader = NULL;`, or none assigned) ran D3D9's
    // fixed-function pixel stage, which with no texture stage set outputs the interpolated diffuse
    // colour: COLOR0 (varying location 8, fx/src/SemanticTables.cpp) where the vertex shader writes it,
    // else D3D's default diffuse, white.
    const std::string fixedFunctionPixels =
        pass.vertex.effects.writesDiffuse
            ? "#version 450\nlayout(location = 8) in vec4 fx_v8;\nlayout(location = 0) out vec4 "
              "fx_color;\nvoid main() { fx_color = fx_v8; }\n"
            : "#version 450\nlayout(location = 0) out vec4 fx_color;\nvoid main() { fx_color = "
              "vec4(1.0); }\n";
    const std::string& fragment = pass.fragment.glsl.empty() ? fixedFunctionPixels : pass.fragment.glsl;

    // A stream-output pass that rasterizes nothing (D3D10's NULL pixel shader) links no fragment stage.
    const bool withPixel = stages == Stages::VertexAndPixel &&
                           !(pass.streamOut && !pass.streamOut->rasterizes && pass.fragment.glsl.empty());
    std::string log;
    const GLuint vs = compileShader(GL_VERTEX_SHADER, pass.vertex.glsl, &pass.vertex, pass, log, diagnostics);
    const GLuint fs = withPixel ? compileShader(GL_FRAGMENT_SHADER, fragment,
                                                pass.fragment.glsl.empty() ? nullptr : &pass.fragment, pass,
                                                log, diagnostics)
                                : 0;
    // D3D10's geometry shader runs in both variants: it decides what is rasterized.
    const bool withGeometry = !pass.geometry.glsl.empty();
    const GLuint gs = withGeometry ? compileShader(GL_GEOMETRY_SHADER, pass.geometry.glsl, &pass.geometry,
                                                   pass, log, diagnostics)
                                   : 0;
    // So do D3D11's hull and domain shaders (GL's tessellation stages); the effect compiler has made sure
    // a pass has both or neither.
    const bool withTessellation = !pass.hull.glsl.empty() && !pass.domain.glsl.empty();
    const GLuint tcs = withTessellation ? compileShader(GL_TESS_CONTROL_SHADER, pass.hull.glsl, &pass.hull,
                                                        pass, log, diagnostics)
                                        : 0;
    const GLuint tes = withTessellation ? compileShader(GL_TESS_EVALUATION_SHADER, pass.domain.glsl,
                                                        &pass.domain, pass, log, diagnostics)
                                        : 0;
    if (vs && (fs || !withPixel) && (gs || !withGeometry) && ((tcs && tes) || !withTessellation)) {
        program->mProgram = gl::CreateProgram();
        gl::AttachShader(program->mProgram, vs);
        if (tcs) gl::AttachShader(program->mProgram, tcs);
        if (tes) gl::AttachShader(program->mProgram, tes);
        if (gs) gl::AttachShader(program->mProgram, gs);
        if (fs) gl::AttachShader(program->mProgram, fs);
        // D3D10's stream output: the declaration's outputs, skips and buffer breaks, as the compiler
        // resolved them (fx::StreamOutput), captured interleaved per buffer.
        if (pass.streamOut) {
            std::vector<const char*> varyings;
            for (const std::string& name : pass.streamOut->varyings) varyings.push_back(name.c_str());
            gl::TransformFeedbackVaryings(program->mProgram, static_cast<GLsizei>(varyings.size()),
                                          varyings.data(), GL_INTERLEAVED_ATTRIBS);
        }
        gl::LinkProgram(program->mProgram);
        GLint ok = GL_FALSE;
        gl::GetProgramiv(program->mProgram, GL_LINK_STATUS, &ok);
        if (!ok) {
            log += programInfoLog(program->mProgram);
            gl::DeleteProgram(program->mProgram);
            program->mProgram = 0;
        } else {
            reportDriverLog(programInfoLog(program->mProgram), fx::DiagId::DriverLinkLog, {pass.name}, pass,
                            diagnostics);
        }
    }
    if (vs) gl::DeleteShader(vs);
    if (fs) gl::DeleteShader(fs);
    if (gs) gl::DeleteShader(gs);
    if (tcs) gl::DeleteShader(tcs);
    if (tes) gl::DeleteShader(tes);
    if (!program->mProgram) {
        diagnostics.report(fx::DiagId::LinkError, pass.loc, {pass.name, log});
        return nullptr;
    }

    // SV_ClipDistance: GL clips only against the planes enabled, so enable those the program writes.
    program->mClipDistances = pass.vertex.effects.clipDistances;
    // PSIZE: the last stage before the rasterizer sizes its points (D3D9 took PSIZE over the PointSize
    // state); GL does so only with GL_PROGRAM_POINT_SIZE, and a program that does not write gl_PointSize
    // then has undefined sizes, so it is enabled for the programs that write it and no others.
    const fx::StageProgram& rasterized = withGeometry       ? pass.geometry
                                         : withTessellation ? pass.domain
                                                            : pass.vertex;
    program->mWritesPointSize = rasterized.effects.writesPointSize;
    const fx::StageProgram* linked[5] = {
        &pass.vertex, withPixel ? &pass.fragment : nullptr, withGeometry ? &pass.geometry : nullptr,
        withTessellation ? &pass.hull : nullptr, withTessellation ? &pass.domain : nullptr};
    // Every sampler, image and storage block is declared at its unit or binding point in the GLSL
    // (layout(binding)): the program is bound by no name.
    for (int i = 0; i < 5; ++i) {
        StageBlock& block = program->mBlocks[i];
        block.stage = linked[i];
        if (!linked[i] || linked[i]->uniformBlockSize == 0 || linked[i]->uniformBlockBinding < 0) continue;
        block.data.assign(linked[i]->uniformBlockSize, 0);
    }
    return program;
}

std::unique_ptr<GpuProgram> GpuProgram::createCompute(const fx::CompiledPass& pass,
                                                      fx::DiagnosticSink& diagnostics) {
    // Compute shaders are core OpenGL 4.3; the runtime's contexts are 4.5 (runtime/GlApi.h loads its core
    // functions or none), so no context that gets here lacks them.
    std::unique_ptr<GpuProgram> program(new GpuProgram());
    std::string log;
    const GLuint cs =
        compileShader(GL_COMPUTE_SHADER, pass.compute.glsl, &pass.compute, pass, log, diagnostics);
    if (cs) {
        program->mProgram = gl::CreateProgram();
        gl::AttachShader(program->mProgram, cs);
        gl::LinkProgram(program->mProgram);
        gl::DeleteShader(cs);
        GLint ok = GL_FALSE;
        gl::GetProgramiv(program->mProgram, GL_LINK_STATUS, &ok);
        if (!ok) {
            log += programInfoLog(program->mProgram);
            gl::DeleteProgram(program->mProgram);
            program->mProgram = 0;
        }
    }
    if (!program->mProgram) {
        diagnostics.report(fx::DiagId::LinkError, pass.loc, {pass.name, log});
        return nullptr;
    }
    program->mCompute = true;
    StageBlock& block = program->mBlocks[5];
    block.stage = &pass.compute;
    if (pass.compute.uniformBlockSize > 0 && pass.compute.uniformBlockBinding >= 0)
        block.data.assign(pass.compute.uniformBlockSize, 0);
    return program;
}

bool GpuProgram::pixelShaderHasSideEffects(const fx::StageProgram& pixel) {
    const fx::StageEffects& e = pixel.effects;
    return e.discards || e.writesDepth || e.writesSampleMask || e.writesImages || e.writesBuffers ||
           e.atomics;
}

GpuProgram::~GpuProgram() {
    if (mProgram) gl::DeleteProgram(mProgram);
}

void GpuProgram::bind() {
    gl::UseProgram(mProgram);
    for (int i = 0; i < 8; ++i) {
        if (i < mClipDistances)
            gl::Enable(GL_CLIP_DISTANCE0 + static_cast<GLenum>(i));
        else
            gl::Disable(GL_CLIP_DISTANCE0 + static_cast<GLenum>(i));
    }
    if (mWritesPointSize)
        gl::Enable(GL_PROGRAM_POINT_SIZE);
    else
        gl::Disable(GL_PROGRAM_POINT_SIZE);
    for (StageBlock& block : mBlocks) block.uploaded.clear();
}

void GpuProgram::upload(const std::vector<fx::Value>& parameters, const std::vector<fx::Value>& arguments,
                        UniformRing& ring) {
    for (StageBlock& block : mBlocks) {
        if (block.data.empty()) continue;
        for (const fx::UniformBinding& member : block.stage->uniforms) {
            if (!member.active) continue;  // the code never reads it
            const std::vector<fx::Value>& source =
                member.source == fx::UniformBinding::Source::Parameter ? parameters : arguments;
            if (member.index < source.size()) UniformPacker::pack(member, source[member.index], block.data);
        }
    }
    const uint64_t lap = ring.lap();
    bindStaleBlocks(ring);
    // Binding one block may start the ring over; a block this call left bound from the lap before may lie
    // where the new lap writes next: bind it again before the draw (once: the blocks together are far
    // smaller than the ring).
    if (ring.lap() != lap) bindStaleBlocks(ring);
}

void GpuProgram::bindStaleBlocks(UniformRing& ring) {
    for (StageBlock& block : mBlocks) {
        if (block.data.empty()) continue;
        if (block.uploaded == block.data && block.uploadedLap == ring.lap()) continue;
        ring.bindBlock(static_cast<GLuint>(block.stage->uniformBlockBinding), block.data);
        block.uploaded = block.data;
        block.uploadedLap = ring.lap();
    }
}

// [SECTION] UniformRing

UniformRing::UniformRing() {
    GLint alignment = 0;
    gl::GetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &alignment);
    if (alignment > 0) mAlignment = static_cast<size_t>(alignment);
    gl::GenBuffers(1, &mBuffer);
    gl::BindBuffer(GL_UNIFORM_BUFFER, mBuffer);
    const GLbitfield flags = GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
    gl::BufferStorage(GL_UNIFORM_BUFFER, static_cast<GLsizeiptr>(kCapacity), nullptr, flags);
    mMapped = static_cast<uint8_t*>(
        gl::MapBufferRange(GL_UNIFORM_BUFFER, 0, static_cast<GLsizeiptr>(kCapacity), flags));
    gl::BindBuffer(GL_UNIFORM_BUFFER, 0);
}

UniformRing::~UniformRing() {
    if (!mBuffer) return;
    if (mMapped) {
        gl::BindBuffer(GL_UNIFORM_BUFFER, mBuffer);
        gl::UnmapBuffer(GL_UNIFORM_BUFFER);
        gl::BindBuffer(GL_UNIFORM_BUFFER, 0);
    }
    gl::DeleteBuffers(1, &mBuffer);
}

void UniformRing::bindBlock(GLuint binding, const std::vector<uint8_t>& data) {
    const size_t size = (data.size() + mAlignment - 1) / mAlignment * mAlignment;
    if (!mMapped || size > kCapacity) return;
    if (mHead + size > kCapacity) {
        // Everything queued so far may still read the ring: wait for it before overwriting.
        GLsync fence = gl::FenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
        while (gl::ClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, 1'000'000'000) == GL_TIMEOUT_EXPIRED) {
        }
        gl::DeleteSync(fence);
        mHead = 0;
        ++mLap;
    }
    std::memcpy(mMapped + mHead, data.data(), data.size());
    gl::BindBufferRange(GL_UNIFORM_BUFFER, binding, mBuffer, static_cast<GLintptr>(mHead),
                        static_cast<GLsizeiptr>(data.size()));
    mHead += size;
}

GLuint linkRuntimeProgram(const char* vertexSource, const char* fragmentSource) {
    const GLuint vertex = compileRuntimeShader(GL_VERTEX_SHADER, vertexSource);
    const GLuint fragment = compileRuntimeShader(GL_FRAGMENT_SHADER, fragmentSource);
    GLuint program = 0;
    if (vertex && fragment) {
        program = gl::CreateProgram();
        gl::AttachShader(program, vertex);
        gl::AttachShader(program, fragment);
        gl::LinkProgram(program);
        GLint linked = GL_FALSE;
        gl::GetProgramiv(program, GL_LINK_STATUS, &linked);
        if (!linked) {
            gl::DeleteProgram(program);
            program = 0;
        }
    }
    if (vertex) gl::DeleteShader(vertex);
    if (fragment) gl::DeleteShader(fragment);
    return program;
}

}  // namespace runtime
