// PoolMembership: see PoolMembership.h.
#include "PoolMembership.h"

#include "EffectResources.h"

namespace runtime {

bool PoolMembership::join(std::shared_ptr<EffectPool> pool, const EffectResources& resources,
                          fx::DiagnosticSink& diagnostics) {
    mPool = std::move(pool);
    if (!mPool) return true;
    bool ok = true;
    const std::vector<fx::ParameterInfo>& parameters = resources.parameterInfo();
    for (size_t i = 0; i < parameters.size(); ++i) {
        if (!parameters[i].isShared) continue;
        fx::TypeDesc existing;
        EffectPool::Slot* slot =
            mPool->join(parameters[i].name, parameters[i].type, resources.values[i], existing);
        if (!slot) {
            diagnostics.report(fx::DiagId::PoolSharedTypeMismatch, parameters[i].loc,
                               {parameters[i].name, parameters[i].type.hlslName(), existing.hlslName()});
            ok = false;
            continue;
        }
        mShared.push_back({i, slot, 0});
    }
    return ok;
}

void PoolMembership::published(const EffectResources& resources, size_t index) {
    for (Shared& shared : mShared) {
        if (shared.parameter != index) continue;
        EffectPool::publish(*shared.slot, resources.values[index]);
        shared.seen = shared.slot->generation;
    }
}

void PoolMembership::pull(EffectResources& resources) {
    for (Shared& shared : mShared) {
        if (shared.slot->generation == shared.seen) continue;
        resources.values.pin(shared.parameter, shared.slot->value);
        shared.seen = shared.slot->generation;
    }
}

}  // namespace runtime
