// EffectVariable: see runtime/EffectVariable.h. Values go through ParameterValues::pin(), the one way the
// application's values change, so the preshaders and uniform blocks see them by their change stamps.
#include <runtime/EffectVariable.h>

#include "EffectResources.h"

#include <runtime/EffectPass.h>

#include <fx/RenderStates.h>

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
        case fx::BaseType::Texture2DMSArray:
            return GL_TEXTURE_2D_MULTISAMPLE_ARRAY;
        // A sampler without a texture of its own (`sampler2D Texture : register(s0);`).
        case fx::BaseType::Sampler:
        case fx::BaseType::Sampler2D:
            return GL_TEXTURE_2D;
        case fx::BaseType::Sampler1D:
            return GL_TEXTURE_1D;
        case fx::BaseType::Sampler3D:
            return GL_TEXTURE_3D;
        case fx::BaseType::SamplerCube:
            return GL_TEXTURE_CUBE_MAP;
        default:
            return std::nullopt;
    }
}

}  // namespace

EffectVariable::EffectVariable(EffectResources* resources, size_t parameter)
    : mResources(resources), mParameter(parameter) {
    const fx::ParameterInfo& info = resources->parameterInfo()[parameter];
    mType = info.type;
    mSemantic = &info.semantic;
}

EffectVariable::EffectVariable(const EffectVariable& whole, std::string path, fx::TypeDesc type, size_t first,
                               const std::string* semantic)
    : mResources(whole.mResources),
      mParameter(whole.mParameter),
      mPath(std::move(path)),
      mType(std::move(type)),
      mFirst(first),
      mSemantic(semantic) {}

std::string EffectVariable::name() const {
    return isValid() ? mResources->parameterInfo()[mParameter].name + mPath : "";
}

const std::string& EffectVariable::semantic() const {
    static const std::string none;
    return isValid() ? *mSemantic : none;
}

fx::TypeDesc EffectVariable::type() const {
    return isValid() ? mType : fx::TypeDesc{};
}

size_t EffectVariable::elementCount() const {
    return isValid() && !mType.arrayDims.empty() ? static_cast<size_t>(std::max(mType.arrayDims[0], 0)) : 0;
}

EffectVariable EffectVariable::element(size_t i) const {
    if (i >= elementCount()) return {};
    fx::TypeDesc element = elementType(mType);
    const size_t first = mFirst + i * mResources->effect().componentCount(element);
    return EffectVariable(*this, mPath + "[" + std::to_string(i) + "]", std::move(element), first, mSemantic);
}

// [SECTION] Struct members

namespace {

const fx::StructInfo* structOf(const fx::CompiledEffect& effect, const fx::TypeDesc& type) {
    return type.base == fx::BaseType::Struct && type.arrayDims.empty() ? effect.findStruct(type.structName)
                                                                       : nullptr;
}

}  // namespace

size_t EffectVariable::memberCount() const {
    const fx::StructInfo* info = isValid() ? structOf(mResources->effect(), mType) : nullptr;
    return info ? info->members.size() : 0;
}

EffectVariable EffectVariable::member(size_t i) const {
    if (i >= memberCount()) return {};
    const fx::CompiledEffect& effect = mResources->effect();
    const fx::StructInfo& info = *structOf(effect, mType);
    size_t first = mFirst;
    for (size_t m = 0; m < i; ++m) first += effect.componentCount(info.members[m].type);
    const fx::StructMemberInfo& member = info.members[i];
    return EffectVariable(*this, mPath + "." + member.name, member.type, first, &member.semantic);
}

EffectVariable EffectVariable::member(std::string_view name) const {
    for (size_t i = 0; i < memberCount(); ++i)
        if (structOf(mResources->effect(), mType)->members[i].name == name) return member(i);
    return {};
}

EffectVariable EffectVariable::memberBySemantic(std::string_view semantic) const {
    if (semantic.empty()) return {};
    for (size_t i = 0; i < memberCount(); ++i)
        if (fx::equalsIgnoreCase(structOf(mResources->effect(), mType)->members[i].semantic, semantic))
            return member(i);
    return {};
}

// [SECTION] Values

bool EffectVariable::store(std::span<const float> components, size_t firstComponent) {
    if (!isValid() || !(mType.isNumeric() || mType.base == fx::BaseType::Struct)) return false;
    const fx::CompiledEffect& effect = mResources->effect();
    const size_t own = effect.componentCount(mType);
    if (components.empty() || firstComponent + components.size() > own) return false;
    mResources->values.pinComponents(mParameter,
                                     effect.componentCount(mResources->parameterInfo()[mParameter].type),
                                     mFirst + firstComponent, components);
    mResources->pool.published(*mResources, mParameter);
    return true;
}

bool EffectVariable::setFloat(float value) {
    if (mType.shape != fx::Shape::Scalar || !mType.arrayDims.empty() || !mType.isNumeric()) return false;
    return store(std::span<const float>(&value, 1), 0);
}

bool EffectVariable::setInt(int value) {
    return setFloat(static_cast<float>(value));
}

bool EffectVariable::setBool(bool value) {
    return setFloat(value ? 1.0f : 0.0f);
}

bool EffectVariable::setVector(const glm::vec2& value) {
    return mType.shape == fx::Shape::Vector && mType.cols == 2 && mType.arrayDims.empty() &&
           store({&value.x, 2}, 0);
}

bool EffectVariable::setVector(const glm::vec3& value) {
    return mType.shape == fx::Shape::Vector && mType.cols == 3 && mType.arrayDims.empty() &&
           store({&value.x, 3}, 0);
}

bool EffectVariable::setVector(const glm::vec4& value) {
    return mType.shape == fx::Shape::Vector && mType.cols == 4 && mType.arrayDims.empty() &&
           store({&value.x, 4}, 0);
}

bool EffectVariable::setMatrixData(int rows, int cols, const float* data) {
    if (mType.shape != fx::Shape::Matrix || mType.rows != rows || mType.cols != cols ||
        !mType.arrayDims.empty())
        return false;
    return store({data, static_cast<size_t>(rows * cols)}, 0);
}

bool EffectVariable::setFloatArray(std::span<const float> components, size_t first) {
    if (!isValid()) return false;
    const size_t elements = mType.arrayDims.empty() ? 1 : static_cast<size_t>(mType.arrayDims[0]);
    if (first >= elements) return false;
    const size_t perElement = mResources->effect().componentCount(elementType(mType));
    return store(components, first * (mType.arrayDims.empty() ? 0 : perElement));
}

bool EffectVariable::setValue(const fx::Value& value) {
    if (!isValid()) return false;
    if (mType.base == fx::BaseType::String && isWhole()) {
        if (value.type.base != fx::BaseType::String) return false;
        mResources->values.pin(mParameter, value);
        mResources->pool.published(*mResources, mParameter);
        return true;
    }
    const size_t count = mResources->effect().componentCount(mType);
    if (value.data.size() == 1 && count > 1) {  // HLSL's scalar broadcast
        const std::vector<float> broadcast(count, value.data[0]);
        return store(broadcast, 0);
    }
    return value.data.size() == count && store(value.data, 0);
}

fx::Value EffectVariable::value() const {
    if (!isValid()) return fx::Value::scalar(0.0f);
    const fx::Value& whole = mResources->values[mParameter];
    if (isWhole()) return whole;
    fx::Value part;
    part.type = mType;
    part.data.assign(mResources->effect().componentCount(mType), 0.0f);
    for (size_t i = 0; i < part.data.size() && mFirst + i < whole.data.size(); ++i)
        part.data[i] = whole.data[mFirst + i];
    return part;
}

std::span<const float> EffectVariable::components() const {
    if (!isValid()) return {};
    const std::span<const float> whole(mResources->values[mParameter].data);
    if (isWhole()) return whole;
    const size_t first = std::min(mFirst, whole.size());
    return whole.subspan(first, std::min(mResources->effect().componentCount(mType), whole.size() - first));
}

// [SECTION] Textures

bool EffectVariable::setTexture(GLuint name) {
    if (!isValid() || !isWhole()) return false;
    // A sampler with a texture of its own (`sampler_state { Texture = <T>; }`) passes it on to T, as
    // setting T does; a bare sampler, whose texture only its application gave it, takes it itself.
    size_t parameter = mParameter;
    if (const fx::SamplerDesc* sampler = mResources->effect().findSampler(mParameter);
        sampler && sampler->texture)
        parameter = *sampler->texture;
    const std::optional<GLenum> target = textureTarget(mResources->parameterInfo()[parameter].type.base);
    if (!target) return false;
    mResources->setApplicationTexture(parameter, name, *target);
    return true;
}

// [SECTION] Use and annotations

bool EffectVariable::isUsed(const EffectPass& pass) const {
    if (!isValid() || !pass.isValid() || pass.techniqueIndex() >= mResources->effect().techniques.size())
        return false;
    const std::vector<size_t>& reads =
        mResources->effect().techniques[pass.techniqueIndex()].passes[pass.index()].readParameters;
    return std::binary_search(reads.begin(), reads.end(), mParameter);
}

size_t EffectVariable::annotationCount() const {
    return isValid() && isWhole() ? mResources->annotations.parameter(mParameter).size() : 0;
}

EffectAnnotation EffectVariable::annotation(size_t i) const {
    if (!isValid() || !isWhole()) return {};
    return AnnotationTable::at(mResources->annotations.parameter(mParameter), i);
}

EffectAnnotation EffectVariable::annotation(std::string_view name) const {
    if (!isValid() || !isWhole()) return {};
    return AnnotationTable::find(mResources->annotations.parameter(mParameter), name);
}

}  // namespace runtime
