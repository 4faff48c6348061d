// PassUse: see PassUse.h.
#include "PassUse.h"

#include <algorithm>

namespace runtime {

bool PassUse::projectsWith(const Light* portLight, const SemanticBinder& binder) const {
    if (readsPortMatrix) return true;
    return portLight && std::any_of(lightMatrices.begin(), lightMatrices.end(),
                                    [&](int slot) { return binder.slotLight(slot) == portLight; });
}

std::vector<bool> passValueReads(const fx::CompiledPass& pass, size_t count) {
    std::vector<bool> used(count, false);
    const auto mark = [&](const fx::PreshaderProgram& program) {
        for (size_t p : program.inputs())
            if (p < count) used[p] = true;
    };
    for (const fx::StageProgram* stage :
         {&pass.vertex, &pass.hull, &pass.domain, &pass.geometry, &pass.fragment, &pass.compute})
        for (const fx::UniformBinding& member : stage->uniforms)
            if (member.active && member.source == fx::UniformBinding::Source::Parameter &&
                member.index < count)
                used[member.index] = true;
    for (const fx::RenderStateSetting& setting : pass.states) mark(setting.value);
    for (const fx::CompileArgument& argument : pass.arguments) mark(argument.value);
    return used;
}

std::vector<PassUse> passUses(const fx::CompiledTechnique& technique, size_t count,
                              const SemanticBinder& binder) {
    std::vector<PassUse> uses;
    for (const fx::CompiledPass& pass : technique.passes) {
        PassUse use;
        use.used = passValueReads(pass, count);
        for (const fx::CompileArgument& argument : pass.arguments) {
            const std::vector<size_t>& inputs = argument.value.inputs();
            const bool perObject = std::any_of(inputs.begin(), inputs.end(),
                                               [&binder](size_t p) { return binder.isPerObject(p); });
            use.argumentPerObject.push_back(perObject);
            use.argumentPerPass.push_back(!perObject);
            use.anyArgumentPerObject = use.anyArgumentPerObject || perObject;
        }
        use.viewDerived.assign(count, false);
        for (size_t p = 0; p < count; ++p) use.viewDerived[p] = use.used[p] && binder.derivesFromView(p);
        use.viewRebound = use.viewDerived;
        for (size_t a = 0; a < pass.arguments.size(); ++a) {
            if (!use.argumentPerObject[a]) continue;
            for (size_t p : pass.arguments[a].value.inputs())
                if (p < count && binder.isPerObject(p)) use.viewRebound[p] = true;
        }
        for (size_t p = 0; p < count; ++p) {
            if (!use.used[p]) continue;
            if (!binder.isPerObject(p)) use.perPassParameters.push_back(p);
            int light = -1;
            if (!binder.projectionSource(p, light)) continue;
            if (light >= 0) {
                use.lightMatrices.push_back(light);
            } else {
                use.readsPortMatrix = true;
            }
        }
        uses.push_back(std::move(use));
    }
    return uses;
}

}  // namespace runtime
