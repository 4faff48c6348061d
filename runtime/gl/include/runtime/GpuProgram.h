// GpuProgram: one compiled pass on the GPU: the linked GL program of its vertex and pixel stages, whose
// uniform blocks are packed from effect parameter values and compile arguments (UniformPacker) and
// uploaded through a UniformRing.
#pragma once

#include <runtime/GlApi.h>

#include <fx/CompiledEffect.h>
#include <fx/Diagnostics.h>
#include <fx/Value.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace runtime {

// A program of the runtime's own GLSL 4.50 (not an effect's: the host's scene material, the camera
// pre-pass of the visible-sample fits), vertex and fragment stages; 0 if either does not compile or they
// do not link, which only a driver without GLSL 4.50 gives.
GLuint linkRuntimeProgram(const char* vertexSource, const char* fragmentSource);

// Writes values into a std140 uniform block image as the reflection describes it.
class UniformPacker {
public:
    // Packs `value` (HLSL element order, see fx/Value.h) into `block` at the member's offset, honouring
    // array and matrix strides and the GLSL matrix orientation.
    static void pack(const fx::UniformBinding& member, const fx::Value& value, std::vector<uint8_t>& block);
};

// One persistently mapped uniform buffer that every draw's blocks are written to at a fresh offset. A
// per-program buffer updated with glBufferSubData makes the driver wait for (llvmpipe: flush) the draws
// still reading the old contents at every draw; writing ahead in a ring never touches bytes in flight.
// When the ring is full it fences, waits for the GPU to finish what it queued, and starts over: a new lap,
// whose writes overwrite the ranges of the laps before, bound or not.
class UniformRing {
public:
    UniformRing();
    ~UniformRing();
    UniformRing(const UniformRing&) = delete;
    UniformRing& operator=(const UniformRing&) = delete;

    // Copies `data` into the ring and binds that range to uniform block binding `binding`.
    void bindBlock(GLuint binding, const std::vector<uint8_t>& data);
    // How many times the ring has started over. A block bound in an earlier lap must be copied in again
    // before the next draw, even if its bytes did not change: what the ring wrote since may be on its range.
    uint64_t lap() const { return mLap; }

private:
    static constexpr size_t kCapacity = size_t(8) << 20;
    GLuint mBuffer = 0;
    uint8_t* mMapped = nullptr;
    size_t mHead = 0;
    size_t mAlignment = 256;
    uint64_t mLap = 0;
};

class GpuProgram {
public:
    // Which stages a program links. DepthOnly links the vertex stage alone, for a pass that writes no
    // colour: the rasterizer then writes depth (and stencil) without running a fragment program.
    enum class Stages { VertexAndPixel, DepthOnly };

    // Compiles and links the pass's GLSL. Returns nullptr and reports LinkError (with the driver's log)
    // at the pass's location on failure; on success, what the driver still said (warnings) is reported
    // there as DriverShaderLog, DriverFixedFunctionLog and DriverLinkLog notes.
    static std::unique_ptr<GpuProgram> create(const fx::CompiledPass& pass, fx::DiagnosticSink& diagnostics,
                                              Stages stages = Stages::VertexAndPixel);
    // The program of a pass's compute stage alone: what create() makes for a pass without graphics
    // stages, and the second program of a pass that sets both (FX11 dispatched one and drew the other).
    static std::unique_ptr<GpuProgram> createCompute(const fx::CompiledPass& pass,
                                                     fx::DiagnosticSink& diagnostics);

    // True if the pixel shader can change what a pass without colour writes leaves behind: it discards
    // (clip(), texkill, an alpha test written as clip), writes depth or the sample mask, or stores to
    // images or buffers. Only a pass whose pixel shader cannot may drop it (Stages::DepthOnly).
    static bool pixelShaderHasSideEffects(const fx::StageProgram& pixel);
    ~GpuProgram();
    GpuProgram(const GpuProgram&) = delete;
    GpuProgram& operator=(const GpuProgram&) = delete;

    bool hasShaders() const { return mProgram != 0; }

    // True for a compute pass's program: dispatched (glDispatchCompute), never drawn.
    bool isCompute() const { return mCompute; }

    // Makes the program current; the next upload() binds every stage's block whatever it holds.
    void bind();
    // Packs the stages' uniform blocks from `parameters` (one value per effect parameter) and `arguments`
    // (one value per CompiledPass::arguments entry) and uploads a block only where its bytes changed since
    // this program's last upload (per-pass values stay put between the draws of a pass), or where the ring
    // has started over since (UniformRing::lap).
    void upload(const std::vector<fx::Value>& parameters, const std::vector<fx::Value>& arguments,
                UniformRing& ring);

private:
    struct StageBlock {
        const fx::StageProgram* stage = nullptr;
        std::vector<uint8_t> data;
        std::vector<uint8_t> uploaded;  // what the bound range holds; empty = nothing bound yet
        uint64_t uploadedLap = 0;       // the ring's lap when it was bound
    };
    GpuProgram() = default;
    // Binds each stage's block whose bytes changed or whose range is from an earlier lap of the ring.
    void bindStaleBlocks(UniformRing& ring);

    GLuint mProgram = 0;
    StageBlock mBlocks[6];  // vertex, pixel, geometry, hull, domain, compute
    bool mCompute = false;
    bool mWritesPointSize = false;  // the stage before the rasterizer writes gl_PointSize (PSIZE)
    int mClipDistances = 0;         // gl_ClipDistance entries the vertex stage writes (SV_ClipDistance)
};

}  // namespace runtime
