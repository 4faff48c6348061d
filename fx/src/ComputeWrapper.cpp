// ComputeWrapper: the `fx_main` of a compute shader's unit (see StageWrapper.h). A compute shader has no
// varyings to rebuild: the wrapper repeats the user's [numthreads] (glslang turns it into GL's
// local_size), takes the system values the user's function takes under their own semantics, and calls it
// with the compile expression's uniform arguments.
#include "StageWrapper.h"

#include "SemanticTables.h"

namespace fx {

namespace {

// The thread and group ids D3D11 gives a compute shader; GL has each as a built-in
// (gl_GlobalInvocationID, gl_WorkGroupID, gl_LocalInvocationID, gl_LocalInvocationIndex).
bool isComputeSystemValue(const std::string& semantic) {
    const std::string s = canonicalSemantic(semantic);
    return s == "SV_DISPATCHTHREADID" || s == "SV_GROUPID" || s == "SV_GROUPTHREADID" || s == "SV_GROUPINDEX";
}

}  // namespace

bool WrapperBuilder::buildCompute(std::string& globals, std::string& wrapper) {
    const FunctionAttribute* threads = mFn.attribute("numthreads");
    if (!threads) return fail(DiagId::ComputeNumThreadsMissing, mFn.loc, {mFn.name});
    std::string params, callArgs;
    size_t uniformIndex = 0;
    for (size_t i = 0; i < mFn.params.size(); ++i) {
        const FunctionParam& p = mFn.params[i];
        std::string arg;
        if (p.isUniform) {
            if (!uniformArgument(p, uniformIndex++, arg, globals)) return false;
        } else {
            if (p.direction != FunctionParam::Direction::In || !isComputeSystemValue(p.semantic) ||
                p.type.base == BaseType::Struct || !p.type.arrayDims.empty())
                return fail(DiagId::ComputeParameterUnsupported, p.loc, {p.name});
            arg = "fx_p" + std::to_string(i);
            params +=
                (params.empty() ? "" : ",\n    ") + hlslTypeName(p.type) + " " + arg + " : " + p.semantic;
        }
        callArgs += (i ? ", " : "") + arg;
    }
    if (!everyArgumentTaken(uniformIndex)) return false;
    wrapper += "[numthreads(" + threads->argument + ")]\nvoid " + std::string(kWrapperEntryPoint) + "(" +
               (params.empty() ? "" : "\n    " + params) + ")\n{\n";
    wrapper += "    " + mFn.name + "(" + callArgs + ");\n}\n";
    return true;
}

}  // namespace fx
