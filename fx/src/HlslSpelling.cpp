// HlslSpelling: see HlslSpelling.h.
#include "HlslSpelling.h"

#include <cstdio>

namespace fx {

std::string hlslTypeName(const TypeDesc& type) {
    // glslang needs concrete types where D3D9 allows untyped ones (`sampler`, `texture`); types with no
    // HLSL counterpart in a shader (strings, shader variables) never reach a unit and read as float.
    TypeDesc concrete = type;
    switch (type.base) {
        case BaseType::Sampler:
            concrete.base = BaseType::Sampler2D;
            break;
        case BaseType::Texture:
            concrete.base = BaseType::Texture2D;
            break;
        case BaseType::Void:
        case BaseType::String:
            concrete.base = BaseType::Float;
            break;
        default:
            if (type.isShader() || type.isStateObject()) concrete.base = BaseType::Float;
            break;
    }
    const bool rowMajor = type.shape == Shape::Matrix && type.rowMajor;
    return (rowMajor ? "row_major " : "") + concrete.hlslName();
}

std::string hlslUniformTypeName(const TypeDesc& type) {
    TypeDesc declared = type;
    if (type.shape == Shape::Matrix &&
        (type.base == BaseType::Int || type.base == BaseType::UInt || type.base == BaseType::Bool))
        declared.rowMajor = true;
    return hlslTypeName(declared);
}

TypeDesc float4Type() {
    TypeDesc t;
    t.base = BaseType::Float;
    t.shape = Shape::Vector;
    t.cols = 4;
    return t;
}

bool isNumericType(const TypeDesc& t) {
    return t.base == BaseType::Bool || t.base == BaseType::Int || t.base == BaseType::UInt ||
           t.base == BaseType::Half || t.base == BaseType::Float || t.base == BaseType::Double;
}

bool isSamplerType(const TypeDesc& t) {
    return t.base == BaseType::Sampler || t.base == BaseType::Sampler1D || t.base == BaseType::Sampler2D ||
           t.base == BaseType::Sampler3D || t.base == BaseType::SamplerCube;
}

std::string arraySuffix(const TypeDesc& t) {
    std::string out;
    for (int d : t.arrayDims) out += "[" + std::to_string(d) + "]";
    return out;
}

std::string formatFloat(float x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(x));
    std::string s = buf;
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
    return s;
}

// HLSL literal for a host value of type `type` ("float3(1.0, 2.0, 3.0)", "true", "4").
std::string literalText(const Value& v, const TypeDesc& type) {
    auto component = [&](float x) -> std::string {
        if (type.base == BaseType::Bool) return x != 0.0f ? "true" : "false";
        if (type.base == BaseType::Int || type.base == BaseType::UInt)
            return std::to_string(static_cast<long long>(x));
        return formatFloat(x);
    };
    if (v.data.size() == 1 && type.shape == Shape::Scalar && type.arrayDims.empty())
        return component(v.data[0]);
    TypeDesc plain = type;
    plain.rowMajor = false;
    plain.arrayDims.clear();
    std::string out = hlslTypeName(plain) + "(";
    for (size_t i = 0; i < v.data.size(); ++i) out += (i ? ", " : "") + component(v.data[i]);
    return out + ")";
}

// An expression with no parameter references: it can be folded into the HLSL as a literal.
bool isLiteralOnly(const Expr& e) {
    if (e.kind == Expr::Kind::Identifier) return e.text == "true" || e.text == "false";
    if (e.kind == Expr::Kind::String || e.kind == Expr::Kind::TextureRef || e.kind == Expr::Kind::Compile)
        return false;
    for (const Expr& a : e.args)
        if (!isLiteralOnly(a)) return false;
    return true;
}

}  // namespace fx
