// EffectPool: effects created in one pool share the values of their parameters declared `shared`, as
// D3DXCreateEffectPool and FX11's effect pools did: setting a shared parameter through one effect (a
// variable's setter, EffectRenderer::setParameter) changes what every effect of the pool draws with it
// from its next apply(), commitChanges() or render() on.
//
//     auto pool = std::make_shared<runtime::EffectPool>();
//     auto shadow = runtime::EffectRenderer::create(shadowEffect, diagnostics, pool);
//     auto scene = runtime::EffectRenderer::create(sceneEffect, diagnostics, pool);
//     shadow->variable("LightViewProjection").setMatrix(lightMatrix);  // `shared float4x4 ...` in both
//
// Parameters are shared by name; every effect of the pool must declare a shared parameter with the same
// type. The first effect to declare one gives the pool its initial value. The pool lives while any of its
// effects does. Not thread-safe: one context's effects, as the rest of the runtime.
#pragma once

#include <fx/Types.h>
#include <fx/Value.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>

namespace runtime {

class EffectPool {
public:
    // A shared parameter's current value and how often it was set (0: never, not even initialised).
    struct Slot {
        fx::TypeDesc type;
        fx::Value value;
        uint64_t generation = 0;
    };

    // What an effect joining the pool calls for each shared parameter: the slot of `name`, made with
    // `initial` if no effect declared it yet; nullptr where another effect declared it with another type
    // (its type is then in `existing`).
    Slot* join(const std::string& name, const fx::TypeDesc& type, const fx::Value& initial,
               fx::TypeDesc& existing);
    // A new value of a shared parameter, in the slot join() gave (a member's setter calls it, through the
    // slot it holds: by no name).
    static void publish(Slot& slot, const fx::Value& value);
    // The slot of `name`, or nullptr if no effect of the pool declares it.
    const Slot* find(const std::string& name) const;

private:
    std::map<std::string, Slot> mSlots;
};

}  // namespace runtime
