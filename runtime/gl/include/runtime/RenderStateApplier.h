// RenderStateApplier: a pass's D3D9 render states (fx/RenderStateDefs.h, D3D9 numeric values) applied to
// GL. Every state is applied on every call, so a state a pass does not set returns to its D3D default
// (RenderStateBlock::defaults()) instead of leaking from the previous pass; the ~40 GL calls cost nothing
// next to a draw.
//
// Mapping decisions (the "why" for each lives next to the code in RenderStateApplier.cpp):
// - CullMode: D3D culls by on-screen winding (y down): CW culls clockwise triangles, CCW counter-
//   clockwise ones. Under the runtime's glClipControl(GL_UPPER_LEFT, ...) GL evaluates winding with the
//   window y axis pointing down, i.e. as D3D sees the screen, so glFrontFace(GL_CW) makes GL's "front" be
//   D3D's clockwise front; CCW -> glCullFace(GL_BACK), CW -> glCullFace(GL_FRONT). Pinned by
//   test_gl_states (CullConvention*).
// - DepthBias: D3D9 adds DepthBias to the depth value itself; glPolygonOffset's `units` are multiples of
//   the smallest resolvable depth difference r, r = 2^-24 for 24-bit depth. units = DepthBias * 2^depthBits
//   with depthBits the bound depth target's (24 unless told; 16 for D16). For D32F GL's r depends on the
//   primitive's depth exponent; 2^24 is exact for depths in [0.5, 1), the usual range of perspective
//   depth. SlopeScaleDepthBias -> `factor` as is (both multiply the maximum depth slope).
//   Measured on llvmpipe (Mesa 22.3): D32F gets exactly DepthBias; D16/D24 get 2 x DepthBias, because GL
//   leaves r implementation-defined and llvmpipe uses 2 / 2^bits for UNORM depth. Pinned by
//   test_gl_states (DepthBiasOffsetsDepthInDepthUnits); prefer D32F shadow maps where the bias matters.
//   D3D10's DepthBiasClamp -> glPolygonOffsetClamp's `clamp` where the context has it
//   (gl::PolygonOffsetClamp).
// - AlphaTestEnable/AlphaFunc/AlphaRef: the core profile has no alpha test. They are recorded in the
//   block and left to shaders (the effect compiler or the pass's own clip()); applyRenderStates ignores
//   them.
// - StencilEnable with TwoSidedStencilMode: D3D's Stencil* states apply to clockwise (front) triangles,
//   CCW_* to counter-clockwise ones: GL_FRONT and GL_BACK under the front-face convention above.
// - Fixed-function states (Lighting, FogEnable, ShadeMode, ...) have no effect. SRGBWriteEnable toggles
//   GL_FRAMEBUFFER_SRGB, which only matters for sRGB targets (the runtime creates none).
// Scissor rectangles and viewports are not render states: the caller sets them.
#pragma once

#include <runtime/GlApi.h>

#include <fx/RenderStates.h>

#include <array>
#include <cstddef>

namespace runtime {

struct RenderStateBlock {
    std::array<double, size_t(fx::RenderStateId::Count)> values{};

    // Every state at its D3D9 default (the table's third column).
    static RenderStateBlock defaults();

    double get(fx::RenderStateId id) const { return values[size_t(id)]; }
    void set(fx::RenderStateId id, double value) { values[size_t(id)] = value; }
};

// Applies every state of `block` to the current context. `depthBits`: the bound depth target's bits, for
// DepthBias scaling (see above).
void applyRenderStates(const RenderStateBlock& block, int depthBits = 24);

// The GL enums behind the D3D9 values (exposed for tests and for the comparison sampler).
GLenum glCompareFromD3d(int d3dCmp);
GLenum glBlendFactorFromD3d(int d3dBlend);
GLenum glBlendEquationFromD3d(int d3dBlendOp);
GLenum glStencilOpFromD3d(int d3dStencilOp);

// The front-face convention (see above): glFrontFace value under the runtime's clip control.
constexpr GLenum kD3dFrontFace = GL_CW;

}  // namespace runtime
