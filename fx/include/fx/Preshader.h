// Preshader: evaluates effect expressions on the host. D3DX runs the arguments of compile expressions
// (`compile vs_3_0 VS(mul(World, LightViewProj))`), parameter initializers and expression-valued states
// on the CPU; so do we, every frame for what depends on parameters.
//
// Supported: number/bool/string literals, parameter references, unary/binary/ternary operators
// (component-wise, with HLSL scalar broadcast), constructors (float4(...), float4x4(...)), casts,
// initializer lists, swizzles and matrix members (._13, ._m02), indexing, and the intrinsics real effect
// files use here: mul, transpose, inverse (determinant-based), determinant, normalize, length, dot, cross,
// abs, min, max, clamp, saturate, lerp, sqrt, rsqrt, pow, exp, log, sin, cos, tan, asin, acos, atan,
// atan2, radians, degrees, floor, ceil, frac, fmod, step, smoothstep, sign.
#pragma once

#include <fx/Diagnostics.h>
#include <fx/Effect.h>
#include <fx/Value.h>

#include <functional>
#include <optional>
#include <string_view>

namespace fx {

// Looks up a parameter's current value by name; nullptr if there is none.
using ParameterLookup = std::function<const Value*(std::string_view name)>;

// Evaluates `expr`. If `targetType` is given, the result is converted to it (scalar broadcast, int/bool
// conversion, initializer lists flattened into vectors, matrices and arrays). Reports problems to
// `diagnostics` (when given) and returns nullopt on error.
std::optional<Value> evaluate(const Expr& expr, const ParameterLookup& lookup, const TypeDesc* targetType,
                              DiagnosticSink* diagnostics);

}  // namespace fx
