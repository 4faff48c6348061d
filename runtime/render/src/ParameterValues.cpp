// ParameterValues: see ParameterValues.h.
#include "ParameterValues.h"

#include <algorithm>

namespace runtime {

ParameterValues::ParameterValues(const std::vector<fx::ParameterInfo>& parameters,
                                 const std::vector<fx::Value>& initial)
    : mParameters(&parameters), mValues(initial), mPinned(parameters.size(), false) {
    mValues.resize(parameters.size());
    mStamps.stamps.assign(parameters.size(), 0);
    for (size_t i = 0; i < parameters.size(); ++i)
        if (mValues[i].type.base == fx::BaseType::Float && mValues[i].data.empty())
            mValues[i] = fx::zeroValue(parameters[i].type);
}

void ParameterValues::store(size_t index, fx::Value value) {
    value.type = mParameters->at(index).type;
    const size_t components = static_cast<size_t>(std::max(1, value.type.componentCount()));
    if (value.type.isNumeric() && value.data.size() < components)
        value.data.resize(components, value.asFloat());
    mValues.at(index) = std::move(value);
    mStamps.touch(index);
}

void ParameterValues::storeScalar(size_t index, float scalar) {
    fx::Value& value = mValues.at(index);
    value.type = mParameters->at(index).type;
    const size_t components =
        value.type.isNumeric() ? static_cast<size_t>(std::max(1, value.type.componentCount())) : 1;
    value.data.assign(components, scalar);
    value.string.clear();
    mStamps.touch(index);
}

void ParameterValues::pin(size_t index, fx::Value value) {
    store(index, std::move(value));
    mPinned.at(index) = true;
}

void ParameterValues::pinComponents(size_t index, size_t componentCount, size_t first,
                                    std::span<const float> components) {
    fx::Value& value = mValues.at(index);
    value.data.resize(componentCount, 0.0f);
    std::copy(components.begin(), components.end(), value.data.begin() + static_cast<std::ptrdiff_t>(first));
    value.type = mParameters->at(index).type;
    const size_t typeComponents = static_cast<size_t>(std::max(1, value.type.componentCount()));
    if (value.type.isNumeric() && value.data.size() < typeComponents)
        value.data.resize(typeComponents, value.asFloat());
    mStamps.touch(index);
    mPinned.at(index) = true;
}

void ParameterValues::bindSemantics(const SemanticBinder& binder, const RenderPortView& port,
                                    const SceneObject* object, float time, SemanticBinder::Scope scope,
                                    const std::vector<bool>* used) {
    binder.bind(port, object, time, mValues, mPinned, scope, used, &mStamps);
}

void ParameterValues::copyFrom(const ParameterValues& other) {
    mParameters = other.mParameters;
    mValues = other.mValues;
    mPinned = other.mPinned;
    mStamps = other.mStamps;
}

}  // namespace runtime
