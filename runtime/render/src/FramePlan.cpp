#include <private/runtime/FramePlan.h>

#include <fx/CompiledEffect.h>

#include <algorithm>
#include <cstring>

namespace runtime {

bool passWritesStorage(const fx::CompiledPass& pass) {
    for (const fx::StageProgram* stage :
         {&pass.vertex, &pass.hull, &pass.domain, &pass.geometry, &pass.fragment}) {
        const fx::StageEffects& e = stage->effects;
        if (e.writesBuffers || e.writesImages || e.atomics) return true;
    }
    return false;
}

uint64_t hashCombine(uint64_t seed, uint64_t value) {
    uint64_t z = seed ^ (value + 0x9E3779B97F4A7C15ull + (seed << 6) + (seed >> 2));
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

uint64_t hashBytes(uint64_t seed, const void* data, size_t size) {
    const auto* bytes = static_cast<const uint8_t*>(data);
    size_t i = 0;
    for (; i + 8 <= size; i += 8) {
        uint64_t word;
        std::memcpy(&word, bytes + i, 8);
        seed = hashCombine(seed, word);
    }
    uint64_t tail = size;
    for (; i < size; ++i) tail = (tail << 8) | bytes[i];
    return hashCombine(seed, tail);
}

bool techniqueTestsStencil(const fx::CompiledTechnique& technique) {
    for (const fx::CompiledPass& pass : technique.passes)
        for (const fx::RenderStateSetting& setting : pass.states)
            if ((setting.id == fx::RenderStateId::StencilEnable ||
                 setting.id == fx::RenderStateId::TwoSidedStencilMode) &&
                setting.constant.value_or(1.0) != 0.0)
                return true;
    return false;
}

PlannedOp& FramePlan::add() {
    if (mRecorded == ops.size()) {
        ops.emplace_back();
    } else {
        // The last frame's operation at this place, reset with its lists' storage.
        PlannedOp& op = ops[mRecorded];
        std::vector<int> writes = std::move(op.writes), reads = std::move(op.reads);
        op = PlannedOp{};
        writes.clear();
        reads.clear();
        op.writes = std::move(writes);
        op.reads = std::move(reads);
    }
    return ops[mRecorded++];
}

FramePlan::Track& FramePlan::track(int resource) {
    for (Track& track : mTracks)
        if (track.resource == resource) return track;
    Track& track = mTracks.emplace_back();
    track.resource = resource;
    return track;
}

void FramePlan::markDead(const std::vector<int>& outputs, bool leaveOut) {
    // Dead work: backward liveness from the frame's colour. Colour and depth clears overwrite their targets
    // entirely; draws read theirs (PlannedOp::reads).
    if (leaveOut) {
        for (PlannedOp& op : ops)
            if (op.sceneSaysSkip) op.leftOut = LeftOut::Scene;
        for (Track& track : mTracks) track.live = false;
        for (int output : outputs) track(output).live = true;
        track(kFrameColor).live = true;
        for (auto op = ops.rbegin(); op != ops.rend(); ++op) {
            if (op->leftOut != LeftOut::No) continue;
            const bool needed = std::any_of(op->writes.begin(), op->writes.end(),
                                            [&](int w) { return track(w).live || isPassOutputResource(w); });
            if (!needed) {
                op->leftOut = LeftOut::Dead;
                continue;
            }
            if ((op->kind == PlannedOp::Kind::ClearColor || op->kind == PlannedOp::Kind::ClearDepth) &&
                op->wholeTarget)
                for (int w : op->writes) track(w).live = false;
            for (int r : op->reads) track(r).live = true;
        }
    }
}

void FramePlan::decide(const std::map<int, TargetHistory>& history,
                       const std::function<uint64_t(int)>& identity, bool leaveOut) {
    // Contents: chain hashes per target, forward over what will run.
    for (Track& track : mTracks) {
        track.known = false;
        track.chain.clear();
        track.eligible = false;
    }
    for (const auto& [resource, record] : history) {
        Track& past = track(resource);
        past.known = true;
        past.contents = record.contents;
    }
    mWritten.clear();
    for (size_t i = 0; i < ops.size(); ++i) {
        PlannedOp& op = ops[i];
        if (op.leftOut != LeftOut::No) continue;
        uint64_t signature = op.signature;
        for (int r : op.reads) {
            const Track& read = track(r);
            signature = hashCombine(signature, read.known ? read.contents : 0);
        }
        const bool overwrites =
            (op.kind == PlannedOp::Kind::ClearColor || op.kind == PlannedOp::Kind::ClearDepth) &&
            op.wholeTarget;
        for (int w : op.writes) {
            Track& written = track(w);
            const uint64_t before = overwrites ? 0 : (written.known ? written.contents : 0x5eedull);
            written.contents = hashCombine(hashCombine(before, identity(w)), signature);
            written.known = true;
            if (written.chain.empty()) mWritten.push_back(w);
            written.chain.push_back(i);
        }
    }
    std::sort(mWritten.begin(), mWritten.end());

    // Unchanged targets: written only from light ports, nobody else reads them in the middle of their
    // chain, the same chain as what they hold, and regions that still cover this frame's receivers.
    if (leaveOut) {
        for (int target : mWritten) {
            if (target < 0) continue;
            Track& written = track(target);
            const std::vector<size_t>& chain = written.chain;
            auto past = history.find(target);
            if (past == history.end() || past->second.contents != written.contents) continue;
            bool ok = std::all_of(chain.begin(), chain.end(), [&](size_t i) { return ops[i].lightPort; });
            for (size_t i = chain.front(); ok && i <= chain.back(); ++i) {
                const bool inChain = std::find(chain.begin(), chain.end(), i) != chain.end();
                // An operation already left out (dead, or a sub-view without receivers) reads nothing.
                const bool runs = ops[i].leftOut == LeftOut::No;
                const auto& reads = ops[i].reads;
                if (!inChain && runs && std::find(reads.begin(), reads.end(), target) != reads.end())
                    ok = false;
            }
            size_t draw = 0;
            for (size_t i : chain) {
                if (!ok || !ops[i].isDraw()) continue;
                ok = draw < past->second.regions.size() && past->second.regions[draw].contains(ops[i].region);
                ++draw;
            }
            written.eligible = ok;
        }
        // An operation is left out only if everything it writes is; one that must run spoils its targets.
        for (bool changed = true; changed;) {
            changed = false;
            for (const PlannedOp& op : ops) {
                if (op.leftOut != LeftOut::No || op.writes.empty()) continue;
                const bool all =
                    std::all_of(op.writes.begin(), op.writes.end(), [&](int w) { return track(w).eligible; });
                if (all) continue;
                for (int w : op.writes) {
                    Track& written = track(w);
                    changed = written.eligible || changed;
                    written.eligible = false;
                }
            }
        }
    }

    mRedrawn.clear();
    for (int target : mWritten) {
        const Track& written = track(target);
        if (written.eligible) {
            for (size_t i : written.chain) ops[i].leftOut = LeftOut::Cached;
            continue;
        }
        mRedrawn.push_back(target);
        // Redrawn although only the receivers moved out of the old region: cover the whole light frustum,
        // so that the map serves every later viewpoint.
        auto past = history.find(target);
        const bool onlyRegionsDiffer = past != history.end() && past->second.contents == written.contents;
        for (size_t i : written.chain) {
            PlannedOp& op = ops[i];
            if (!op.isDraw()) continue;
            if (!leaveOut || !op.lightPort || op.kind == PlannedOp::Kind::DrawBuffer)
                op.cullToReceivers = false;
            if (onlyRegionsDiffer) op.cullToReceivers = false;
        }
    }
    // Regions are recorded after every target's decision: an operation writing two targets uses one.
    for (int target : mRedrawn) {
        Track& written = track(target);
        written.regions.clear();
        for (size_t i : written.chain)
            if (ops[i].isDraw())
                written.regions.push_back(ops[i].cullToReceivers ? ops[i].region : fullLightRegion());
    }
}

void FramePlan::commit(std::map<int, TargetHistory>& history) const {
    for (int target : mRedrawn) {
        const auto written = std::find_if(mTracks.begin(), mTracks.end(),
                                          [&](const Track& track) { return track.resource == target; });
        TargetHistory& record = history[target];
        record.contents = written->contents;
        record.regions = written->regions;
    }
}

}  // namespace runtime
