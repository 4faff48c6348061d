// FixedFunctionPass: D3D9's fixed-function pipeline for the passes of an effect that leave a stage without a
// shader and set its states instead (`WorldTransform[0]`, `LightEnable[0]`, `ColorOp[0]`, `FogEnable`, ...;
// RenderStateDefs.h's fixed-function section, docs/fixed-function.md).
//
// The stage is generated as HLSL, an ordinary function of the effect that the pass compiles
// (`VertexShader = compile vs_3_0 fx_FixedFunctionVS_0_0(<state values>)`), so that it goes through the
// same lowering, glslang, SPIRV-Cross, reflection and cache as the effect's own shaders. Each state value
// is a compile argument: a constant is folded into the code, an expression over parameters (`<g_mWorld>`,
// `(g_LightDiffuse)`) becomes a uniform the runtime re-evaluates when a parameter changes, as D3DX's
// preshaders did. States that choose code (light types, texture-stage operations, fog modes) must be
// constants; switches (`LightEnable[i]`, `SpecularEnable`, `Lighting`, `FogEnable`) may follow parameters.
#pragma once

#include <fx/Diagnostics.h>
#include <fx/Effect.h>

#include <memory>

namespace fx::detail {

// The effect with a generated stage for every D3D9 pass that needs one, and the fixed-function states
// taken out of every pass (a shader stage ignores them, as in D3D9). Returns `effect` itself when no pass
// sets such a state, nullptr after reporting an error.
std::shared_ptr<const Effect> withFixedFunctionStages(std::shared_ptr<const Effect> effect,
                                                      DiagnosticSink& diagnostics);

}  // namespace fx::detail
