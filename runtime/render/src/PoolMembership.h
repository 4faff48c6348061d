// PoolMembership: an effect's side of its EffectPool (runtime/EffectPool.h): which of its parameters are
// shared, which value of each it holds, and the two moves between its values and the pool's.
#pragma once

#include <runtime/EffectPool.h>

#include <fx/CompiledEffect.h>
#include <fx/Diagnostics.h>

#include <memory>
#include <vector>

namespace runtime {

class EffectResources;

class PoolMembership {
public:
    // Joins `pool` with every `shared` parameter of the effect. False, with a diagnostic at the parameter,
    // where the pool holds one of them with another type.
    bool join(std::shared_ptr<EffectPool> pool, const EffectResources& resources,
              fx::DiagnosticSink& diagnostics);
    // After the effect set parameter `index`: the pool gets its value if it is shared.
    void published(const EffectResources& resources, size_t index);
    // Before the effect draws: the values other effects of the pool set since, pinned as the application's.
    void pull(EffectResources& resources);

private:
    struct Shared {
        size_t parameter = 0;
        EffectPool::Slot* slot = nullptr;  // in mPool, found by name once, when the effect joined
        uint64_t seen = 0;                 // the pool generation the effect's value is
    };
    std::shared_ptr<EffectPool> mPool;
    std::vector<Shared> mShared;
};

}  // namespace runtime
