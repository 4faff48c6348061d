// EffectPool: see runtime/EffectPool.h.
#include <runtime/EffectPool.h>

namespace runtime {

EffectPool::Slot* EffectPool::join(const std::string& name, const fx::TypeDesc& type,
                                   const fx::Value& initial, fx::TypeDesc& existing) {
    auto [it, inserted] = mSlots.try_emplace(name);
    Slot& slot = it->second;
    if (inserted) {
        slot.type = type;
        slot.value = initial;
        slot.generation = 1;
        return &slot;
    }
    if (slot.type.hlslName() != type.hlslName()) {
        existing = slot.type;
        return nullptr;
    }
    return &slot;
}

void EffectPool::publish(Slot& slot, const fx::Value& value) {
    // The value again (an application's setter each frame, a script's loop of one) changes nothing, so
    // that the other effects' values keep their change stamps and the passes leave-out cached on them.
    if (slot.value.data == value.data && slot.value.string == value.string) return;
    slot.value = value;
    ++slot.generation;
}

const EffectPool::Slot* EffectPool::find(const std::string& name) const {
    auto it = mSlots.find(name);
    return it == mSlots.end() ? nullptr : &it->second;
}

}  // namespace runtime
