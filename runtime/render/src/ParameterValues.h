// ParameterValues: an effect's parameter values, each with its change stamp and its pinned flag, changed
// only through the methods below. What the preshaders and uniform uploads skip by (FX11's EffectRuntime
// re-evaluates only what changed) depends on every write touching its stamp, and what semantics may
// overwrite on every value the application set being pinned; keeping the three together, behind one set of
// writers, is what keeps those true.
#pragma once

#include "SemanticBinder.h"

#include <fx/CompiledEffect.h>
#include <runtime/Scene.h>

#include <span>
#include <vector>

namespace runtime {

class ParameterValues {
public:
    // Empty: a copy that copyFrom() fills (the dry run's, kept between frames for its storage).
    ParameterValues() = default;
    // One value per parameter: `initial` where the compiler gave one, zero for a float parameter without
    // one; none pinned, every stamp 0. `parameters` outlives this object (the compiled effect's).
    ParameterValues(const std::vector<fx::ParameterInfo>& parameters, const std::vector<fx::Value>& initial);

    size_t size() const { return mValues.size(); }
    const fx::Value& operator[](size_t index) const { return mValues[index]; }
    const fx::Value& at(size_t index) const { return mValues.at(index); }
    // All values, one per parameter: what preshaders, uploads and the binder's fits read.
    const std::vector<fx::Value>& all() const { return mValues; }
    const ParameterStamps& stamps() const { return mStamps; }
    // Set by the application (or its pool): the semantics no longer overwrite it.
    bool isPinned(size_t index) const { return mPinned.at(index); }

    // Stores `value` as parameter `index` (its type becomes the parameter's; a value with fewer components
    // than the type is broadcast, as HLSL broadcasts a scalar) and touches that parameter's stamp alone.
    // The one way values change, whether a script, a pool or the application sets them.
    void store(size_t index, fx::Value value);
    // The same for a scalar (a script's loop index), broadcast into the value's own storage: a frame that
    // stores it again allocates nothing.
    void storeScalar(size_t index, float scalar);
    // store(), and the value pinned: what the application's setters and a pool's shared values do.
    void pin(size_t index, fx::Value value);
    // pin() of a value that holds `componentCount` numbers, `components` written from number `first` on
    // (the rest as they were): in the value's own storage, so that setting it again allocates nothing.
    void pinComponents(size_t index, size_t componentCount, size_t first, std::span<const float> components);
    // Writes the values `binder` binds by semantic (SemanticBinder::bind), leaving the pinned ones, and
    // touches the stamps of those whose value changed.
    void bindSemantics(const SemanticBinder& binder, const RenderPortView& port, const SceneObject* object,
                       float time, SemanticBinder::Scope scope, const std::vector<bool>* used);
    // Becomes a copy of `other`, element by element so that a copy kept between frames reuses its storage.
    // Stamps keep `other`'s clock: a stamp the copy gives is never one `other` gives.
    void copyFrom(const ParameterValues& other);

private:
    const std::vector<fx::ParameterInfo>* mParameters = nullptr;
    std::vector<fx::Value> mValues;  // one per parameter
    std::vector<bool> mPinned;       // one per parameter
    ParameterStamps mStamps;         // one per parameter
};

}  // namespace runtime
