// PositionPassThrough: whether a vertex shader hands its input position to the rasterizer unchanged, the
// vertex shader of a post-processing pass whose application drew a quad already in clip space. Private to
// fx.
#pragma once

#include <fx/Effect.h>

namespace fx::detail {

// True when `function` writes its position output (a return value or `out` parameter with the semantic
// SV_Position or POSITION, or such a member of the struct it returns) as its position input (POSITION, or
// a free name fx/VertexStreams.h reads as one): the whole input, or its `xy`/`xyz` completed to a float4 by
// constants (`float4(In.Pos, 1)`, `float4(In.Pos.xy, 0, 1)`), by the last write before the return. Only a
// body the parser read as straight-line code (FunctionDecl::straightBody: declarations, assignments, one
// return at the end) is judged; anything else, a branch or a call that may write the position, is not a
// pass-through.
bool passesPositionThrough(const Effect& effect, const FunctionDecl& function);

}  // namespace fx::detail
