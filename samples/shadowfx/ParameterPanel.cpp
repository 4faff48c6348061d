// ParameterPanel: SAS annotations -> ImGui widgets (see ParameterPanel.h).
#include "ParameterPanel.h"

#include <fx/CompiledEffect.h>

#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <string>

namespace shadowfx::cli {

namespace {

std::string lowerCase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

// An annotation's number (`float UIMin = -1.0;`), as the compiler evaluated it.
std::optional<float> annotationNumber(const fx::ParameterInfo& parameter, const char* name) {
    const fx::AnnotationValue* annotation = fx::findAnnotation(parameter.annotations, name);
    if (!annotation || annotation->value.data.empty()) return std::nullopt;
    return annotation->value.data[0];
}

std::string annotationText(const fx::ParameterInfo& parameter, const char* name) {
    const fx::AnnotationValue* annotation = fx::findAnnotation(parameter.annotations, name);
    if (!annotation || annotation->value.type.base != fx::BaseType::String) return "";
    return annotation->value.string;
}

// Numeric scalars and vectors that no semantic drives and no `UIWidget = "none"` hides.
bool isTweakable(const fx::ParameterInfo& parameter) {
    if (parameter.isStatic || !parameter.semantic.empty() || !parameter.type.arrayDims.empty()) return false;
    if (!parameter.type.isNumeric() || parameter.type.shape == fx::Shape::Matrix) return false;
    if (parameter.type.cols > 4) return false;
    return lowerCase(annotationText(parameter, "UIWidget")) != "none";
}

}  // namespace

bool ParameterPanel::draw(runtime::EffectRenderer& renderer) {
    const std::vector<fx::ParameterInfo>& parameters = renderer.effect().parameters;
    bool anyChanged = false;
    for (size_t i = 0; i < parameters.size(); ++i) {
        const fx::ParameterInfo& parameter = parameters[i];
        if (!isTweakable(parameter)) continue;
        fx::Value value = renderer.parameter(i);
        const int components = parameter.type.shape == fx::Shape::Scalar ? 1 : parameter.type.cols;
        value.data.resize(static_cast<size_t>(components), 0.0f);
        std::string label = annotationText(parameter, "UIName");
        if (label.empty()) label = parameter.name;
        label += "##" + parameter.name;  // ImGui ids stay unique when two UINames match
        const std::string widget = lowerCase(annotationText(parameter, "UIWidget"));
        const std::optional<float> min = annotationNumber(parameter, "UIMin");
        const std::optional<float> max = annotationNumber(parameter, "UIMax");
        const std::optional<float> step = annotationNumber(parameter, "UIStep");
        const bool integer =
            parameter.type.base == fx::BaseType::Int || parameter.type.base == fx::BaseType::UInt;

        bool changed = false;
        if (parameter.type.base == fx::BaseType::Bool && components == 1) {
            bool on = value.asBool();
            changed = ImGui::Checkbox(label.c_str(), &on);
            value.data[0] = on ? 1.0f : 0.0f;
        } else if (widget == "color" && components >= 3) {
            changed = components == 3
                          ? ImGui::ColorEdit3(label.c_str(), value.data.data(), ImGuiColorEditFlags_Float)
                          : ImGui::ColorEdit4(label.c_str(), value.data.data(), ImGuiColorEditFlags_Float);
        } else if (integer) {
            int ints[4] = {};
            for (int c = 0; c < components; ++c) ints[c] = static_cast<int>(value.data[c]);
            if (widget == "slider" && min && max) {
                const int lo = static_cast<int>(*min), hi = static_cast<int>(*max);
                changed = ImGui::SliderScalarN(label.c_str(), ImGuiDataType_S32, ints, components, &lo, &hi);
            } else {
                changed = ImGui::DragScalarN(label.c_str(), ImGuiDataType_S32, ints, components,
                                             step.value_or(1.0f));
            }
            for (int c = 0; c < components; ++c) value.data[c] = static_cast<float>(ints[c]);
        } else if (widget == "slider" && min && max) {
            changed = ImGui::SliderScalarN(label.c_str(), ImGuiDataType_Float, value.data.data(), components,
                                           &*min, &*max, "%.4g");
            if (changed && step && *step > 0.0f) {
                // UIStep: FX Composer's sliders moved in steps from UIMin.
                for (float& v : value.data) v = *min + std::round((v - *min) / *step) * *step;
            }
        } else {
            const float speed =
                step.value_or(std::max(0.001f, (max && min) ? (*max - *min) / 200.0f : 0.01f));
            changed = ImGui::DragScalarN(label.c_str(), ImGuiDataType_Float, value.data.data(), components,
                                         speed, min ? &*min : nullptr, max ? &*max : nullptr, "%.4g");
        }
        if (ImGui::IsItemHovered()) {
            ImGui::SetTooltip("%s %s", parameter.type.hlslName().c_str(), parameter.name.c_str());
        }
        if (changed) {
            renderer.setParameter(i, value);
            anyChanged = true;
        }
    }
    return anyChanged;
}

}  // namespace shadowfx::cli
