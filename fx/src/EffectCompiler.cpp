// EffectCompiler: orchestration (see EffectCompiler.h).
//
// [SECTION] Initial values
// [SECTION] Textures and samplers
// [SECTION] Scripts
// [SECTION] Stages: lowering, cache, glslang, SPIRV-Cross, reflection
// [SECTION] Passes and techniques

#include <fx/CompileCache.h>
#include <fx/CompileWorkers.h>
#include <fx/EffectCompiler.h>
#include <fx/Preshader.h>

#include "CaseBlindPath.h"
#include "HlslToSpirv.h"
#include "PassLowering.h"
#include "SpirvToGlsl.h"
#include "StageCompile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

namespace fx {

namespace {

std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

bool literalOnly(const Expr& e) {
    if (e.kind == Expr::Kind::Identifier) return e.text == "true" || e.text == "false";
    if (e.kind == Expr::Kind::TextureRef || e.kind == Expr::Kind::Compile) return false;
    for (const Expr& a : e.args)
        if (!literalOnly(a)) return false;
    return true;
}

class Compiler {
public:
    Compiler(std::shared_ptr<const Effect> effect, const CompileOptions& options, DiagnosticSink& diagnostics)
        : mEffect(*effect), mOptions(options), mDiagnostics(diagnostics) {
        mOut = std::make_unique<CompiledEffect>();
        mOut->effect = std::move(effect);
    }

    std::unique_ptr<CompiledEffect> run();

private:
    void error(DiagId id, const SourceLoc& loc, const std::vector<std::string>& args) {
        mDiagnostics.report(id, loc, args);
        mFailed = true;
    }
    std::optional<Value> eval(const Expr& e, const TypeDesc* type) {
        auto v = evaluate(
            e, [this](std::string_view n) { return lookup(n); }, type, &mDiagnostics);
        if (!v) mFailed = true;
        return v;
    }
    // Parameters are the preshaders' slots, by their index in the effect.
    SlotResolver slotResolver() const {
        return [this](std::string_view name) -> std::optional<size_t> {
            auto it = mIndex.find(std::string(name));
            if (it == mIndex.end()) return std::nullopt;
            return it->second;
        };
    }
    const Value* lookup(std::string_view name) const {
        auto it = mIndex.find(std::string(name));
        return it == mIndex.end() || it->second >= mOut->initialValues.size()
                   ? nullptr
                   : &mOut->initialValues[it->second];
    }

    void initialValues();
    void parameterInfo();
    void passAnnotations(const Pass& source, CompiledPass& pass);
    void textures();
    void procedural(const Parameter& p, const Annotation& annotation, TextureDesc& t);
    void resourceShape(const Parameter& p, TextureDesc& t);
    void samplers();
    void assignPairUnits();
    void scripts();
    std::vector<ScriptCommand> script(const std::vector<Annotation>& annotations, bool& has);
    void validateScript(std::vector<ScriptCommand>& commands, const Technique* technique);
    // A stage's place in mOut: technique and pass index.
    struct PassSlot {
        size_t technique = 0;
        size_t pass = 0;
    };
    // A stage the cache did not have: compiled with all the others once every pass is lowered, so that
    // the stages of an effect compile concurrently across the worker pool.
    struct PendingStage {
        PassSlot slot;
        LoweredStage lowered;
        uint64_t key = 0;
        size_t job = 0;  // index into mJobs (identical units share one job)
    };
    bool compileStage(const Expr& compile, ShaderStage stage, CompiledPass& pass, PassSlot slot);
    std::vector<StageOutcome> runJobs();
    void finishPendingStages();
    SourceLoc functionLocation(const LoweredStage& lowered) const;
    void reportHlslMessages(const std::vector<HlslMessage>& messages, const LoweredStage& lowered);
    SourceLoc userLocation(const HlslMessage& m, const LoweredStage& lowered) const;
    void resolveReflection(StageProgram& program, const CompiledPass& pass);
    const Expr* shaderExpr(const StateAssignment& s);
    CompiledPass compilePass(const Pass& p, PassSlot slot);

    const Effect& mEffect;
    const CompileOptions& mOptions;
    DiagnosticSink& mDiagnostics;
    std::unique_ptr<CompiledEffect> mOut;
    std::map<std::string, size_t> mIndex;  // parameter name -> index
    std::map<std::string, int> mSamplerUnits;
    std::vector<LoweredArgument> mPassArguments;  // the current pass's, as lowering numbers them
    // The outputs (by varying location) of the current pass's stage before its pixel shader: its geometry
    // shader's, else its vertex shader's (none after tessellation), which the pixel shader reads.
    std::optional<std::map<int, TypeDesc>> mPreviousOutputs;
    // The current pass's hull shader, whose partitioning and output topology its domain shader takes.
    const FunctionDecl* mHull = nullptr;
    bool mFailed = false;
    // The diagnostics of the current technique's stages that the lowering could not express
    // (UnsupportedFeature), held back until run() knows whether another technique can run.
    std::vector<Diagnostic> mTechniqueUnsupported;
    std::vector<PendingStage> mPending;
    std::vector<StageJob> mJobs;
    std::map<uint64_t, size_t> mJobByKey;
};

StageProgram& stageProgram(CompiledPass& pass, ShaderStage stage) {
    return stage == ShaderStage::Vertex     ? pass.vertex
           : stage == ShaderStage::Fragment ? pass.fragment
           : stage == ShaderStage::Geometry ? pass.geometry
           : stage == ShaderStage::Hull     ? pass.hull
                                            : pass.domain;
}

// [SECTION] Initial values

void Compiler::initialValues() {
    // In order, so that later initializers see earlier values (`float4 c = {Z, Z, Z, Z}` after `float Z`).
    for (size_t i = 0; i < mEffect.parameters.size(); ++i) {
        const Parameter& p = mEffect.parameters[i];
        Value v = zeroValue(p.type);
        if (p.initializer && p.initializer->kind != Expr::Kind::Compile &&
            (p.type.isNumeric() || p.type.base == BaseType::String)) {
            if (auto r = eval(*p.initializer, &p.type)) v = std::move(*r);
        } else if (p.initializer && p.initializer->kind == Expr::Kind::String) {
            v = Value::text(p.initializer->text);  // a texture's file name
        }
        mOut->initialValues.push_back(std::move(v));
        mIndex[p.name] = i;
    }
}

// What the runtime reads of each parameter (its binding by semantic, the light it names, the light-space
// parameterization it selects), so that the runtime never reads the syntax tree.
void Compiler::parameterInfo() {
    mOut->path = mEffect.path;
    for (const Parameter& p : mEffect.parameters) {
        ParameterInfo info;
        info.name = p.name;
        info.type = p.type;
        info.semantic = p.semantic;
        info.isStatic = p.isStatic;
        info.loc = p.loc;
        for (const char* name : {"frustum", "Object"}) {
            const Annotation* a = p.annotation(name);
            if (a && a->value.kind == Expr::Kind::String) {
                info.light = a->value.text;
                break;
            }
        }
        if (const Annotation* a = p.annotation("Parameterization")) {
            info.hasParameterization = true;
            if (a->value.kind == Expr::Kind::String) info.parameterization = a->value.text;
            info.parameterizationLoc = a->loc;
        }
        mOut->parameters.push_back(std::move(info));
    }
}

// The pass annotations the runtime acts on (CompiledPass): CullClosedOnly, LeaveOutWhen, FilterReachTexels.
void Compiler::passAnnotations(const Pass& source, CompiledPass& pass) {
    if (const Annotation* a = source.annotation("CullClosedOnly")) {
        std::optional<Value> value = eval(a->value, nullptr);
        if (value && !value->data.empty()) {
            pass.cullClosedOnly = value->asBool();
        } else if (value) {
            error(DiagId::InvalidAnnotation, a->loc, {"CullClosedOnly", "expected true or false"});
        }
    }
    if (const Annotation* a = source.annotation("LeaveOutWhen")) {
        const std::string text = a->value.kind == Expr::Kind::String ? a->value.text : "";
        if (text == "NoClosedObjects") {
            pass.leaveOutWhen = LeaveOutCondition::NoClosedObjects;
        } else if (text == "NoLightArea") {
            pass.leaveOutWhen = LeaveOutCondition::NoLightArea;
        } else {
            error(DiagId::InvalidAnnotation, a->loc,
                  {"LeaveOutWhen", "expected \"NoClosedObjects\" or \"NoLightArea\""});
        }
    }
    if (const Annotation* a = source.annotation("FilterReachTexels")) {
        std::optional<Value> value = eval(a->value, nullptr);
        if (value && value->data.size() == 1 && std::isfinite(value->asFloat())) {
            pass.filterReachTexels = std::max(1.0f, value->asFloat());  // a texel for rounding at least
        } else if (value) {
            error(DiagId::InvalidAnnotation, a->loc, {"FilterReachTexels", "expected a number of texels"});
        }
    }
}

// [SECTION] Textures and samplers

void Compiler::textures() {
    std::filesystem::path base = std::filesystem::path(mEffect.path).parent_path();
    for (size_t i = 0; i < mEffect.parameters.size(); ++i) {
        const Parameter& p = mEffect.parameters[i];
        if (!p.type.isTexture()) continue;
        TextureDesc t;
        t.parameter = i;
        t.loc = p.loc;
        t.type = p.type.base == BaseType::TextureCube ? BaseType::TextureCube
                 : p.type.base == BaseType::Texture3D ? BaseType::Texture3D
                 : p.type.base >= BaseType::Texture1DArray && p.type.base <= BaseType::Texture2DMS
                     ? p.type.base
                     : BaseType::Texture2D;
        resourceShape(p, t);
        // An untyped `texture` says what it holds in FX Composer's ResourceType annotation.
        if (const Annotation* a = p.annotation("ResourceType");
            a && p.type.base == BaseType::Texture && a->value.kind == Expr::Kind::String) {
            if (equalsIgnoreCase(a->value.text, "Cube")) t.type = BaseType::TextureCube;
            if (equalsIgnoreCase(a->value.text, "3D") || equalsIgnoreCase(a->value.text, "Volume"))
                t.type = BaseType::Texture3D;
        }
        std::string semantic = upper(p.semantic);
        t.kind = semantic == "RENDERCOLORTARGET"          ? TextureDesc::Kind::RenderColorTarget
                 : semantic == "RENDERDEPTHSTENCILTARGET" ? TextureDesc::Kind::RenderDepthStencilTarget
                                                          : TextureDesc::Kind::Runtime;
        bool depth = t.kind == TextureDesc::Kind::RenderDepthStencilTarget;
        t.format = depth ? TextureFormat::D24S8 : TextureFormat::RGBA8;
        TypeDesc int2;
        int2.base = BaseType::Float;
        int2.shape = Shape::Vector;
        int2.cols = 2;
        TypeDesc scalar;
        // Written so that NaN, infinities and fractions below 1 fail too (`w <= 0` let NaN and 0.5 through,
        // and the cast of NaN or 1e30 to an integer was undefined behaviour).
        const int maxSize = mOptions.maxRenderTargetSize;
        auto checkSize = [&](float w, float h, const SourceLoc& loc) {
            auto inRange = [&](float side) { return side >= 1 && side <= static_cast<float>(maxSize); };
            if (!inRange(w) || !inRange(h)) {
                auto shown = [](float side) {
                    if (side != side) return std::string("NaN");
                    char text[32];
                    std::snprintf(text, sizeof text, "%g", static_cast<double>(side));
                    return std::string(text);
                };
                error(
                    DiagId::InvalidDimensions, loc,
                    {shown(w) + "x" + shown(h) + " (each side must be 1.." + std::to_string(maxSize) + ")"});
                return false;
            }
            return true;
        };
        // FX Composer also treated a texture as a render target when only its size annotations said so
        // (`RenderTargetDimensions`, `ViewPortRatio`), with no RENDERCOLORTARGET semantic; its Format
        // tells colour from depth.
        if (t.kind == TextureDesc::Kind::Runtime && p.semantic.empty() &&
            (p.annotation("RenderTargetDimensions") || p.annotation("ViewPortRatio"))) {
            const Annotation* format = p.annotation("Format");
            const std::optional<TextureFormat> f = format && format->value.kind == Expr::Kind::String
                                                       ? parseTextureFormat(format->value.text)
                                                       : std::nullopt;
            depth = f && isDepthFormat(*f);
            t.kind =
                depth ? TextureDesc::Kind::RenderDepthStencilTarget : TextureDesc::Kind::RenderColorTarget;
            t.format = depth ? TextureFormat::D24S8 : TextureFormat::RGBA8;
        }
        for (const char* dimensions : {"Dimensions", "RenderTargetDimensions"})
            if (const Annotation* a = p.annotation(dimensions)) {
                if (auto v = eval(a->value, &int2); v && checkSize(v->data[0], v->data[1], a->loc)) {
                    t.width = static_cast<int>(v->data[0]);
                    t.height = static_cast<int>(v->data[1]);
                }
            }
        const Annotation* w = p.annotation("width");
        const Annotation* h = p.annotation("height");
        if (w || h) {
            auto wv = w ? eval(w->value, &scalar) : std::optional<Value>(Value::scalar(1));
            auto hv = h ? eval(h->value, &scalar) : wv;
            if (wv && hv && checkSize(wv->asFloat(), hv->asFloat(), (w ? w : h)->loc)) {
                t.width = static_cast<int>(wv->asFloat());
                t.height = static_cast<int>(hv->asFloat());
            }
        }
        if (const Annotation* a = p.annotation("ViewPortRatio")) {
            if (auto v = eval(a->value, nullptr)) {
                t.viewportRatio[0] = v->data.empty() ? 1.0f : v->data[0];
                t.viewportRatio[1] = v->data.size() > 1 ? v->data[1] : t.viewportRatio[0];
                if (t.viewportRatio[0] <= 0 || t.viewportRatio[1] <= 0 || t.viewportRatio[0] > 16 ||
                    t.viewportRatio[1] > 16)
                    error(DiagId::InvalidDimensions, a->loc, {"ViewPortRatio must be in (0, 16]"});
            }
        }
        if (const Annotation* a = p.annotation("Format")) {
            if (a->value.kind != Expr::Kind::String) {
                error(DiagId::InvalidTextureFormat, a->value.loc, {a->value.str()});
            } else if (auto f = parseTextureFormat(a->value.text)) {
                t.format = *f;
            } else {
                error(DiagId::InvalidTextureFormat, a->value.loc, {a->value.text});
            }
        }
        if (const Annotation* a = p.annotation("MipLevels")) {
            if (auto v = eval(a->value, &scalar)) t.mipLevels = std::max(0, v->asInt());
        }
        if (const Annotation* a = p.annotation("Procedural")) procedural(p, *a, t);
        std::string resource;
        SourceLoc resourceLoc = p.loc;
        if (const Annotation* a = p.annotation("ResourceName"); a && a->value.kind == Expr::Kind::String) {
            resource = a->value.text;
            resourceLoc = a->value.loc;
        } else if (p.initializer && p.initializer->kind == Expr::Kind::String) {
            resource = p.initializer->text;
            resourceLoc = p.initializer->loc;
        }
        if (!resource.empty() && t.kind == TextureDesc::Kind::Runtime) {
            t.kind = TextureDesc::Kind::File;
            t.resourceName = resource;
            std::string name = resource;  // "textures\\rock.dds" names a folder on Windows
            for (char& c : name)
                if (c == '\\') c = '/';
            std::filesystem::path path = base / name;
            std::error_code ec;
            if (std::filesystem::exists(path, ec)) {
                t.resolvedPath = path.string();
            } else if (std::optional<std::string> found = detail::findPathIgnoringCase(path.string())) {
                t.resolvedPath = *found;
                mDiagnostics.report(DiagId::TextureCaseMismatch, resourceLoc, {resource, *found});
            } else {
                // FX Composer drew with a default texture when a file was missing, and so do we, whatever
                // the file's type: a located warning, and a neutral (white) texture at run time.
                mDiagnostics.report(DiagId::TextureFileNotFound, resourceLoc, {resource});
            }
        }
        if (t.kind == TextureDesc::Kind::Runtime && !resource.empty()) t.resourceName = resource;
        const bool array = t.type == BaseType::Texture1DArray || t.type == BaseType::Texture2DArray ||
                           t.type == BaseType::TextureCubeArray;
        if (array && (t.kind == TextureDesc::Kind::RenderColorTarget ||
                      t.kind == TextureDesc::Kind::RenderDepthStencilTarget))
            error(DiagId::UnsupportedFeature, p.loc,
                  {"texture array '" + p.name +
                   "' cannot be a render target: a pass's RenderColorTarget has no way to choose the "
                   "element it renders into"});
        if (t.type == BaseType::Texture2DMS && t.samples == 0) {
            if (t.kind == TextureDesc::Kind::RenderColorTarget ||
                t.kind == TextureDesc::Kind::RenderDepthStencilTarget)
                error(DiagId::TypeMismatch, p.loc,
                      {"Texture2DMS '" + p.name +
                       "': a multisample render target needs its sample count (Texture2DMS<float4, 4>)"});
            t.samples = 1;
        }
        mOut->textures.push_back(std::move(t));
    }
}

// A D3D10 array's element count (`int ArraySize = N;`, default 1) and a Texture2DMS<T, N>'s sample count.
void Compiler::resourceShape(const Parameter& p, TextureDesc& t) {
    const bool array = t.type == BaseType::Texture1DArray || t.type == BaseType::Texture2DArray ||
                       t.type == BaseType::TextureCubeArray;
    if (const Annotation* a = p.annotation("ArraySize")) {
        TypeDesc scalar;
        std::optional<Value> v = array ? eval(a->value, &scalar) : std::nullopt;
        const float n = v ? v->asFloat() : 0.0f;
        if (!array)
            error(DiagId::InvalidAnnotation, a->loc, {"ArraySize", "only a texture array has elements"});
        else if (!(n >= 1 && n <= 2048 && n == std::floor(n)))
            error(DiagId::InvalidAnnotation, a->value.loc, {"ArraySize", "must be an integer in 1..2048"});
        else
            t.arraySize = static_cast<int>(n);
    }
    if (t.type != BaseType::Texture2DMS) return;
    // `Texture2DMS<float4, 4>`: the count follows the element type; D3D10 allows 1..32, GL's limit is the
    // driver's (GL_MAX_COLOR_TEXTURE_SAMPLES, at least 1), checked when the runtime creates it.
    const std::string& args = p.type.templateArgs;
    const size_t comma = args.rfind(',');
    std::string count = comma == std::string::npos ? "" : args.substr(comma + 1);
    count.erase(0, count.find_first_not_of(" \t"));
    count.erase(count.find_last_not_of(" \t") + 1);
    if (comma == std::string::npos) {
        t.samples = 0;  // `Texture2DMS<float4>`: any count (SM 5); a render target needs one (below)
        return;
    }
    const bool digits =
        !count.empty() && count.size() <= 2 && count.find_first_not_of("0123456789") == std::string::npos;
    const int n = digits ? std::atoi(count.c_str()) : 0;
    if (n < 1 || n > 32)
        error(DiagId::TypeMismatch, p.loc,
              {"Texture2DMS '" + p.name +
               "': its sample count must be the second template argument, 1..32 (Texture2DMS<float4, 4>)"});
    else
        t.samples = static_cast<int>(n);
}

// `string Procedural = "noise"; int Seed = 7;` with Dimensions (default 64x64) and Format (default
// A8R8G8B8): a texture the runtime generates once when it creates the effect.
void Compiler::procedural(const Parameter& p, const Annotation& annotation, TextureDesc& t) {
    if (t.kind != TextureDesc::Kind::Runtime || t.type != BaseType::Texture2D) {
        error(DiagId::InvalidAnnotation, annotation.loc,
              {"Procedural", "only a 2D texture that is not a render target can be procedural"});
        return;
    }
    if (annotation.value.kind != Expr::Kind::String || !equalsIgnoreCase(annotation.value.text, "noise")) {
        error(DiagId::InvalidAnnotation, annotation.value.loc,
              {"Procedural", "'" + annotation.value.str() + "' is not a generator (known: \"noise\")"});
        return;
    }
    if (isDepthFormat(t.format)) {
        error(DiagId::InvalidAnnotation, annotation.loc,
              {"Procedural", "a noise texture needs a colour format"});
        return;
    }
    t.kind = TextureDesc::Kind::Procedural;
    if (t.width == 0) t.width = t.height = 64;
    if (const Annotation* seed = p.annotation("Seed")) {
        TypeDesc scalar;
        if (auto v = eval(seed->value, &scalar)) {
            const float value = v->asFloat();
            if (!(value >= 0 && value <= 4294967295.0f && value == std::floor(value)))
                error(DiagId::InvalidAnnotation, seed->value.loc,
                      {"Seed", "must be an integer between 0 and 4294967295"});
            else
                t.seed = static_cast<uint32_t>(value);
        }
    }
}

void Compiler::samplers() {
    int unit = 0;
    for (size_t i = 0; i < mEffect.parameters.size(); ++i) {
        const Parameter& p = mEffect.parameters[i];
        if (!p.type.isSampler()) continue;
        SamplerDesc s;
        s.parameter = i;
        s.loc = p.loc;
        const bool d3d10 =
            p.type.base == BaseType::SamplerState || p.type.base == BaseType::SamplerComparisonState;
        if (d3d10) {
            // D3D10's sampler defaults (D3D11_SAMPLER_DESC's, which FX11 uses) differ from D3D9's: trilinear
            // and clamped, white border; a comparison sampler compares with NEVER until told otherwise.
            s.minFilter = s.magFilter = s.mipFilter = 2;
            s.addressU = s.addressV = s.addressW = 3;
            for (float& c : s.borderColor) c = 1.0f;
            s.comparisonFunc = p.type.base == BaseType::SamplerComparisonState ? 1 : 0;
        } else {
            mSamplerUnits[p.name] = unit++;  // D3D10 samplers get units per (texture, sampler) pair
        }
        bool hasComparison = false;
        for (const StateAssignment& a : p.samplerState) {
            auto id = findSamplerState(a.name);
            if (!id) {
                error(DiagId::UnknownState, a.loc, {a.name});
                continue;
            }
            const StateInfo& info = samplerStateInfo(*id);
            if (*id == SamplerStateId::Texture) {
                auto it = mIndex.find(a.value.text);
                if (it == mIndex.end())
                    error(DiagId::UnknownIdentifier, a.value.loc, {a.value.text});
                else if (const TypeDesc& type = mEffect.parameters[it->second].type; !type.isTexture())
                    // Declared, but of the wrong type: say so in the author's terms.
                    error(DiagId::InvalidStateValue, a.value.loc,
                          {a.name,
                           "'" + a.value.text + "' is a " + type.hlslName() + " parameter, not a texture"});
                else
                    s.texture = it->second;
                // An untyped `texture` sampled through a samplerCUBE or sampler3D holds that kind.
                if (s.texture && mEffect.parameters[*s.texture].type.base == BaseType::Texture &&
                    (p.type.base == BaseType::SamplerCube || p.type.base == BaseType::Sampler3D)) {
                    for (TextureDesc& t : mOut->textures)
                        if (t.parameter == *s.texture)
                            t.type = p.type.base == BaseType::SamplerCube ? BaseType::TextureCube
                                                                          : BaseType::Texture3D;
                }
                continue;
            }
            std::vector<float> value;
            if (a.value.kind == Expr::Kind::Identifier && !mIndex.count(a.value.text)) {
                auto e = findEnumValue(info.domain, a.value.text);
                if (!e) {
                    error(DiagId::UnknownStateValue, a.value.loc, {a.value.text, a.name, ""});
                    continue;
                }
                value = {static_cast<float>(*e)};
            } else if (auto v = eval(a.value, nullptr)) {
                value = v->data;
            } else {
                continue;
            }
            if (value.empty()) continue;
            int n = static_cast<int>(value[0]);
            switch (*id) {
                case SamplerStateId::AddressU:
                    s.addressU = n;
                    break;
                case SamplerStateId::AddressV:
                    s.addressV = n;
                    break;
                case SamplerStateId::AddressW:
                    s.addressW = n;
                    break;
                case SamplerStateId::MinFilter:
                    s.minFilter = n;
                    break;
                case SamplerStateId::MagFilter:
                    s.magFilter = n;
                    break;
                case SamplerStateId::MipFilter:
                    s.mipFilter = n;
                    break;
                case SamplerStateId::MaxAnisotropy:
                    s.maxAnisotropy = n;
                    break;
                case SamplerStateId::MipMapLodBias:
                    s.mipLodBias = value[0];
                    break;
                case SamplerStateId::MinLOD:
                    s.minLod = std::max(value[0], -1000.0f);
                    break;
                case SamplerStateId::MaxLOD:
                    s.maxLod = std::min(value[0], 1000.0f);
                    break;
                case SamplerStateId::ComparisonFunc:
                    s.comparisonFunc = n;
                    break;
                case SamplerStateId::BorderColor:
                    if (value.size() >= 4) {
                        for (int k = 0; k < 4; ++k) s.borderColor[k] = value[static_cast<size_t>(k)];
                    } else {  // packed D3DCOLOR 0xAARRGGBB
                        auto c = static_cast<uint32_t>(static_cast<int64_t>(value[0]));
                        s.borderColor[0] = static_cast<float>((c >> 16) & 255) / 255.0f;
                        s.borderColor[1] = static_cast<float>((c >> 8) & 255) / 255.0f;
                        s.borderColor[2] = static_cast<float>(c & 255) / 255.0f;
                        s.borderColor[3] = static_cast<float>((c >> 24) & 255) / 255.0f;
                    }
                    break;
                case SamplerStateId::Filter: {
                    // D3D10_FILTER bits: mip linear 0x1, mag linear 0x4, min linear 0x10, anisotropic 0x40,
                    // comparison 0x80.
                    auto tex = [&](int bit) { return (n & 0x40) ? 3 : ((n & bit) ? 2 : 1); };
                    s.minFilter = tex(0x10);
                    s.magFilter = tex(0x04);
                    s.mipFilter = (n & 0x01) ? 2 : 1;
                    hasComparison = (n & 0x80) != 0;
                    break;
                }
                default:
                    break;
            }
        }
        if (hasComparison && s.comparisonFunc == 0) s.comparisonFunc = 4;  // LESSEQUAL
        // A D3D10 SamplerState compares only through SampleCmp on a SamplerComparisonState.
        if (p.type.base == BaseType::SamplerState) s.comparisonFunc = 0;
        mOut->samplers.push_back(s);
    }
}

// D3D10 (texture, sampler) pairs: units after the D3D9 samplers', one per pair a pass samples (the same
// in both stages, so that they link to one GL sampler unit).
void Compiler::assignPairUnits() {
    const int first = static_cast<int>(mSamplerUnits.size());
    for (CompiledTechnique& technique : mOut->techniques)
        for (CompiledPass& pass : technique.passes) {
            std::map<std::string, int> units;
            for (StageProgram* stage :
                 {&pass.vertex, &pass.hull, &pass.domain, &pass.geometry, &pass.fragment})
                for (SamplerBinding& s : stage->samplers)
                    if (!s.pairTexture.empty())
                        s.unit = units.try_emplace(s.glslName, first + static_cast<int>(units.size()))
                                     .first->second;
        }
}

// [SECTION] Scripts

std::vector<ScriptCommand> Compiler::script(const std::vector<Annotation>& annotations, bool& has) {
    has = false;
    for (const Annotation& a : annotations) {
        if (!equalsIgnoreCase(a.name, "Script") || a.value.kind != Expr::Kind::String) continue;
        has = true;
        DiagnosticList local;
        auto commands = parseSasScript(a.value, local);
        for (const Diagnostic& d : local.items()) {
            if (d.severity == Severity::Error) mFailed = true;
            mDiagnostics.report(d);
        }
        return commands;
    }
    return {};
}

void Compiler::validateScript(std::vector<ScriptCommand>& commands, const Technique* technique) {
    int loops = 0;
    // Commands FX Composer warned about and skipped: left out of the compiled script, so that the runtime
    // runs what FX Composer ran.
    std::vector<bool> ignored(commands.size(), false);
    for (size_t index = 0; index < commands.size(); ++index) {
        const ScriptCommand& c = commands[index];
        auto ignore = [&](const std::string& why) {
            mDiagnostics.report(DiagId::ScriptCommandIgnored, c.loc,
                                {std::string(scriptCommandName(c.kind)), why});
            ignored[index] = true;
        };
        switch (c.kind) {
            case ScriptCommand::Kind::Pass: {
                bool found = false;
                if (technique)
                    for (const Pass& p : technique->passes) found |= scriptNameMatches(c.value, p.name);
                if (!found)
                    error(DiagId::ScriptUnknownPass, c.loc, {c.value, technique ? technique->name : ""});
                break;
            }
            case ScriptCommand::Kind::ClearSetColor:
            case ScriptCommand::Kind::ClearSetDepth:
            case ScriptCommand::Kind::ClearSetStencil: {
                // A parameter's name or a literal ("0.5", "1,0,0,1"), as the runtime reads it.
                bool literal = true;
                std::stringstream items(c.value);
                for (std::string item; std::getline(items, item, ',');) {
                    char* end = nullptr;
                    std::strtod(item.c_str(), &end);
                    literal = literal && end != item.c_str();
                }
                if (!mIndex.count(c.value) && !literal)
                    ignore("'" + c.value +
                           "' is neither a parameter nor a number; the clear value stays as it was");
                break;
            }
            case ScriptCommand::Kind::RenderColorTarget:
            case ScriptCommand::Kind::RenderDepthStencilTarget: {
                if (c.value.empty()) break;
                // What textures() made of the declaration: a RENDERCOLORTARGET semantic, or FX Composer's
                // size annotations alone.
                auto it = mIndex.find(c.value);
                const bool wantDepth = c.kind == ScriptCommand::Kind::RenderDepthStencilTarget;
                const TextureDesc::Kind want = wantDepth ? TextureDesc::Kind::RenderDepthStencilTarget
                                                         : TextureDesc::Kind::RenderColorTarget;
                bool isTarget = false;
                for (const TextureDesc& t : mOut->textures)
                    isTarget =
                        isTarget || (it != mIndex.end() && t.parameter == it->second && t.kind == want);
                if (!isTarget)
                    ignore("'" + c.value + "' is not a " + (wantDepth ? "depth-stencil" : "render") +
                           "-target texture; the pass draws into the target bound before");
                break;
            }
            case ScriptCommand::Kind::Technique: {
                // D3DX and FX Composer never failed an effect over its technique selector: names the
                // effect lacks (its D3D10 twins, techniques a #define renamed) are skipped with a warning,
                // and with none left the first technique runs (runtime/src/ScriptInterpreter.cpp).
                const std::vector<std::string> names =
                    c.selectorCondition.empty() ? std::vector<std::string>{c.value} : c.selectorAlternatives;
                bool any = false;
                for (const std::string& name : names) {
                    any = any || mEffect.findTechnique(name);
                    if (!mEffect.findTechnique(name))
                        mDiagnostics.report(DiagId::ScriptUnknownTechnique, c.loc, {name});
                }
                if (!any && !mEffect.techniques.empty())
                    mDiagnostics.report(DiagId::ScriptTechniqueFallback, c.loc,
                                        {mEffect.techniques.front().name});
                break;
            }
            case ScriptCommand::Kind::LoopByCount: {
                ++loops;
                // A literal count is checked here, once, rather than failing every frame in the runtime
                // (runtime/render/src/ScriptInterpreter.cpp checks parameter values, with the same limit).
                const char* text = c.value.c_str();
                char* end = nullptr;
                const double count = std::strtod(text, &end);
                if (end != text && *end == '\0' && !mIndex.count(c.value)) {
                    if (!(count >= 0) || std::floor(count) != count)
                        error(DiagId::InvalidScriptCommand, c.loc,
                              {"LoopByCount", "'" + c.value + "' is not a non-negative whole count"});
                    else if (count > mOptions.maxScriptLoopCount)
                        error(DiagId::InvalidScriptCommand, c.loc,
                              {"LoopByCount", c.value + " iterations exceed the limit of " +
                                                  std::to_string(mOptions.maxScriptLoopCount)});
                }
                break;
            }
            case ScriptCommand::Kind::LoopEnd:
                if (--loops < 0) {
                    error(DiagId::ScriptLoopEndWithoutLoop, c.loc, {});
                    loops = 0;
                }
                break;
            default:
                break;
        }
    }
    if (loops > 0 && !commands.empty()) error(DiagId::ScriptUnbalancedLoop, commands.back().loc, {});
    size_t kept = 0;
    for (size_t index = 0; index < commands.size(); ++index) {
        if (ignored[index]) continue;
        if (kept != index) commands[kept] = std::move(commands[index]);  // never onto itself
        ++kept;
    }
    commands.resize(kept);
}

void Compiler::scripts() {
    for (const Parameter& p : mEffect.parameters) {
        if (upper(p.semantic) != "STANDARDSGLOBAL") continue;
        mOut->globalScript = script(p.annotations, mOut->hasGlobalScript);
        validateScript(mOut->globalScript, nullptr);
    }
}

// [SECTION] Stages: lowering, cache, glslang, SPIRV-Cross, reflection

SourceLoc Compiler::userLocation(const HlslMessage& m, const LoweredStage& lowered) const {
    if (m.file.empty() || m.file == kGeneratedFile || m.line <= 0) return lowered.compileLoc;
    SourceLoc loc{m.file, m.line, m.column};
    if (loc.column == 0) {
        // glslang 12 gives no column: find the token the message quotes ('name' : ...) on that line of the
        // unit, whose columns are the preprocessed text's (declarations are padded to their column).
        std::string line, file;
        int number = 0;
        size_t pos = 0;
        const std::string& text = lowered.hlsl;
        while (pos < text.size()) {
            size_t end = text.find('\n', pos);
            if (end == std::string::npos) end = text.size();
            std::string l = text.substr(pos, end - pos);
            pos = end + 1;
            if (l.rfind("#line ", 0) == 0) {
                size_t q = l.find('"');
                number = std::stoi(l.substr(6)) - 1;
                file = q == std::string::npos ? file : l.substr(q + 1, l.rfind('"') - q - 1);
            } else {
                ++number;
                if (file == m.file && number == m.line) {
                    line = l;
                    break;
                }
            }
        }
        size_t q1 = m.text.find('\''), q2 = q1 == std::string::npos ? q1 : m.text.find('\'', q1 + 1);
        size_t column = std::string::npos;
        if (q2 != std::string::npos && q2 > q1 + 1) column = line.find(m.text.substr(q1 + 1, q2 - q1 - 1));
        if (column == std::string::npos) column = line.find_first_not_of(" \t");
        loc.column = column == std::string::npos ? 0 : static_cast<int>(column) + 1;
    }
    return mEffect.sourceMap.map(loc);
}

void Compiler::reportHlslMessages(const std::vector<HlslMessage>& messages, const LoweredStage& lowered) {
    // After glslang's first error its parser recovers with generic follow-ons at column 1 ("'declaration'
    // : Expected", "'' : Could not perform requested binary operation") that only repeat the first one.
    bool hadError = false;
    auto isFollowOn = [](const std::string& text) {
        return text.rfind("'declaration' : Expected", 0) == 0 ||
               text.rfind("'function call arguments' : Expected", 0) == 0 || text.rfind("'' : ", 0) == 0;
    };
    for (const HlslMessage& m : messages) {
        if (m.error && hadError && isFollowOn(m.text)) continue;
        hadError = hadError || m.error;
        SourceLoc loc = userLocation(m, lowered);
        std::string text = m.text;
        while (!text.empty() && text.back() == ' ') text.pop_back();
        if (m.file == kGeneratedFile) text += " (in the code generated for '" + lowered.entryPoint + "')";
        if (m.error)
            error(DiagId::HlslError, loc, {text});
        else if (m.file != kGeneratedFile)
            mDiagnostics.report(DiagId::HlslWarning, loc, {text});
    }
}

void Compiler::resolveReflection(StageProgram& program, const CompiledPass& pass) {
    // Indices are resolved on every compile, cache hit or not: an unchanged unit may belong to an effect
    // whose parameter list changed elsewhere (a texture added before it).
    for (UniformBinding& u : program.uniforms) {
        for (size_t a = 0; a < pass.arguments.size(); ++a)
            if (pass.arguments[a].memberName == u.name) {
                u.source = UniformBinding::Source::CompileArgument;
                u.index = a;
                u.type = pass.arguments[a].type;
            }
        if (u.source == UniformBinding::Source::Parameter) {
            auto it = mIndex.find(u.name);
            if (it != mIndex.end()) {
                u.index = it->second;
                u.type = mEffect.parameters[it->second].type;
            }
        }
    }
    for (SamplerBinding& s : program.samplers) {
        auto it = mIndex.find(s.pairTexture.empty() ? s.glslName : s.pairSampler);
        if (it != mIndex.end())
            s.samplerParameter = it->second;
        else if (!s.pairTexture.empty())
            s.samplerParameter = kNoSampler;  // Texture2D.Load: the texture alone
        if (auto texture = mIndex.find(s.pairTexture); !s.pairTexture.empty() && texture != mIndex.end())
            s.textureParameter = texture->second;
    }
    for (StorageBufferBinding& b : program.storageBuffers)
        if (auto it = mIndex.find(b.blockName); it != mIndex.end()) b.parameter = it->second;
}

bool Compiler::compileStage(const Expr& compile, ShaderStage stage, CompiledPass& pass, PassSlot slot) {
    DiagnosticList lowering;
    auto lowered = lowerStage(mEffect, compile, stage, mPassArguments, lowering,
                              mPreviousOutputs ? &*mPreviousOutputs : nullptr, mHull);
    // What the pass lowering cannot express (a semantic or stage form shadowfx has no GL counterpart
    // for) makes the technique invalid, not the effect: run() decides once every technique is lowered.
    const bool onlyUnsupported =
        !lowered && std::all_of(lowering.items().begin(), lowering.items().end(), [](const Diagnostic& d) {
            return d.severity != Severity::Error || d.id == DiagId::UnsupportedFeature;
        });
    if (onlyUnsupported) {
        mTechniqueUnsupported.insert(mTechniqueUnsupported.end(), lowering.items().begin(),
                                     lowering.items().end());
        return false;
    }
    for (const Diagnostic& d : lowering.items()) mDiagnostics.report(d);
    if (!lowered) {
        mFailed = true;
        return false;
    }
    if (stage == ShaderStage::Vertex && !mPreviousOutputs && !mHull)
        mPreviousOutputs = lowered->varyingOutputs;
    if (stage == ShaderStage::Geometry) {
        mPreviousOutputs = lowered->varyingOutputs;
        pass.primitive = lowered->primitive;
    }
    if (stage == ShaderStage::Hull) {
        pass.patchVertices = lowered->patchVertices;
        const std::vector<const FunctionDecl*> hull = mEffect.findFunctions(lowered->entryPoint);
        mHull = hull.empty() ? nullptr : hull.front();
    }
    // The stage's new arguments, as programs over the parameters they read.
    for (size_t a = pass.arguments.size(); a < mPassArguments.size(); ++a) {
        const LoweredArgument& argument = mPassArguments[a];
        pass.arguments.push_back(
            CompileArgument{compilePreshader(argument.expr, slotResolver(), &argument.type), argument.type,
                            argument.memberName});
    }
    StageProgram& program = stageProgram(pass, stage);
    std::string options = hlslToSpirvOptionsKey() + "|" + spirvToGlslOptionsKey() + "|" + lowered->profile;
    uint64_t key = CompileCache::hash(lowered->hlsl, stage, options);
    // A unit already waiting for a worker is looked up once that job is done (finishPendingStages).
    const bool waiting = mJobByKey.count(key) > 0;
    if (const StageProgram* cached = mOptions.cache && !waiting ? mOptions.cache->find(key) : nullptr) {
        program = *cached;
        resolveReflection(program, pass);
        return true;
    }
    auto [it, added] = mJobByKey.emplace(key, mJobs.size());
    if (added) {
        StageJob job;
        job.hlsl = lowered->hlsl;
        job.stage = stage;
        job.entryPoint = kWrapperEntryPoint;
        job.cross.uniformBlockName = stage == ShaderStage::Vertex     ? "fx_VsGlobals"
                                     : stage == ShaderStage::Fragment ? "fx_PsGlobals"
                                     : stage == ShaderStage::Geometry ? "fx_GsGlobals"
                                     : stage == ShaderStage::Hull     ? "fx_HsGlobals"
                                                                      : "fx_DsGlobals";
        // One uniform block binding per stage: the stage enum's order.
        job.cross.uniformBlockBinding = static_cast<int>(stage);
        job.cross.samplerUnits = mSamplerUnits;
        job.cross.depthSamplers = lowered->depthSamplers;
        mJobs.push_back(std::move(job));
    }
    mPending.push_back(PendingStage{slot, std::move(*lowered), key, it->second});
    return true;
}

std::vector<StageOutcome> Compiler::runJobs() {
    std::vector<StageOutcome> outcomes;
    if (mJobs.empty()) return outcomes;
    if (mOptions.isolation == CompileIsolation::Workers) {
        CompileWorkers& workers = mOptions.workers ? *mOptions.workers : CompileWorkers::shared();
        if (workers.available()) return workers.run(mJobs);
        mDiagnostics.report(DiagId::CompileWorkerNotFound, SourceLoc{mEffect.path, 0, 0});
    }
    for (const StageJob& job : mJobs) outcomes.push_back(compileStageInProcess(job));
    return outcomes;
}

// SPIRV-Cross speaks of SPIR-V, which the user never wrote: say which shader of the effect it failed on
// and, where the cause is known, what in the effect led there.
std::string crossErrorInEffectTerms(const std::string& message, const LoweredStage& lowered) {
    const char* stage = lowered.stage == ShaderStage::Vertex     ? "vertex"
                        : lowered.stage == ShaderStage::Fragment ? "pixel"
                        : lowered.stage == ShaderStage::Geometry ? "geometry"
                        : lowered.stage == ShaderStage::Hull     ? "hull"
                                                                 : "domain";
    std::string cause;
    if (message.find("Cannot find mapping for combined sampler") != std::string::npos)
        cause =
            "a texture object's Sample or Gather method is given a D3D9 sampler (sampler2D, samplerCUBE, "
            "or a sampler the code also reads with tex2D and its kin), where it takes a SamplerState; ";
    return cause + "the " + std::string(stage) + " shader '" + lowered.entryPoint + "' (" + lowered.profile +
           ") cannot be written as GLSL (SPIRV-Cross: " + message + ")";
}

SourceLoc Compiler::functionLocation(const LoweredStage& lowered) const {
    std::vector<const FunctionDecl*> functions = mEffect.findFunctions(lowered.entryPoint);
    return functions.empty() || !functions.front()->loc.valid() ? lowered.compileLoc : functions.front()->loc;
}

void Compiler::finishPendingStages() {
    std::vector<StageOutcome> outcomes = runJobs();
    std::vector<bool> reported(outcomes.size(), false);
    for (PendingStage& pending : mPending) {
        const StageOutcome& outcome = outcomes[pending.job];
        const LoweredStage& lowered = pending.lowered;
        CompiledPass& pass = mOut->techniques[pending.slot.technique].passes[pending.slot.pass];
        // A unit shared by several passes is reported once, at the first.
        const bool first = !reported[pending.job];
        reported[pending.job] = true;
        if (first) reportHlslMessages(outcome.messages, lowered);
        // The repeats of a unit count as cache hits (misses if it failed), as when stages compiled singly.
        if (!first && mOptions.cache) mOptions.cache->find(pending.key);
        const SourceLoc function = functionLocation(lowered);
        using Status = StageOutcome::Status;
        switch (outcome.status) {
            case Status::Compiled:
                break;
            case Status::HlslFailed:
                mFailed = true;
                continue;
            case Status::CrossFailed:
                if (first)
                    error(DiagId::CrossCompileError, lowered.compileLoc,
                          {crossErrorInEffectTerms(outcome.crossError, lowered)});
                mFailed = true;
                continue;
            case Status::Crashed:
                if (first)
                    error(DiagId::HlslCompilerCrashed, function,
                          {outcome.signal ? "signal " + std::to_string(outcome.signal) : outcome.crossError});
                mFailed = true;
                continue;
            case Status::TimedOut: {
                CompileWorkers& workers = mOptions.workers ? *mOptions.workers : CompileWorkers::shared();
                if (first)
                    error(DiagId::HlslCompilerTimedOut, function, {std::to_string(workers.timeLimitMs())});
                mFailed = true;
                continue;
            }
            case Status::WorkerFailed:
                if (first) error(DiagId::CompileWorkerFailed, function, {outcome.crossError});
                mFailed = true;
                continue;
            case Status::SanitizerReport:
                if (first) error(DiagId::CompileWorkerSanitizerReport, function, {outcome.crossError});
                mFailed = true;
                continue;
        }
        StageProgram& program = stageProgram(pass, lowered.stage);
        program = outcome.program;
        program.stage = lowered.stage;
        program.entryPoint = lowered.entryPoint;
        program.profile = lowered.profile;
        program.hlsl = lowered.hlsl;
        program.sourceHash = pending.key;
        if (mOptions.cache) mOptions.cache->store(pending.key, program);
        resolveReflection(program, pass);
    }
}

// [SECTION] Passes and techniques

// A pass whose blend factors name the pixel shader's second output (SRC1_COLOR .. INV_SRC1_ALPHA).
bool blendsDualSource(const CompiledPass& pass) {
    return std::any_of(pass.states.begin(), pass.states.end(), [](const RenderStateSetting& s) {
        const bool factor = s.id == RenderStateId::SrcBlend || s.id == RenderStateId::DestBlend ||
                            s.id == RenderStateId::SrcBlendAlpha || s.id == RenderStateId::DestBlendAlpha;
        return factor && s.constant && *s.constant >= 16 && *s.constant <= 19;
    });
}

const Expr* Compiler::shaderExpr(const StateAssignment& s) {
    if (s.value.kind == Expr::Kind::Compile) return &s.value;
    if (s.value.kind == Expr::Kind::Identifier) {
        if (s.value.text == "NULL" || s.value.text == "null") return nullptr;
        // `VertexShader = (vsVar);` with `vertexshader vsVar = compile vs_3_0 VS();`
        if (const Parameter* p = mEffect.findParameter(s.value.text);
            p && p->initializer && p->initializer->kind == Expr::Kind::Compile)
            return &*p->initializer;
        // FX10's `GeometryShader gsNone = NULL;` (or `= 0;`): a variable that holds no shader.
        if (const Parameter* p = mEffect.findParameter(s.value.text);
            p && p->type.isShader() && p->initializer &&
            ((p->initializer->kind == Expr::Kind::Identifier &&
              (p->initializer->text == "NULL" || p->initializer->text == "null")) ||
             (p->initializer->kind == Expr::Kind::Number && p->initializer->number == 0)))
            return nullptr;
    }
    // `VertexShader = (vsArray[CurNumBones]);`, the DirectX SDK's skinning idiom: an element of a shader
    // array, the index a constant or a parameter. D3DX chose the element at every draw; shadowfx chooses
    // it once, from the index's initial value.
    if (s.value.kind == Expr::Kind::Index && s.value.args.size() == 2 &&
        s.value.args[0].kind == Expr::Kind::Identifier) {
        const Parameter* p = mEffect.findParameter(s.value.args[0].text);
        TypeDesc scalar;
        const std::optional<Value> index = eval(s.value.args[1], &scalar);
        if (p && p->initializer && p->initializer->kind == Expr::Kind::InitList && index) {
            const int i = index->asInt();
            if (i >= 0 && static_cast<size_t>(i) < p->initializer->args.size() &&
                p->initializer->args[static_cast<size_t>(i)].kind == Expr::Kind::Compile)
                return &p->initializer->args[static_cast<size_t>(i)];
            error(DiagId::InvalidCompileExpression, s.value.args[1].loc,
                  {"index " + std::to_string(i) + " is outside shader array '" + p->name + "'"});
            return nullptr;
        }
    }
    error(DiagId::InvalidCompileExpression, s.value.loc,
          {"'" + s.value.str() + "' is not a compile expression"});
    return nullptr;
}

CompiledPass Compiler::compilePass(const Pass& p, PassSlot slot) {
    CompiledPass pass;
    mPassArguments.clear();
    mPreviousOutputs.reset();
    mHull = nullptr;
    pass.name = p.name;
    pass.loc = p.loc;
    // The geometry shader first, wherever the pass sets it: the pixel shader's inputs take its outputs'
    // types. The hull shader before the domain shader, which takes its tessellator settings.
    const StateAssignment* hull = nullptr;
    const StateAssignment* domain = nullptr;
    const StateAssignment* geometry = nullptr;
    for (const StateAssignment& s : p.states) {
        const std::optional<RenderStateId> id = findRenderState(s.name);
        if (id == RenderStateId::GeometryShader) {
            geometry = &s;
            if (const Expr* compile = shaderExpr(s))
                compileStage(*compile, ShaderStage::Geometry, pass, slot);
        } else if (id == RenderStateId::HullShader || id == RenderStateId::DomainShader) {
            const bool set = !(s.value.kind == Expr::Kind::Identifier && s.value.text == "NULL") &&
                             !(s.value.kind == Expr::Kind::Number && s.value.number == 0);
            (id == RenderStateId::HullShader ? hull : domain) = set ? &s : nullptr;
        }
    }
    if (hull && !domain) {
        error(DiagId::UnsupportedFeature, hull->loc,
              {"a hull shader needs a domain shader in the same pass (SetDomainShader)"});
    } else if (domain && !hull) {
        error(DiagId::UnsupportedFeature, domain->loc,
              {"a domain shader needs a hull shader in the same pass (SetHullShader)"});
    } else if (hull && domain) {
        const Expr* hullCompile = shaderExpr(*hull);
        if (hullCompile && compileStage(*hullCompile, ShaderStage::Hull, pass, slot))
            if (const Expr* domainCompile = shaderExpr(*domain))
                compileStage(*domainCompile, ShaderStage::Domain, pass, slot);
        if (geometry && pass.primitive != CompiledPass::DrawPrimitive::Triangles)
            error(DiagId::UnsupportedFeature, geometry->loc,
                  {"a geometry shader after tessellation takes 'triangle' input: the domain shader outputs "
                   "triangles"});
    }
    // The vertex shader before the pixel shader, whose inputs it may leave unwritten.
    for (const StateAssignment& s : p.states)
        if (findRenderState(s.name) == RenderStateId::VertexShader)
            if (const Expr* compile = shaderExpr(s)) compileStage(*compile, ShaderStage::Vertex, pass, slot);
    for (const StateAssignment& s : p.states) {
        auto id = findRenderState(s.name);
        if (!id) {
            error(DiagId::UnknownState, s.loc, {s.name});
            continue;
        }
        if (*id == RenderStateId::GeometryShader || *id == RenderStateId::HullShader ||
            *id == RenderStateId::DomainShader || *id == RenderStateId::VertexShader)
            continue;
        if (*id == RenderStateId::PixelShader) {
            if (const Expr* compile = shaderExpr(s))
                compileStage(*compile, ShaderStage::Fragment, pass, slot);
            continue;
        }
        const StateInfo& info = renderStateInfo(*id);
        RenderStateSetting setting{*id, std::nullopt, {}, s.loc};
        if (s.value.kind == Expr::Kind::Number || s.value.kind == Expr::Kind::Bool) {
            setting.constant = s.value.number;
        } else if (s.value.kind == Expr::Kind::Identifier && !mIndex.count(s.value.text)) {
            if (auto e = findEnumValue(info.domain, s.value.text)) {
                setting.constant = *e;
            } else if (!equalsIgnoreCase(s.value.text, "true") && !equalsIgnoreCase(s.value.text, "false")) {
                error(DiagId::UnknownStateValue, s.value.loc, {s.value.text, s.name, ""});
                continue;
            }
        }
        if (!setting.constant && literalOnly(s.value)) {
            if (auto v = eval(s.value, nullptr); v && v->data.size() == 1) {
                const bool isBool = info.domain == StateDomain::Bool;
                setting.constant = isBool ? (v->data[0] != 0.0f ? 1.0 : 0.0) : v->data[0];
            }
        }
        if (!setting.constant) setting.value = compilePreshader(s.value, slotResolver(), nullptr);
        pass.states.push_back(std::move(setting));
    }
    passAnnotations(p, pass);
    pass.script = script(p.annotations, pass.hasScript);
    validateScript(pass.script, nullptr);
    return pass;
}

std::unique_ptr<CompiledEffect> Compiler::run() {
    initialValues();
    parameterInfo();
    textures();
    samplers();
    scripts();
    bool found = mOptions.technique.empty();
    // Techniques whose code uses what the lowering cannot express, with what it said. D3DX offered the
    // next valid technique where one did not validate (FindNextValidTechnique): such a technique is left
    // out with a warning while another technique can run; where none can, its errors fail the effect as
    // they stand.
    std::vector<std::pair<std::string, std::vector<Diagnostic>>> invalid;
    for (const Technique& t : mEffect.techniques) {
        if (!mOptions.technique.empty() && mEffect.findTechnique(mOptions.technique) != &t) continue;
        found = true;
        CompiledTechnique technique;
        technique.name = t.name;
        technique.group = t.group;
        technique.loc = t.loc;
        technique.script = script(t.annotations, technique.hasScript);
        validateScript(technique.script, &t);
        mTechniqueUnsupported.clear();
        for (const Pass& p : t.passes)
            technique.passes.push_back(
                compilePass(p, PassSlot{mOut->techniques.size(), technique.passes.size()}));
        if (!mTechniqueUnsupported.empty()) {
            const size_t index = mOut->techniques.size();
            std::erase_if(mPending,
                          [index](const PendingStage& stage) { return stage.slot.technique == index; });
            invalid.emplace_back(t.name.empty() ? "(unnamed)" : t.name, std::move(mTechniqueUnsupported));
            continue;
        }
        mOut->techniques.push_back(std::move(technique));
    }
    for (auto& [name, diagnostics] : invalid) {
        if (mOut->techniques.empty()) {
            for (const Diagnostic& d : diagnostics) mDiagnostics.report(d);
            mFailed = true;
            continue;
        }
        const auto first = std::find_if(diagnostics.begin(), diagnostics.end(),
                                        [](const Diagnostic& d) { return d.severity == Severity::Error; });
        mDiagnostics.report(DiagId::TechniqueRefused, first->loc, {name, first->message});
    }
    finishPendingStages();
    for (CompiledTechnique& technique : mOut->techniques)
        for (CompiledPass& pass : technique.passes)
            if (blendsDualSource(pass)) declareDualSourceOutput(pass.fragment.glsl);
    assignPairUnits();
    // An empty file, or one of helpers only; said only when nothing else is wrong with it.
    if (mEffect.techniques.empty() && !mFailed)
        error(DiagId::NoTechniques, SourceLoc{mEffect.path, 1, 1}, {});
    else if (!found)
        error(DiagId::UnknownTechnique, SourceLoc{mEffect.path, 0, 0}, {mOptions.technique});
    if (mFailed) return nullptr;
    return std::move(mOut);
}

}  // namespace

std::unique_ptr<CompiledEffect> compileEffect(std::shared_ptr<const Effect> effect,
                                              const CompileOptions& options, DiagnosticSink& diagnostics) {
    if (!effect) return nullptr;
    return Compiler(std::move(effect), options, diagnostics).run();
}

}  // namespace fx
