// RenderStates: the D3D9 state table of RenderStateDefs.h as lookup functions. Names and enum values are
// case-insensitive as in D3DX; enum values also accept their D3D prefix ("D3DCULL_CCW") and underscores
// ("INV_SRC_ALPHA" for InvSrcAlpha).
#include <fx/RenderStates.h>

#include "CaseFolding.h"

#include <cctype>

namespace fx {

namespace {

const StateInfo kRenderStates[] = {
#define FX_RENDER_STATE(name, domain, def) {#name, StateDomain::domain, static_cast<double>(def)},
#include <fx/RenderStateDefs.h>
};

const StateInfo kSamplerStates[] = {
#define FX_SAMPLER_STATE(name, domain, def) {#name, StateDomain::domain, static_cast<double>(def)},
#include <fx/RenderStateDefs.h>
};

struct Alias {
    std::string_view alias;
    std::string_view name;
};
const Alias kAliases[] = {
#define FX_STATE_ALIAS(alias, name) {#alias, #name},
#include <fx/RenderStateDefs.h>
};

struct EnumValue {
    StateDomain domain;
    std::string_view name;
    double value;
};
const EnumValue kEnumValues[] = {
#define FX_ENUM_VALUE(domain, name, value) {StateDomain::domain, #name, static_cast<double>(value)},
#include <fx/RenderStateDefs.h>
};

const StateObjectField kObjectFields[] = {
#define FX_OBJECT_FIELD(object, field, domain, def, state) \
    {StateObjectKind::object, #field, StateDomain::domain, static_cast<double>(def), RenderStateId::state},
#include <fx/RenderStateDefs.h>
};

// Compares ignoring case and underscores ("INV_SRC_ALPHA" == "InvSrcAlpha").
bool equalsLoose(std::string_view a, std::string_view b) {
    size_t i = 0, j = 0;
    for (;;) {
        while (i < a.size() && a[i] == '_') ++i;
        while (j < b.size() && b[j] == '_') ++j;
        if (i == a.size() || j == b.size()) return i == a.size() && j == b.size();
        if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[j])))
            return false;
        ++i, ++j;
    }
}

bool startsWithIgnoreCase(std::string_view s, std::string_view prefix) {
    return s.size() >= prefix.size() && equalsIgnoreCase(s.substr(0, prefix.size()), prefix);
}

// The D3D header prefixes of each enum domain.
std::vector<std::string_view> domainPrefixes(StateDomain domain) {
    switch (domain) {
        case StateDomain::Cull:
            return {"D3DCULL_"};
        case StateDomain::Shade:
            return {"D3DSHADE_"};
        case StateDomain::Cmp:
            return {"D3DCMP_", "D3D10_COMPARISON_", "D3D11_COMPARISON_", "COMPARISON_"};
        case StateDomain::Blend:
            return {"D3DBLEND_", "D3D10_BLEND_", "D3D11_BLEND_"};
        case StateDomain::BlendOp:
            return {"D3DBLENDOP_", "D3D10_BLEND_OP_", "D3D11_BLEND_OP_"};
        case StateDomain::StencilOp:
            return {"D3DSTENCILOP_", "D3D10_STENCIL_OP_", "D3D11_STENCIL_OP_"};
        case StateDomain::Address:
            return {"D3DTADDRESS_", "D3D10_TEXTURE_ADDRESS_", "D3D11_TEXTURE_ADDRESS_"};
        case StateDomain::TexFilter:
            return {"D3DTEXF_"};
        case StateDomain::Filter10:
            return {"D3D10_FILTER_", "D3D11_FILTER_"};
        case StateDomain::Cull10:
            return {"D3D10_CULL_", "D3D11_CULL_"};
        case StateDomain::DepthWriteMask:
            return {"D3D10_DEPTH_WRITE_MASK_", "D3D11_DEPTH_WRITE_MASK_"};
        case StateDomain::Fill:
            return {"D3DFILL_", "D3D10_FILL_", "D3D11_FILL_"};
        case StateDomain::ColorMask:
            return {"D3DCOLORWRITEENABLE_", "D3D10_COLOR_WRITE_ENABLE_", "D3D11_COLOR_WRITE_ENABLE_"};
        case StateDomain::FogMode:
            return {"D3DFOG_"};
        case StateDomain::LightType:
            return {"D3DLIGHT_"};
        case StateDomain::MaterialSource:
            return {"D3DMCS_"};
        case StateDomain::TextureOp:
            return {"D3DTOP_"};
        case StateDomain::TextureArg:
            return {"D3DTA_"};
        default:
            return {};
    }
}

template <class Id>
std::optional<Id> findState(const StateInfo* table, size_t count, std::string_view name) {
    for (size_t i = 0; i < count; ++i)
        if (equalsIgnoreCase(table[i].name, name)) return static_cast<Id>(i);
    for (const Alias& alias : kAliases) {
        if (!equalsIgnoreCase(alias.alias, name)) continue;
        for (size_t i = 0; i < count; ++i)
            if (equalsIgnoreCase(table[i].name, alias.name)) return static_cast<Id>(i);
    }
    return std::nullopt;
}

}  // namespace

bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i])))
            return false;
    return true;
}

std::string upperCase(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

const StateInfo& renderStateInfo(RenderStateId id) {
    return kRenderStates[static_cast<size_t>(id)];
}
const StateInfo& samplerStateInfo(SamplerStateId id) {
    return kSamplerStates[static_cast<size_t>(id)];
}

std::optional<RenderStateId> findRenderState(std::string_view name) {
    return findState<RenderStateId>(kRenderStates, std::size(kRenderStates), name);
}

std::optional<SamplerStateId> findSamplerState(std::string_view name) {
    return findState<SamplerStateId>(kSamplerStates, std::size(kSamplerStates), name);
}

std::optional<double> findEnumValue(StateDomain domain, std::string_view name) {
    std::string_view bare = name;
    for (std::string_view prefix : domainPrefixes(domain)) {
        if (startsWithIgnoreCase(name, prefix)) {
            bare = name.substr(prefix.size());
            break;
        }
    }
    for (const EnumValue& value : kEnumValues)
        if (value.domain == domain && equalsIgnoreCase(value.name, bare)) return value.value;
    for (const EnumValue& value : kEnumValues)
        if (value.domain == domain && equalsLoose(value.name, bare)) return value.value;
    return std::nullopt;
}

std::vector<std::string_view> enumValueNames(StateDomain domain) {
    std::vector<std::string_view> names;
    for (const EnumValue& value : kEnumValues)
        if (value.domain == domain) names.push_back(value.name);
    return names;
}

std::vector<const StateObjectField*> stateObjectFields(StateObjectKind object) {
    std::vector<const StateObjectField*> fields;
    for (const StateObjectField& f : kObjectFields)
        if (f.object == object) fields.push_back(&f);
    return fields;
}

const StateObjectField* findStateObjectField(StateObjectKind object, std::string_view name) {
    for (const StateObjectField& f : kObjectFields)
        if (f.object == object && equalsIgnoreCase(f.name, name)) return &f;
    return nullptr;
}

std::string_view stateObjectTypeName(StateObjectKind object) {
    switch (object) {
        case StateObjectKind::Rasterizer:
            return "RasterizerState";
        case StateObjectKind::DepthStencil:
            return "DepthStencilState";
        case StateObjectKind::Blend:
            return "BlendState";
    }
    return "?";
}

std::string_view domainName(StateDomain domain) {
    switch (domain) {
        case StateDomain::Bool:
            return "Bool";
        case StateDomain::Int:
            return "Int";
        case StateDomain::Float:
            return "Float";
        case StateDomain::Color:
            return "Color";
        case StateDomain::ColorMask:
            return "ColorMask";
        case StateDomain::Shader:
            return "Shader";
        case StateDomain::TextureRef:
            return "TextureRef";
        case StateDomain::Cull:
            return "Cull";
        case StateDomain::Fill:
            return "Fill";
        case StateDomain::Shade:
            return "Shade";
        case StateDomain::Cmp:
            return "Cmp";
        case StateDomain::Blend:
            return "Blend";
        case StateDomain::BlendOp:
            return "BlendOp";
        case StateDomain::StencilOp:
            return "StencilOp";
        case StateDomain::Address:
            return "Address";
        case StateDomain::TexFilter:
            return "TexFilter";
        case StateDomain::Filter10:
            return "Filter10";
        case StateDomain::Cull10:
            return "Cull10";
        case StateDomain::DepthWriteMask:
            return "DepthWriteMask";
        case StateDomain::FogMode:
            return "FogMode";
        case StateDomain::Vector:
            return "Vector";
        case StateDomain::Matrix:
            return "Matrix";
        case StateDomain::LightType:
            return "LightType";
        case StateDomain::MaterialSource:
            return "MaterialSource";
        case StateDomain::TextureOp:
            return "TextureOp";
        case StateDomain::TextureArg:
            return "TextureArg";
    }
    return "?";
}

}  // namespace fx
