// Compiler: a D3D9 pass's sampler-register states (`MinFilter[0] = LINEAR;`, `AddressU[1] = CLAMP;`,
// `Texture[0] = <t>;`, `Sampler[0] = (s);`) on the samplers of its pixel shader they reach.
//
// D3D9 addressed samplers by register: the states of stage N are those of whichever sampler the pixel
// shader has bound to sN. fxc gave each sampler the shader uses the register its `register(sN)` names,
// and the others the lowest free ones in declaration order. D3DX applied a pass's states in source order,
// and setting the pixel shader set the states its samplers' sampler_state blocks list: a register state
// before `PixelShader = ...` holds where the sampler's block does not set that state, one after it
// always.
#include "Compiler.h"
#include "StateAssignments.h"

#include <algorithm>
#include <set>

namespace fx::detail {

namespace {

// The D3D9 register of each sampler parameter the stage samples through a combined sampler.
std::map<size_t, int> samplerRegisters(const Effect& effect, const StageProgram& stage) {
    std::set<size_t> used;
    for (const SamplerBinding& b : stage.samplers)
        if (b.pairTexture.empty() && b.samplerParameter != kNoSampler && b.read)
            used.insert(b.samplerParameter);
    std::map<size_t, int> registers;
    std::set<int> taken;
    for (size_t parameter : used)
        if (const int reg = effect.parameters[parameter].samplerRegister; reg >= 0) {
            registers[parameter] = reg;
            taken.insert(reg);
        }
    int next = 0;
    for (size_t parameter : used) {  // parameter indices are declaration order
        if (registers.count(parameter)) continue;
        while (taken.count(next)) ++next;
        registers[parameter] = next;
        taken.insert(next);
    }
    return registers;
}

}  // namespace

void Compiler::passSamplerStates() {
    for (const auto& [slot, source] : mSamplerRegisterPasses)
        if (slot.technique < mOut->techniques.size() &&
            slot.pass < mOut->techniques[slot.technique].passes.size())
            passSamplerStates(*source, mOut->techniques[slot.technique].passes[slot.pass]);
}

void Compiler::passSamplerStates(const Pass& source, CompiledPass& pass) {
    size_t pixelShaderAt = source.states.size();
    for (size_t i = 0; i < source.states.size(); ++i)
        if (findRenderState(source.states[i].name) == RenderStateId::PixelShader) pixelShaderAt = i;
    const std::map<size_t, int> registers = samplerRegisters(mEffect, pass.fragment);
    for (const auto& [parameter, reg] : registers) {
        const SamplerDesc* own = mOut->findSampler(parameter);
        if (!own) continue;
        const Parameter& sampler = mEffect.parameters[parameter];
        SamplerDesc desc = *own;
        std::optional<size_t> texture;
        bool set = false, hasComparison = false;
        // Whether the sampler's own block sets a state: setting the pixel shader then overrode the pass's.
        auto ownBlockSets = [&](const std::string& name) {
            return std::any_of(sampler.samplerState.begin(), sampler.samplerState.end(),
                               [&](const StateAssignment& a) {
                                   const std::optional<SamplerStateId> id = findSamplerState(a.name);
                                   return id && id == findSamplerState(name);
                               });
        };
        for (size_t i = 0; i < source.states.size(); ++i) {
            const StateAssignment& state = source.states[i];
            if (state.index != reg || findRenderState(state.name) || !isSamplerRegisterState(state.name))
                continue;
            const bool beforeShader = i < pixelShaderAt;
            // `Sampler[N] = (s);` sets the states s's block lists, and s's texture.
            std::vector<const StateAssignment*> assignments;
            if (state.name == "Sampler") {
                if (const Parameter* other = mEffect.findParameter(state.value.text))
                    for (const StateAssignment& a : other->samplerState) assignments.push_back(&a);
            } else {
                assignments.push_back(&state);
            }
            for (const StateAssignment* a : assignments) {
                if (beforeShader && ownBlockSets(a->name)) continue;
                if (findSamplerState(a->name) == SamplerStateId::Texture) {
                    auto it = mIndex.find(a->value.text);
                    if (it != mIndex.end()) texture = it->second;
                    set = true;
                    continue;
                }
                applySamplerState(*a, sampler.type.base, desc, hasComparison);
                set = true;
            }
        }
        if (!set) continue;
        if (hasComparison && desc.comparisonFunc == 0) desc.comparisonFunc = 4;  // LESSEQUAL
        const int index = static_cast<int>(mOut->passSamplers.size());
        mOut->passSamplers.push_back(desc);
        for (SamplerBinding& b : pass.fragment.samplers) {
            if (!b.pairTexture.empty() || b.samplerParameter != parameter) continue;
            b.passSampler = index;
            if (texture) b.textureParameter = texture;
        }
    }
}

}  // namespace fx::detail
