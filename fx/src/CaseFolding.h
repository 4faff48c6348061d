// CaseFolding: HLSL's names and semantics compared and spelled without regard to case, ASCII letters only
// (equalsIgnoreCase is fx/RenderStates.h's). Private to fx.
#pragma once

#include <string>
#include <string_view>

namespace fx {

// "texcoord0" -> "TEXCOORD0".
std::string upperCase(std::string_view text);

}  // namespace fx
