// PointSprites: D3D9's point sprites (PointSpriteEnable = TRUE) in a pass's GLSL. Private to fx.
#pragma once

#include <string>

namespace fx::detail {

// D3D9 replaced the texture coordinates a pixel shader reads (TEXCOORD0..7) by the position in the point
// sprite, (0, 0) at its top left to (1, 1) at its bottom right: the fragment shader's inputs at those
// varying locations become globals set from gl_PointCoord (u, v, 0, 1 for wider inputs) at the start of
// main. Returns how many inputs it replaced.
int readPointSpriteCoordinates(std::string& fragmentGlsl);

}  // namespace fx::detail
