// Types: what a TypeDesc is (numeric, texture, sampler, ...) and its HLSL spelling; part of the contract
// library, which the compiled effect's types need without the syntax tree.
#include <fx/Types.h>

#include <algorithm>
#include <string>

namespace fx {

bool TypeDesc::isNumeric() const {
    switch (base) {
        case BaseType::Bool:
        case BaseType::Int:
        case BaseType::UInt:
        case BaseType::Half:
        case BaseType::Float:
        case BaseType::Double:
            return true;
        default:
            return false;
    }
}

bool TypeDesc::isTexture() const {
    return base >= BaseType::Texture && base <= BaseType::Texture2DMSArray;
}
bool TypeDesc::isBuffer() const {
    return base >= BaseType::Buffer && base <= BaseType::ConsumeStructuredBuffer;
}
bool TypeDesc::isImage() const {
    return base >= BaseType::RWTexture1D && base <= BaseType::RWBuffer;
}
bool TypeDesc::isSampler() const {
    return base >= BaseType::Sampler && base <= BaseType::SamplerComparisonState;
}

bool TypeDesc::isStateObject() const {
    return base >= BaseType::RasterizerState && base <= BaseType::BlendState;
}
bool TypeDesc::isShader() const {
    return base >= BaseType::VertexShader && base <= BaseType::ComputeShader;
}

int TypeDesc::componentCount() const {
    int count = rows * cols;
    for (int dim : arrayDims) count *= std::max(dim, 1);
    return count;
}

std::string TypeDesc::hlslName() const {
    auto withTemplate = [this](const char* object) {
        return templateArgs.empty() ? std::string(object) : std::string(object) + "<" + templateArgs + ">";
    };
    std::string name;
    switch (base) {
        case BaseType::Void:
            return "void";
        case BaseType::Bool:
            name = "bool";
            break;
        case BaseType::Int:
            name = "int";
            break;
        case BaseType::UInt:
            name = "uint";
            break;
        case BaseType::Half:
            name = "half";
            break;
        case BaseType::Float:
            name = "float";
            break;
        case BaseType::Double:
            name = "double";
            break;
        case BaseType::String:
            return "string";
        case BaseType::Texture:
            return "texture";
        case BaseType::Texture1D:
            return withTemplate("Texture1D");
        case BaseType::Texture2D:
            return withTemplate("Texture2D");
        case BaseType::Texture3D:
            return withTemplate("Texture3D");
        case BaseType::TextureCube:
            return withTemplate("TextureCube");
        case BaseType::Texture1DArray:
            return withTemplate("Texture1DArray");
        case BaseType::Texture2DArray:
            return withTemplate("Texture2DArray");
        case BaseType::TextureCubeArray:
            return withTemplate("TextureCubeArray");
        case BaseType::Texture2DMS:
            return withTemplate("Texture2DMS");
        case BaseType::Texture2DMSArray:
            return withTemplate("Texture2DMSArray");
        case BaseType::Buffer:
            return withTemplate("Buffer");
        case BaseType::StructuredBuffer:
            return withTemplate("StructuredBuffer");
        case BaseType::ByteAddressBuffer:
            return "ByteAddressBuffer";
        case BaseType::RWStructuredBuffer:
            return withTemplate("RWStructuredBuffer");
        case BaseType::RWByteAddressBuffer:
            return "RWByteAddressBuffer";
        case BaseType::AppendStructuredBuffer:
            return withTemplate("AppendStructuredBuffer");
        case BaseType::ConsumeStructuredBuffer:
            return withTemplate("ConsumeStructuredBuffer");
        case BaseType::RWTexture1D:
            return withTemplate("RWTexture1D");
        case BaseType::RWTexture2D:
            return withTemplate("RWTexture2D");
        case BaseType::RWTexture3D:
            return withTemplate("RWTexture3D");
        case BaseType::RWTexture2DArray:
            return withTemplate("RWTexture2DArray");
        case BaseType::RWBuffer:
            return withTemplate("RWBuffer");
        case BaseType::Sampler:
            return "sampler";
        case BaseType::Sampler1D:
            return "sampler1D";
        case BaseType::Sampler2D:
            return "sampler2D";
        case BaseType::Sampler3D:
            return "sampler3D";
        case BaseType::SamplerCube:
            return "samplerCUBE";
        case BaseType::SamplerState:
            return "SamplerState";
        case BaseType::SamplerComparisonState:
            return "SamplerComparisonState";
        case BaseType::VertexShader:
            return "VertexShader";
        case BaseType::PixelShader:
            return "PixelShader";
        case BaseType::GeometryShader:
            return "GeometryShader";
        case BaseType::HullShader:
            return "HullShader";
        case BaseType::DomainShader:
            return "DomainShader";
        case BaseType::ComputeShader:
            return "ComputeShader";
        case BaseType::RasterizerState:
            return "RasterizerState";
        case BaseType::DepthStencilState:
            return "DepthStencilState";
        case BaseType::BlendState:
            return "BlendState";
        case BaseType::RenderTargetView:
            return "RenderTargetView";
        case BaseType::DepthStencilView:
            return "DepthStencilView";
        case BaseType::Struct:
            return structName;
    }
    if (shape == Shape::Vector) name += std::to_string(cols);
    if (shape == Shape::Matrix) name += std::to_string(rows) + "x" + std::to_string(cols);
    return name;
}

}  // namespace fx
