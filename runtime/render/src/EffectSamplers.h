// EffectSamplers: the GL sampler objects of an effect's samplers and of its passes' sampler-register
// states (fx::CompiledEffect::passSamplers), each made once at load in a plain and a depth-comparing form
// (a shader may sample the same sampler both ways) and unchanged after: binding one looks nothing up by
// name and creates nothing.
#pragma once

#include <fx/CompiledEffect.h>
#include <runtime/SamplerObject.h>

#include <map>
#include <vector>

namespace runtime {

class EffectSamplers {
public:
    EffectSamplers() = default;  // an effect without samplers
    explicit EffectSamplers(const fx::CompiledEffect& effect);

    // Binds what the binding samples through on its unit: the pass's states on that register where the
    // pass sets them, else the sampler parameter's, else none (GL's default sampling of the texture).
    void bind(const fx::SamplerBinding& binding) const;

private:
    std::map<size_t, SamplerObject> mSamplers;  // by sampler parameter index
    std::map<size_t, SamplerObject> mComparisonSamplers;
    std::vector<SamplerObject> mPassSamplers;  // by SamplerBinding::passSampler
    std::vector<SamplerObject> mPassComparisonSamplers;
};

}  // namespace runtime
