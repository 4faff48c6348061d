// EffectSamplers: see EffectSamplers.h.
#include "EffectSamplers.h"

namespace runtime {

EffectSamplers::EffectSamplers(const fx::CompiledEffect& effect) {
    for (const fx::SamplerDesc& desc : effect.samplers) {
        mSamplers.emplace(desc.parameter, SamplerObject(desc, false));
        mComparisonSamplers.emplace(desc.parameter, SamplerObject(desc, true));
    }
    for (const fx::SamplerDesc& desc : effect.passSamplers) {
        mPassSamplers.emplace_back(desc, false);
        mPassComparisonSamplers.emplace_back(desc, true);
    }
}

void EffectSamplers::bind(const fx::SamplerBinding& binding) const {
    const auto passSampler = static_cast<size_t>(binding.passSampler);
    const auto& passSamplers = binding.depthCompare ? mPassComparisonSamplers : mPassSamplers;
    const auto& samplers = binding.depthCompare ? mComparisonSamplers : mSamplers;
    auto sampler = samplers.find(binding.samplerParameter);
    if (binding.passSampler >= 0 && passSampler < passSamplers.size()) {
        passSamplers[passSampler].bind(binding.unit);  // the states the pass sets on its register
    } else if (sampler != samplers.end()) {
        sampler->second.bind(binding.unit);
    } else {
        SamplerObject::unbind(binding.unit);
    }
}

}  // namespace runtime
