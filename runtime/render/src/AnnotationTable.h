// AnnotationTable: every annotation of an effect's parameters, techniques and passes as the application's
// handles (runtime/EffectVariable.h), made once when the effect is loaded from the values the compiled
// effect carries.
#pragma once

#include <runtime/EffectVariable.h>

#include <fx/CompiledEffect.h>

#include <string_view>
#include <vector>

namespace runtime {

class AnnotationTable {
public:
    AnnotationTable() = default;
    explicit AnnotationTable(const fx::CompiledEffect& effect);

    using List = std::vector<EffectAnnotation>;
    const List& parameter(size_t index) const;
    const List& technique(size_t index) const;
    const List& pass(size_t technique, size_t pass) const;

    // Case-blind, as fx::Parameter::annotation; invalid when missing.
    static EffectAnnotation find(const List& list, std::string_view name);
    static EffectAnnotation at(const List& list, size_t index);

private:
    std::vector<List> mParameters;
    std::vector<List> mTechniques;
    std::vector<std::vector<List>> mPasses;
};

}  // namespace runtime
