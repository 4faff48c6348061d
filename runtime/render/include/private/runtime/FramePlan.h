// FramePlan: what one frame's scripts will do, recorded by a dry run before any GL work (EffectRenderer's
// PlanRecorder), and which of it the frame leaves out:
// - dead work: an operation none of whose writes is read later in the frame (or is the frame's colour,
//   the output) is skipped (backward liveness over the recorded operations; loops arrive unrolled);
// - unchanged shadow maps: a render target written only by light-port operations keeps last frame's
//   contents when the chain of operations that produced them is the same again (same signatures: pass,
//   light matrices, parameter values, render states, targets, the sampled textures' contents and the
//   scene's objects) and the receiver region each draw culled to last time contains this frame's.
//
// Contents are tracked as hashes: a full clear starts a new chain, every other write extends the chain
// of what the target held, so a target that accumulates over frames never matches and is always redrawn.
#pragma once

#include <runtime/IntersectionBody.h>
#include <runtime/RenderStateApplier.h>

#include <cstdint>
#include <functional>
#include <map>
#include <vector>

namespace fx {
struct CompiledEffect;
struct CompiledPass;
struct CompiledTechnique;
}  // namespace fx

namespace runtime {

// A resource an operation writes or reads: a texture parameter index, or the frame's own targets.
constexpr int kFrameColor = -1;
constexpr int kFrameDepth = -2;
// What a pass's draws write besides its targets: a stream-output pass's capture (its StreamOutBuffers),
// read by the passes that draw it (DrawAuto), and the storage buffers and images its shaders write
// (RWStructuredBuffer, RWTexture2D, ...), read by any later pass or dispatch. Always live, never cached:
// the next frame and the application read them too, and the plan does not follow them.
constexpr int kFirstPassOutput = -16;
constexpr int passOutputResource(size_t pass) {
    return kFirstPassOutput - static_cast<int>(pass);
}
constexpr bool isPassOutputResource(int resource) {
    return resource <= kFirstPassOutput;
}
// Whether a graphics stage of `pass` may write a storage buffer or an image: the stage effects the
// compiler read from its SPIR-V (a read-only StructuredBuffer or ByteAddressBuffer writes nothing).
bool passWritesStorage(const fx::CompiledPass& pass);

// Why an operation does not run: nothing reads what it writes, its targets already hold its result, or
// the scene does not need it (its pass's `LeaveOutWhen` annotation, or a cascade draw whose depth slice
// holds no receiver).
enum class LeftOut { No, Dead, Cached, Scene };

struct PlannedOp {
    enum class Kind { ClearColor, ClearDepth, ClearStencil, DrawGeometry, DrawBuffer };
    Kind kind = Kind::ClearColor;
    size_t pass = 0;             // the pass's index in its technique
    bool hostScene = false;      // the host's scene drawn at ScriptExternal, by none of the passes' programs
    bool lightPort = false;      // RenderPort names a light
    std::vector<int> writes;     // targets it changes
    std::vector<int> reads;      // sampled textures, and a draw's bound targets (blending, depth test)
    uint64_t signature = 0;      // what decides the written contents, besides the targets' old contents
    ReceiverRegion region;       // light draws: where the camera's receivers read (before the decision)
    bool sceneSaysSkip = false;  // the pass's LeaveOutWhen condition holds, or a cascade's slice is empty
    bool wholeTarget = true;     // a clear of the whole target (false: one cascade's tile, a partial write)
    RenderStateBlock states;     // draws: the pass's render states, evaluated once by the dry run

    // Decisions (FramePlan::decide)
    LeftOut leftOut = LeftOut::No;
    bool cullToReceivers = true;  // light draws: cull to `region`; false: to the whole light frustum

    bool isDraw() const { return kind == Kind::DrawGeometry || kind == Kind::DrawBuffer; }
};

// What a target held after the last frame that wrote it, kept by the renderer between frames.
struct TargetHistory {
    uint64_t contents = 0;                // chain hash
    std::vector<ReceiverRegion> regions;  // per draw of the chain, the region its casters covered
};

class FramePlan {
public:
    // The frame's operations, in script order (add() and finishRecording() build them).
    std::vector<PlannedOp> ops;

    // Starts recording a frame's operations. The plan is kept between frames: the operations, their lists
    // and the working tables below keep their storage, so planning a frame like the last allocates nothing.
    void beginRecording() { mRecorded = 0; }
    // A new operation after those recorded, at its defaults (its lists empty).
    PlannedOp& add();
    // Drops what the last frame recorded beyond this one's operations.
    void finishRecording() { ops.resize(mRecorded); }

    // Marks dead and cached operations. `history` is the renderer's record of its targets (updated by
    // commit()); `identity(resource)` hashes a target's allocation (size, format, GL name) so that a
    // reallocated target never matches. With `leaveOut` false nothing is left out.
    // Marks operations the scene does not need (LeaveOutWhen) and dead ones. `outputs`: what the frame
    // must leave behind besides its colour (FrameOptions::outputTargets).
    void markDead(const std::vector<int>& outputs, bool leaveOut);
    // Then marks cached operations (see above) and chooses light draws' culling regions.
    void decide(const std::map<int, TargetHistory>& history, const std::function<uint64_t(int)>& identity,
                bool leaveOut);
    // After the frame ran: records what the executed operations left in their targets.
    void commit(std::map<int, TargetHistory>& history) const;

private:
    // What the plan knows of one resource, kept between frames (the frames of one technique use the same
    // few resources).
    struct Track {
        int resource = 0;
        bool live = false;                    // markDead: read by an operation after the current one
        bool known = false;                   // decide: `contents` holds something
        uint64_t contents = 0;                // decide: its chain hash so far; after decide, its final one
        std::vector<size_t> chain;            // decide: the operations writing it, in order
        bool eligible = false;                // decide: its operations may be left out (Cached)
        std::vector<ReceiverRegion> regions;  // after decide: its draws' regions, if redrawn
    };
    // The resource's track, added the first time (a reference valid until the next call).
    Track& track(int resource);

    size_t mRecorded = 0;
    std::vector<Track> mTracks;
    std::vector<int> mWritten;  // decide: the targets written this frame, ascending
    std::vector<int> mRedrawn;  // targets whose operations ran
};

// Whether a pass of the technique enables the stencil test (a state a preshader computes counts as yes).
// When none does, no draw reads a stencil value, so a depth clear clears the stencil bits with it (one
// whole-texel clear instead of a masked one: a quarter of llvmpipe's rasterizer time on a 2048² D24S8
// map) and overwrites its whole target; when one does, a depth clear keeps stencil, a partial write.
bool techniqueTestsStencil(const fx::CompiledTechnique& technique);

// 64-bit hash combining (splitmix64 finalizer over the running value and each word).
uint64_t hashCombine(uint64_t seed, uint64_t value);
uint64_t hashBytes(uint64_t seed, const void* data, size_t size);

}  // namespace runtime
