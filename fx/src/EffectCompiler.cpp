// EffectCompiler: orchestration (see EffectCompiler.h): initial values, what the runtime reads of each
// parameter and pass, and the passes and techniques, calling the stages in Compiler.h's files.
//
// [SECTION] Initial values
// [SECTION] Passes and techniques

#include "Compiler.h"
#include "ConstantFolding.h"
#include "FixedFunctionPass.h"
#include "MacroNoteSink.h"
#include "PointSprites.h"
#include "PositionPassThrough.h"
#include "StateAssignments.h"
#include "TechniqueSupport.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace fx::detail {

namespace {

bool literalOnly(const Expr& e) {
    if (e.kind == Expr::Kind::Identifier) return e.text == "true" || e.text == "false";
    if (e.kind == Expr::Kind::TextureRef || e.kind == Expr::Kind::Compile) return false;
    for (const Expr& a : e.args)
        if (!literalOnly(a)) return false;
    return true;
}

}  // namespace

// [SECTION] Initial values

// The structs that parameters are of, with the structs their members are of, in declaration order: HLSL
// declares a struct before a struct that holds it.
void Compiler::structTable() {
    std::set<std::string> used;
    for (const Parameter& p : mEffect.parameters)
        if (p.type.base == BaseType::Struct) used.insert(p.type.structName);
    for (auto s = mEffect.structs.rbegin(); s != mEffect.structs.rend(); ++s)
        if (used.count(s->name))
            for (const StructMember& m : s->members)
                if (m.type.base == BaseType::Struct) used.insert(m.type.structName);
    for (const StructDecl& s : mEffect.structs) {
        if (!used.count(s.name)) continue;
        StructInfo info;
        info.name = s.name;
        for (const StructMember& m : s.members) info.members.push_back({m.name, m.type, m.semantic});
        mOut->structs.push_back(std::move(info));
    }
}

void Compiler::initialValues() {
    // In order, so that later initializers see earlier values (`float4 c = {Z, Z, Z, Z}` after `float Z`).
    for (size_t i = 0; i < mEffect.parameters.size(); ++i) {
        const Parameter& p = mEffect.parameters[i];
        Value v = zeroValue(p.type);
        // A struct starts at zero, its initializer unevaluated: the preshaders read no struct.
        if (p.type.base == BaseType::Struct) v.data.assign(mOut->componentCount(p.type), 0.0f);
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

// Annotations hold literals (a number, a string, a vector's initializer list): evaluated without
// parameters and converted to the annotation's declared type. One that does not evaluate (it names a
// parameter) is left out silently, as if absent: an annotation the compiler acts on then takes its
// default (an image's `Width`: 64).
Annotations Compiler::annotationValues(const std::vector<Annotation>& annotations) {
    Annotations values;
    for (const Annotation& annotation : annotations) {
        const bool text = annotation.type.base == BaseType::String;
        std::optional<Value> value = evaluate(
            annotation.value, [](std::string_view) -> const Value* { return nullptr; },
            text ? nullptr : &annotation.type, nullptr);
        if (!value) continue;
        if (text) value->type = annotation.type;
        values.push_back({annotation.name, std::move(*value)});
    }
    return values;
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
        info.isShared = p.isShared;
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
        info.annotations = annotationValues(p.annotations);
        mOut->parameters.push_back(std::move(info));
    }
}

// The pass annotations the runtime acts on (CompiledPass): CullClosedOnly, LeaveOutWhen, FilterReachTexels,
// CastersOnly.
void Compiler::passAnnotations(const Pass& source, CompiledPass& pass) {
    if (const Annotation* a = source.annotation("CastersOnly")) {
        std::optional<Value> value = eval(a->value, nullptr);
        if (value && !value->data.empty()) {
            pass.castersOnly = value->asBool();
        } else if (value) {
            error(DiagId::AnnotationNumberExpected, a->loc, {a->name});
        }
    }
    if (const Annotation* a = source.annotation("CullClosedOnly")) {
        std::optional<Value> value = eval(a->value, nullptr);
        if (value && !value->data.empty()) {
            pass.cullClosedOnly = value->asBool();
        } else if (value) {
            error(DiagId::CullClosedOnlyInvalid, a->loc, {});
        }
    }
    if (const Annotation* a = source.annotation("LeaveOutWhen")) {
        const std::string text = a->value.kind == Expr::Kind::String ? a->value.text : "";
        if (text == "NoClosedObjects") {
            pass.leaveOutWhen = LeaveOutCondition::NoClosedObjects;
        } else if (text == "NoLightArea") {
            pass.leaveOutWhen = LeaveOutCondition::NoLightArea;
        } else {
            error(DiagId::LeaveOutWhenInvalid, a->loc, {});
        }
    }
    if (const Annotation* a = source.annotation("FilterReachTexels")) {
        std::optional<Value> value = eval(a->value, nullptr);
        if (value && value->data.size() == 1 && std::isfinite(value->asFloat())) {
            pass.filterReachTexels = std::max(1.0f, value->asFloat());  // a texel for rounding at least
        } else if (value) {
            error(DiagId::FilterReachTexelsInvalid, a->loc, {});
        }
    }
}

// [SECTION] Passes and techniques

namespace {

// The first index in a state's value that is a constant outside its parameter array's bounds
// (`AlphaRef = Refs[3];` of `int Refs[2]`): fxc refuses it when it compiles the effect, where evaluating the
// value would fail only when the pass is first applied.
const Expr* constantIndexOutOfBounds(const Effect& effect, const Expr& e) {
    if (e.kind == Expr::Kind::Index && e.args.size() == 2 && e.args[0].kind == Expr::Kind::Identifier) {
        const Parameter* array = effect.findParameter(e.args[0].text);
        double index = 0;
        if (array && !array->type.arrayDims.empty() && foldConstant(effect, e.args[1], index) &&
            !(index >= 0 && index < array->type.arrayDims[0]))
            return &e;
    }
    for (const Expr& arg : e.args)
        if (const Expr* found = constantIndexOutOfBounds(effect, arg)) return found;
    return nullptr;
}

// A pass whose blend factors name the pixel shader's second output (SRC1_COLOR .. INV_SRC1_ALPHA).
bool blendsDualSource(const CompiledPass& pass) {
    return std::any_of(pass.states.begin(), pass.states.end(), [](const RenderStateSetting& s) {
        const bool factor = s.id == RenderStateId::SrcBlend || s.id == RenderStateId::DestBlend ||
                            s.id == RenderStateId::SrcBlendAlpha || s.id == RenderStateId::DestBlendAlpha;
        return factor && s.constant && *s.constant >= 16 && *s.constant <= 19;
    });
}

}  // namespace

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
            error(DiagId::CompileShaderArrayIndexOutOfRange, s.value.args[1].loc,
                  {std::to_string(i), p->name});
            return nullptr;
        }
    }
    error(DiagId::NotCompileExpression, s.value.loc, {s.value.str()});
    return nullptr;
}

bool Compiler::vertexShaderPassesPosition(const Expr& compile) const {
    const FunctionDecl* shader = nullptr;
    for (const FunctionDecl* f : mEffect.findFunctions(compile.text)) {
        if (!f->hasBody) continue;
        if (shader) return false;  // overloads: which one the arguments choose is glslang's to say
        shader = f;
    }
    return shader && passesPositionThrough(mEffect, *shader);
}

CompiledPass Compiler::compilePass(const Pass& p, PassSlot slot) {
    CompiledPass pass;
    mPassArguments.clear();
    mPreviousOutputs.reset();
    mHull = nullptr;
    pass.name = p.name;
    pass.loc = p.loc;
    if (computePass(p, pass, slot)) {
        passAnnotations(p, pass);
        pass.annotations = annotationValues(p.annotations);
        pass.script = script(p.annotations, pass.hasScript);
        validateScript(pass.script, nullptr);
        return pass;
    }
    // The geometry shader first, wherever the pass sets it: the pixel shader's inputs take its outputs'
    // types. The hull shader before the domain shader, which takes its tessellator settings.
    const StateAssignment* hull = nullptr;
    const StateAssignment* domain = nullptr;
    const StateAssignment* geometry = nullptr;
    bool geometryStage = false;  // a geometry shader, not NULL
    for (const StateAssignment& s : p.states) {
        const std::optional<RenderStateId> id = findRenderState(s.name);
        if (id == RenderStateId::GeometryShader) {
            geometry = &s;
            geometryStage = false;
            if (const Expr* call = streamOutCall(s)) {
                streamOutStage(*call, p, pass, slot);
                geometryStage = true;
            } else if (const Expr* compile = shaderExpr(s)) {
                geometryStage = compileStage(*compile, ShaderStage::Geometry, pass, slot);
            }
        } else if (id == RenderStateId::HullShader || id == RenderStateId::DomainShader) {
            const bool set = !(s.value.kind == Expr::Kind::Identifier && s.value.text == "NULL") &&
                             !(s.value.kind == Expr::Kind::Number && s.value.number == 0);
            (id == RenderStateId::HullShader ? hull : domain) = set ? &s : nullptr;
        }
    }
    if (hull && !domain) {
        error(DiagId::HullWithoutDomain, hull->loc, {});
    } else if (domain && !hull) {
        error(DiagId::DomainWithoutHull, domain->loc, {});
    } else if (hull && domain) {
        const Expr* hullCompile = shaderExpr(*hull);
        if (hullCompile && compileStage(*hullCompile, ShaderStage::Hull, pass, slot))
            if (const Expr* domainCompile = shaderExpr(*domain))
                compileStage(*domainCompile, ShaderStage::Domain, pass, slot);
        if (geometry && pass.primitive != CompiledPass::DrawPrimitive::Triangles)
            error(DiagId::GeometryAfterTessellationInput, geometry->loc, {});
    }
    // The vertex shader before the pixel shader, whose inputs it may leave unwritten; a pass drawing a
    // capture (DrawAuto) feeds it the capture's elements.
    drawAutoSource(p, pass);
    const Expr* vertexCompile = nullptr;
    for (const StateAssignment& s : p.states)
        if (findRenderState(s.name) == RenderStateId::VertexShader)
            if (const Expr* compile = shaderExpr(s)) {
                compileStage(*compile, ShaderStage::Vertex, pass, slot);
                vertexCompile = compile;
            }
    const bool positionPassedThrough = vertexCompile && !geometryStage && !hull && pass.drawAuto < 0 &&
                                       vertexShaderPassesPosition(*vertexCompile);
    // Point sprites gave the pixel shader's texture coordinates the position in the sprite, whether the
    // vertex shader wrote them or not: they stay inputs, which pointSprites() then reads from gl_PointCoord.
    bool sprites = false;
    for (const StateAssignment& s : p.states)
        if (findRenderState(s.name) == RenderStateId::PointSpriteEnable)
            sprites = (s.value.kind == Expr::Kind::Number || s.value.kind == Expr::Kind::Bool) &&
                      s.value.number != 0;
    if (sprites && mPreviousOutputs) {
        TypeDesc float4;
        float4.shape = Shape::Vector;
        float4.cols = 4;
        for (int texcoord = 0; texcoord < 8; ++texcoord) mPreviousOutputs->try_emplace(texcoord, float4);
    }
    bool setsSamplerRegisters = false;
    mStageStreamOut = {};
    for (const StateAssignment& s : p.states) {
        auto id = findRenderState(s.name);
        if (!id && isSamplerRegisterState(s.name)) {
            setsSamplerRegisters = true;  // applied once the stages compiled (passSamplerStates)
            continue;
        }
        if (!id) {
            error(DiagId::UnknownState, s.loc, {s.name});
            continue;
        }
        if (*id == RenderStateId::GeometryShader || *id == RenderStateId::HullShader ||
            *id == RenderStateId::DomainShader || *id == RenderStateId::VertexShader ||
            *id == RenderStateId::ComputeShader)
            continue;
        if (*id == RenderStateId::PixelShader) {
            if (const Expr* compile = shaderExpr(s))
                compileStage(*compile, ShaderStage::Fragment, pass, slot);
            continue;
        }
        if (const Expr* index = constantIndexOutOfBounds(mEffect, s.value)) {
            const Parameter* array = mEffect.findParameter(index->args[0].text);
            error(DiagId::StateObjectIndexOutOfBounds, index->args[1].loc,
                  {index->args[1].str(), array->name, std::to_string(array->type.arrayDims[0])});
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
    // D3D10 has no fixed-function pixel stage: a NULL pixel shader writes no colour, only depth and stencil
    // (a shadow map's depth pass). GL runs the D3D9 stand-in the runtime links for a pass without one, so
    // the colour writes are masked, after whatever the pass's blend state wrote.
    const auto nullPixelShader = [](const StateAssignment& s) {
        return findRenderState(s.name) == RenderStateId::PixelShader &&
               s.value.kind == Expr::Kind::Identifier && s.value.text == "NULL";
    };
    if (mTechnique && mTechnique->d3d10 && std::any_of(p.states.begin(), p.states.end(), nullPixelShader))
        for (RenderStateId mask : {RenderStateId::ColorWriteEnable, RenderStateId::ColorWriteEnable1,
                                   RenderStateId::ColorWriteEnable2, RenderStateId::ColorWriteEnable3})
            pass.states.push_back(RenderStateSetting{mask, 0.0, {}, p.loc});
    if (setsSamplerRegisters) mSamplerRegisterPasses.emplace_back(slot, &p);
    passAnnotations(p, pass);
    pass.annotations = annotationValues(p.annotations);
    pass.script = script(p.annotations, pass.hasScript);
    // A vertex shader that hands its input position straight to the rasterizer drew its application's
    // screen quad (the DirectX SDK's D3D10 post-processing `QuadVS`): the pass draws the runtime's, as a
    // D3D9 pass with a pixel shader alone does, and its samplers may read the host's picture. Not where
    // the pass's own script says what it draws and renders into (FX Composer's ScreenQuadVS passes).
    const bool drawsScreenQuad = p.drawsScreenQuad || (positionPassedThrough && !pass.hasScript);
    if (drawsScreenQuad) mScreenQuadPasses.push_back(slot);
    if (drawsScreenQuad && !pass.hasScript) {
        ScriptCommand draw{};
        draw.kind = ScriptCommand::Kind::Draw;
        draw.draw = ScriptCommand::DrawWhat::Buffer;
        draw.loc = p.loc;
        pass.script.push_back(std::move(draw));
        pass.hasScript = true;
    }
    validateScript(pass.script, nullptr);
    return pass;
}

// PointSpriteEnable = TRUE: the pixel shader's texture coordinates are the position in the point. It
// decides what the pixel shader reads, so it is a constant, and the last setting of the pass counts.
void Compiler::pointSprites(CompiledPass& pass) {
    const RenderStateSetting* sprites = nullptr;
    for (const RenderStateSetting& setting : pass.states)
        if (setting.id == RenderStateId::PointSpriteEnable) sprites = &setting;
    if (!sprites) return;
    if (!sprites->constant) {
        error(DiagId::PointSpriteEnableNotConstant, sprites->loc, {});
        return;
    }
    if (*sprites->constant != 0.0 && !pass.fragment.glsl.empty())
        readPointSpriteCoordinates(pass.fragment.glsl);
}

// What each pass reads, once, so that the runtime's EffectVariable::isUsed is a search of a list: the
// parameters of the uniform-block members its code reads (SPIRV-Cross's active ranges), of the samplers it
// reads and the textures they sample (SamplerBinding::read, from the SPIR-V), of its storage buffers and
// images, and the inputs of its states' and compile arguments' programs.
void Compiler::passReads() {
    const size_t count = mOut->parameters.size();
    for (CompiledTechnique& technique : mOut->techniques)
        for (CompiledPass& pass : technique.passes) {
            std::vector<bool> reads(count, false);
            const auto mark = [&reads, count](size_t parameter) {
                if (parameter < count) reads[parameter] = true;
            };
            for (const StageProgram* stage :
                 {&pass.vertex, &pass.hull, &pass.domain, &pass.geometry, &pass.fragment, &pass.compute}) {
                for (const UniformBinding& member : stage->uniforms)
                    if (member.active && member.source == UniformBinding::Source::Parameter)
                        mark(member.index);
                for (const SamplerBinding& binding : stage->samplers) {
                    if (!binding.read) continue;
                    mark(binding.samplerParameter);
                    if (binding.textureParameter) {
                        mark(*binding.textureParameter);
                    } else if (const SamplerDesc* desc = mOut->findSampler(binding.samplerParameter);
                               desc && desc->texture) {
                        mark(*desc->texture);
                    }
                }
                for (const StorageBufferBinding& buffer : stage->storageBuffers) mark(buffer.parameter);
                for (const ImageBinding& image : stage->images) mark(image.parameter);
            }
            for (const RenderStateSetting& setting : pass.states)
                for (size_t parameter : setting.value.inputs()) mark(parameter);
            for (const CompileArgument& argument : pass.arguments)
                for (size_t parameter : argument.value.inputs()) mark(parameter);
            for (size_t parameter = 0; parameter < count; ++parameter)
                if (reads[parameter]) pass.readParameters.push_back(parameter);
        }
}

std::unique_ptr<CompiledEffect> Compiler::run() {
    structTable();
    initialValues();
    parameterInfo();
    storageResources();
    textures();
    samplers();
    storageBindings();
    scripts();
    bool found = mOptions.technique.empty();
    // Techniques whose code uses what the lowering cannot express, with what it said. D3DX offered the
    // next valid technique where one did not validate (FindNextValidTechnique): such a technique is left
    // out with a warning while another technique can run; where none can, its errors fail the effect as
    // they stand.
    std::vector<std::pair<const Technique*, std::vector<Diagnostic>>> invalid;
    mOut->refusedTechniques = mEffect.refusedTechniques;
    for (const Technique& t : mEffect.techniques) {
        if (!mOptions.technique.empty() && mEffect.findTechnique(mOptions.technique) != &t) continue;
        found = true;
        CompiledTechnique technique;
        technique.name = t.name;
        technique.group = t.group;
        technique.loc = t.loc;
        technique.script = script(t.annotations, technique.hasScript);
        technique.annotations = annotationValues(t.annotations);
        validateScript(technique.script, &t);
        mTechniqueUnsupported.clear();
        mTechnique = &t;
        for (const Pass& p : t.passes)
            technique.passes.push_back(
                compilePass(p, PassSlot{mOut->techniques.size(), technique.passes.size()}));
        if (!mTechniqueUnsupported.empty()) {
            const size_t index = mOut->techniques.size();
            std::erase_if(mPending,
                          [index](const PendingStage& stage) { return stage.slot.technique == index; });
            std::erase_if(mSamplerRegisterPasses,
                          [index](const auto& p) { return p.first.technique == index; });
            std::erase_if(mScreenQuadPasses, [index](const PassSlot& p) { return p.technique == index; });
            std::erase_if(mStreamOutRequests,
                          [index](const StreamOutRequest& r) { return r.slot.technique == index; });
            invalid.emplace_back(&t, std::move(mTechniqueUnsupported));
            continue;
        }
        mOut->techniques.push_back(std::move(technique));
    }
    resolveTechniqueSelection();
    if (!reportUnsupportedTechniques(invalid, !mOut->techniques.empty(), mDiagnostics,
                                     mOut->refusedTechniques))
        mFailed = true;
    lowerTextureFunctions();
    finishPendingStages();
    imageFormats();
    resolveStreamOutputs();
    for (CompiledTechnique& technique : mOut->techniques)
        for (CompiledPass& pass : technique.passes) {
            if (blendsDualSource(pass)) declareDualSourceOutput(pass.fragment.glsl);
            pointSprites(pass);
        }
    assignPairUnits();
    assignImageUnits();
    passSamplerStates();
    hostPictureSamplers();
    passReads();
    // A file without techniques compiles, as under fxc and D3DX: an effect pool's shared parameters,
    // declarations for other effects. Only running it needs a technique (the runtime says so).
    if (!found) error(DiagId::UnknownTechnique, SourceLoc{mEffect.path, 0, 0}, {mOptions.technique});
    if (mFailed) return nullptr;
    return std::move(mOut);
}

}  // namespace fx::detail

namespace fx {

std::unique_ptr<CompiledEffect> compileEffect(std::shared_ptr<const Effect> effect,
                                              const CompileOptions& options, DiagnosticSink& diagnostics) {
    if (!effect) return nullptr;
    detail::MacroNoteSink noted(diagnostics, effect->sourceMap);
    // D3D9's fixed-function stages become generated shaders of the effect before anything else reads it.
    effect = detail::withFixedFunctionStages(std::move(effect), noted);
    if (!effect) return nullptr;
    return detail::Compiler(*effect, options, noted).run();
}

}  // namespace fx
