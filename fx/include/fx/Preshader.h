// Preshader: compiles effect expressions for the host. D3DX runs the arguments of compile expressions
// (`compile vs_3_0 VS(mul(World, LightViewProj))`), parameter initializers and expression-valued states
// on the CPU; so do we: the effect compiler turns each into a PreshaderProgram over parameter slots
// (fx/PreshaderProgram.h) that the runtime runs when its inputs change.
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
#include <fx/PreshaderProgram.h>
#include <fx/Value.h>

#include <functional>
#include <optional>
#include <string_view>

namespace fx {

// A parameter's slot (its index in the effect) by name; nullopt if there is none.
using SlotResolver = std::function<std::optional<size_t>(std::string_view name)>;

// Compiles `expr` into a program over the slots `slotOf` names. If `targetType` is given, the program
// converts its result to it. Never fails: what cannot be evaluated (an unknown name, a texture) becomes an
// instruction that reports it when the program runs and its value is needed. A program that reads no slot
// is folded to its value.
PreshaderProgram compilePreshader(const Expr& expr, const SlotResolver& slotOf, const TypeDesc* targetType);

// Looks up a parameter's current value by name; nullptr if there is none.
using ParameterLookup = std::function<const Value*(std::string_view name)>;

// Evaluates `expr` once (compilePreshader over the names `lookup` knows, then run). If `targetType` is given,
// the result is converted to it (scalar broadcast, int/bool conversion, initializer lists flattened into
// vectors, matrices and arrays). Reports problems to `diagnostics` (when given) and returns nullopt on error.
std::optional<Value> evaluate(const Expr& expr, const ParameterLookup& lookup, const TypeDesc* targetType,
                              DiagnosticSink* diagnostics);

}  // namespace fx
