// PassPreshaders: see PassPreshaders.h.
#include "PassPreshaders.h"

namespace runtime {

PassPreshaders::PassPreshaders(const fx::CompiledPass& pass)
    : mPass(&pass),
      mStateResults(pass.states.size()),
      mArgumentResults(pass.arguments.size()),
      mStates(RenderStateBlock::defaults()) {}

const fx::Value* PassPreshaders::run(const fx::PreshaderProgram& program, Result& result,
                                     const std::vector<fx::Value>& values, const ParameterStamps& stamps,
                                     fx::DiagnosticSink& diagnostics) {
    const std::vector<size_t>& inputs = program.inputs();
    bool current = result.valid && result.inputStamps.size() == inputs.size();
    for (size_t i = 0; current && i < inputs.size(); ++i)
        current = inputs[i] < stamps.stamps.size() && result.inputStamps[i] == stamps.stamps[inputs[i]];
    if (current) return result.failed ? nullptr : &result.value;
    result.inputStamps.resize(inputs.size());
    for (size_t i = 0; i < inputs.size(); ++i)
        result.inputStamps[i] = inputs[i] < stamps.stamps.size() ? stamps.stamps[inputs[i]] : 0;
    const fx::Value* value = program.run(values, mRegisters, &diagnostics);
    result.failed = !value;
    if (value) result.value = *value;
    result.valid = true;
    ++mRuns;
    return value ? &result.value : nullptr;
}

const RenderStateBlock& PassPreshaders::states(const std::vector<fx::Value>& values,
                                               const ParameterStamps& stamps,
                                               fx::DiagnosticSink& diagnostics) {
    for (size_t i = 0; i < mPass->states.size(); ++i) {
        const fx::RenderStateSetting& setting = mPass->states[i];
        if (setting.constant) {
            mStates.set(setting.id, *setting.constant);
            continue;
        }
        const fx::Value* value = run(setting.value, mStateResults[i], values, stamps, diagnostics);
        mStates.set(setting.id, value ? value->asFloat() : RenderStateBlock::defaults().get(setting.id));
    }
    return mStates;
}

void PassPreshaders::arguments(const std::vector<fx::Value>& values, const ParameterStamps& stamps,
                               const std::vector<bool>* which, std::vector<fx::Value>& arguments,
                               fx::DiagnosticSink& diagnostics) {
    arguments.resize(mPass->arguments.size());
    for (size_t i = 0; i < mPass->arguments.size(); ++i) {
        if (which && !(*which)[i]) continue;
        const fx::CompileArgument& argument = mPass->arguments[i];
        const fx::Value* value = run(argument.value, mArgumentResults[i], values, stamps, diagnostics);
        // Assigned, not built and moved: the argument keeps its storage.
        if (value)
            arguments[i] = *value;
        else
            arguments[i] = fx::zeroValue(argument.type);
    }
}

}  // namespace runtime
