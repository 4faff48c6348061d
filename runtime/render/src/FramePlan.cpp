#include <private/runtime/FramePlan.h>

#include <fx/CompiledEffect.h>

#include <algorithm>
#include <cstring>
#include <set>

namespace runtime {

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

void FramePlan::markDead(const std::vector<int>& outputs, bool leaveOut) {
    // Dead work: backward liveness from the frame's colour. Colour and depth clears overwrite their targets
    // entirely; draws read theirs (PlannedOp::reads).
    if (leaveOut) {
        for (PlannedOp& op : ops)
            if (op.sceneSaysSkip) op.leftOut = LeftOut::Scene;
        std::set<int> live(outputs.begin(), outputs.end());
        live.insert(kFrameColor);
        for (auto op = ops.rbegin(); op != ops.rend(); ++op) {
            if (op->leftOut != LeftOut::No) continue;
            const bool needed = std::any_of(op->writes.begin(), op->writes.end(), [&](int w) {
                return live.count(w) > 0 || isStreamOutResource(w);
            });
            if (!needed) {
                op->leftOut = LeftOut::Dead;
                continue;
            }
            if ((op->kind == PlannedOp::Kind::ClearColor || op->kind == PlannedOp::Kind::ClearDepth) &&
                op->wholeTarget)
                for (int w : op->writes) live.erase(w);
            live.insert(op->reads.begin(), op->reads.end());
        }
    }
}

void FramePlan::decide(const std::map<int, TargetHistory>& history,
                       const std::function<uint64_t(int)>& identity, bool leaveOut) {
    // Contents: chain hashes per target, forward over what will run.
    std::map<int, uint64_t> contents;
    for (const auto& [resource, record] : history) contents[resource] = record.contents;
    std::map<int, std::vector<size_t>> chains;  // per target, the operations writing it, in order
    for (size_t i = 0; i < ops.size(); ++i) {
        PlannedOp& op = ops[i];
        if (op.leftOut != LeftOut::No) continue;
        uint64_t signature = op.signature;
        for (int r : op.reads) {
            auto it = contents.find(r);
            signature = hashCombine(signature, it == contents.end() ? 0 : it->second);
        }
        const bool overwrites =
            (op.kind == PlannedOp::Kind::ClearColor || op.kind == PlannedOp::Kind::ClearDepth) &&
            op.wholeTarget;
        for (int w : op.writes) {
            const uint64_t before = overwrites ? 0 : (contents.count(w) ? contents[w] : 0x5eedull);
            contents[w] = hashCombine(hashCombine(before, identity(w)), signature);
            chains[w].push_back(i);
        }
    }

    // Unchanged targets: written only from light ports, nobody else reads them in the middle of their
    // chain, the same chain as what they hold, and regions that still cover this frame's receivers.
    std::set<int> eligible;
    if (leaveOut) {
        for (const auto& [target, chain] : chains) {
            if (target < 0) continue;
            auto past = history.find(target);
            if (past == history.end() || past->second.contents != contents[target]) continue;
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
            if (ok) eligible.insert(target);
        }
        // An operation is left out only if everything it writes is; one that must run spoils its targets.
        for (bool changed = true; changed;) {
            changed = false;
            for (const PlannedOp& op : ops) {
                if (op.leftOut != LeftOut::No || op.writes.empty()) continue;
                const bool all = std::all_of(op.writes.begin(), op.writes.end(),
                                             [&](int w) { return eligible.count(w) > 0; });
                if (all) continue;
                for (int w : op.writes) changed = eligible.erase(w) > 0 || changed;
            }
        }
    }

    mFinalContents.clear();
    mRegions.clear();
    mRedrawn.clear();
    for (const auto& [target, chain] : chains) {
        if (eligible.count(target)) {
            for (size_t i : chain) ops[i].leftOut = LeftOut::Cached;
            continue;
        }
        mRedrawn.push_back(target);
        mFinalContents[target] = contents[target];
        // Redrawn although only the receivers moved out of the old region: cover the whole light frustum,
        // so that the map serves every later viewpoint.
        auto past = history.find(target);
        const bool onlyRegionsDiffer = past != history.end() && past->second.contents == contents[target];
        for (size_t i : chain) {
            PlannedOp& op = ops[i];
            if (!op.isDraw()) continue;
            if (!leaveOut || !op.lightPort || op.kind == PlannedOp::Kind::DrawBuffer)
                op.cullToReceivers = false;
            if (onlyRegionsDiffer) op.cullToReceivers = false;
        }
    }
    // Regions are recorded after every target's decision: an operation writing two targets uses one.
    for (const auto& [target, chain] : chains) {
        if (eligible.count(target)) continue;
        for (size_t i : chain)
            if (ops[i].isDraw())
                mRegions[target].push_back(ops[i].cullToReceivers ? ops[i].region : fullLightRegion());
    }
}

void FramePlan::commit(std::map<int, TargetHistory>& history) const {
    for (int target : mRedrawn) {
        TargetHistory& record = history[target];
        record.contents = mFinalContents.at(target);
        auto regions = mRegions.find(target);
        record.regions = regions == mRegions.end() ? std::vector<ReceiverRegion>{} : regions->second;
    }
}

}  // namespace runtime
