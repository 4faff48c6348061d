// TunableParameters: see TunableParameters.h.
#include "TunableParameters.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <optional>
#include <set>
#include <string>

namespace shadowfx::cli {

namespace {

std::string lowerCase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

std::optional<double> annotationNumber(const fx::ParameterInfo& parameter, const char* name) {
    const fx::AnnotationValue* annotation = fx::findAnnotation(parameter.annotations, name);
    if (!annotation || annotation->value.type.base == fx::BaseType::String || annotation->value.data.empty())
        return std::nullopt;
    return annotation->value.data[0];
}

std::string annotationText(const fx::ParameterInfo& parameter, const char* name) {
    const fx::AnnotationValue* annotation = fx::findAnnotation(parameter.annotations, name);
    if (!annotation || annotation->value.type.base != fx::BaseType::String) return "";
    return annotation->value.string;
}

std::string numberText(double value) {
    return report::formatTuneValue(report::TuneParameter{}, value);
}

// An annotation's float as its literal was written (0.02, not 0.0199999996).
double asWritten(double value) {
    return std::strtod(numberText(value).c_str(), nullptr);
}

// Every parameter index the technique's passes read: active uniforms of their stages, and the inputs of
// their compile arguments and state values (host-evaluated, D3DX's preshaders).
std::set<size_t> parametersRead(const fx::CompiledTechnique& technique) {
    std::set<size_t> read;
    for (const fx::CompiledPass& pass : technique.passes) {
        for (const fx::StageProgram* stage :
             {&pass.vertex, &pass.fragment, &pass.geometry, &pass.hull, &pass.domain, &pass.compute})
            for (const fx::UniformBinding& uniform : stage->uniforms)
                if (uniform.active && uniform.source == fx::UniformBinding::Source::Parameter)
                    read.insert(uniform.index);
        for (const fx::CompileArgument& argument : pass.arguments)
            read.insert(argument.value.inputs().begin(), argument.value.inputs().end());
        for (const fx::RenderStateSetting& state : pass.states)
            read.insert(state.value.inputs().begin(), state.value.inputs().end());
    }
    return read;
}

}  // namespace

std::vector<report::TuneParameter> tunableParameters(const fx::CompiledEffect& effect,
                                                     const fx::CompiledTechnique& technique,
                                                     fx::DiagnosticSink& sink) {
    const std::set<size_t> read = parametersRead(technique);
    std::vector<report::TuneParameter> tunable;
    for (size_t i = 0; i < effect.parameters.size(); ++i) {
        const fx::ParameterInfo& parameter = effect.parameters[i];
        const fx::TypeDesc& type = parameter.type;
        if (read.count(i) == 0 || parameter.isStatic || !parameter.semantic.empty()) continue;
        if (type.shape != fx::Shape::Scalar || !type.arrayDims.empty() || !type.isNumeric()) continue;
        if (lowerCase(annotationText(parameter, "UIWidget")) == "none") continue;
        if (const fx::AnnotationValue* tune = fx::findAnnotation(parameter.annotations, "Tune");
            tune && !tune->value.asBool())
            continue;
        report::TuneParameter p;
        p.name = parameter.name;
        const fx::Value& initial = effect.initialValues[i];
        p.initial = initial.data.empty() ? 0.0 : initial.data[0];
        if (type.base == fx::BaseType::Bool) {
            p.kind = report::TuneParameter::Kind::Bool;
            p.min = 0.0;
            p.max = 1.0;
            tunable.push_back(p);
            continue;
        }
        const std::optional<double> min = annotationNumber(parameter, "UIMin");
        const std::optional<double> max = annotationNumber(parameter, "UIMax");
        if (!min || !max) continue;  // no range to search
        if (*min > *max) {
            sink.report(fx::DiagId::TuneRangeEmpty, parameter.loc,
                        {numberText(*min), parameter.name, numberText(*max)});
            continue;
        }
        p.kind = type.base == fx::BaseType::Int || type.base == fx::BaseType::UInt
                     ? report::TuneParameter::Kind::Int
                     : report::TuneParameter::Kind::Float;
        p.min = asWritten(*min);
        p.max = asWritten(*max);
        p.step = std::max(asWritten(annotationNumber(parameter, "UIStep").value_or(0.0)), 0.0);
        const std::string scale = lowerCase(annotationText(parameter, "UIScale"));
        if (scale == "log") {
            p.logScale = *min > 0.0;
            if (!p.logScale)
                sink.report(fx::DiagId::TuneLogScaleMinimum, parameter.loc,
                            {parameter.name, numberText(*min)});
        } else if (!scale.empty() && scale != "linear") {
            sink.report(fx::DiagId::TuneScaleUnknown, parameter.loc,
                        {annotationText(parameter, "UIScale"), parameter.name});
        }
        tunable.push_back(p);
    }
    return tunable;
}

}  // namespace shadowfx::cli
