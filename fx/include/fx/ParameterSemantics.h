// ParameterSemantics: what the runtime gives a parameter by its semantic (docs/effect-format.md, "What the
// runtime provides"), classified once by the compiler from the semantic as written (case-blind, as D3DX
// and SAS match them) or, for a parameter written without one, from its conventional name. The runtime
// binds by the enum and never reads the semantic's text.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace fx {

enum class SemanticKind {
    None,  // no semantic, or the user's own: the parameter keeps the value it is given
    // Matrices; SemanticBinding::inverse and ::transpose say which variant.
    World,
    View,
    Projection,
    WorldView,
    ViewProjection,
    WorldViewProjection,
    ViewportPixelSize,
    Time,
    CameraPosition,
    ObjectId,
    // A light's properties: SemanticBinding::light names the light. Position and Direction written
    // without a light annotation are the object's, which nothing supplies: they keep light -1.
    LightPosition,
    LightDirection,
    LightColor,
    LightAreaRadius,
    LightRange,  // the distance from the light past the scene's farthest point: a point light's reach
    ObjectColor,
    Ambient,
    LightCount,  // how many lights the scene has (at most the length of the effect's per-light arrays)
    SceneHasClosedObjects,
    CascadeViewProjection,  // a light's cascades (arrays, one element per cascade)
    CascadeAtlasRects,
    CascadeSplitDepths,
    CubeFaceSelect,
    // Skinning palettes (arrays of matrices) of a mesh drawn as modelled: every element the object's World
    // (the DirectX SDK's WORLDMATRIXARRAY, bones already placed in the world), or every element the
    // identity (bones a World transform follows, XNA's `Bones`).
    WorldMatrixArray,
    BonePalette,
    // FX Composer's reset pulse: true in the first frame after the effect is created or reset, false in
    // the others.
    ResetPulse,
    // Tunables the light fits read (runtime/LightParameterization.h), not bound.
    LispsmNScale,
    LispsmNOpt,
    LispsmDepthExtent,
    LispsmMiddleVector,
    LightPancaking,
    TsmFocus,
    PsmSlideBack,
    PsmMaxWarpRatio,
    CascadeCount,
    CascadeSplitLambda,
    CascadeBlend,
    LightFitVisibleSamples,
    StandardsGlobal,  // the parameter whose Script the compiler reads (fx/SasScript.h)
};

struct SemanticBinding {
    SemanticKind kind = SemanticKind::None;
    bool inverse = false;  // a matrix's Inverse / InverseTranspose suffix
    bool transpose = false;
    // Read from the parameter's name (`gWorldViewProj`): it was written without a semantic.
    bool byName = false;
    // A light property of a one-dimensional array without a light annotation (`float3 g_LightDir[3]`):
    // element k is the scene's k-th light, zero past the last one; `light` stays -1.
    bool eachLight = false;
    // A light's position or direction in the view space of the render port (`g_ViewSpaceLightDir`), not
    // in world space.
    bool viewSpace = false;
    // A light direction that points from the scene towards the light, as the D3D samples that set one by
    // name use it (`dot(N, g_LightDir)`); the LightDirection semantic, as SAS's Direction, points from
    // the light into the scene.
    bool towardsLight = false;
    // CompiledEffect::lights index of the light whose matrices or properties the value is (a `frustum` or
    // `Object` annotation, or light0 for a light property without one); -1: the render port's or the
    // object's.
    int light = -1;
};

// True for the kinds the runtime writes a value for (neither None, a tunable nor StandardsGlobal).
bool isBoundSemantic(SemanticKind kind);
// The semantic as the docs spell it, with a matrix's suffix ("WorldViewProjectionInverse") or what a
// light property's flags say ("LightDirection of each light in view space"), and the light it is read
// from where `lightName` is given ("LightColor of light1"); "" for None.
std::string semanticBindingName(const SemanticBinding& binding, std::string_view lightName = {});
// Every semantic the runtime gives a value or reads, as the docs spell them (shadowfx info lists them).
std::vector<std::string> standardSemanticNames();

}  // namespace fx
