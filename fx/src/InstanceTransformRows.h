// InstanceTransformRows: the vertex inputs a vertex shader assembles into a per-instance transform. Private
// to fx.
#pragma once

#include <fx/Effect.h>

#include <map>
#include <string>

namespace fx::detail {

// Instancing input layouts carry an instance's transform as four float4 rows at consecutive semantic
// indices, which the vertex shader assembles (`float4x4(In.vRight, In.vUp, In.vLook, In.vTranslation)`,
// or `matrix(...)`): each such input of `function`, by its path in the function's terms (`In.vRight`; a
// parameter's name where the input is a parameter of its own), and the row it is. Read on the straight-line
// body (FunctionDecl::straightBody); empty for any other body, and where no constructor takes four float4
// inputs that no mesh stream feeds (TEXCOORD1 and up, COLOR, free names).
std::map<std::string, int> instanceTransformRows(const Effect& effect, const FunctionDecl& function);

}  // namespace fx::detail
