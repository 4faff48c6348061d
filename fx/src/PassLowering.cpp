// PassLowering: AST + compile expression -> HLSL unit (see PassLowering.h): the effect's declarations
// behind #line, the intrinsic rewrites (HlslRewriting.h) and the stage's wrapper (StageWrapper.h).
//
// [SECTION] Depth-compare samplers
// [SECTION] Effect declarations (verbatim, behind #line)
// [SECTION] lowerStage()
#include "PassLowering.h"
#include "CaseFolding.h"

#include "HlslRewriting.h"
#include "HlslSpelling.h"
#include "SemanticTables.h"
#include "StageWrapper.h"

#include <fx/Preshader.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <map>
#include <set>
#include <utility>

namespace fx {

// [SECTION] Depth-compare samplers

const Parameter* samplerTexture(const Effect& effect, const Parameter& sampler) {
    for (const StateAssignment& s : sampler.samplerState) {
        if (upperCase(s.name) != "TEXTURE") continue;
        if (s.value.kind == Expr::Kind::TextureRef || s.value.kind == Expr::Kind::Identifier)
            return effect.findParameter(s.value.text);
    }
    return nullptr;
}

bool isDepthCompareSampler(const Effect& effect, const Parameter& sampler) {
    const Parameter* texture = samplerTexture(effect, sampler);
    if (!texture) return false;
    if (upperCase(texture->semantic) == "RENDERDEPTHSTENCILTARGET") return true;
    if (const Annotation* format = texture->annotation("Format");
        format && format->value.kind == Expr::Kind::String) {
        auto f = parseTextureFormat(format->value.text);
        return f && isDepthFormat(*f);
    }
    return false;
}

namespace {

// [SECTION] Effect declarations (verbatim, behind #line)

void emitAt(std::string& out, const std::string& text, const SourceLoc& loc) {
    if (loc.line > 0) {
        out += "#line " + std::to_string(loc.line) + " \"" + loc.file + "\"\n";
        if (loc.column > 1) out.append(static_cast<size_t>(loc.column - 1), ' ');
    }
    out += text;
    out += "\n";
}

// glslang's HLSL front end reports "Recursion detected" for a user function called in a static's
// initializer (`static float4x4 BiasXf = make_bias_mat(Bias);`, FX Composer's shadow includes). Such a
// static is declared without its initializer, and the entry point assigns it before anything else runs:
// the value each invocation sees is the same. `declaration` and `assignment` are empty for any other
// static, and for a declaration of several names or an initializer list.
struct SplitStatic {
    std::string declaration;
    std::string assignment;
};

SplitStatic splitStaticInitializer(const Effect& effect, const Parameter& p) {
    const std::string& text = p.hlslText;
    size_t equals = std::string::npos;
    int nesting = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '(' || c == '[' || c == '{') ++nesting;
        if (c == ')' || c == ']' || c == '}') --nesting;
        const bool comparison = (i + 1 < text.size() && text[i + 1] == '=') ||
                                (i > 0 && std::strchr("=<>!", text[i - 1]) != nullptr);
        if (c == '=' && nesting == 0 && !comparison) {
            if (equals != std::string::npos) return {};
            equals = i;
        }
        if (c == ',' && nesting == 0) return {};
    }
    if (equals == std::string::npos) return {};
    std::string value = text.substr(equals + 1);
    const size_t semicolon = value.rfind(';');
    if (semicolon == std::string::npos) return {};
    value.erase(semicolon);
    if (value.find_first_not_of(" \t\r\n") == std::string::npos ||
        value[value.find_first_not_of(" \t\r\n")] == '{')
        return {};
    const std::set<std::string> names = identifiersIn(value);
    const bool callsFunction = std::any_of(effect.functions.begin(), effect.functions.end(),
                                           [&](const FunctionDecl& f) { return names.count(f.name) > 0; });
    if (!callsFunction) return {};
    // The entry point must be able to assign a `static const`; nothing else writes it.
    std::string declaration = text.substr(0, equals);
    for (size_t at = declaration.find("const"); at != std::string::npos;
         at = declaration.find("const", at + 1)) {
        const size_t end = at + 5;
        if ((at == 0 || !isIdentChar(declaration[at - 1])) &&
            (end >= declaration.size() || !isIdentChar(declaration[end])))
            declaration.erase(at, 5);
    }
    return {declaration + ";", p.name + " = " + value + ";"};
}

bool profileMatches(const std::string& profile, ShaderStage stage) {
    // The DXC-era profiles too (5_1, 6_0..6_8): engines' headers select them on newer back ends for the
    // same code, which glslang compiles alike.
    static const char* kVersions[] = {"1_1",  "1_2", "1_3",  "1_4", "2_0",           "2_a",           "2_b",
                                      "2_sw", "3_0", "3_sw", "4_0", "4_0_level_9_1", "4_0_level_9_3", "4_1",
                                      "5_0",  "5_1", "6_0",  "6_1", "6_2",           "6_3",           "6_4",
                                      "6_5",  "6_6", "6_7",  "6_8"};
    auto modern = [](const std::string& v) {
        return v == "5_0" || v == "5_1" ||
               (v.size() == 3 && v[0] == '6' && v[1] == '_' && v[2] >= '0' && v[2] <= '8');
    };
    std::string prefix = stage == ShaderStage::Vertex     ? "vs_"
                         : stage == ShaderStage::Fragment ? "ps_"
                         : stage == ShaderStage::Geometry ? "gs_"
                         : stage == ShaderStage::Hull     ? "hs_"
                         : stage == ShaderStage::Domain   ? "ds_"
                                                          : "cs_";
    std::string p = profile;
    for (char& c : p) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (p.rfind(prefix, 0) != 0) return false;
    std::string version = p.substr(3);
    if (stage == ShaderStage::Hull || stage == ShaderStage::Domain) return modern(version);
    // cs_4_x is D3D10.1 hardware's compute subset; GL's compute shaders run it as they run cs_5_0.
    if (stage == ShaderStage::Geometry || stage == ShaderStage::Compute)
        return version == "4_0" || version == "4_1" || modern(version);
    if (stage == ShaderStage::Vertex && (version == "1_2" || version == "1_3" || version == "1_4"))
        return false;
    if (stage == ShaderStage::Fragment && version == "1_1") return true;
    return std::any_of(std::begin(kVersions), std::end(kVersions),
                       [&](const char* v) { return version == v; });
}

// The uniform parameters of `fn` whose compile argument (or default) names an effect sampler or texture
// of the parameter's kind, bound into `boundFn` (bindParameters) with their arguments left out of
// `boundCompile`. False where there are none, or the signature is not as the parse read it; an argument
// that does not fit is left to the wrapper, which reports it.
bool bindObjectArguments(const Effect& effect, const FunctionDecl& fn, const Expr& compile,
                         FunctionDecl& boundFn, Expr& boundCompile) {
    std::map<std::string, std::string> bound;
    std::vector<size_t> boundArguments;
    std::vector<FunctionParam> kept;
    size_t uniformIndex = 0;
    for (const FunctionParam& p : fn.params) {
        const size_t argIndex = p.isUniform ? uniformIndex++ : compile.args.size();
        const Expr* expr = !p.isUniform                     ? nullptr
                           : argIndex < compile.args.size() ? &compile.args[argIndex]
                           : p.defaultValue                 ? &*p.defaultValue
                                                            : nullptr;
        const Parameter* object =
            expr && expr->kind == Expr::Kind::Identifier && (p.type.isSampler() || p.type.isTexture())
                ? effect.findParameter(expr->text)
                : nullptr;
        const bool fits = object && (p.type.isTexture() ? object->type.isTexture()
                                     : p.type.base == BaseType::SamplerState ||
                                             p.type.base == BaseType::SamplerComparisonState
                                         ? object->type.base == p.type.base
                                         : isSamplerType(object->type));
        if (!fits || !p.type.arrayDims.empty() || !object->type.arrayDims.empty()) {
            kept.push_back(p);
            continue;
        }
        bound[p.name] = object->name;
        if (argIndex < compile.args.size()) boundArguments.push_back(argIndex);
    }
    if (bound.empty()) return false;
    const std::optional<std::string> text =
        bindParameters(fn.hlslText, fn.name, fn.name, fn.params.size(), bound);
    if (!text) return false;
    boundFn = fn;
    boundFn.params = std::move(kept);
    boundFn.hlslText = *text;
    boundCompile = compile;
    for (auto i = boundArguments.rbegin(); i != boundArguments.rend(); ++i)
        boundCompile.args.erase(boundCompile.args.begin() + static_cast<std::ptrdiff_t>(*i));
    return true;
}

// An effect object passed on to a function's parameter of its kind, which the unit declares again with
// the object bound in place of the parameter (once per callee and objects, before the first function that
// calls it; the call then names the copy):
//   - a depth sampler passed to a sampler parameter (`float shadow(sampler2D s, float4 p) { return
//     tex2Dproj(s, p).r; }` called as `shadow(ShadowSampler, p)`, or with a compile argument the entry
//     point passes on): D3D9 inlined every call, so the lookups inside compared depth as the global's own;
//   - an array of textures passed to a texture array parameter (`get(Texture2D g[3], float2 uv)` called as
//     `get(GBuffer, uv)`): glslang copies the array into a temporary, which spirv-opt's legalization
//     leaves as a load of the whole array, so SPIRV-Cross paired the copy's element with the sampler, an
//     unnamed single sampler indexed as the array (the GL driver refused to link it); bound, the callee
//     indexes the effect's array, as the entry point's own code does.
class ObjectArgumentForwarding {
public:
    ObjectArgumentForwarding(const Effect& effect, const std::set<std::string>& depth,
                             const std::set<std::string>& textureArrays)
        : mEffect(effect), mDepth(depth) {
        mObjects = depth;
        mObjects.insert(textureArrays.begin(), textureArrays.end());
    }

    // `text` with its calls that pass an object on naming the copies, which are added to pending().
    std::string bindCalls(const std::string& text, int nesting = 0) {
        if (mObjects.empty()) return text;
        return bindCallArguments(text, mObjects,
                                 [this, nesting](const std::string& function, size_t argumentCount,
                                                 const std::map<size_t, std::string>& objects) {
                                     return copyFor(function, argumentCount, objects, nesting);
                                 });
    }

    // The copies bindCalls made since the last call, each behind its `#line`, callees before callers.
    std::string takePending() { return std::exchange(mPending, {}); }

private:
    // Whether `p` takes the effect object named `object` as bound: a sampler parameter a depth sampler, a
    // texture array parameter an array of its type and size.
    bool takes(const FunctionParam& p, const std::string& object) const {
        if (p.direction != FunctionParam::Direction::In) return false;
        if (mDepth.count(object)) return isSamplerType(p.type) && p.type.arrayDims.empty();
        const Parameter* textures = mEffect.findParameter(object);
        return textures && p.type.isTexture() && p.type.base == textures->type.base &&
               p.type.arrayDims == textures->type.arrayDims;
    }

    std::optional<std::string> copyFor(const std::string& function, size_t argumentCount,
                                       const std::map<size_t, std::string>& objects, int nesting) {
        // HLSL has no recursion; this bounds a chain of calls all the same.
        constexpr int kMaxNesting = 16;
        if (nesting >= kMaxNesting) return std::nullopt;
        const FunctionDecl* callee = nullptr;
        for (const FunctionDecl& f : mEffect.functions) {
            if (f.name != function || !f.hasBody || f.params.size() != argumentCount) continue;
            bool takesObjects = true;
            for (const auto& [index, object] : objects)
                takesObjects = takesObjects && takes(f.params[index], object);
            if (takesObjects) callee = &f;
        }
        if (!callee) return std::nullopt;
        std::string name = function + "_fx";
        std::map<std::string, std::string> bound;
        for (const auto& [index, object] : objects) {
            name += "_" + std::to_string(index) + "_" + object;
            bound[callee->params[index].name] = object;
        }
        if (mCopied.count(name)) return name;
        const std::optional<std::string> text =
            bindParameters(callee->hlslText, callee->name, name, argumentCount, bound);
        if (!text) return std::nullopt;
        mCopied.insert(name);
        const std::string body = bindCalls(*text, nesting + 1);
        emitAt(mPending, rewriteIntrinsics(body, mDepth), callee->hlslLoc);
        return name;
    }

    const Effect& mEffect;
    const std::set<std::string>& mDepth;
    std::set<std::string> mObjects;  // the depth samplers and the arrays of textures
    std::set<std::string> mCopied;
    std::string mPending;
};

}  // namespace

EffectDeclarations emitEffectDeclarations(const Effect& effect, const std::set<std::string>& reached,
                                          const std::string& wrapper, const std::string& streamStruct,
                                          const std::string& streamStructText,
                                          const FunctionDecl* boundEntry) {
    auto isBoundEntry = [&](const FunctionDecl& f) {
        return boundEntry && f.name == boundEntry->name && f.hlslLoc.line == boundEntry->hlslLoc.line &&
               f.hlslLoc.column == boundEntry->hlslLoc.column && f.hlslLoc.file == boundEntry->hlslLoc.file;
    };
    auto textOf = [&](const FunctionDecl& f) -> const std::string& {
        return isBoundEntry(f) ? boundEntry->hlslText : f.hlslText;
    };
    std::set<std::string> depth;
    for (const Parameter& p : effect.parameters)
        if (isSamplerType(p.type) && isDepthCompareSampler(effect, p)) depth.insert(p.name);
    // D3D10 textures and sampler objects are declared only where the unit's code names them: a D3D9
    // effect's `texture2D` is reached through its sampler_state alone.
    std::set<std::string> named;
    auto nameAll = [&](const std::string& text) {
        for (const std::string& id : identifiersIn(text)) named.insert(id);
    };
    for (const FunctionDecl& f : effect.functions)
        if (reached.count(f.name)) nameAll(textOf(f));
    for (const Parameter& p : effect.parameters)
        if (p.isStatic) nameAll(p.hlslText);
    for (const VerbatimDecl& v : effect.verbatim) nameAll(v.hlslText);
    nameAll(wrapper);
    std::set<std::string> usedDepth;
    std::set<std::string> textureArrays;
    for (const Parameter& p : effect.parameters)
        if (p.type.isTexture() && !p.type.arrayDims.empty()) textureArrays.insert(p.name);
    ObjectArgumentForwarding forwarding(effect, depth, textureArrays);
    EffectDeclarations out;
    std::string& hlsl = out.hlsl;
    std::string& staticAssignments = out.staticAssignments;
    hlsl += "#line 1 \"" + std::string(kGeneratedFile) + "\"\n" + kLitReplacement;
    for (const DeclRef& ref : effect.order) {
        switch (ref.kind) {
            case DeclRef::Kind::Parameter: {
                const Parameter& p = effect.parameters[ref.index];
                // GLSL's `shared` exists in compute shaders only: those whose wrapper declares numthreads.
                if (p.isStatic && wrapper.find("[numthreads(") == std::string::npos &&
                    identifiersIn(p.hlslText).count("groupshared"))
                    break;
                if (p.isStatic) {
                    const SplitStatic split = splitStaticInitializer(effect, p);
                    if (split.declaration.empty()) {
                        emitAt(hlsl, rewriteIntrinsics(regroupMatrixInitializer(p.hlslText, p.type), depth),
                               p.hlslLoc);
                    } else {
                        emitAt(hlsl, split.declaration, p.hlslLoc);
                        emitAt(staticAssignments, rewriteIntrinsics(split.assignment, depth), p.hlslLoc);
                    }
                } else if (isNumericType(p.type) && p.type.base != BaseType::String) {
                    // A plain global: it lands in the $Global block; the runtime fills it.
                    hlsl += hlslUniformTypeName(p.type) + " " + p.name + arraySuffix(p.type) + ";\n";
                } else if (p.type.base == BaseType::Struct && named.count(p.name)) {
                    // A struct-typed global (D3D10 effects keep lights and materials in cbuffers so): in
                    // the block too, zero as an application that never set it leaves it.
                    hlsl += p.type.structName + " " + p.name + arraySuffix(p.type) + ";\n";
                } else if (((p.type.isTexture() && p.type.base != BaseType::Texture) || p.type.isBuffer() ||
                            p.type.isImage() || p.type.base == BaseType::SamplerState ||
                            p.type.base == BaseType::SamplerComparisonState) &&
                           named.count(p.name)) {
                    hlsl += hlslTypeName(p.type) + " " + p.name + arraySuffix(p.type) + ";\n";
                } else if (isSamplerType(p.type)) {
                    if (depth.count(p.name)) {
                        hlsl += depthSamplerHelpers(p.name);
                        usedDepth.insert(p.name);
                    } else {
                        TypeDesc t = p.type;
                        if (t.base == BaseType::Sampler) {
                            const Parameter* tex = samplerTexture(effect, p);
                            // An untyped texture's ResourceType annotation says "Cube" or "3D".
                            const Annotation* kind = tex ? tex->annotation("ResourceType") : nullptr;
                            const std::string resourceType = kind && kind->value.kind == Expr::Kind::String
                                                                 ? upperCase(kind->value.text)
                                                                 : "";
                            t.base =
                                tex && (tex->type.base == BaseType::TextureCube || resourceType == "CUBE")
                                    ? BaseType::SamplerCube
                                : tex && (tex->type.base == BaseType::Texture3D || resourceType == "3D" ||
                                          resourceType == "VOLUME")
                                    ? BaseType::Sampler3D
                                : tex && tex->type.base == BaseType::Texture1D ? BaseType::Sampler1D
                                                                               : BaseType::Sampler2D;
                        }
                        hlsl += hlslTypeName(t) + " " + p.name + arraySuffix(p.type) + ";\n";
                    }
                }
                break;  // textures, strings and shader variables have no HLSL counterpart
            }
            case DeclRef::Kind::Struct: {
                const StructDecl& s = effect.structs[ref.index];
                const bool stream = !streamStruct.empty() && s.name == streamStruct;
                emitAt(hlsl, stream ? streamStructText : s.hlslText, s.hlslLoc);
                break;
            }
            case DeclRef::Kind::Function: {
                const FunctionDecl& f = effect.functions[ref.index];
                if (reached.count(f.name) && !isBoundEntry(f)) {
                    const std::string text = forwarding.bindCalls(f.hlslText);
                    hlsl += forwarding.takePending();
                    emitAt(hlsl, rewriteIntrinsics(text, depth), f.hlslLoc);
                }
                break;
            }
            case DeclRef::Kind::Verbatim: {
                const VerbatimDecl& v = effect.verbatim[ref.index];
                emitAt(hlsl, rewriteIntrinsics(v.hlslText, depth), v.hlslLoc);
                break;
            }
        }
    }
    // Last: its body names the objects bound, which the effect may declare after the function (FX
    // Composer's quad include defines the pixel shaders the effects then pass their samplers to).
    if (boundEntry) {
        const std::string text = forwarding.bindCalls(boundEntry->hlslText);
        hlsl += forwarding.takePending();
        emitAt(hlsl, rewriteIntrinsics(text, depth), boundEntry->hlslLoc);
    }
    out.depthSamplers.assign(usedDepth.begin(), usedDepth.end());
    return out;
}

// Functions the entry point reaches (by name, over-approximated by identifiers in the bodies), plus any
// named by static initializers and verbatim declarations. Unreached functions are not emitted, so that
// editing one function only changes the units (and cache keys) of the passes that use it.
std::set<std::string> reachableFunctions(const Effect& effect, const std::string& entry) {
    std::set<std::string> names;
    for (const FunctionDecl& f : effect.functions) names.insert(f.name);
    std::set<std::string> reached{entry};
    std::vector<std::string> work{entry};
    auto visitText = [&](const std::string& text) {
        for (const std::string& id : identifiersIn(text))
            if (names.count(id) && reached.insert(id).second) work.push_back(id);
    };
    for (const Parameter& p : effect.parameters)
        if (p.isStatic) visitText(p.hlslText);
    for (const VerbatimDecl& v : effect.verbatim) visitText(v.hlslText);
    while (!work.empty()) {
        std::string name = work.back();
        work.pop_back();
        for (const FunctionDecl& f : effect.functions)
            if (f.name == name) visitText(f.hlslText);
    }
    return reached;
}

// [SECTION] lowerStage()

namespace {

// The function a compile expression compiles. fxc chose among overloads of one name by the compile
// expression's arguments: `PS()` and `PS(0)` compile `float4 PS(VSOut)` and `float4 PS(VSOut, uniform int)`.
// The first overload whose uniform parameters take the arguments (those with defaults may be left out);
// with a single definition, the wrapper says what does not fit.
const FunctionDecl* compiledFunction(const Effect& effect, const Expr& compile, DiagnosticSink& diagnostics) {
    std::vector<const FunctionDecl*> overloads;
    for (const FunctionDecl* f : effect.findFunctions(compile.text))
        if (f->hasBody) overloads.push_back(f);
    if (overloads.empty()) {
        diagnostics.report(DiagId::MissingEntryPoint, compile.loc, {compile.text});
        return nullptr;
    }
    if (overloads.size() == 1) return overloads.front();
    std::string counts;
    for (const FunctionDecl* f : overloads) {
        size_t uniforms = 0, required = 0;
        for (const FunctionParam& p : f->params)
            if (p.isUniform) {
                ++uniforms;
                if (!p.defaultValue) required = uniforms;
            }
        if (compile.args.size() >= required && compile.args.size() <= uniforms) return f;
        counts += (counts.empty() ? "" : ", ") + std::to_string(uniforms);
    }
    diagnostics.report(DiagId::CompileNoOverloadFits, compile.loc,
                       {compile.text, std::to_string(compile.args.size()), counts});
    return nullptr;
}

}  // namespace

std::optional<LoweredStage> lowerStage(const Effect& effect, const Expr& compile, ShaderStage stage,
                                       std::vector<LoweredArgument>& arguments, DiagnosticSink& diagnostics,
                                       const std::map<int, TypeDesc>* previousOutputs,
                                       const FunctionDecl* hull, const StageStreamOut* streamOut) {
    if (!profileMatches(compile.profile, stage)) {
        // `VertexShader = compile ps_3_0 VS()` read "unsupported shader profile 'ps_3_0'": say what is wrong.
        for (ShaderStage other : {ShaderStage::Vertex, ShaderStage::Fragment, ShaderStage::Geometry,
                                  ShaderStage::Hull, ShaderStage::Domain, ShaderStage::Compute})
            if (other != stage && profileMatches(compile.profile, other)) {
                diagnostics.report(DiagId::ProfileOfOtherStage, compile.loc,
                                   {compile.profile, std::string(shaderStageName(other)),
                                    std::string(shaderStageName(stage))});
                return std::nullopt;
            }
        diagnostics.report(DiagId::UnsupportedProfile, compile.loc, {compile.profile});
        return std::nullopt;
    }
    const FunctionDecl* fn = compiledFunction(effect, compile, diagnostics);
    if (!fn) return std::nullopt;

    LoweredStage out;
    out.stage = stage;
    out.entryPoint = fn->name;
    out.profile = compile.profile;
    out.compileLoc = compile.loc;

    // D3DX bound a sampler or texture compile argument when it compiled the shader: the entry point's body
    // names the effect's object itself, so that what follows sees a depth sampler's lookups as its own.
    FunctionDecl boundFn;
    Expr boundCompile;
    const bool bound = bindObjectArguments(effect, *fn, compile, boundFn, boundCompile);
    const FunctionDecl& entry = bound ? boundFn : *fn;
    const Expr& entryCompile = bound ? boundCompile : compile;

    // Wrapper first (it may fail on arguments) but emitted last.
    size_t firstArgument = arguments.size();
    std::string argumentGlobals, wrapper;
    WrapperBuilder builder(effect, entry, entryCompile, stage, arguments, diagnostics,
                           stage == ShaderStage::Fragment ? previousOutputs : nullptr,
                           stage == ShaderStage::Domain ? hull : nullptr);
    if (streamOut) builder.setStreamOut(*streamOut);
    if (!builder.build(argumentGlobals, wrapper)) {
        arguments.resize(firstArgument);
        return std::nullopt;
    }
    out.varyingOutputs = builder.varyingOutputs();
    out.patchVertices = builder.patchVertices();
    out.primitive = builder.primitive();
    out.streamType = builder.streamType();
    out.positionVarying = builder.positionVarying();

    std::set<std::string> reached = reachableFunctions(effect, fn->name);
    if (!builder.patchConstantFunction().empty())  // named in an attribute's string, so not found as a call
        reached.merge(reachableFunctions(effect, builder.patchConstantFunction()));
    std::string& hlsl = out.hlsl;
    hlsl += "// shadowfx: " + std::string(shaderStageName(stage)) + " shader " + fn->name + " (" +
            compile.profile + ")\n";
    EffectDeclarations declarations =
        emitEffectDeclarations(effect, reached, wrapper, builder.streamStruct(), builder.streamStructText(),
                               bound ? &boundFn : nullptr);
    hlsl += declarations.hlsl;
    const std::string& staticAssignments = declarations.staticAssignments;
    if (!staticAssignments.empty()) {
        const size_t entry = wrapper.find(std::string(kWrapperEntryPoint) + "(");
        const size_t body = entry == std::string::npos ? entry : wrapper.find(")\n{\n", entry);
        if (body != std::string::npos)
            wrapper.insert(body + 4, staticAssignments + "#line 1 \"" + std::string(kGeneratedFile) + "\"\n");
    }
    hlsl += "#line 1 \"" + std::string(kGeneratedFile) + "\"\n" + argumentGlobals + wrapper;
    out.depthSamplers = std::move(declarations.depthSamplers);
    return out;
}

}  // namespace fx
