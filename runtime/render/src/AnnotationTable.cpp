// AnnotationTable: see AnnotationTable.h.
#include "AnnotationTable.h"

#include <fx/RenderStates.h>

namespace runtime {

namespace {

AnnotationTable::List handles(const fx::Annotations& annotations) {
    AnnotationTable::List list;
    for (const fx::AnnotationValue& annotation : annotations)
        list.emplace_back(annotation.name, annotation.value);
    return list;
}

const AnnotationTable::List& emptyList() {
    static const AnnotationTable::List empty;
    return empty;
}

}  // namespace

AnnotationTable::AnnotationTable(const fx::CompiledEffect& effect) {
    for (const fx::ParameterInfo& parameter : effect.parameters)
        mParameters.push_back(handles(parameter.annotations));
    mPasses.resize(effect.techniques.size());
    for (size_t t = 0; t < effect.techniques.size(); ++t) {
        mTechniques.push_back(handles(effect.techniques[t].annotations));
        for (const fx::CompiledPass& pass : effect.techniques[t].passes)
            mPasses[t].push_back(handles(pass.annotations));
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
