// HlslRewriting: the lowering's edits of the user's HLSL text, made on identifiers outside comments and
// string literals: the intrinsic calls glslang gets wrong or cannot express rewritten, the names a text
// uses collected. Private to fx.
#pragma once

#include <fx/Types.h>

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>

namespace fx {

// glslang 12.0 decomposes HLSL's lit() with n.h * m where HLSL specifies pow(n.h, m) (its specular term
// then grows linearly with the exponent and saturates everything lit). Every unit gets a correct lit and
// calls of lit( are renamed to it by rewriteIntrinsics. HLSL: lit(n.l, n.h, m) = (1, max(n.l, 0),
// (n.l < 0 || n.h < 0) ? 0 : pow(n.h, m), 1).
inline constexpr const char* kLitReplacement =
    "float4 fx_lit(float n_dot_l, float n_dot_h, float m)\n"
    "{ return float4(1, max(n_dot_l, 0), (n_dot_l < 0 || n_dot_h < 0) ? 0 : pow(max(n_dot_h, 0), m), 1); }\n";

bool isIdentChar(char c);
// Identifiers of HLSL text, skipping comments and string literals.
std::set<std::string> identifiersIn(const std::string& text);
// Rewrites, token by token (comments untouched), the intrinsic calls glslang gets wrong or cannot express:
// `lit(` -> `fx_lit(` (see kLitReplacement), and `tex2D(S,` (`tex2Dproj`, `tex2Dlod`, `tex2Dbias`) for
// the depth samplers S into calls of the comparison helpers. A depth sampler that a shader's compile argument
// names is bound into the entry point first (bindParameters), and one passed on to a function's sampler
// parameter into a copy of that function (bindCallArguments), so that every lookup names S itself.
std::string rewriteIntrinsics(const std::string& text, const std::set<std::string>& depthSamplers);
// The D3D9 shadow-map lookups on a comparison sampler: the result of comparing the reference depth with
// the texel (filtered when the sampler filters linearly), in every component; tex2Dlod, tex2Dbias and
// tex2D with gradients compare as tex2D does (a shadow map has one level).
std::string depthSamplerHelpers(const std::string& s);
// A function's definition `text` (named `name`, renamed `newName`) with the parameters that `bound` maps
// taken out of its signature, and each use of them in the body naming the effect object they map to
// instead: D3DX bound a sampler or texture compile argument when it compiled the shader. Line breaks are
// kept, so the text's `#line` still holds. nullopt where the signature does not have `parameterCount`
// parameters as written.
std::optional<std::string> bindParameters(const std::string& text, const std::string& name,
                                          const std::string& newName, size_t parameterCount,
                                          const std::map<std::string, std::string>& bound);
// Decides a call whose arguments at the map's indices are exactly the objects it names: the name of the
// function to call instead with those arguments left out, or nullopt to keep the call as written.
using CallBinder = std::function<std::optional<std::string>(const std::string& function, size_t argumentCount,
                                                            const std::map<size_t, std::string>& objects)>;
// `text` with each call (not a member call) having an argument that is exactly one of `objects` put to
// `binder`, innermost calls' arguments included. The line breaks of a left-out argument are kept.
std::string bindCallArguments(const std::string& text, const std::set<std::string>& objects,
                              const CallBinder& binder);

// fxc flattened a brace initializer completely, so a static array of matrices may list its rows in braces
// without grouping them by matrix: `static const uint4x4 R[2] = { {1,0,0,0}, {0,1,0,0}, ... };` (eight
// rows). glslang matches braces to the type's levels and refuses that (`cannot convert parameter 5 from
// 'const float'`). For a declaration of a matrix or an array of matrices (`type`) whose initializer lists
// exactly as many values as the matrices have elements, this returns the declaration with the values
// regrouped one brace per matrix (`{ {16 values}, {16 values} }`), line breaks kept; any other
// declaration unchanged (values that are vectors or constructors, `uint4x4(...)`, count otherwise).
std::string regroupMatrixInitializer(const std::string& declaration, const TypeDesc& type);

}  // namespace fx
