// PositionPassThrough: whether a vertex shader hands its input position to the rasterizer unchanged, the
// vertex shader of a post-processing pass whose application drew a quad already in clip space. Private to
// fx.
#pragma once

#include <fx/Effect.h>

namespace fx::detail {

// True when `function` last writes its position output (a return value or `out` parameter with the
// semantic SV_Position or POSITION, or such a member of the struct it returns or of an `out` struct) with
// x and y of its position input (POSITION, or a free name fx/VertexStreams.h reads as one), z the input's
// or a constant in [0, 1] and w the input's or 1: whole, through float2/3/4 constructors of the input's
// swizzles and numbers, or a component at a time; and writes no input on the way (none transformed in
// place, none handed to one of the effect's functions). Only a body the parser read as straight-line code
// (FunctionDecl::straightBody: declarations, assignments, one return at the end) is judged; anything
// else, a branch or a call statement that may write the position, is not a pass-through.
bool passesPositionThrough(const Effect& effect, const FunctionDecl& function);

}  // namespace fx::detail
