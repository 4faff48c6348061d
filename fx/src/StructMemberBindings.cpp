// Compiler: the members of light and material structs bound by their names (ParameterInfo::memberBindings).
//
// Frank Luna's D3D11 book effects (2012, "LightHelper.fx") and many engines keep a light and a material
// in structs (`DirectionalLight gDirLights[3]`, `Material gMaterial`) that their application fills member
// by member; the struct parameter has no semantic, and none of its members has one. Read by the members'
// names in the struct's context (a light's `Diffuse` is the light's colour, a material's the object's),
// the members the scene gives are bound (docs/effect-format.md, "What the runtime provides"), and the
// members that only an application's choice gives (a point light's attenuation, a material's specular
// power) get a neutral value in the parameter's initial value: Luna's lighting then lights the object as
// his demos do.
#include "CaseFolding.h"
#include "Compiler.h"

#include <algorithm>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace fx::detail {

namespace {

enum class StructRole { None, Light, Material };

// The type's name decides; the parameter's name where the type's says neither (`LightParams gSun`,
// `Params gMaterial`).
StructRole structRole(const ParameterInfo& parameter) {
    for (const std::string& name : {parameter.type.structName, parameter.name}) {
        const std::string upper = upperCase(name);
        if (upper.find("MATERIAL") != std::string::npos || upper.find("MTRL") != std::string::npos)
            return StructRole::Material;
        if (upper.find("LIGHT") != std::string::npos) return StructRole::Light;
    }
    return StructRole::None;
}

// The member's name in capitals, without a `m_` scope prefix and underscores: `m_SpecularPower` is
// SPECULARPOWER.
std::string memberStem(std::string_view name) {
    if (name.rfind("m_", 0) == 0) name.remove_prefix(2);
    std::string stem;
    for (char c : upperCase(name))
        if (c != '_') stem += c;
    return stem;
}

bool isOneOf(const std::string& stem, std::initializer_list<std::string_view> names) {
    for (std::string_view name : names)
        if (stem == name) return true;
    return false;
}

// What a member gives: a semantic the runtime binds, or a constant (its numbers, repeated into every
// element), or nothing (the member keeps zero: a material's Emissive and Reflect, a pad).
struct MemberValue {
    SemanticKind kind = SemanticKind::None;
    std::vector<float> constant;
};

MemberValue lightMember(const std::string& stem, const TypeDesc& type) {
    const bool colour = type.shape == Shape::Vector && type.cols >= 3;
    if (colour && isOneOf(stem, {"DIFFUSE", "DIFFUSECOLOR", "COLOR", "COLOUR", "SPECULAR", "SPECULARCOLOR"}))
        return {SemanticKind::LightColor, {}};
    if (colour && isOneOf(stem, {"AMBIENT", "AMBIENTCOLOR"})) return {SemanticKind::Ambient, {}};
    if (colour && isOneOf(stem, {"DIRECTION", "DIR"})) return {SemanticKind::LightDirection, {}};
    if (colour && isOneOf(stem, {"POSITION", "POS"})) return {SemanticKind::LightPosition, {}};
    if (type.shape == Shape::Scalar && stem == "RANGE") return {SemanticKind::LightRange, {}};
    // Luna's attenuation 1 / dot(Att, (1, d, d²)): (1, 0, 0) lights without falloff.
    if (colour && isOneOf(stem, {"ATT", "ATTENUATION"}))
        return {SemanticKind::None, {1.0f, 0.0f, 0.0f, 0.0f}};
    // A spot light's exponent on the cosine to its axis (Luna's pow(dot(-L, Direction), Spot)): a cone
    // that fades towards its rim.
    if (type.shape == Shape::Scalar && isOneOf(stem, {"SPOT", "SPOTPOWER", "SPOTEXPONENT"}))
        return {SemanticKind::None, {8.0f}};
    if (type.shape == Shape::Scalar && stem == "INTENSITY") return {SemanticKind::None, {1.0f}};
    return {};
}

// A material's specular: a modest white highlight; Luna keeps the specular power in a float4's w.
constexpr float kSpecular = 0.5f;
constexpr float kSpecularPower = 16.0f;

MemberValue materialMember(const std::string& stem, const TypeDesc& type) {
    const bool colour = type.shape == Shape::Vector && type.cols >= 3;
    if (colour && isOneOf(stem, {"DIFFUSE", "DIFFUSECOLOR", "COLOR", "COLOUR", "AMBIENT", "AMBIENTCOLOR"}))
        return {SemanticKind::ObjectColor, {}};
    if (colour && isOneOf(stem, {"SPECULAR", "SPECULARCOLOR"}))
        return {SemanticKind::None, {kSpecular, kSpecular, kSpecular, kSpecularPower}};
    if (type.shape == Shape::Scalar &&
        isOneOf(stem, {"SPECULARPOWER", "SPECPOWER", "SHININESS", "POWER", "SPECULAREXPONENT"}))
        return {SemanticKind::None, {kSpecularPower}};
    return {};
}

}  // namespace

void Compiler::structMemberBindings(const std::vector<bool>& hasInitializer) {
    // Luna's lighting adds each light's Ambient: the scene's ambient is the first light struct's alone
    // (element 0 of an array, SemanticBinder's per-light ambient), as his demos give it to their first
    // light, so that three lights do not light the shadows three times.
    bool ambientGiven = false;
    for (size_t i = 0; i < mOut->parameters.size(); ++i) {
        ParameterInfo& parameter = mOut->parameters[i];
        const TypeDesc& type = parameter.type;
        // A semantic, a light annotation or a value of the effect's own says what the struct holds.
        if (type.base != BaseType::Struct || type.arrayDims.size() > 1 || !parameter.semantic.empty() ||
            !parameter.light.empty() || parameter.isStatic || hasInitializer[i])
            continue;
        const StructRole role = structRole(parameter);
        const StructInfo* info = mOut->findStruct(type.structName);
        // An array of materials has no object to take its colours from; a member with a semantic says its
        // struct is set by semantics (EffectVariable::memberBySemantic), as its author chose.
        if (role == StructRole::None || !info || (role == StructRole::Material && !type.arrayDims.empty()) ||
            std::any_of(info->members.begin(), info->members.end(),
                        [](const StructMemberInfo& member) { return !member.semantic.empty(); }))
            continue;
        TypeDesc elementType = type;
        elementType.arrayDims.clear();
        const size_t stride = mOut->componentCount(elementType);
        const size_t elements = type.arrayDims.empty() ? 1 : static_cast<size_t>(type.arrayDims.front());
        std::vector<float>& initial = mOut->initialValues[i].data;
        size_t first = 0;
        for (const StructMemberInfo& member : info->members) {
            const size_t count = mOut->componentCount(member.type);
            const size_t at = first;
            first += count;
            if (!member.type.isNumeric() || !member.type.arrayDims.empty()) continue;
            const std::string stem = memberStem(member.name);
            const MemberValue value = role == StructRole::Light ? lightMember(stem, member.type)
                                                                : materialMember(stem, member.type);
            for (size_t e = 0; e < elements && !value.constant.empty(); ++e)
                for (size_t c = 0; c < count && c < value.constant.size(); ++c)
                    if (e * stride + at + c < initial.size())
                        initial[e * stride + at + c] = value.constant[c];
            if (value.kind == SemanticKind::None || (value.kind == SemanticKind::Ambient && ambientGiven))
                continue;
            if (value.kind == SemanticKind::Ambient) ambientGiven = true;
            MemberBinding binding;
            binding.member = member.name;
            binding.type = member.type;
            binding.firstComponent = static_cast<uint32_t>(at);
            binding.standard.kind = value.kind;
            binding.standard.byName = true;
            if (!type.arrayDims.empty()) binding.elementStride = static_cast<uint32_t>(stride);
            // Element k of an array is the scene's light k, zero past the last one; one light is light0.
            // The ambient, no light's, is an array's element 0 alone: a binding not of each light writes
            // the first element only.
            const bool lightProperty = role == StructRole::Light && value.kind != SemanticKind::Ambient;
            if (lightProperty && !type.arrayDims.empty()) binding.standard.eachLight = true;
            if (lightProperty && type.arrayDims.empty()) binding.standard.light = lightIndex("light0");
            parameter.memberBindings.push_back(std::move(binding));
        }
    }
}

}  // namespace fx::detail
