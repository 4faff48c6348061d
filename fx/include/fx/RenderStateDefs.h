// The D3D9 render and sampler states an effect pass or sampler_state block may set, one table for the
// parser (names, value domains), the compiler (normalizing values) and the runtime (GL mapping, defaults).
// Names and enum values are case-insensitive, as in D3DX. Numeric values are D3D9's.
//
// FX_RENDER_STATE(Name, Domain, DefaultValue)      pass states
// FX_SAMPLER_STATE(Name, Domain, DefaultValue)     sampler_state states
// FX_STATE_ALIAS(Alias, Name)                      another spelling of a state (pass or sampler)
// FX_OBJECT_FIELD(Object, Field, Domain, D3D10Default, RenderState)
//                                                  a field of a D3D10 state object (Rasterizer,
//                                                  DepthStencil, Blend) and the pass state it sets
// FX_ENUM_VALUE(Domain, Name, Value)               the named values of an enum domain
//
// Domains: Bool, Int (unsigned/int), Float, Vector (a float4), Matrix (a float4x4), ColorMask
// (ColorWriteEnable flags, or RED|GREEN|...), Shader (VertexShader/PixelShader/GeometryShader), TextureRef
// (Texture = <t>), and the enum domains listed below. Default values are D3D9's documented defaults. Define
// the macros you need; undefined ones expand to nothing. This file undefines them all at the end.

#ifndef FX_RENDER_STATE
#define FX_RENDER_STATE(name, domain, def)
#endif
#ifndef FX_SAMPLER_STATE
#define FX_SAMPLER_STATE(name, domain, def)
#endif
#ifndef FX_STATE_ALIAS
#define FX_STATE_ALIAS(alias, name)
#endif
#ifndef FX_ENUM_VALUE
#define FX_ENUM_VALUE(domain, name, value)
#endif
#ifndef FX_OBJECT_FIELD
#define FX_OBJECT_FIELD(object, field, domain, def, state)
#endif

// [SECTION] Pass states
FX_RENDER_STATE(VertexShader, Shader, 0)
FX_RENDER_STATE(PixelShader, Shader, 0)
FX_RENDER_STATE(GeometryShader, Shader, 0)  // D3D10: SetGeometryShader
FX_RENDER_STATE(HullShader, Shader, 0)      // D3D11: SetHullShader (GL tessellation control)
FX_RENDER_STATE(DomainShader, Shader, 0)    // D3D11: SetDomainShader (GL tessellation evaluation)
FX_RENDER_STATE(ComputeShader, Shader, 0)   // D3D11: SetComputeShader (a pass of its own, dispatched)
FX_RENDER_STATE(ZEnable, Bool, 1)
FX_RENDER_STATE(ZWriteEnable, Bool, 1)
FX_RENDER_STATE(ZFunc, Cmp, 4)      // LESSEQUAL
FX_RENDER_STATE(CullMode, Cull, 3)  // CCW
FX_RENDER_STATE(FillMode, Fill, 3)  // SOLID
FX_RENDER_STATE(AlphaBlendEnable, Bool, 0)
FX_RENDER_STATE(SrcBlend, Blend, 2)   // ONE
FX_RENDER_STATE(DestBlend, Blend, 1)  // ZERO
FX_RENDER_STATE(BlendOp, BlendOp, 1)  // ADD
FX_RENDER_STATE(SeparateAlphaBlendEnable, Bool, 0)
FX_RENDER_STATE(SrcBlendAlpha, Blend, 2)
FX_RENDER_STATE(DestBlendAlpha, Blend, 1)
FX_RENDER_STATE(BlendOpAlpha, BlendOp, 1)
FX_RENDER_STATE(BlendFactor, Color, 0xffffffff)
FX_RENDER_STATE(ColorWriteEnable, ColorMask, 15)
FX_RENDER_STATE(ColorWriteEnable1, ColorMask, 15)
FX_RENDER_STATE(ColorWriteEnable2, ColorMask, 15)
FX_RENDER_STATE(ColorWriteEnable3, ColorMask, 15)
FX_RENDER_STATE(AlphaTestEnable, Bool, 0)
FX_RENDER_STATE(AlphaFunc, Cmp, 8)  // ALWAYS
FX_RENDER_STATE(AlphaRef, Int, 0)
FX_RENDER_STATE(DepthBias, Float, 0)
FX_RENDER_STATE(SlopeScaleDepthBias, Float, 0)
FX_RENDER_STATE(ScissorTestEnable, Bool, 0)
FX_RENDER_STATE(MultiSampleAntialias, Bool, 1)
// D3D10's rasterizer state, accepted in D3D9-style passes: false clamps depth instead of clipping at the near
// and far planes (GL_DEPTH_CLAMP), the "pancaking" of casters in front of a light frustum fitted to
// receivers.
FX_RENDER_STATE(DepthClipEnable, Bool, 1)
// D3D10's rasterizer and blend fields with no D3D9 state. DepthBiasUnits is D3D10's integer DepthBias, in
// multiples of the smallest resolvable depth difference (glPolygonOffset's `units` as they are);
// DepthBiasClamp bounds the total bias (0 = unbounded, as D3D9 always was).
FX_RENDER_STATE(DepthBiasUnits, Float, 0)
FX_RENDER_STATE(DepthBiasClamp, Float, 0)
FX_RENDER_STATE(AntialiasedLineEnable, Bool, 0)
FX_RENDER_STATE(AlphaToCoverageEnable, Bool, 0)
FX_RENDER_STATE(SampleMask, Int, 0xffffffff)
FX_RENDER_STATE(StencilEnable, Bool, 0)
FX_RENDER_STATE(StencilFunc, Cmp, 8)  // ALWAYS
FX_RENDER_STATE(StencilRef, Int, 0)
FX_RENDER_STATE(StencilMask, Int, 0xffffffff)
FX_RENDER_STATE(StencilWriteMask, Int, 0xffffffff)
FX_RENDER_STATE(StencilFail, StencilOp, 1)  // KEEP
FX_RENDER_STATE(StencilZFail, StencilOp, 1)
FX_RENDER_STATE(StencilPass, StencilOp, 1)
FX_RENDER_STATE(TwoSidedStencilMode, Bool, 0)
FX_RENDER_STATE(CCW_StencilFunc, Cmp, 8)
FX_RENDER_STATE(CCW_StencilFail, StencilOp, 1)
FX_RENDER_STATE(CCW_StencilZFail, StencilOp, 1)
FX_RENDER_STATE(CCW_StencilPass, StencilOp, 1)
// Fixed-function states real FX Composer files set; accepted, and without effect on a shader pipeline.
FX_RENDER_STATE(Lighting, Bool, 1)
FX_RENDER_STATE(FogEnable, Bool, 0)
FX_RENDER_STATE(ShadeMode, Shade, 2)  // GOURAUD
FX_RENDER_STATE(DitherEnable, Bool, 0)
FX_RENDER_STATE(SpecularEnable, Bool, 0)
FX_RENDER_STATE(NormalizeNormals, Bool, 0)
FX_RENDER_STATE(PointSpriteEnable, Bool, 0)  // not fixed-function: see the point states below
FX_RENDER_STATE(SRGBWriteEnable, Bool, 0)
// D3D10's independent blend, set from a BlendState's per-target fields (BlendEnable[i], SrcBlend[i], ...):
// with IndependentBlendEnable, render target i (1..7) blends by the states suffixed i and target 0 by the
// unsuffixed ones (glEnablei, glBlendFuncSeparatei, glBlendEquationSeparatei); without it every target
// blends by the unsuffixed ones, as in D3D9.
FX_RENDER_STATE(IndependentBlendEnable, Bool, 0)
#define FX_TARGET_BLEND_STATES(i)                 \
    FX_RENDER_STATE(AlphaBlendEnable##i, Bool, 0) \
    FX_RENDER_STATE(SrcBlend##i, Blend, 2)        \
    FX_RENDER_STATE(DestBlend##i, Blend, 1)       \
    FX_RENDER_STATE(BlendOp##i, BlendOp, 1)       \
    FX_RENDER_STATE(SrcBlendAlpha##i, Blend, 2)   \
    FX_RENDER_STATE(DestBlendAlpha##i, Blend, 1)  \
    FX_RENDER_STATE(BlendOpAlpha##i, BlendOp, 1)
FX_TARGET_BLEND_STATES(1)
FX_TARGET_BLEND_STATES(2)
FX_TARGET_BLEND_STATES(3)
FX_TARGET_BLEND_STATES(4)
FX_TARGET_BLEND_STATES(5)
FX_TARGET_BLEND_STATES(6)
FX_TARGET_BLEND_STATES(7)
#undef FX_TARGET_BLEND_STATES
// D3D9's fixed-function fog, which the SDK's samples switch off beside their shaders (FogTableMode = NONE):
// accepted, and without effect, as FogEnable.
FX_RENDER_STATE(FogColor, Color, 0)
FX_RENDER_STATE(FogTableMode, FogMode, 0)   // NONE
FX_RENDER_STATE(FogVertexMode, FogMode, 0)  // NONE
FX_RENDER_STATE(FogStart, Float, 0)
FX_RENDER_STATE(FogEnd, Float, 1)
FX_RENDER_STATE(FogDensity, Float, 1)
FX_RENDER_STATE(RangeFogEnable, Bool, 0)
// D3D9's points: PointSize (glPointSize) clamped to [PointSize_Min, PointSize_Max], unless the vertex shader
// writes PSIZE (gl_PointSize, GL_PROGRAM_POINT_SIZE). PointSpriteEnable above gives the pixel shader's
// texture coordinates the position in the point (gl_PointCoord). Point scaling is D3D9's fixed-function
// vertex processing, which a vertex shader replaces: accepted, and without effect.
FX_RENDER_STATE(PointSize, Float, 1)
FX_RENDER_STATE(PointSize_Min, Float, 1)
FX_RENDER_STATE(PointSize_Max, Float, 64)
FX_RENDER_STATE(PointScaleEnable, Bool, 0)
FX_RENDER_STATE(PointScale_A, Float, 1)
FX_RENDER_STATE(PointScale_B, Float, 0)
FX_RENDER_STATE(PointScale_C, Float, 0)
// D3D9's fixed-function pipeline: a pass without a vertex or pixel shader runs the stage it lacks from these
// (fx/src/FixedFunctionPass.cpp generates it; docs/fixed-function.md). Indexed states take the light
// (0..7) or texture stage (0..1); the defaults listed are D3D9's. Lighting, SpecularEnable,
// NormalizeNormals and the fog states above belong to the same pipeline.
FX_RENDER_STATE(WorldTransform, Matrix, 0)  // [0] only: no vertex blending
FX_RENDER_STATE(ViewTransform, Matrix, 0)
FX_RENDER_STATE(ProjectionTransform, Matrix, 0)
FX_RENDER_STATE(LightEnable, Bool, 0)
FX_RENDER_STATE(LightType, LightType, 1)  // POINT
FX_RENDER_STATE(LightDiffuse, Vector, 0)
FX_RENDER_STATE(LightSpecular, Vector, 0)
FX_RENDER_STATE(LightAmbient, Vector, 0)
FX_RENDER_STATE(LightPosition, Vector, 0)
FX_RENDER_STATE(LightDirection, Vector, 0)
FX_RENDER_STATE(LightRange, Float, 0)
FX_RENDER_STATE(LightFalloff, Float, 0)
FX_RENDER_STATE(LightAttenuation0, Float, 0)
FX_RENDER_STATE(LightAttenuation1, Float, 0)
FX_RENDER_STATE(LightAttenuation2, Float, 0)
FX_RENDER_STATE(LightTheta, Float, 0)
FX_RENDER_STATE(LightPhi, Float, 0)
FX_RENDER_STATE(MaterialDiffuse, Vector, 0)
FX_RENDER_STATE(MaterialAmbient, Vector, 0)
FX_RENDER_STATE(MaterialSpecular, Vector, 0)
FX_RENDER_STATE(MaterialEmissive, Vector, 0)
FX_RENDER_STATE(MaterialPower, Float, 0)
FX_RENDER_STATE(Ambient, Color, 0)
FX_RENDER_STATE(ColorVertex, Bool, 1)
FX_RENDER_STATE(LocalViewer, Bool, 1)
FX_RENDER_STATE(DiffuseMaterialSource, MaterialSource, 1)   // COLOR1
FX_RENDER_STATE(SpecularMaterialSource, MaterialSource, 2)  // COLOR2
FX_RENDER_STATE(AmbientMaterialSource, MaterialSource, 0)   // MATERIAL
FX_RENDER_STATE(EmissiveMaterialSource, MaterialSource, 0)  // MATERIAL
FX_RENDER_STATE(ColorOp, TextureOp, 4)                      // MODULATE on stage 0, DISABLE after
FX_RENDER_STATE(ColorArg0, TextureArg, 1)                   // CURRENT
FX_RENDER_STATE(ColorArg1, TextureArg, 2)                   // TEXTURE
FX_RENDER_STATE(ColorArg2, TextureArg, 1)                   // CURRENT
FX_RENDER_STATE(AlphaOp, TextureOp, 2)                      // SELECTARG1 on stage 0, DISABLE after
FX_RENDER_STATE(AlphaArg0, TextureArg, 1)
FX_RENDER_STATE(AlphaArg1, TextureArg, 2)
FX_RENDER_STATE(AlphaArg2, TextureArg, 1)
FX_RENDER_STATE(TexCoordIndex, Int, 0)  // the stage's own index
FX_RENDER_STATE(TextureFactor, Color, 0xffffffff)

FX_STATE_ALIAS(ZWriteEnabled, ZWriteEnable)
FX_STATE_ALIAS(DepthEnable, ZEnable)
FX_STATE_ALIAS(DepthWriteEnable, ZWriteEnable)
FX_STATE_ALIAS(DepthFunc, ZFunc)
FX_STATE_ALIAS(ColorWriteEnable0, ColorWriteEnable)
FX_STATE_ALIAS(SlopeScaleBias, SlopeScaleDepthBias)

// [SECTION] Sampler states (inside sampler_state { ... })
FX_SAMPLER_STATE(Texture, TextureRef, 0)
FX_SAMPLER_STATE(AddressU, Address, 1)  // WRAP
FX_SAMPLER_STATE(AddressV, Address, 1)
FX_SAMPLER_STATE(AddressW, Address, 1)
FX_SAMPLER_STATE(BorderColor, Color, 0)
FX_SAMPLER_STATE(MagFilter, TexFilter, 1)  // POINT
FX_SAMPLER_STATE(MinFilter, TexFilter, 1)  // POINT
FX_SAMPLER_STATE(MipFilter, TexFilter, 0)  // NONE
FX_SAMPLER_STATE(MipMapLodBias, Float, 0)
FX_SAMPLER_STATE(MaxMipLevel, Int, 0)
FX_SAMPLER_STATE(MaxAnisotropy, Int, 1)
FX_SAMPLER_STATE(SRGBTexture, Bool, 0)
FX_SAMPLER_STATE(Filter, Filter10, 0x15)          // D3D10 MIN_MAG_MIP_LINEAR; decomposed by the compiler
FX_SAMPLER_STATE(ComparisonFunc, Cmp, 0)          // D3D10 style; 0 = not a comparison sampler
FX_SAMPLER_STATE(MinLOD, Float, -3.402823466e38)  // D3D10 style
FX_SAMPLER_STATE(MaxLOD, Float, 3.402823466e38)

FX_STATE_ALIAS(AddressS, AddressU)
FX_STATE_ALIAS(AddressT, AddressV)
FX_STATE_ALIAS(AddressR, AddressW)
FX_STATE_ALIAS(MipMapLODBias, MipMapLodBias)
FX_STATE_ALIAS(MipLODBias, MipMapLodBias)

// [SECTION] D3D10 state objects
// Every field of D3D10/11's RasterizerState, DepthStencilState and BlendState with its D3D10 default (which
// is what a field a state object leaves out takes, and what a technique10/11 pass that sets no such object
// runs with). Where D3D10 and D3D9 differ: DepthFunc LESS (D3D9 LESSEQUAL), stencil masks 0xff (D3D9
// 0xffffffff), MultisampleEnable false (D3D9 true). CullMode is folded with FrontCounterClockwise into
// D3D9's CullMode by the parser; BlendEnable[i] and RenderTargetWriteMask[i] take a render-target index.
FX_OBJECT_FIELD(Rasterizer, FillMode, Fill, 3, FillMode)    // SOLID
FX_OBJECT_FIELD(Rasterizer, CullMode, Cull10, 3, CullMode)  // BACK
FX_OBJECT_FIELD(Rasterizer, FrontCounterClockwise, Bool, 0, CullMode)
FX_OBJECT_FIELD(Rasterizer, DepthBias, Int, 0, DepthBiasUnits)
FX_OBJECT_FIELD(Rasterizer, DepthBiasClamp, Float, 0, DepthBiasClamp)
FX_OBJECT_FIELD(Rasterizer, SlopeScaledDepthBias, Float, 0, SlopeScaleDepthBias)
FX_OBJECT_FIELD(Rasterizer, DepthClipEnable, Bool, 1, DepthClipEnable)
FX_OBJECT_FIELD(Rasterizer, ScissorEnable, Bool, 0, ScissorTestEnable)
FX_OBJECT_FIELD(Rasterizer, MultisampleEnable, Bool, 0, MultiSampleAntialias)
FX_OBJECT_FIELD(Rasterizer, AntialiasedLineEnable, Bool, 0, AntialiasedLineEnable)
FX_OBJECT_FIELD(DepthStencil, DepthEnable, Bool, 1, ZEnable)
FX_OBJECT_FIELD(DepthStencil, DepthWriteMask, DepthWriteMask, 1, ZWriteEnable)  // ALL
FX_OBJECT_FIELD(DepthStencil, DepthFunc, Cmp, 2, ZFunc)                         // LESS
FX_OBJECT_FIELD(DepthStencil, StencilEnable, Bool, 0, StencilEnable)
FX_OBJECT_FIELD(DepthStencil, StencilReadMask, Int, 0xff, StencilMask)
FX_OBJECT_FIELD(DepthStencil, StencilWriteMask, Int, 0xff, StencilWriteMask)
FX_OBJECT_FIELD(DepthStencil, FrontFaceStencilFunc, Cmp, 8, StencilFunc)        // ALWAYS
FX_OBJECT_FIELD(DepthStencil, FrontFaceStencilFail, StencilOp, 1, StencilFail)  // KEEP
FX_OBJECT_FIELD(DepthStencil, FrontFaceStencilDepthFail, StencilOp, 1, StencilZFail)
FX_OBJECT_FIELD(DepthStencil, FrontFaceStencilPass, StencilOp, 1, StencilPass)
FX_OBJECT_FIELD(DepthStencil, BackFaceStencilFunc, Cmp, 8, CCW_StencilFunc)
FX_OBJECT_FIELD(DepthStencil, BackFaceStencilFail, StencilOp, 1, CCW_StencilFail)
FX_OBJECT_FIELD(DepthStencil, BackFaceStencilDepthFail, StencilOp, 1, CCW_StencilZFail)
FX_OBJECT_FIELD(DepthStencil, BackFaceStencilPass, StencilOp, 1, CCW_StencilPass)
FX_OBJECT_FIELD(Blend, AlphaToCoverageEnable, Bool, 0, AlphaToCoverageEnable)
FX_OBJECT_FIELD(Blend, BlendEnable, Bool, 0, AlphaBlendEnable)
FX_OBJECT_FIELD(Blend, SrcBlend, Blend, 2, SrcBlend)    // ONE
FX_OBJECT_FIELD(Blend, DestBlend, Blend, 1, DestBlend)  // ZERO
FX_OBJECT_FIELD(Blend, BlendOp, BlendOp, 1, BlendOp)    // ADD
FX_OBJECT_FIELD(Blend, SrcBlendAlpha, Blend, 2, SrcBlendAlpha)
FX_OBJECT_FIELD(Blend, DestBlendAlpha, Blend, 1, DestBlendAlpha)
FX_OBJECT_FIELD(Blend, BlendOpAlpha, BlendOp, 1, BlendOpAlpha)
FX_OBJECT_FIELD(Blend, RenderTargetWriteMask, ColorMask, 15, ColorWriteEnable)

// [SECTION] Enum domains (D3D9 numeric values)
FX_ENUM_VALUE(Bool, False, 0)
FX_ENUM_VALUE(Bool, True, 1)
FX_ENUM_VALUE(Cull, None, 1)
FX_ENUM_VALUE(Cull, CW, 2)
FX_ENUM_VALUE(Cull, CCW, 3)
FX_ENUM_VALUE(Fill, Point, 1)
FX_ENUM_VALUE(Fill, Wireframe, 2)
FX_ENUM_VALUE(Fill, Solid, 3)
FX_ENUM_VALUE(Cull10, None, 1)  // D3D10_CULL_MODE: which faces, not which winding
FX_ENUM_VALUE(Cull10, Front, 2)
FX_ENUM_VALUE(Cull10, Back, 3)
FX_ENUM_VALUE(DepthWriteMask, Zero, 0)
FX_ENUM_VALUE(DepthWriteMask, All, 1)
FX_ENUM_VALUE(FogMode, None, 0)
FX_ENUM_VALUE(FogMode, Exp, 1)
FX_ENUM_VALUE(FogMode, Exp2, 2)
FX_ENUM_VALUE(FogMode, Linear, 3)
FX_ENUM_VALUE(LightType, Point, 1)
FX_ENUM_VALUE(LightType, Spot, 2)
FX_ENUM_VALUE(LightType, Directional, 3)
FX_ENUM_VALUE(MaterialSource, Material, 0)
FX_ENUM_VALUE(MaterialSource, Color1, 1)
FX_ENUM_VALUE(MaterialSource, Color2, 2)
FX_ENUM_VALUE(TextureOp, Disable, 1)
FX_ENUM_VALUE(TextureOp, SelectArg1, 2)
FX_ENUM_VALUE(TextureOp, SelectArg2, 3)
FX_ENUM_VALUE(TextureOp, Modulate, 4)
FX_ENUM_VALUE(TextureOp, Modulate2x, 5)
FX_ENUM_VALUE(TextureOp, Modulate4x, 6)
FX_ENUM_VALUE(TextureOp, Add, 7)
FX_ENUM_VALUE(TextureOp, AddSigned, 8)
FX_ENUM_VALUE(TextureOp, AddSigned2x, 9)
FX_ENUM_VALUE(TextureOp, Subtract, 10)
FX_ENUM_VALUE(TextureOp, AddSmooth, 11)
FX_ENUM_VALUE(TextureOp, BlendDiffuseAlpha, 12)
FX_ENUM_VALUE(TextureOp, BlendTextureAlpha, 13)
FX_ENUM_VALUE(TextureOp, BlendFactorAlpha, 14)
FX_ENUM_VALUE(TextureOp, BlendTextureAlphaPM, 15)
FX_ENUM_VALUE(TextureOp, BlendCurrentAlpha, 16)
FX_ENUM_VALUE(TextureOp, PreModulate, 17)
FX_ENUM_VALUE(TextureOp, ModulateAlpha_AddColor, 18)
FX_ENUM_VALUE(TextureOp, ModulateColor_AddAlpha, 19)
FX_ENUM_VALUE(TextureOp, ModulateInvAlpha_AddColor, 20)
FX_ENUM_VALUE(TextureOp, ModulateInvColor_AddAlpha, 21)
FX_ENUM_VALUE(TextureOp, BumpEnvMap, 22)
FX_ENUM_VALUE(TextureOp, BumpEnvMapLuminance, 23)
FX_ENUM_VALUE(TextureOp, DotProduct3, 24)
FX_ENUM_VALUE(TextureOp, MultiplyAdd, 25)
FX_ENUM_VALUE(TextureOp, Lerp, 26)
// D3DTA_*: a source, optionally | Complement (1 - x) and | AlphaReplicate (x.aaaa).
FX_ENUM_VALUE(TextureArg, Diffuse, 0)
FX_ENUM_VALUE(TextureArg, Current, 1)
FX_ENUM_VALUE(TextureArg, Texture, 2)
FX_ENUM_VALUE(TextureArg, TFactor, 3)
FX_ENUM_VALUE(TextureArg, Specular, 4)
FX_ENUM_VALUE(TextureArg, Temp, 5)
FX_ENUM_VALUE(TextureArg, Constant, 6)
FX_ENUM_VALUE(TextureArg, Complement, 0x10)
FX_ENUM_VALUE(TextureArg, AlphaReplicate, 0x20)
FX_ENUM_VALUE(Shade, Flat, 1)
FX_ENUM_VALUE(Shade, Gouraud, 2)
FX_ENUM_VALUE(Shade, Phong, 3)
FX_ENUM_VALUE(Cmp, Never, 1)
FX_ENUM_VALUE(Cmp, Less, 2)
FX_ENUM_VALUE(Cmp, Equal, 3)
FX_ENUM_VALUE(Cmp, LessEqual, 4)
FX_ENUM_VALUE(Cmp, Greater, 5)
FX_ENUM_VALUE(Cmp, NotEqual, 6)
FX_ENUM_VALUE(Cmp, GreaterEqual, 7)
FX_ENUM_VALUE(Cmp, Always, 8)
FX_ENUM_VALUE(Blend, Zero, 1)
FX_ENUM_VALUE(Blend, One, 2)
FX_ENUM_VALUE(Blend, SrcColor, 3)
FX_ENUM_VALUE(Blend, InvSrcColor, 4)
FX_ENUM_VALUE(Blend, SrcAlpha, 5)
FX_ENUM_VALUE(Blend, InvSrcAlpha, 6)
FX_ENUM_VALUE(Blend, DestAlpha, 7)
FX_ENUM_VALUE(Blend, InvDestAlpha, 8)
FX_ENUM_VALUE(Blend, DestColor, 9)
FX_ENUM_VALUE(Blend, InvDestColor, 10)
FX_ENUM_VALUE(Blend, SrcAlphaSat, 11)
FX_ENUM_VALUE(Blend, BlendFactor, 14)
FX_ENUM_VALUE(Blend, InvBlendFactor, 15)
// Dual-source blending: the pixel shader's second output (SV_Target1) as the source (GL 3.3's GL_SRC1_*).
FX_ENUM_VALUE(Blend, Src1Color, 16)
FX_ENUM_VALUE(Blend, InvSrc1Color, 17)
FX_ENUM_VALUE(Blend, Src1Alpha, 18)
FX_ENUM_VALUE(Blend, InvSrc1Alpha, 19)
FX_ENUM_VALUE(BlendOp, Add, 1)
FX_ENUM_VALUE(BlendOp, Subtract, 2)
FX_ENUM_VALUE(BlendOp, RevSubtract, 3)
FX_ENUM_VALUE(BlendOp, Min, 4)
FX_ENUM_VALUE(BlendOp, Max, 5)
FX_ENUM_VALUE(StencilOp, Keep, 1)
FX_ENUM_VALUE(StencilOp, Zero, 2)
FX_ENUM_VALUE(StencilOp, Replace, 3)
FX_ENUM_VALUE(StencilOp, IncrSat, 4)
FX_ENUM_VALUE(StencilOp, DecrSat, 5)
FX_ENUM_VALUE(StencilOp, Invert, 6)
FX_ENUM_VALUE(StencilOp, Incr, 7)
FX_ENUM_VALUE(StencilOp, Decr, 8)
FX_ENUM_VALUE(ColorMask, Red, 1)
FX_ENUM_VALUE(ColorMask, Green, 2)
FX_ENUM_VALUE(ColorMask, Blue, 4)
FX_ENUM_VALUE(ColorMask, Alpha, 8)
// MonoGame's names for every channel and for none (its effect compiler also takes true and false).
FX_ENUM_VALUE(ColorMask, All, 15)
FX_ENUM_VALUE(ColorMask, None, 0)
FX_ENUM_VALUE(Address, Wrap, 1)
FX_ENUM_VALUE(Address, Mirror, 2)
FX_ENUM_VALUE(Address, Clamp, 3)
FX_ENUM_VALUE(Address, Border, 4)
FX_ENUM_VALUE(Address, MirrorOnce, 5)
FX_ENUM_VALUE(TexFilter, None, 0)
FX_ENUM_VALUE(TexFilter, Point, 1)
FX_ENUM_VALUE(TexFilter, Linear, 2)
FX_ENUM_VALUE(TexFilter, Anisotropic, 3)
FX_ENUM_VALUE(TexFilter, PyramidalQuad, 6)
FX_ENUM_VALUE(TexFilter, GaussianQuad, 7)
// D3D10_FILTER values: bits 4-5 min, 2-3 mag, 0-1 mip (1 = linear), 0x40 anisotropic, 0x80 comparison.
FX_ENUM_VALUE(Filter10, MIN_MAG_MIP_POINT, 0x00)
FX_ENUM_VALUE(Filter10, MIN_MAG_POINT_MIP_LINEAR, 0x01)
FX_ENUM_VALUE(Filter10, MIN_POINT_MAG_LINEAR_MIP_POINT, 0x04)
FX_ENUM_VALUE(Filter10, MIN_POINT_MAG_MIP_LINEAR, 0x05)
FX_ENUM_VALUE(Filter10, MIN_LINEAR_MAG_MIP_POINT, 0x10)
FX_ENUM_VALUE(Filter10, MIN_LINEAR_MAG_POINT_MIP_LINEAR, 0x11)
FX_ENUM_VALUE(Filter10, MIN_MAG_LINEAR_MIP_POINT, 0x14)
FX_ENUM_VALUE(Filter10, MIN_MAG_MIP_LINEAR, 0x15)
FX_ENUM_VALUE(Filter10, ANISOTROPIC, 0x55)
FX_ENUM_VALUE(Filter10, COMPARISON_MIN_MAG_MIP_POINT, 0x80)
FX_ENUM_VALUE(Filter10, COMPARISON_MIN_MAG_POINT_MIP_LINEAR, 0x81)
FX_ENUM_VALUE(Filter10, COMPARISON_MIN_POINT_MAG_LINEAR_MIP_POINT, 0x84)
FX_ENUM_VALUE(Filter10, COMPARISON_MIN_POINT_MAG_MIP_LINEAR, 0x85)
FX_ENUM_VALUE(Filter10, COMPARISON_MIN_LINEAR_MAG_MIP_POINT, 0x90)
FX_ENUM_VALUE(Filter10, COMPARISON_MIN_LINEAR_MAG_POINT_MIP_LINEAR, 0x91)
FX_ENUM_VALUE(Filter10, COMPARISON_MIN_MAG_LINEAR_MIP_POINT, 0x94)
FX_ENUM_VALUE(Filter10, COMPARISON_MIN_MAG_MIP_LINEAR, 0x95)
FX_ENUM_VALUE(Filter10, COMPARISON_ANISOTROPIC, 0xd5)

#undef FX_RENDER_STATE
#undef FX_SAMPLER_STATE
#undef FX_STATE_ALIAS
#undef FX_ENUM_VALUE
#undef FX_OBJECT_FIELD
