// EffectVariable: see runtime/EffectVariable.h. Values go through storeParameter(), the one way values
// change (EffectResources.h), so the preshaders and uniform blocks see them by their change stamps.
#include <runtime/EffectVariable.h>

#include "EffectResources.h"
#include "PassUse.h"

#include <runtime/EffectPass.h>

#include <fx/StageReads.h>

#include <algorithm>

namespace runtime {

namespace {

fx::TypeDesc elementType(fx::TypeDesc type) {
    if (!type.arrayDims.empty()) type.arrayDims.erase(type.arrayDims.begin());
    return type;
}

// The GL target a texture parameter's type is sampled through.
std::optional<GLenum> textureTarget(fx::BaseType type) {
    switch (type) {
        case fx::BaseType::Texture:
        case fx::BaseType::Texture2D:
            return GL_TEXTURE_2D;
        case fx::BaseType::Texture1D:
            return GL_TEXTURE_1D;
        case fx::BaseType::Texture3D:
            return GL_TEXTURE_3D;
        case fx::BaseType::TextureCube:
            return GL_TEXTURE_CUBE_MAP;
        case fx::BaseType::Texture1DArray:
            return GL_TEXTURE_1D_ARRAY;
        case fx::BaseType::Texture2DArray:
            return GL_TEXTURE_2D_ARRAY;
        case fx::BaseType::TextureCubeArray:
            return GL_TEXTURE_CUBE_MAP_ARRAY;
        case fx::BaseType::Texture2DMS:
            return GL_TEXTURE_2D_MULTISAMPLE;
        default:
            return std::nullopt;
    }
}

}  // namespace

std::string EffectVariable::name() const {
    if (!isValid()) return "";
    const std::string& name = mResources->parameterInfo()[mParameter].name;
    return mElement < 0 ? name : name + "[" + std::to_string(mElement) + "]";
}

const std::string& EffectVariable::semantic() const {
    static const std::string none;
    return isValid() ? mResources->parameterInfo()[mParameter].semantic : none;
}

fx::TypeDesc EffectVariable::type() const {
    if (!isValid()) return {};
    const fx::TypeDesc& type = mResources->parameterInfo()[mParameter].type;
    return mElement < 0 ? type : elementType(type);
}

size_t EffectVariable::elementCount() const {
    const fx::TypeDesc t = type();
    return isValid() && !t.arrayDims.empty() ? static_cast<size_t>(std::max(t.arrayDims[0], 0)) : 0;
}

EffectVariable EffectVariable::element(size_t i) const {
    // Elements of elements (float4 a[3][2]) are not addressed one by one: setFloatArray writes them.
    if (mElement >= 0 || i >= elementCount()) return {};
    return EffectVariable(mResources, mParameter, static_cast<int>(i));
}

// [SECTION] Values

bool EffectVariable::store(std::span<const float> components, size_t firstComponent) {
    if (!isValid()) return false;
    const fx::ParameterInfo& info = mResources->parameterInfo()[mParameter];
    if (!info.type.isNumeric()) return false;
    const size_t total = static_cast<size_t>(info.type.componentCount());
    const fx::TypeDesc own = type();
    const size_t ownCount = static_cast<size_t>(own.componentCount());
    const size_t start = (mElement < 0 ? 0 : static_cast<size_t>(mElement) * ownCount) + firstComponent;
    if (components.empty() || start + components.size() > total) return false;
    fx::Value value = mResources->values[mParameter];
    value.data.resize(total, 0.0f);
    std::copy(components.begin(), components.end(), value.data.begin() + static_cast<std::ptrdiff_t>(start));
    storeParameter(mResources->parameterInfo(), mParameter, std::move(value), mResources->values,
                   mResources->stamps);
    mResources->pinned[mParameter] = true;
    mResources->pool.published(*mResources, mParameter);
    return true;
}

bool EffectVariable::setFloat(float value) {
    const fx::TypeDesc t = type();
    if (t.shape != fx::Shape::Scalar || !t.arrayDims.empty()) return false;
    return store(std::span<const float>(&value, 1), 0);
}

bool EffectVariable::setInt(int value) {
    return setFloat(static_cast<float>(value));
}

bool EffectVariable::setBool(bool value) {
    return setFloat(value ? 1.0f : 0.0f);
}

bool EffectVariable::setVector(const glm::vec2& value) {
    const fx::TypeDesc t = type();
    return t.shape == fx::Shape::Vector && t.cols == 2 && t.arrayDims.empty() && store({&value.x, 2}, 0);
}

bool EffectVariable::setVector(const glm::vec3& value) {
    const fx::TypeDesc t = type();
    return t.shape == fx::Shape::Vector && t.cols == 3 && t.arrayDims.empty() && store({&value.x, 3}, 0);
}

bool EffectVariable::setVector(const glm::vec4& value) {
    const fx::TypeDesc t = type();
    return t.shape == fx::Shape::Vector && t.cols == 4 && t.arrayDims.empty() && store({&value.x, 4}, 0);
}

bool EffectVariable::setMatrixData(int rows, int cols, const float* data) {
    const fx::TypeDesc t = type();
    if (t.shape != fx::Shape::Matrix || t.rows != rows || t.cols != cols || !t.arrayDims.empty())
        return false;
    return store({data, static_cast<size_t>(rows * cols)}, 0);
}

bool EffectVariable::setFloatArray(std::span<const float> components, size_t first) {
    const fx::TypeDesc t = type();
    const size_t elements = t.arrayDims.empty() ? 1 : static_cast<size_t>(t.arrayDims[0]);
    if (first >= elements) return false;
    const size_t perElement = static_cast<size_t>(elementType(t).componentCount());
    return store(components, first * (t.arrayDims.empty() ? 0 : perElement));
}

bool EffectVariable::setValue(const fx::Value& value) {
    if (!isValid()) return false;
    const fx::TypeDesc t = type();
    if (t.base == fx::BaseType::String && mElement < 0) {
        if (value.type.base != fx::BaseType::String) return false;
        storeParameter(mResources->parameterInfo(), mParameter, value, mResources->values,
                       mResources->stamps);
        mResources->pinned[mParameter] = true;
        mResources->pool.published(*mResources, mParameter);
        return true;
    }
    const size_t count = static_cast<size_t>(t.componentCount());
    if (value.data.size() == 1 && count > 1) {  // HLSL's scalar broadcast
        const std::vector<float> broadcast(count, value.data[0]);
        return store(broadcast, 0);
    }
    return value.data.size() == count && store(value.data, 0);
}

fx::Value EffectVariable::value() const {
    if (!isValid()) return fx::Value::scalar(0.0f);
    const fx::Value& whole = mResources->values[mParameter];
    if (mElement < 0) return whole;
    fx::Value element = fx::zeroValue(type());
    const size_t count = element.data.size();
    const size_t start = static_cast<size_t>(mElement) * count;
    for (size_t i = 0; i < count && start + i < whole.data.size(); ++i)
        element.data[i] = whole.data[start + i];
    return element;
}

// [SECTION] Textures

bool EffectVariable::setTexture(GLuint name) {
    if (!isValid() || mElement >= 0) return false;
    const std::optional<GLenum> target = textureTarget(mResources->parameterInfo()[mParameter].type.base);
    if (!target) return false;
    if (name == 0) {
        mResources->applicationTextures.erase(mParameter);
    } else {
        mResources->applicationTextures[mParameter] = EffectResources::ApplicationTexture{name, *target};
    }
    // What render(Scene) kept in its targets may have been drawn from the texture this replaces.
    mResources->targetHistory.clear();
    return true;
}

// [SECTION] Use and annotations

bool EffectVariable::isUsed(const EffectPass& pass) const {
    if (!isValid() || !pass.isValid() || pass.techniqueIndex() >= mResources->effect().techniques.size())
        return false;
    const fx::CompiledPass& compiled =
        mResources->effect().techniques[pass.techniqueIndex()].passes[pass.index()];
    if (passValueReads(compiled, mResources->values.size())[mParameter]) return true;
    for (const fx::StageProgram* stage : {&compiled.vertex, &compiled.hull, &compiled.domain,
                                          &compiled.geometry, &compiled.fragment, &compiled.compute}) {
        for (const fx::SamplerBinding& binding : stage->samplers) {
            const fx::SamplerDesc* desc = mResources->effect().findSampler(binding.samplerParameter);
            const bool names = binding.samplerParameter == mParameter ||
                               binding.textureParameter == mParameter ||
                               (!binding.textureParameter && desc && desc->texture == mParameter);
            if (names && fx::stageReads(*stage, binding.glslName)) return true;
        }
        for (const fx::StorageBufferBinding& buffer : stage->storageBuffers)
            if (buffer.parameter == mParameter) return true;
    }
    return false;
}

size_t EffectVariable::annotationCount() const {
    return isValid() && mElement < 0 ? mResources->annotations.parameter(mParameter).size() : 0;
}

EffectAnnotation EffectVariable::annotation(size_t i) const {
    if (!isValid() || mElement >= 0) return {};
    return AnnotationTable::at(mResources->annotations.parameter(mParameter), i);
}

EffectAnnotation EffectVariable::annotation(std::string_view name) const {
    if (!isValid() || mElement >= 0) return {};
    return AnnotationTable::find(mResources->annotations.parameter(mParameter), name);
}

}  // namespace runtime
