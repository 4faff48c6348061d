#include <runtime/RenderStateApplier.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace runtime {

using fx::RenderStateId;

RenderStateBlock RenderStateBlock::defaults() {
    // Straight from the table rather than fx::renderStateInfo(): the same numbers, no lookup per call.
    static const RenderStateBlock block = [] {
        RenderStateBlock result;
        size_t index = 0;
#define FX_RENDER_STATE(name, domain, def) result.values[index++] = double(def);
#include <fx/RenderStateDefs.h>
        return result;
    }();
    return block;
}

GLenum glCompareFromD3d(int d3dCmp) {
    switch (d3dCmp) {
        case 1:
            return GL_NEVER;
        case 2:
            return GL_LESS;
        case 3:
            return GL_EQUAL;
        case 4:
            return GL_LEQUAL;
        case 5:
            return GL_GREATER;
        case 6:
            return GL_NOTEQUAL;
        case 7:
            return GL_GEQUAL;
        default:
            return GL_ALWAYS;  // 8, and nonsense values: never reject a pixel by accident
    }
}

GLenum glBlendFactorFromD3d(int d3dBlend) {
    switch (d3dBlend) {
        case 1:
            return GL_ZERO;
        case 2:
            return GL_ONE;
        case 3:
            return GL_SRC_COLOR;
        case 4:
            return GL_ONE_MINUS_SRC_COLOR;
        case 5:
            return GL_SRC_ALPHA;
        case 6:
            return GL_ONE_MINUS_SRC_ALPHA;
        case 7:
            return GL_DST_ALPHA;
        case 8:
            return GL_ONE_MINUS_DST_ALPHA;
        case 9:
            return GL_DST_COLOR;
        case 10:
            return GL_ONE_MINUS_DST_COLOR;
        case 11:
            return GL_SRC_ALPHA_SATURATE;
        case 14:
            return GL_CONSTANT_COLOR;  // BLENDFACTOR (alpha channel: the constant's alpha, as D3D)
        case 15:
            return GL_ONE_MINUS_CONSTANT_COLOR;
        case 16:
            return GL_SRC1_COLOR;  // D3D10 SRC1_COLOR (D3D9Ex SRCCOLOR2)
        case 17:
            return GL_ONE_MINUS_SRC1_COLOR;
        case 18:
            return GL_SRC1_ALPHA;  // D3D10 SRC1_ALPHA
        case 19:
            return GL_ONE_MINUS_SRC1_ALPHA;
        default:
            return GL_ONE;
    }
}

GLenum glBlendEquationFromD3d(int d3dBlendOp) {
    switch (d3dBlendOp) {
        case 2:
            return GL_FUNC_SUBTRACT;  // src - dst
        case 3:
            return GL_FUNC_REVERSE_SUBTRACT;  // dst - src
        case 4:
            return GL_MIN;  // factors ignored, in D3D and GL alike
        case 5:
            return GL_MAX;
        default:
            return GL_FUNC_ADD;
    }
}

GLenum glStencilOpFromD3d(int d3dStencilOp) {
    switch (d3dStencilOp) {
        case 2:
            return GL_ZERO;
        case 3:
            return GL_REPLACE;
        case 4:
            return GL_INCR;  // INCRSAT: clamps
        case 5:
            return GL_DECR;  // DECRSAT
        case 6:
            return GL_INVERT;
        case 7:
            return GL_INCR_WRAP;  // INCR: wraps
        case 8:
            return GL_DECR_WRAP;
        default:
            return GL_KEEP;
    }
}

namespace {

void enable(GLenum capability, bool on) {
    if (on) {
        gl::Enable(capability);
    } else {
        gl::Disable(capability);
    }
}

}  // namespace

void applyRenderStates(const RenderStateBlock& block, int depthBits) {
    auto value = [&](RenderStateId id) { return block.get(id); };
    auto flag = [&](RenderStateId id) { return value(id) != 0.0; };
    auto integer = [&](RenderStateId id) { return int(value(id)); };
    // Masks and packed colours are 32-bit unsigned values stored as doubles (0xffffffff fits exactly).
    auto bits = [&](RenderStateId id) { return uint32_t(int64_t(value(id))); };

    // [SECTION] Depth. ZEnable = FALSE disables writes too, in D3D and GL; D3DZB_USEW (2) counts as TRUE.
    enable(GL_DEPTH_TEST, flag(RenderStateId::ZEnable));
    gl::DepthMask(flag(RenderStateId::ZWriteEnable) ? GL_TRUE : GL_FALSE);
    gl::DepthFunc(glCompareFromD3d(integer(RenderStateId::ZFunc)));

    // [SECTION] Rasterizer
    gl::FrontFace(kD3dFrontFace);
    switch (integer(RenderStateId::CullMode)) {
        case 2:  // CW: cull clockwise (D3D's front) triangles
            gl::Enable(GL_CULL_FACE);
            gl::CullFace(GL_FRONT);
            break;
        case 3:  // CCW
            gl::Enable(GL_CULL_FACE);
            gl::CullFace(GL_BACK);
            break;
        default:  // NONE
            gl::Disable(GL_CULL_FACE);
            break;
    }
    switch (integer(RenderStateId::FillMode)) {
        case 1:
            gl::PolygonMode(GL_FRONT_AND_BACK, GL_POINT);
            break;
        case 2:
            gl::PolygonMode(GL_FRONT_AND_BACK, GL_LINE);
            break;
        default:
            gl::PolygonMode(GL_FRONT_AND_BACK, GL_FILL);
            break;
    }
    float depthBias = float(value(RenderStateId::DepthBias));
    // D3D10's integer DepthBias is already in GL's units (multiples of the smallest resolvable difference).
    // Its DepthBiasClamp bounds the total offset in depth units, as glPolygonOffsetClamp's `clamp` does
    // (GL 4.6 / ARB_polygon_offset_clamp; without it the bias stays unbounded, and the effect runtime warns).
    float depthBiasUnits = float(value(RenderStateId::DepthBiasUnits));
    float depthBiasClamp = float(value(RenderStateId::DepthBiasClamp));
    float slopeScale = float(value(RenderStateId::SlopeScaleDepthBias));
    bool offset = depthBias != 0.0f || slopeScale != 0.0f || depthBiasUnits != 0.0f;
    enable(GL_POLYGON_OFFSET_FILL, offset);
    enable(GL_POLYGON_OFFSET_LINE, offset);
    enable(GL_POLYGON_OFFSET_POINT, offset);
    const float units = depthBias * std::ldexp(1.0f, depthBits > 0 ? depthBits : 24) + depthBiasUnits;
    if (gl::PolygonOffsetClamp)
        gl::PolygonOffsetClamp(slopeScale, units, depthBiasClamp);
    else
        gl::PolygonOffset(slopeScale, units);
    // D3D9 clamps PointSize to [PointSize_Min, PointSize_Max]; GL refuses a size that is not positive. A
    // vertex shader that writes PSIZE sizes its points itself (GpuProgram::bind, GL_PROGRAM_POINT_SIZE).
    const float pointSize = std::clamp(
        float(value(RenderStateId::PointSize)), float(value(RenderStateId::PointSize_Min)),
        std::max(float(value(RenderStateId::PointSize_Min)), float(value(RenderStateId::PointSize_Max))));
    gl::PointSize(std::isfinite(pointSize) ? std::max(pointSize, 1.0f / 64.0f) : 1.0f);
    enable(GL_SCISSOR_TEST, flag(RenderStateId::ScissorTestEnable));
    enable(GL_MULTISAMPLE, flag(RenderStateId::MultiSampleAntialias));
    enable(GL_DEPTH_CLAMP, !flag(RenderStateId::DepthClipEnable));
    enable(GL_FRAMEBUFFER_SRGB, flag(RenderStateId::SRGBWriteEnable));
    enable(GL_SAMPLE_ALPHA_TO_COVERAGE, flag(RenderStateId::AlphaToCoverageEnable));
    const uint32_t sampleMask = bits(RenderStateId::SampleMask);
    enable(GL_SAMPLE_MASK, sampleMask != 0xffffffffu);
    gl::SampleMaski(0, sampleMask);

    // [SECTION] Blending. One blend state for all targets as in D3D9, or D3D10's independent blend: target
    // i by the states suffixed i (RenderStateDefs.h). The calls without an index set every target, so a
    // pass after an independent one starts from one blend again.
    enable(GL_BLEND, flag(RenderStateId::AlphaBlendEnable));
    GLenum srcColor = glBlendFactorFromD3d(integer(RenderStateId::SrcBlend));
    GLenum dstColor = glBlendFactorFromD3d(integer(RenderStateId::DestBlend));
    GLenum opColor = glBlendEquationFromD3d(integer(RenderStateId::BlendOp));
    GLenum srcAlpha = srcColor, dstAlpha = dstColor, opAlpha = opColor;
    if (flag(RenderStateId::SeparateAlphaBlendEnable)) {
        srcAlpha = glBlendFactorFromD3d(integer(RenderStateId::SrcBlendAlpha));
        dstAlpha = glBlendFactorFromD3d(integer(RenderStateId::DestBlendAlpha));
        opAlpha = glBlendEquationFromD3d(integer(RenderStateId::BlendOpAlpha));
    }
    gl::BlendFuncSeparate(srcColor, dstColor, srcAlpha, dstAlpha);
    gl::BlendEquationSeparate(opColor, opAlpha);
    if (flag(RenderStateId::IndependentBlendEnable)) {
        // The seven states of target i follow target 1's in the table, in the same order.
        constexpr int kPerTarget =
            int(RenderStateId::AlphaBlendEnable2) - int(RenderStateId::AlphaBlendEnable1);
        for (int target = 1; target < 8; ++target) {
            const auto at = [&](RenderStateId target1) {
                return RenderStateId(int(target1) + (target - 1) * kPerTarget);
            };
            const GLuint i = GLuint(target);
            if (flag(at(RenderStateId::AlphaBlendEnable1)))
                gl::Enablei(GL_BLEND, i);
            else
                gl::Disablei(GL_BLEND, i);
            gl::BlendFuncSeparatei(i, glBlendFactorFromD3d(integer(at(RenderStateId::SrcBlend1))),
                                   glBlendFactorFromD3d(integer(at(RenderStateId::DestBlend1))),
                                   glBlendFactorFromD3d(integer(at(RenderStateId::SrcBlendAlpha1))),
                                   glBlendFactorFromD3d(integer(at(RenderStateId::DestBlendAlpha1))));
            gl::BlendEquationSeparatei(i, glBlendEquationFromD3d(integer(at(RenderStateId::BlendOp1))),
                                       glBlendEquationFromD3d(integer(at(RenderStateId::BlendOpAlpha1))));
        }
    }
    uint32_t factor = bits(RenderStateId::BlendFactor);  // D3DCOLOR: 0xAARRGGBB
    gl::BlendColor(float((factor >> 16) & 0xff) / 255.0f, float((factor >> 8) & 0xff) / 255.0f,
                   float(factor & 0xff) / 255.0f, float((factor >> 24) & 0xff) / 255.0f);
    const RenderStateId writeMasks[4] = {RenderStateId::ColorWriteEnable, RenderStateId::ColorWriteEnable1,
                                         RenderStateId::ColorWriteEnable2, RenderStateId::ColorWriteEnable3};
    for (GLuint i = 0; i < 4; ++i) {
        uint32_t mask = bits(writeMasks[i]);  // D3DCOLORWRITEENABLE_RED 1, GREEN 2, BLUE 4, ALPHA 8
        gl::ColorMaski(i, (mask & 1) != 0, (mask & 2) != 0, (mask & 4) != 0, (mask & 8) != 0);
    }

    // [SECTION] Stencil
    enable(GL_STENCIL_TEST, flag(RenderStateId::StencilEnable));
    GLint ref = GLint(bits(RenderStateId::StencilRef));
    GLuint readMask = bits(RenderStateId::StencilMask);
    GLuint writeMask = bits(RenderStateId::StencilWriteMask);
    GLenum frontFunc = glCompareFromD3d(integer(RenderStateId::StencilFunc));
    GLenum frontFail = glStencilOpFromD3d(integer(RenderStateId::StencilFail));
    GLenum frontZFail = glStencilOpFromD3d(integer(RenderStateId::StencilZFail));
    GLenum frontPass = glStencilOpFromD3d(integer(RenderStateId::StencilPass));
    GLenum backFunc = frontFunc, backFail = frontFail, backZFail = frontZFail, backPass = frontPass;
    if (flag(RenderStateId::TwoSidedStencilMode)) {
        backFunc = glCompareFromD3d(integer(RenderStateId::CCW_StencilFunc));
        backFail = glStencilOpFromD3d(integer(RenderStateId::CCW_StencilFail));
        backZFail = glStencilOpFromD3d(integer(RenderStateId::CCW_StencilZFail));
        backPass = glStencilOpFromD3d(integer(RenderStateId::CCW_StencilPass));
    }
    gl::StencilFuncSeparate(GL_FRONT, frontFunc, ref, readMask);
    gl::StencilFuncSeparate(GL_BACK, backFunc, ref, readMask);
    gl::StencilOpSeparate(GL_FRONT, frontFail, frontZFail, frontPass);
    gl::StencilOpSeparate(GL_BACK, backFail, backZFail, backPass);
    gl::StencilMask(writeMask);

    // AlphaTestEnable / AlphaFunc / AlphaRef: no core-profile equivalent; recorded in the block for the
    // shader side (see the header).
}

}  // namespace runtime
