// FixedFunctionPass: see FixedFunctionPass.h. The formulas are those of the Direct3D 9 documentation's
// "Mathematics of Lighting" (ambient, diffuse, specular, attenuation and spotlight factor), "Texture
// Blending" (D3DTEXTUREOP, D3DTA) and "Fog Formulas".
//
// [SECTION] The pass's states
// [SECTION] Vertex stage: transforms, per-vertex lighting, vertex fog
// [SECTION] Pixel stage: texture stages 0-1, specular, fog
// [SECTION] withFixedFunctionStages()
#include "FixedFunctionPass.h"

#include "CaseFolding.h"
#include "PassLowering.h"

#include <fx/EffectParser.h>
#include <fx/RenderStates.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace fx::detail {

namespace {

constexpr int kLights = 8;
constexpr int kTextureStages = 2;

// D3DTEXTUREOP, D3DTA, D3DLIGHTTYPE, D3DMATERIALCOLORSOURCE and D3DFOGMODE values (RenderStateDefs.h).
enum TextureOp {
    kDisable = 1,
    kSelectArg1,
    kSelectArg2,
    kModulate,
    kModulate2x,
    kModulate4x,
    kAdd,
    kAddSigned,
    kAddSigned2x,
    kSubtract,
    kAddSmooth,
    kBlendDiffuseAlpha,
    kBlendTextureAlpha,
    kBlendFactorAlpha,
    kBlendTextureAlphaPM,
    kBlendCurrentAlpha,
    kPreModulate,
    kModulateAlphaAddColor,
    kModulateColorAddAlpha,
    kModulateInvAlphaAddColor,
    kModulateInvColorAddAlpha,
    kBumpEnvMap,
    kBumpEnvMapLuminance,
    kDotProduct3,
    kMultiplyAdd,
    kLerp,
};
enum TextureArg { kDiffuse = 0, kCurrent, kTexture, kTFactor, kSpecular, kTemp, kConstant };
constexpr int kComplement = 0x10, kAlphaReplicate = 0x20;
enum LightType { kPoint = 1, kSpot, kDirectional };
enum MaterialSource { kMaterial = 0, kColor1, kColor2 };
enum FogMode { kFogNone = 0, kFogExp, kFogExp2, kFogLinear };

bool isFixedFunctionState(RenderStateId id) {
    return id >= RenderStateId::WorldTransform && id <= RenderStateId::TextureFactor;
}

// States of the fixed-function section, and the older ones of the same pipeline, that make a pass without
// shaders a fixed-function pass.
bool selectsFixedFunction(const StateAssignment& s) {
    const std::optional<RenderStateId> id = findRenderState(s.name);
    if (!id) return equalsIgnoreCase(s.name, "Texture");
    return isFixedFunctionState(*id) || *id == RenderStateId::Lighting || *id == RenderStateId::FogEnable ||
           *id == RenderStateId::SpecularEnable || *id == RenderStateId::NormalizeNormals;
}

bool isNull(const Expr& e) {
    return (e.kind == Expr::Kind::Identifier && e.text == "NULL") ||
           (e.kind == Expr::Kind::Number && e.number == 0);
}

// <g_mWorld> names the parameter whose value the state takes: as an argument it is the name itself.
Expr referenceAsName(Expr e) {
    if (e.kind == Expr::Kind::TextureRef) e.kind = Expr::Kind::Identifier;
    for (Expr& a : e.args) a = referenceAsName(std::move(a));
    return e;
}

Expr number(double value, const SourceLoc& loc) {
    Expr e;
    e.kind = Expr::Kind::Number;
    e.number = value;
    e.loc = loc;
    return e;
}

// A D3DCOLOR (0xAARRGGBB) as the float4 the generated code reads.
Expr packedColor(double packed, const SourceLoc& loc) {
    const auto bits = static_cast<uint32_t>(static_cast<int64_t>(packed));
    Expr e;
    e.kind = Expr::Kind::Call;
    e.text = "float4";
    e.loc = loc;
    for (int shift : {16, 8, 0, 24}) e.args.push_back(number(((bits >> shift) & 0xff) / 255.0, loc));
    return e;
}

// The uniform parameters of one generated function and the compile arguments that feed them.
struct Uniforms {
    std::string parameters;
    std::vector<Expr> arguments;

    std::string add(const std::string& type, Expr argument) {
        const std::string name = "fx_state" + std::to_string(arguments.size());
        parameters += ",\n    uniform " + type + " " + name;
        arguments.push_back(std::move(argument));
        return name;
    }
};

// [SECTION] The pass's states

class FixedFunctionStates {
public:
    FixedFunctionStates(const Pass& pass, DiagnosticSink& diagnostics)
        : mPass(pass), mDiagnostics(diagnostics) {
        for (const StateAssignment& s : pass.states) {
            const std::optional<RenderStateId> id = findRenderState(s.name);
            if (id)
                mLast[{*id, std::max(s.index, 0)}] = &s;
            else if (equalsIgnoreCase(s.name, "Texture"))
                mTextures[std::max(s.index, 0)] = &s;
        }
    }

    // What the generated vertex stage does not offer: vertex blending, lights beyond the eighth.
    void checkVertexIndices() {
        for (const auto& [key, s] : mLast) {
            const auto [id, index] = key;
            if (id == RenderStateId::WorldTransform && index > 0)
                unsupported(*s, DiagId::FixedFunctionVertexBlending, {std::to_string(index)});
            else if (id >= RenderStateId::LightEnable && id <= RenderStateId::LightPhi && index >= kLights)
                unsupported(*s, DiagId::FixedFunctionLightBeyondEighth, {std::to_string(index)});
        }
    }

    bool failed() const { return mFailed; }
    bool hasTexture(int stage) const { return mTextures.count(stage) > 0; }

    const StateAssignment* find(RenderStateId id, int index = 0) const {
        auto it = mLast.find({id, index});
        return it == mLast.end() ? nullptr : it->second;
    }

    // The HLSL the generated code reads for a state: a compile argument where the pass sets it, else D3D9's
    // default spelled as HLSL.
    std::string value(Uniforms& uniforms, RenderStateId id, int index, const std::string& type,
                      const std::string& fallback) const {
        const StateAssignment* s = find(id, index);
        if (!s) return fallback;
        Expr argument = referenceAsName(s->value);
        if (renderStateInfo(id).domain == StateDomain::Color && argument.kind == Expr::Kind::Number)
            argument = packedColor(argument.number, argument.loc);
        return uniforms.add(type, std::move(argument));
    }

    // A switch: "true"/"false" where constant, else a bool argument that follows its parameters.
    std::string flag(Uniforms& uniforms, RenderStateId id, int index, bool fallback) const {
        const StateAssignment* s = find(id, index);
        if (!s) return fallback ? "true" : "false";
        if (s->value.kind == Expr::Kind::Bool || s->value.kind == Expr::Kind::Number)
            return s->value.number != 0 ? "true" : "false";
        return uniforms.add("bool", referenceAsName(s->value));
    }

    // A state that chooses the code generated: a constant, or an error at its value.
    int choice(RenderStateId id, int index, int fallback) {
        const StateAssignment* s = find(id, index);
        if (!s) return fallback;
        if (s->value.kind == Expr::Kind::Number || s->value.kind == Expr::Kind::Bool)
            return static_cast<int>(s->value.number);
        mDiagnostics.report(DiagId::FixedFunctionStateNotConstant, s->value.loc, {s->name});
        mFailed = true;
        return fallback;
    }

    // Whether a switch can be on: a constant true, or one that follows parameters.
    bool mayBeOn(RenderStateId id, int index, bool fallback) const {
        const StateAssignment* s = find(id, index);
        if (!s) return fallback;
        return !(s->value.kind == Expr::Kind::Bool || s->value.kind == Expr::Kind::Number) ||
               s->value.number != 0;
    }

    void unsupported(const StateAssignment& s, DiagId what, const std::vector<std::string>& args) {
        mDiagnostics.report(what, s.loc, args);
        mFailed = true;
    }
    void unsupportedAt(RenderStateId id, int index, DiagId what, const std::vector<std::string>& args) {
        if (const StateAssignment* s = find(id, index))
            unsupported(*s, what, args);
        else
            unsupported(StateAssignment{std::string(renderStateInfo(id).name), index, {}, mPass.loc}, what,
                        args);
    }

    const Pass& pass() const { return mPass; }

private:
    const Pass& mPass;
    DiagnosticSink& mDiagnostics;
    std::map<std::pair<RenderStateId, int>, const StateAssignment*> mLast;  // the last setting counts
    std::map<int, const StateAssignment*> mTextures;                        // Texture[stage] = <t>
    bool mFailed = false;
};

std::string fogFactor(int mode, const std::string& distance, const std::string& start, const std::string& end,
                      const std::string& density) {
    switch (mode) {
        case kFogLinear:
            return "saturate((" + end + " - " + distance + ") / (" + end + " - " + start + "))";
        case kFogExp:
            return "saturate(exp(-" + density + " * " + distance + "))";
        case kFogExp2:
            return "saturate(exp(-(" + density + " * " + distance + ") * (" + density + " * " + distance +
                   ")))";
        default:
            return "1.0";
    }
}

// [SECTION] Vertex stage: transforms, per-vertex lighting, vertex fog

// The host's transforms, which a pass that does not set its own uses: D3D9 kept the device's transforms
// as the application last set them, the object's world and the camera's view and projection. Declared
// for the generated stages, each bound to its semantic, where a stage reads it.
struct HostTransform {
    RenderStateId state;
    const char* parameter;
    const char* semantic;
};
constexpr HostTransform kHostTransforms[] = {
    {RenderStateId::WorldTransform, "fx_HostWorld", "WORLD"},
    {RenderStateId::ViewTransform, "fx_HostView", "VIEW"},
    {RenderStateId::ProjectionTransform, "fx_HostProjection", "PROJECTION"},
};

// D3D9's per-vertex lighting in camera space (left-handed: the camera looks down +z). `eyeDistanceOut`:
// the pixel stage computes table fog from the interpolated camera-space depth (TEXCOORD7). The host
// transforms it reads are added to `hostTransforms`.
std::string vertexStage(FixedFunctionStates& states, const std::string& name, Uniforms& u,
                        bool eyeDistanceOut, std::set<std::string>& hostTransforms) {
    using Id = RenderStateId;
    states.checkVertexIndices();
    std::string body;
    for (const HostTransform& host : kHostTransforms) {
        if (!states.find(host.state)) hostTransforms.insert(host.parameter);
        const std::string local = host.state == Id::WorldTransform  ? "fx_world"
                                  : host.state == Id::ViewTransform ? "fx_view"
                                                                    : "fx_projection";
        body += "    float4x4 " + local + " = " + states.value(u, host.state, 0, "float4x4", host.parameter) +
                ";\n";
    }
    body +=
        "    float4x4 fx_worldView = mul(fx_world, fx_view);\n"
        "    float4 fx_viewPosition = mul(float4(fx_position.xyz, 1.0), fx_worldView);\n"
        "    oPosition = mul(fx_viewPosition, fx_projection);\n"
        "    oTexcoord0 = fx_texcoord0;\n"
        "    oTexcoord1 = fx_texcoord1;\n"
        // D3D9 transforms normals by the inverse transpose of world-view; for the rotations, translations
        // and uniform scales of a scene's transforms that is the matrix itself up to a scale, which
        // NormalizeNormals removes.
        "    float3 fx_normal = mul(fx_inNormal, (float3x3)fx_worldView);\n";
    body +=
        "    if (" + states.flag(u, Id::NormalizeNormals, 0, false) + ") fx_normal = normalize(fx_normal);\n";
    body +=
        "    oDiffuse = fx_color0;\n"
        "    oSpecular = float4(0, 0, 0, 0);\n";

    const std::string lighting = states.flag(u, Id::Lighting, 0, true);
    if (lighting != "false") {
        // The material's colours, or the vertex colours where a *MaterialSource state picks them.
        const bool colorVertex = states.flag(u, Id::ColorVertex, 0, true) != "false";
        auto material = [&](Id source, Id color, int fallbackSource, const std::string& fallback) {
            const int from = colorVertex ? states.choice(source, 0, fallbackSource) : kMaterial;
            if (from == kColor1) return std::string("fx_color0");
            if (from == kColor2) return std::string("fx_color1");
            return states.value(u, color, 0, "float4", fallback);
        };
        // D3D9's own default sources are the vertex colours where the vertex has them; a mesh's colours are
        // not known here, so the material is the default (docs/fixed-function.md).
        const std::string diffuse =
            material(Id::DiffuseMaterialSource, Id::MaterialDiffuse, kMaterial, "float4(1, 1, 1, 1)");
        const std::string ambient =
            material(Id::AmbientMaterialSource, Id::MaterialAmbient, kMaterial, "float4(0, 0, 0, 0)");
        const std::string specular =
            material(Id::SpecularMaterialSource, Id::MaterialSpecular, kMaterial, "float4(0, 0, 0, 0)");
        const std::string emissive =
            material(Id::EmissiveMaterialSource, Id::MaterialEmissive, kMaterial, "float4(0, 0, 0, 0)");
        const std::string power = states.value(u, Id::MaterialPower, 0, "float", "0.0");
        const std::string specularOn = states.flag(u, Id::SpecularEnable, 0, false);
        const std::string localViewer = states.flag(u, Id::LocalViewer, 0, true);
        body += "    if (" + lighting + ") {\n";
        body += "        float3 fx_ambientLight = " +
                states.value(u, Id::Ambient, 0, "float4", "float4(0, 0, 0, 0)") + ".rgb;\n";
        body +=
            "        float3 fx_diffuseLight = float3(0, 0, 0);\n"
            "        float3 fx_specularLight = float3(0, 0, 0);\n";
        body += "        float3 fx_toEye = " + localViewer +
                " ? normalize(-fx_viewPosition.xyz) : float3(0, 0, -1);\n";
        for (int i = 0; i < kLights; ++i) {
            if (!states.mayBeOn(Id::LightEnable, i, false)) continue;
            const std::string enabled = states.flag(u, Id::LightEnable, i, false);
            const int type = states.choice(Id::LightType, i, kPoint);
            if (type != kPoint && type != kSpot && type != kDirectional) {
                states.unsupportedAt(Id::LightType, i, DiagId::FixedFunctionLightType,
                                     {std::to_string(type)});
                continue;
            }
            const std::string light = "fx_light" + std::to_string(i);
            body += "        if (" + enabled + ") {  // light " + std::to_string(i) + "\n";
            if (type == kDirectional) {
                body += "            float3 " + light + "ToLight = -normalize(mul(" +
                        states.value(u, Id::LightDirection, i, "float4", "float4(0, 0, 1, 0)") +
                        ".xyz, (float3x3)fx_view));\n";
                body += "            float " + light + "Attenuation = 1.0;\n";
            } else {
                // Attenuation = 1 / (a0 + a1 d + a2 d^2) within the range, 0 beyond it. An effect that sets
                // none of the three gets D3D9's usual (1, 0, 0) instead of a division by zero; one that sets
                // no range lights without limit.
                const bool setsAttenuation = states.find(Id::LightAttenuation0, i) ||
                                             states.find(Id::LightAttenuation1, i) ||
                                             states.find(Id::LightAttenuation2, i);
                const std::string a0 =
                    states.value(u, Id::LightAttenuation0, i, "float", setsAttenuation ? "0.0" : "1.0");
                const std::string a1 = states.value(u, Id::LightAttenuation1, i, "float", "0.0");
                const std::string a2 = states.value(u, Id::LightAttenuation2, i, "float", "0.0");
                const std::string range = states.value(u, Id::LightRange, i, "float", "3.402823466e+38");
                body += "            float3 " + light + "Vector = mul(float4(" +
                        states.value(u, Id::LightPosition, i, "float4", "float4(0, 0, 0, 1)") +
                        ".xyz, 1.0), fx_view).xyz - fx_viewPosition.xyz;\n";
                body += "            float " + light + "Distance = length(" + light + "Vector);\n";
                body += "            float3 " + light + "ToLight = " + light + "Vector / max(" + light +
                        "Distance, 1e-20);\n";
                body += "            float " + light + "Attenuation = " + light + "Distance <= " + range +
                        " ? 1.0 / max(" + a0 + " + " + a1 + " * " + light + "Distance + " + a2 + " * " +
                        light + "Distance * " + light + "Distance, 1e-20) : 0.0;\n";
                if (type == kSpot) {
                    // The spotlight factor: 1 inside the inner cone (theta), 0 outside the outer one (phi),
                    // ((rho - cos(phi/2)) / (cos(theta/2) - cos(phi/2)))^falloff between them.
                    body += "            float " + light + "Rho = dot(-" + light + "ToLight, normalize(mul(" +
                            states.value(u, Id::LightDirection, i, "float4", "float4(0, 0, 1, 0)") +
                            ".xyz, (float3x3)fx_view)));\n";
                    body += "            float " + light + "CosPhi = cos(0.5 * " +
                            states.value(u, Id::LightPhi, i, "float", "0.0") + ");\n";
                    body += "            float " + light + "CosTheta = cos(0.5 * " +
                            states.value(u, Id::LightTheta, i, "float", "0.0") + ");\n";
                    body += "            " + light + "Attenuation *= " + light + "Rho > " + light +
                            "CosTheta ? 1.0 : " + light + "Rho <= " + light +
                            "CosPhi ? 0.0 : pow(saturate((" + light + "Rho - " + light + "CosPhi) / max(" +
                            light + "CosTheta - " + light + "CosPhi, 1e-6)), " +
                            states.value(u, Id::LightFalloff, i, "float", "1.0") + ");\n";
                }
            }
            body += "            float " + light + "NdotL = dot(fx_normal, " + light + "ToLight);\n";
            body += "            fx_ambientLight += " + light + "Attenuation * " +
                    states.value(u, Id::LightAmbient, i, "float4", "float4(0, 0, 0, 0)") + ".rgb;\n";
            body += "            if (" + light + "NdotL > 0.0) {\n";
            body += "                fx_diffuseLight += " + light + "Attenuation * " + light + "NdotL * " +
                    states.value(u, Id::LightDiffuse, i, "float4", "float4(0, 0, 0, 0)") + ".rgb;\n";
            body += "                if (" + specularOn + ") fx_specularLight += " + light +
                    "Attenuation * pow(saturate(dot(fx_normal, normalize(" + light +
                    "ToLight + fx_toEye))), " + power + ") * " +
                    states.value(u, Id::LightSpecular, i, "float4", "float4(0, 0, 0, 0)") + ".rgb;\n";
            body += "            }\n        }\n";
        }
        body += "        float4 fx_materialDiffuse = " + diffuse + ";\n";
        body +=
            "        oDiffuse = float4(saturate(" + emissive + ".rgb + " + ambient +
            ".rgb * fx_ambientLight + fx_materialDiffuse.rgb * fx_diffuseLight), fx_materialDiffuse.a);\n";
        body += "        float4 fx_materialSpecular = " + specular + ";\n";
        body +=
            "        oSpecular = float4(saturate(fx_materialSpecular.rgb * fx_specularLight), "
            "fx_materialSpecular.a);\n";
        body += "    }\n";
    }

    // Vertex fog (FogVertexMode, used where FogTableMode is NONE): the factor per vertex, from the
    // camera-space depth, or the distance with RangeFogEnable.
    const int tableMode = states.choice(Id::FogTableMode, 0, kFogNone);
    const int vertexMode = states.choice(Id::FogVertexMode, 0, kFogNone);
    body += "    float fx_eyeDistance = " + states.flag(u, Id::RangeFogEnable, 0, false) +
            " ? length(fx_viewPosition.xyz) : fx_viewPosition.z;\n";
    if (tableMode == kFogNone && vertexMode != kFogNone)
        body += "    oFog = " +
                fogFactor(vertexMode, "fx_eyeDistance", states.value(u, Id::FogStart, 0, "float", "0.0"),
                          states.value(u, Id::FogEnd, 0, "float", "1.0"),
                          states.value(u, Id::FogDensity, 0, "float", "1.0")) +
                ";\n";
    else
        body += "    oFog = 1.0;\n";
    std::string outputs =
        "    out float4 oPosition : POSITION,\n    out float4 oDiffuse : COLOR0,\n    out float4 oSpecular : "
        "COLOR1,\n    out float4 oTexcoord0 : TEXCOORD0,\n    out float4 oTexcoord1 : TEXCOORD1,\n    out "
        "float "
        "oFog : FOG";
    if (eyeDistanceOut) {
        outputs += ",\n    out float oEyeDistance : TEXCOORD7";
        body += "    oEyeDistance = fx_eyeDistance;\n";
    }
    return "void " + name +
           "(float4 fx_position : POSITION, float3 fx_inNormal : NORMAL, float4 fx_color0 : COLOR0,\n"
           "    float4 fx_color1 : COLOR1, float4 fx_texcoord0 : TEXCOORD0, float4 fx_texcoord1 : "
           "TEXCOORD1,\n" +
           outputs + u.parameters + ")\n{\n" + body + "}\n";
}

// [SECTION] Pixel stage: texture stages 0-1, specular, fog

// A texture-stage argument (D3DTA_*) as HLSL, or nullopt for what the generated stage cannot read.
std::optional<std::string> stageArgument(int code) {
    std::string value;
    switch (code & 0xf) {
        case kDiffuse:
            value = "fx_diffuse";
            break;
        case kCurrent:
            value = "fx_current";
            break;
        case kTexture:
            value = "fx_texel";
            break;
        case kTFactor:
            value = "fx_textureFactor";
            break;
        case kSpecular:
            value = "fx_specular";
            break;
        case kTemp:  // D3DTSS_RESULTARG is not offered: the temporary register holds its initial 0
            value = "float4(0, 0, 0, 0)";
            break;
        default:
            return std::nullopt;
    }
    if (code & ~(0xf | kComplement | kAlphaReplicate)) return std::nullopt;
    if (code & kAlphaReplicate) value = value + ".aaaa";
    if (code & kComplement) value = "(1.0 - " + value + ")";
    return value;
}

// A D3DTEXTUREOP over the arguments, as a float4 expression, or nullopt where it is not generated.
std::optional<std::string> stageOperation(int op, const std::string& a0, const std::string& a1,
                                          const std::string& a2, bool alpha) {
    switch (op) {
        case kSelectArg1:
            return a1;
        case kSelectArg2:
            return a2;
        case kModulate:
            return a1 + " * " + a2;
        case kModulate2x:
            return "2.0 * " + a1 + " * " + a2;
        case kModulate4x:
            return "4.0 * " + a1 + " * " + a2;
        case kAdd:
            return a1 + " + " + a2;
        case kAddSigned:
            return a1 + " + " + a2 + " - 0.5";
        case kAddSigned2x:
            return "2.0 * (" + a1 + " + " + a2 + " - 0.5)";
        case kSubtract:
            return a1 + " - " + a2;
        case kAddSmooth:
            return a1 + " + " + a2 + " - " + a1 + " * " + a2;
        case kBlendDiffuseAlpha:
            return "lerp(" + a2 + ", " + a1 + ", fx_diffuse.a)";
        case kBlendTextureAlpha:
            return "lerp(" + a2 + ", " + a1 + ", fx_texel.a)";
        case kBlendFactorAlpha:
            return "lerp(" + a2 + ", " + a1 + ", fx_textureFactor.a)";
        case kBlendTextureAlphaPM:
            return a1 + " + " + a2 + " * (1.0 - fx_texel.a)";
        case kBlendCurrentAlpha:
            return "lerp(" + a2 + ", " + a1 + ", fx_current.a)";
        case kDotProduct3:
            return "saturate(4.0 * dot(" + a1 + ".rgb - 0.5, " + a2 + ".rgb - 0.5)).xxxx";
        case kMultiplyAdd:
            return a0 + " + " + a1 + " * " + a2;
        case kLerp:
            return "lerp(" + a2 + ", " + a1 + ", " + a0 + ")";
        default:
            break;
    }
    if (alpha) return std::nullopt;  // the four below are colour operations only
    switch (op) {
        case kModulateAlphaAddColor:
            return a1 + " + " + a1 + ".a * " + a2;
        case kModulateColorAddAlpha:
            return a1 + " * " + a2 + " + " + a1 + ".a";
        case kModulateInvAlphaAddColor:
            return "(1.0 - " + a1 + ".a) * " + a2 + " + " + a1;
        case kModulateInvColorAddAlpha:
            return "(1.0 - " + a1 + ") * " + a2 + " + " + a1 + ".a";
        default:
            return std::nullopt;
    }
}

std::string pixelStage(FixedFunctionStates& states, const std::string& name, Uniforms& u, bool fixedVertex) {
    using Id = RenderStateId;
    std::string body = "    float4 fx_current = fx_diffuse;\n";
    body += "    float4 fx_textureFactor = " +
            states.value(u, Id::TextureFactor, 0, "float4", "float4(1, 1, 1, 1)") + ";\n";
    for (int stage = 0; stage < 16; ++stage) {
        const int colorOp = states.choice(Id::ColorOp, stage, stage == 0 ? kModulate : kDisable);
        if (colorOp == kDisable) break;  // D3D9 stops at the first disabled stage
        const std::string where = "texture stage " + std::to_string(stage);
        if (stage >= kTextureStages) {
            states.unsupportedAt(Id::ColorOp, stage, DiagId::FixedFunctionTextureStageBeyondSecond,
                                 {std::to_string(stage)});
            break;
        }
        const int alphaOp = states.choice(Id::AlphaOp, stage, stage == 0 ? kSelectArg1 : kDisable);
        const int texcoord = states.choice(Id::TexCoordIndex, stage, stage);
        if (texcoord != 0 && texcoord != 1) {
            states.unsupportedAt(Id::TexCoordIndex, stage, DiagId::FixedFunctionTexCoordIndex,
                                 {std::to_string(texcoord)});
            continue;
        }
        // A stage without a texture reads white, as the runtime's stand-in pixel stage does.
        const std::string texel = states.hasTexture(stage)
                                      ? "tex2D(fx_FixedFunctionSampler" + std::to_string(stage) +
                                            ", fx_texcoord" + std::to_string(texcoord) + ".xy)"
                                      : "float4(1, 1, 1, 1)";
        auto arguments = [&](Id arg0, Id arg1, Id arg2) -> std::optional<std::vector<std::string>> {
            std::vector<std::string> out;
            for (auto [id, fallback] : {std::pair{arg0, kCurrent}, {arg1, kTexture}, {arg2, kCurrent}}) {
                const int code = states.choice(id, stage, fallback);
                std::optional<std::string> text = stageArgument(code);
                if (!text) {
                    states.unsupportedAt(id, stage, DiagId::FixedFunctionStageArgument,
                                         {std::to_string(code), std::to_string(stage)});
                    return std::nullopt;
                }
                out.push_back("(" + *text + ")");
            }
            return out;
        };
        const auto color = arguments(Id::ColorArg0, Id::ColorArg1, Id::ColorArg2);
        const auto alpha = arguments(Id::AlphaArg0, Id::AlphaArg1, Id::AlphaArg2);
        if (!color || !alpha) continue;
        const std::optional<std::string> colorValue =
            stageOperation(colorOp, (*color)[0], (*color)[1], (*color)[2], false);
        if (!colorValue) {
            states.unsupportedAt(Id::ColorOp, stage, DiagId::FixedFunctionStageOperation,
                                 {std::to_string(colorOp), std::to_string(stage)});
            continue;
        }
        std::optional<std::string> alphaValue = "fx_current";
        if (alphaOp != kDisable)
            alphaValue = stageOperation(alphaOp, (*alpha)[0], (*alpha)[1], (*alpha)[2], true);
        if (!alphaValue) {
            states.unsupportedAt(Id::AlphaOp, stage, DiagId::FixedFunctionStageOperation,
                                 {std::to_string(alphaOp), std::to_string(stage)});
            continue;
        }
        body += "    {  // " + where + "\n";
        body += "        float4 fx_texel = " + texel + ";\n";
        body +=
            "        fx_current = saturate(float4((" + *colorValue + ").rgb, (" + *alphaValue + ").a));\n";
        body += "    }\n";
    }
    body += "    if (" + states.flag(u, Id::SpecularEnable, 0, false) +
            ") fx_current.rgb = saturate(fx_current.rgb + fx_specular.rgb);\n";
    // Fog after texturing: table fog per pixel from the camera-space depth the fixed-function vertex stage
    // interpolates; otherwise the vertex stage's fog factor (a vertex shader's FOG output).
    const std::string fogOn = states.flag(u, Id::FogEnable, 0, false);
    if (fogOn != "false") {
        const int tableMode = states.choice(Id::FogTableMode, 0, kFogNone);
        const std::string factor =
            fixedVertex && tableMode != kFogNone
                ? fogFactor(tableMode, "fx_eyeDistance", states.value(u, Id::FogStart, 0, "float", "0.0"),
                            states.value(u, Id::FogEnd, 0, "float", "1.0"),
                            states.value(u, Id::FogDensity, 0, "float", "1.0"))
                : "saturate(fx_fog)";
        body += "    if (" + fogOn + ") fx_current.rgb = lerp(" +
                states.value(u, Id::FogColor, 0, "float4", "float4(0, 0, 0, 0)") + ".rgb, fx_current.rgb, " +
                factor + ");\n";
    }
    body += "    return fx_current;\n";
    std::string inputs =
        "float4 fx_diffuse : COLOR0, float4 fx_specular : COLOR1, float4 fx_texcoord0 : TEXCOORD0,\n"
        "    float4 fx_texcoord1 : TEXCOORD1, float fx_fog : FOG";
    if (fixedVertex) inputs += ", float fx_eyeDistance : TEXCOORD7";
    return "float4 " + name + "(" + inputs + u.parameters + ") : COLOR0\n{\n" + body + "}\n";
}

// A pass with a pixel shader alone draws a full-screen quad, its vertices passed through untransformed:
// D3D9 ran such a pass on the pre-transformed (XYZRHW) quads the DirectX SDK's post-processing fed it.
// The runtime's quad (Draw=Buffer) is in clip space already; its texture coordinates go to the first two
// sets, as the SDK's quads carried the same screen coordinates in both, and the diffuse colour is D3D9's
// default for a vertex without one, white.
std::string screenQuadStage(const std::string& name) {
    return "void " + name +
           "(float4 fx_position : POSITION, float4 fx_texcoord : TEXCOORD0,\n"
           "    out float4 oPosition : POSITION, out float4 oDiffuse : COLOR0, out float4 oTexcoord0 : "
           "TEXCOORD0,\n"
           "    out float4 oTexcoord1 : TEXCOORD1)\n{\n"
           "    oPosition = float4(fx_position.xyz, 1.0);\n"
           "    oDiffuse = float4(1, 1, 1, 1);\n"
           "    oTexcoord0 = fx_texcoord;\n"
           "    oTexcoord1 = fx_texcoord;\n"
           "}\n";
}

bool needsTableFog(FixedFunctionStates& states) {
    return states.mayBeOn(RenderStateId::FogEnable, 0, false) &&
           states.choice(RenderStateId::FogTableMode, 0, kFogNone) != kFogNone;
}

Expr compileExpression(const std::string& profile, const std::string& function, std::vector<Expr> args,
                       const SourceLoc& loc) {
    Expr e;
    e.kind = Expr::Kind::Compile;
    e.profile = profile;
    e.text = function;
    e.args = std::move(args);
    e.loc = loc;
    return e;
}

// The pass's shader state for a stage (its last assignment), or null; const as the pass is.
template <typename PassType>
auto* shaderState(PassType& pass, RenderStateId stage) {
    decltype(&pass.states.front()) found = nullptr;
    for (auto& s : pass.states)
        if (findRenderState(s.name) == stage) found = &s;
    return found;
}

}  // namespace

// [SECTION] withFixedFunctionStages()

std::shared_ptr<const Effect> withFixedFunctionStages(std::shared_ptr<const Effect> effect,
                                                      DiagnosticSink& diagnostics) {
    bool any = false;
    for (const Technique& t : effect->techniques)
        for (const Pass& p : t.passes) {
            for (const StateAssignment& s : p.states)
                if (selectsFixedFunction(s)) any = true;
            const StateAssignment* vs = shaderState(p, RenderStateId::VertexShader);
            const StateAssignment* ps = shaderState(p, RenderStateId::PixelShader);
            if (!t.d3d10 && (!vs || isNull(vs->value)) && ps && !isNull(ps->value)) any = true;
        }
    if (!any) return effect;

    auto out = std::make_shared<Effect>(*effect);
    std::string generated;  // the generated functions, parsed below as effect source
    bool failed = false;
    int samplersUsed = 0;                  // stages 0..n-1 sample through fx_FixedFunctionSampler<stage>
    std::set<std::string> hostTransforms;  // the host's transforms a generated stage reads
    struct Replacement {
        Pass* pass;
        RenderStateId stage;
        Expr compile;
    };
    std::vector<Replacement> replacements;
    for (size_t t = 0; t < out->techniques.size(); ++t) {
        Technique& technique = out->techniques[t];
        for (size_t p = 0; p < technique.passes.size(); ++p) {
            Pass& pass = technique.passes[p];
            if (technique.d3d10) continue;  // D3D10 has no fixed-function pipeline
            const StateAssignment* vs = shaderState(pass, RenderStateId::VertexShader);
            const StateAssignment* ps = shaderState(pass, RenderStateId::PixelShader);
            const bool hasVertexShader = vs && !isNull(vs->value);
            const bool hasPixelShader = ps && !isNull(ps->value);
            FixedFunctionStates states(pass, diagnostics);
            bool setsVertexStates = false, setsPixelStates = false;
            for (const StateAssignment& s : pass.states) {
                if (!selectsFixedFunction(s)) continue;
                const std::optional<RenderStateId> id = findRenderState(s.name);
                if (!id || (*id >= RenderStateId::ColorOp && *id <= RenderStateId::TextureFactor))
                    setsPixelStates = true;
                // Lighting, SpecularEnable and the fog states, which effects set beside their shaders
                // (`Lighting = false;`), do not ask for a vertex stage of their own.
                else if (isFixedFunctionState(*id))
                    setsVertexStates = true;
            }
            // `FogEnable = false;` beside a vertex shader asks for nothing of the pixel stage.
            if (states.mayBeOn(RenderStateId::FogEnable, 0, false)) setsPixelStates = true;
            // A pass without shaders that sets only texture-stage states still went through D3D9's vertex
            // pipeline, with the device's transforms.
            const bool vertex =
                !hasVertexShader && (setsVertexStates || (!hasPixelShader && setsPixelStates));
            const bool pixel = !hasPixelShader && (vertex || setsPixelStates);
            // A pixel shader alone, even with `Texture[0] = <t>;` beside it: a full-screen pass.
            const bool screenQuad = !hasVertexShader && !setsVertexStates && hasPixelShader;
            const std::string suffix = std::to_string(t) + "_" + std::to_string(p);
            if (vertex) {
                Uniforms u;
                const std::string name = "fx_FixedFunctionVS_" + suffix;
                generated +=
                    vertexStage(states, name, u, pixel && needsTableFog(states), hostTransforms) + "\n";
                replacements.push_back({&pass, RenderStateId::VertexShader,
                                        compileExpression("vs_3_0", name, std::move(u.arguments), pass.loc)});
            }
            if (screenQuad) {
                const std::string name = "fx_ScreenQuadVS_" + suffix;
                generated += screenQuadStage(name) + "\n";
                replacements.push_back(
                    {&pass, RenderStateId::VertexShader, compileExpression("vs_3_0", name, {}, pass.loc)});
                pass.drawsScreenQuad = true;
            }
            if (pixel) {
                Uniforms u;
                const std::string name = "fx_FixedFunctionPS_" + suffix;
                generated += pixelStage(states, name, u, vertex) + "\n";
                replacements.push_back({&pass, RenderStateId::PixelShader,
                                        compileExpression("ps_3_0", name, std::move(u.arguments), pass.loc)});
                for (int stage = 0; stage < kTextureStages; ++stage)
                    if (states.hasTexture(stage)) samplersUsed = std::max(samplersUsed, stage + 1);
            }
            failed = failed || states.failed();
        }
    }
    if (failed) return nullptr;

    // The samplers of the texture stages: a pass's `Texture[i]` and sampler-register states (`MinFilter[i]`)
    // reach them through register si, as they reached a pixel shader's sampler in D3D9.
    std::string samplers;
    for (int stage = 0; stage < samplersUsed; ++stage)
        samplers += "sampler2D fx_FixedFunctionSampler" + std::to_string(stage) + " : register(s" +
                    std::to_string(stage) + ");\n";
    for (const HostTransform& host : kHostTransforms)
        if (hostTransforms.count(host.parameter))
            samplers += std::string("float4x4 ") + host.parameter + " : " + host.semantic + ";\n";
    std::shared_ptr<Effect> parsed = parseEffectSource(samplers + generated, kGeneratedFile, {}, diagnostics);
    if (!parsed) return nullptr;
    for (const DeclRef& ref : parsed->order) {
        if (ref.kind == DeclRef::Kind::Parameter) {
            out->order.push_back({DeclRef::Kind::Parameter, out->parameters.size()});
            out->parameters.push_back(parsed->parameters[ref.index]);
        } else if (ref.kind == DeclRef::Kind::Function) {
            out->order.push_back({DeclRef::Kind::Function, out->functions.size()});
            out->functions.push_back(parsed->functions[ref.index]);
        }
    }
    for (Replacement& r : replacements) {
        if (StateAssignment* existing = shaderState(*r.pass, r.stage)) {
            existing->value = std::move(r.compile);
            continue;
        }
        StateAssignment state;
        state.name = std::string(renderStateInfo(r.stage).name);
        state.loc = r.pass->loc;
        state.value = std::move(r.compile);
        r.pass->states.push_back(std::move(state));
    }
    // A stage with a shader ignores them, as D3D9 did; the runtime has nothing to set for them.
    for (Technique& technique : out->techniques)
        for (Pass& pass : technique.passes)
            std::erase_if(pass.states, [](const StateAssignment& s) {
                const std::optional<RenderStateId> id = findRenderState(s.name);
                return id && isFixedFunctionState(*id);
            });
    return out;
}

}  // namespace fx::detail
