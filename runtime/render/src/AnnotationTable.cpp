// AnnotationTable: see AnnotationTable.h.
#include "AnnotationTable.h"

#include <fx/Effect.h>
#include <fx/Preshader.h>
#include <fx/RenderStates.h>

namespace runtime {

namespace {

// Annotations hold literals (a number, a string, a vector's initializer list): evaluated without
// parameters, converted to the annotation's declared type. One that does not evaluate is left out, as the
// compiler reported it.
AnnotationTable::List evaluate(const std::vector<fx::Annotation>& annotations) {
    AnnotationTable::List list;
    for (const fx::Annotation& annotation : annotations) {
        const bool text = annotation.type.base == fx::BaseType::String;
        std::optional<fx::Value> value = fx::evaluate(
            annotation.value, [](std::string_view) -> const fx::Value* { return nullptr; },
            text ? nullptr : &annotation.type, nullptr);
        if (!value) continue;
        if (text) value->type = annotation.type;
        list.emplace_back(annotation.name, std::move(*value));
    }
    return list;
}

const AnnotationTable::List& emptyList() {
    static const AnnotationTable::List empty;
    return empty;
}

}  // namespace

AnnotationTable::AnnotationTable(const fx::CompiledEffect& effect) {
    mParameters.resize(effect.parameters.size());
    mTechniques.resize(effect.techniques.size());
    mPasses.resize(effect.techniques.size());
    if (!effect.effect) return;
    const fx::Effect& tree = *effect.effect;
    for (size_t i = 0; i < effect.parameters.size() && i < tree.parameters.size(); ++i)
        mParameters[i] = evaluate(tree.parameters[i].annotations);
    for (size_t t = 0; t < effect.techniques.size(); ++t) {
        const fx::CompiledTechnique& compiled = effect.techniques[t];
        // By name: a technique compiled alone, or after one the compiler left out, has another index.
        const std::string key = compiled.group.empty() ? compiled.name : compiled.group + "." + compiled.name;
        const fx::Technique* technique = tree.findTechnique(key);
        mPasses[t].resize(compiled.passes.size());
        if (!technique) continue;
        mTechniques[t] = evaluate(technique->annotations);
        for (size_t p = 0; p < compiled.passes.size() && p < technique->passes.size(); ++p)
            mPasses[t][p] = evaluate(technique->passes[p].annotations);
    }
}

const AnnotationTable::List& AnnotationTable::parameter(size_t index) const {
    return index < mParameters.size() ? mParameters[index] : emptyList();
}

const AnnotationTable::List& AnnotationTable::technique(size_t index) const {
    return index < mTechniques.size() ? mTechniques[index] : emptyList();
}

const AnnotationTable::List& AnnotationTable::pass(size_t technique, size_t pass) const {
    return technique < mPasses.size() && pass < mPasses[technique].size() ? mPasses[technique][pass]
                                                                          : emptyList();
}

EffectAnnotation AnnotationTable::find(const List& list, std::string_view name) {
    for (const EffectAnnotation& annotation : list)
        if (fx::equalsIgnoreCase(annotation.name(), name)) return annotation;
    return {};
}

EffectAnnotation AnnotationTable::at(const List& list, size_t index) {
    return index < list.size() ? list[index] : EffectAnnotation{};
}

}  // namespace runtime
