// PassPreshaders: one compiled pass's preshader programs (fx/PreshaderProgram.h: its expression-valued
// render states and its compile arguments) with their last results. A program runs again only when a
// parameter it reads has changed since its last run (ParameterStamps), the way FX11's EffectRuntime
// re-evaluates a state only when its inputs changed; constant states are folded by the compiler.
#pragma once

#include <runtime/RenderStateApplier.h>
#include "SemanticBinder.h"

#include <fx/CompiledEffect.h>
#include <fx/Diagnostics.h>
#include <fx/Value.h>

#include <cstdint>
#include <vector>

namespace runtime {

class PassPreshaders {
public:
    explicit PassPreshaders(const fx::CompiledPass& pass);

    // The pass's render states over `values` (every state the pass does not set at its D3D9 default). A
    // failing state expression is reported and leaves its state at the default.
    const RenderStateBlock& states(const std::vector<fx::Value>& values, const ParameterStamps& stamps,
                                   fx::DiagnosticSink& diagnostics);

    // Runs the compile arguments `which` selects (one flag per CompiledPass::arguments entry; null: all)
    // into `arguments` (sized to the pass's arguments); a failing one gives a zero of its type.
    void arguments(const std::vector<fx::Value>& values, const ParameterStamps& stamps,
                   const std::vector<bool>* which, std::vector<fx::Value>& arguments,
                   fx::DiagnosticSink& diagnostics);

    // Programs run so far (tests: a program whose inputs did not change is not run again).
    uint64_t runs() const { return mRuns; }

private:
    struct Result {
        bool valid = false;
        std::vector<uint64_t> inputStamps;  // the stamps of the program's inputs when it last ran
        bool failed = false;
        fx::Value value;  // copied from the registers: assigned again, it keeps its storage
    };
    // The program's value (nullptr: it failed), run again only if one of its inputs' stamps differs from
    // its last run's.
    const fx::Value* run(const fx::PreshaderProgram& program, Result& result,
                         const std::vector<fx::Value>& values, const ParameterStamps& stamps,
                         fx::DiagnosticSink& diagnostics);

    const fx::CompiledPass* mPass;
    fx::PreshaderProgram::Registers mRegisters;  // shared by the pass's programs, which run one at a time
    std::vector<Result> mStateResults;           // per CompiledPass::states entry
    std::vector<Result> mArgumentResults;        // per CompiledPass::arguments entry
    RenderStateBlock mStates;
    uint64_t mRuns = 0;
};

}  // namespace runtime
