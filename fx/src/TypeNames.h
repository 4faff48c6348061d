// TypeNames: HLSL's spellings of scalar, vector, matrix and object types read into a TypeDesc, for the
// parser and the constant folder. Private to fx.
#pragma once

#include <fx/Effect.h>

#include <string>

namespace fx::detail {

// "float", "float3", "float4x4", "int2", "bool", "half3x3", "dword" ...
bool parseScalarTypeName(const std::string& name, TypeDesc& type);
// "texture", "sampler2D", "Texture2D", "SamplerState", "VertexShader", "BlendState" ...
bool parseObjectTypeName(const std::string& name, TypeDesc& type);

}  // namespace fx::detail
