// TypeNames: see TypeNames.h.
#include "TypeNames.h"

#include <fx/RenderStates.h>

#include <cstring>

namespace fx::detail {

bool parseScalarTypeName(const std::string& name, TypeDesc& type) {
    static const std::pair<const char*, BaseType> kScalars[] = {
        {"bool", BaseType::Bool},      {"int", BaseType::Int},         {"uint", BaseType::UInt},
        {"dword", BaseType::UInt},     {"half", BaseType::Half},       {"float", BaseType::Float},
        {"double", BaseType::Double},  {"min16float", BaseType::Half}, {"min16int", BaseType::Int},
        {"min16uint", BaseType::UInt}, {"min10float", BaseType::Half}, {"min12int", BaseType::Int},
    };
    for (const auto& [spelling, base] : kScalars) {
        size_t len = std::strlen(spelling);
        if (name.compare(0, len, spelling) != 0) continue;
        std::string rest = name.substr(len);
        type = TypeDesc{};
        type.base = base;
        if (rest.empty()) return true;
        if (rest.size() == 1 && rest[0] >= '1' && rest[0] <= '4') {
            type.shape = Shape::Vector;
            type.cols = rest[0] - '0';
            return true;
        }
        if (rest.size() == 3 && rest[0] >= '1' && rest[0] <= '4' && rest[1] == 'x' && rest[2] >= '1' &&
            rest[2] <= '4') {
            type.shape = Shape::Matrix;
            type.rows = rest[0] - '0';
            type.cols = rest[2] - '0';
            return true;
        }
    }
    return false;
}

bool parseObjectTypeName(const std::string& name, TypeDesc& type) {
    static const std::pair<const char*, BaseType> kObjects[] = {
        {"texture", BaseType::Texture},
        {"texture1D", BaseType::Texture1D},
        {"texture2D", BaseType::Texture2D},
        {"texture3D", BaseType::Texture3D},
        {"textureCUBE", BaseType::TextureCube},
        {"sampler", BaseType::Sampler},
        {"sampler1D", BaseType::Sampler1D},
        {"sampler2D", BaseType::Sampler2D},
        {"sampler3D", BaseType::Sampler3D},
        {"samplerCUBE", BaseType::SamplerCube},
        {"SamplerState", BaseType::SamplerState},
        {"SamplerComparisonState", BaseType::SamplerComparisonState},
        {"VertexShader", BaseType::VertexShader},
        {"PixelShader", BaseType::PixelShader},
        {"GeometryShader", BaseType::GeometryShader},
        {"HullShader", BaseType::HullShader},
        {"DomainShader", BaseType::DomainShader},
        {"ComputeShader", BaseType::ComputeShader},
        {"RasterizerState", BaseType::RasterizerState},
        {"DepthStencilState", BaseType::DepthStencilState},
        {"BlendState", BaseType::BlendState},
        {"RenderTargetView", BaseType::RenderTargetView},
        {"DepthStencilView", BaseType::DepthStencilView},
        {"string", BaseType::String},
        {"void", BaseType::Void},
    };
    for (const auto& [spelling, base] : kObjects) {
        if (equalsIgnoreCase(name, spelling)) {
            type = TypeDesc{};
            type.base = base;
            return true;
        }
    }
    return false;
}

}  // namespace fx::detail
