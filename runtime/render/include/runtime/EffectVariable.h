// EffectVariable, EffectAnnotation: an effect's parameters and annotations as an application sees them,
// in FX11's object model (ID3DX11EffectVariable, GetAnnotationByName). A lookup never returns null and
// never throws: it returns a handle whose isValid() is false, whose setters do nothing and return false,
// and whose lookups return invalid handles again, so a chain of lookups needs no checks in between:
//
//     effect.variableBySemantic("worldviewprojection").setMatrix(proj * view * world);
//     float maximum = effect.variable("Bias").annotation("UIMax").asFloat();  // 0 if either is missing
//
// Values are stored on the host when set; GL sees them when a pass is applied or its changes committed
// (runtime/EffectPass.h). A variable set through a handle is pinned, as EffectRenderer::setParameter pins
// it: render(Scene)'s semantics no longer overwrite it.
//
// Handles are small values that point into their EffectRenderer: they are valid as long as it lives (a
// hot reload makes a new renderer, whose handles are looked up anew).
#pragma once

#include <runtime/GlApi.h>

#include <fx/Types.h>
#include <fx/Value.h>

#include <glm/glm.hpp>

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace runtime {

class EffectResources;
class EffectPass;

// A `<type name = value;>` annotation of a parameter, technique or pass, evaluated once at load.
class EffectAnnotation {
public:
    EffectAnnotation() = default;  // invalid
    EffectAnnotation(std::string name, fx::Value value)
        : mValid(true), mName(std::move(name)), mValue(std::move(value)) {}

    bool isValid() const { return mValid; }
    const std::string& name() const { return mName; }
    const fx::TypeDesc& type() const { return mValue.type; }
    // Numbers in HLSL element order (fx/Value.h), a string in Value::string.
    const fx::Value& value() const { return mValue; }
    // The first component (0 when invalid or a string); the string ("" when invalid or a number).
    float asFloat() const { return mValue.asFloat(); }
    int asInt() const { return mValue.asInt(); }
    bool asBool() const { return mValue.asBool(); }
    const std::string& asString() const { return mValue.string; }

private:
    bool mValid = false;
    std::string mName;
    fx::Value mValue;
};

class EffectVariable {
public:
    EffectVariable() = default;  // invalid
    // The whole of parameter `parameter`.
    EffectVariable(EffectResources* resources, size_t parameter);

    bool isValid() const { return mResources != nullptr; }
    // The parameter's index (EffectRenderer::variable(size_t)); an element's or a member's is its
    // parameter's.
    size_t index() const { return mParameter; }
    // "" when invalid; an element's or a member's is its parameter's with the way to it: "Lights[1].color".
    std::string name() const;
    // A member's is its own (`float3 color : DIFFUSE;`), an element's its array's.
    const std::string& semantic() const;
    // An element's type is its array's without the outer dimension; a member's is as its struct declares it.
    fx::TypeDesc type() const;

    // [SECTION] Arrays
    // Elements of the outer dimension (0 for a variable that is not an array).
    size_t elementCount() const;
    // Element i of an array: a variable of its own (an array again where the array has more dimensions);
    // invalid past the end or for a non-array.
    EffectVariable element(size_t i) const;

    // [SECTION] Struct members, as FX11's GetMemberByIndex, GetMemberByName and GetMemberBySemantic. Only
    // a struct has members: an array of structs gives them through its elements (`Lights.element(1)
    // .member("color")`). A member is a variable of its own, whose setters set its numbers of the
    // parameter's value and so its bytes of every uniform block that holds the parameter.
    size_t memberCount() const;
    EffectVariable member(size_t i) const;
    EffectVariable member(std::string_view name) const;  // case-sensitive, as HLSL
    // The first member declared with that semantic, without regard to case (as variableBySemantic).
    EffectVariable memberBySemantic(std::string_view semantic) const;

    // [SECTION] Values. Each setter is false (and sets nothing) where the variable is invalid or its type
    // does not take the value: a float, int or bool for a scalar, a vector with the variable's component
    // count, a matrix of its rows x columns (glm::mat<R, C> holds an HLSL floatRxC with the memory layout
    // fx/Value.h describes: a glm::mat4 transform is D3DX's row-vector matrix as it stands).
    bool setFloat(float value);
    bool setInt(int value);
    bool setBool(bool value);
    bool setVector(const glm::vec2& value);
    bool setVector(const glm::vec3& value);
    bool setVector(const glm::vec4& value);
    template <glm::length_t R, glm::length_t C>
    bool setMatrix(const glm::mat<R, C, float>& value) {
        return setMatrixData(static_cast<int>(R), static_cast<int>(C), &value[0][0]);
    }
    // Every component of the variable, or of the elements from `first` on: an array of floats, vectors or
    // matrices, element after element, as setValue takes them.
    bool setFloatArray(std::span<const float> components, size_t first = 0);
    // Any value of the variable's type and size (fx/Value.h; a scalar is broadcast as HLSL broadcasts). A
    // struct's value is its members' numbers in declaration order, as D3DX's SetRawValue takes them.
    bool setValue(const fx::Value& value);
    // The current value (an element's or member's part of its parameter's); a zero float when invalid.
    fx::Value value() const;
    // The current value's numbers where the parameter holds them, without a copy: valid until the next
    // setter or frame. Empty when invalid; a part the parameter's value does not hold is left out.
    std::span<const float> components() const;

    // [SECTION] Textures
    // Samples the application's GL texture `name` wherever the effect samples this texture parameter (its
    // GL target follows the parameter's type: GL_TEXTURE_2D for Texture2D, ...). The application keeps it
    // alive while the effect may draw with it; 0 gives the parameter back its own texture. On a sampler:
    // its texture's (`sampler_state { Texture = <T>; }` sets T), or, for a bare sampler that no texture is
    // given to (`sampler2D Texture : register(s0);`, XNA's and MonoGame's), the sampler's own, in place of
    // the neutral white texture. False for a variable that is neither.
    bool setTexture(GLuint name);

    // [SECTION] Use and annotations
    // True if `pass` reads the variable: a member of one of its stages' uniform blocks that the code
    // reads, a texture or sampler it samples, an input of its states' or compile arguments' expressions.
    // An element or a member is used where its parameter is.
    bool isUsed(const EffectPass& pass) const;
    // A parameter's annotations; an element or a member has none.
    size_t annotationCount() const;
    EffectAnnotation annotation(size_t i) const;
    // Case-blind, as the effect language's own lookups.
    EffectAnnotation annotation(std::string_view name) const;

private:
    EffectVariable(const EffectVariable& whole, std::string path, fx::TypeDesc type, size_t first,
                   const std::string* semantic);
    bool isWhole() const { return mPath.empty(); }
    bool setMatrixData(int rows, int cols, const float* data);
    bool store(std::span<const float> components, size_t firstComponent);

    EffectResources* mResources = nullptr;
    size_t mParameter = 0;
    // The part of the parameter this variable is: the way to it after the parameter's name ("" for the
    // whole parameter), its type, where its numbers start in the parameter's value, and its semantic.
    std::string mPath;
    fx::TypeDesc mType;
    size_t mFirst = 0;
    const std::string* mSemantic = nullptr;
};

}  // namespace runtime
