// The D3D9 state table (RenderStateDefs.h) as C++ types: ids, value domains, defaults, and
// case-insensitive lookup of state names and enum values, as D3DX does.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fx {

enum class StateDomain {
    Bool,
    Int,
    Float,
    Color,       // a packed D3DCOLOR or a float4
    ColorMask,   // ColorWriteEnable: 0..15, or RED|GREEN|BLUE|ALPHA
    Shader,      // compile vs_3_0 Func(...), a shader variable, or NULL
    TextureRef,  // <textureName> or (textureName)
    Cull,
    Fill,
    Shade,
    Cmp,
    Blend,
    BlendOp,
    StencilOp,
    Address,
    TexFilter,
    Filter10,        // D3D10 Filter = MIN_MAG_LINEAR_MIP_POINT
    Cull10,          // D3D10 CullMode: NONE, FRONT, BACK
    DepthWriteMask,  // D3D10 DepthWriteMask: ZERO, ALL
    FogMode,         // FogTableMode, FogVertexMode: NONE, EXP, EXP2, LINEAR
    Vector,          // a float4 expression (light and material colours, light positions)
    Matrix,          // a float4x4 expression (WorldTransform[0], ViewTransform, ProjectionTransform)
    LightType,       // POINT, SPOT, DIRECTIONAL
    MaterialSource,  // MATERIAL, COLOR1, COLOR2
    TextureOp,       // D3DTOP_*: DISABLE, SELECTARG1, MODULATE, ...
    TextureArg,      // D3DTA_*: DIFFUSE, CURRENT, TEXTURE, ... | COMPLEMENT | ALPHAREPLICATE
};

enum class RenderStateId {
#define FX_RENDER_STATE(name, domain, def) name,
#include <fx/RenderStateDefs.h>
    Count
};

enum class SamplerStateId {
#define FX_SAMPLER_STATE(name, domain, def) name,
#include <fx/RenderStateDefs.h>
    Count
};

// The D3D10 state objects (RenderStateDefs.h, FX_OBJECT_FIELD).
enum class StateObjectKind { Rasterizer, DepthStencil, Blend };

struct StateObjectField {
    StateObjectKind object;
    std::string_view name;  // canonical spelling ("SlopeScaledDepthBias")
    StateDomain domain;
    double defaultValue;  // D3D10's
    RenderStateId state;  // the pass state it sets
};

// Every field of one object kind, in table order.
std::vector<const StateObjectField*> stateObjectFields(StateObjectKind object);
// Case-insensitive.
const StateObjectField* findStateObjectField(StateObjectKind object, std::string_view name);
std::string_view stateObjectTypeName(StateObjectKind object);  // "RasterizerState", ...

struct StateInfo {
    std::string_view name;  // canonical spelling
    StateDomain domain;
    double defaultValue;  // D3D9 default (numeric domains)
};

const StateInfo& renderStateInfo(RenderStateId id);
const StateInfo& samplerStateInfo(SamplerStateId id);

// Case-insensitive, aliases included ("cullmode", "ZWriteEnabled", "AddressS").
std::optional<RenderStateId> findRenderState(std::string_view name);
std::optional<SamplerStateId> findSamplerState(std::string_view name);

// Case-insensitive; also accepts the D3D spelling with its prefix ("D3DCULL_CCW", "D3DBLENDOP_MIN",
// "D3DTEXF_LINEAR"). Bool also accepts numbers through the expression evaluator, not here.
std::optional<double> findEnumValue(StateDomain domain, std::string_view name);
std::vector<std::string_view> enumValueNames(StateDomain domain);  // for "expected one of" messages
std::string_view domainName(StateDomain domain);

bool equalsIgnoreCase(std::string_view a, std::string_view b);

}  // namespace fx
