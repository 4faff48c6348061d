// HlslSpelling: effect types and host values written as HLSL text (types, array suffixes, literals) for the
// units the lowering generates. Private to fx.
#pragma once

#include <fx/Effect.h>
#include <fx/Value.h>

#include <string>

namespace fx {

// HLSL spelling of a type for a declaration ("float4x4", "row_major float4x3", "sampler2D").
std::string hlslTypeName(const TypeDesc& type);

// The type of a uniform's declaration (a parameter in the $Global block): hlslTypeName, with an integer or
// bool matrix declared row_major, whose rows are then contiguous in the block as the array of rows
// shadowfx makes of it expects (IntegerMatrixArrays.h; the runtime fills the block by its reflection).
std::string hlslUniformTypeName(const TypeDesc& type);
TypeDesc float4Type();
bool isNumericType(const TypeDesc& t);
bool isSamplerType(const TypeDesc& t);
std::string arraySuffix(const TypeDesc& t);
std::string formatFloat(float x);
// HLSL literal for a host value of type `type` ("float3(1.0, 2.0, 3.0)", "true", "4").
std::string literalText(const Value& v, const TypeDesc& type);
// An expression with no parameter references: it can be folded into the HLSL as a literal.
bool isLiteralOnly(const Expr& e);

}  // namespace fx
