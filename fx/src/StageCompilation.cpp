// StageCompilation: a pass's stages lowered, looked up in the cache, compiled together (in worker
// processes or here) and their reflection resolved to the effect's parameters (see Compiler.h).

#include "Compiler.h"

#include "HlslToSpirv.h"
#include "SpirvToGlsl.h"

namespace fx::detail {

namespace {

StageProgram& stageProgram(CompiledPass& pass, ShaderStage stage) {
    return stage == ShaderStage::Vertex     ? pass.vertex
           : stage == ShaderStage::Fragment ? pass.fragment
           : stage == ShaderStage::Geometry ? pass.geometry
           : stage == ShaderStage::Hull     ? pass.hull
           : stage == ShaderStage::Domain   ? pass.domain
                                            : pass.compute;
}

// What the stage wrappers report for a stage form shadowfx has no GL counterpart for (a semantic, a
// parameter, a tessellation or geometry shape): it refuses the technique, where another error fails the
// effect.
bool isUnsupportedStageForm(DiagId id) {
    switch (id) {
        case DiagId::VertexInputNestedTooDeeply:
        case DiagId::PixelInputSemanticUnsupported:
        case DiagId::VertexOutputSemanticUnsupported:
        case DiagId::PixelOutputSemanticUnsupported:
        case DiagId::GeometryStreamElementNotStruct:
        case DiagId::GeometryOutputNotVector:
        case DiagId::GeometryIntegerOutputInterpolated:
        case DiagId::GeometryOutputSemanticUnsupported:
        case DiagId::GeometryMaxVertexCountMissing:
        case DiagId::GeometryStreamRepeated:
        case DiagId::GeometryInputPrimitiveRepeated:
        case DiagId::GeometryParameterUnsupported:
        case DiagId::GeometryInputOrStreamMissing:
        case DiagId::GeometryLineAdjacencyInput:
        case DiagId::GeometryInputPrimitiveUnsupported:
        case DiagId::GeometryInputArraySize:
        case DiagId::GeometryStreamNotInout:
        case DiagId::GeometryInputSemanticUnsupported:
        case DiagId::ControlPointSemanticUnsupported:
        case DiagId::PatchConstantsNotStruct:
        case DiagId::PatchConstantSemanticRepeated:
        case DiagId::PatchConstantSemanticUnsupported:
        case DiagId::PatchConstantsWithoutTessFactor:
        case DiagId::HullAttributeMissing:
        case DiagId::PatchConstantFunctionUndefined:
        case DiagId::OutputControlPointsInvalid:
        case DiagId::HullParameterUnsupported:
        case DiagId::HullInputPatchMissing:
        case DiagId::InputPatchSizeUnsupported:
        case DiagId::HullReturnsNoControlPoint:
        case DiagId::OutputPatchReadsUnwritten:
        case DiagId::PatchConstantParameterUnsupported:
        case DiagId::PatchConstantsNotReturnedAsStruct:
        case DiagId::DomainAttributeMissing:
        case DiagId::DomainWithoutHull:
        case DiagId::DomainMismatch:
        case DiagId::OutputPatchSizeMismatch:
        case DiagId::DomainParameterUnsupported:
        case DiagId::ComputeNumThreadsMissing:
        case DiagId::ComputeParameterUnsupported:
            return true;
        default:
            return false;
    }
}

}  // namespace

namespace {

// Where each numeric member of a value of `type` starts in the value (Value::data), by its path: ".color",
// "[1].lights[0].position" (elements of every dimension counted in turn, as the reflection names them).
void structLeaves(const CompiledEffect& effect, const TypeDesc& type, const std::string& path, size_t first,
                  std::map<std::string, std::pair<TypeDesc, size_t>>& leaves) {
    const StructInfo* info = effect.findStruct(type.structName);
    if (type.base != BaseType::Struct || !info) {
        leaves[path] = {type, first};
        return;
    }
    TypeDesc element = type;
    element.arrayDims.clear();
    const size_t elementComponents = effect.componentCount(element);
    size_t count = 1;
    for (int dim : type.arrayDims) count *= static_cast<size_t>(std::max(dim, 1));
    for (size_t k = 0; k < count; ++k) {
        const std::string at = type.arrayDims.empty() ? path : path + "[" + std::to_string(k) + "]";
        size_t member = first + k * elementComponents;
        for (const StructMemberInfo& m : info->members) {
            structLeaves(effect, m.type, at + "." + m.name, member, leaves);
            member += effect.componentCount(m.type);
        }
    }
}

}  // namespace

// The reflection names each field of a struct parameter by its path; the parameter's type says which
// numbers of its value it holds. A field the type does not have stays out (its bytes stay zero).
void Compiler::resolveStructFields(UniformBinding& u) const {
    std::map<std::string, std::pair<TypeDesc, size_t>> leaves;
    if (u.source == UniformBinding::Source::Parameter && u.type.base == BaseType::Struct)
        structLeaves(*mOut, u.type, "", 0, leaves);
    std::erase_if(u.fields, [&](UniformField& field) {
        auto leaf = leaves.find(field.path);
        if (leaf == leaves.end() || !leaf->second.first.isNumeric()) return true;
        field.type = leaf->second.first;
        field.firstComponent = static_cast<uint32_t>(leaf->second.second);
        return false;
    });
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
        if (!u.fields.empty()) resolveStructFields(u);
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
        if (auto it = mIndex.find(b.glslName); it != mIndex.end()) b.parameter = it->second;
    for (ImageBinding& image : program.images)
        if (auto it = mIndex.find(image.glslName); it != mIndex.end()) image.parameter = it->second;
}

bool Compiler::compileStage(const Expr& compile, ShaderStage stage, CompiledPass& pass, PassSlot slot) {
    DiagnosticList lowering;
    auto lowered = lowerStage(mEffect, compile, stage, mPassArguments, lowering,
                              mPreviousOutputs ? &*mPreviousOutputs : nullptr, mHull, &mStageStreamOut);
    // What the pass lowering cannot express (a semantic or stage form shadowfx has no GL counterpart
    // for) makes the technique invalid, not the effect: run() decides once every technique is lowered.
    const bool onlyUnsupported =
        !lowered && std::all_of(lowering.items().begin(), lowering.items().end(), [](const Diagnostic& d) {
            return d.severity != Severity::Error || isUnsupportedStageForm(d.id);
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
        mLastPositionVarying = lowered->positionVarying;
        mLastStreamType = lowered->streamType;
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
    enqueueStage(std::move(*lowered), pass, slot);
    return true;
}

void Compiler::enqueueStage(LoweredStage&& lowered, CompiledPass& pass, PassSlot slot) {
    const ShaderStage stage = lowered.stage;
    StageProgram& program = stageProgram(pass, stage);
    std::string options = hlslToSpirvOptionsKey() + "|" + spirvToGlslOptionsKey() + "|" + lowered.profile;
    // A stage's blocks take their binding points from the whole effect's storage parameters, which an edit
    // elsewhere in the effect renumbers (hot reload) without changing the stage's source.
    for (const std::map<std::string, int>* bindings : {&mStorageBindings, &mCounterBindings})
        for (const auto& [name, binding] : *bindings) options += "|" + name + "=" + std::to_string(binding);
    uint64_t key = CompileCache::hash(lowered.hlsl, stage, options);
    // A unit already waiting for a worker is looked up once that job is done (finishPendingStages).
    const bool waiting = mJobByKey.count(key) > 0;
    if (const StageProgram* cached = mOptions.cache && !waiting ? mOptions.cache->find(key) : nullptr) {
        program = *cached;
        resolveReflection(program, pass);
        return;
    }
    auto [it, added] = mJobByKey.emplace(key, mJobs.size());
    if (added) {
        StageJob job;
        job.hlsl = lowered.hlsl;
        job.stage = stage;
        job.entryPoint = kWrapperEntryPoint;
        job.cross.uniformBlockName = stage == ShaderStage::Vertex     ? "fx_VsGlobals"
                                     : stage == ShaderStage::Fragment ? "fx_PsGlobals"
                                     : stage == ShaderStage::Geometry ? "fx_GsGlobals"
                                     : stage == ShaderStage::Hull     ? "fx_HsGlobals"
                                     : stage == ShaderStage::Domain   ? "fx_DsGlobals"
                                                                      : "fx_CsGlobals";
        // One uniform block binding per stage: the stage enum's order.
        job.cross.uniformBlockBinding = static_cast<int>(stage);
        job.cross.samplerUnits = mSamplerUnits;
        job.cross.storageBindings = mStorageBindings;
        job.cross.counterBindings = mCounterBindings;
        job.cross.depthSamplers = lowered.depthSamplers;
        mJobs.push_back(std::move(job));
    }
    mPending.push_back(PendingStage{slot, std::move(lowered), key, it->second});
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

void Compiler::finishPendingStages() {
    std::vector<StageOutcome> outcomes = runJobs();
    std::vector<bool> reported(outcomes.size(), false);
    for (PendingStage& pending : mPending) {
        const StageOutcome& outcome = outcomes[pending.job];
        const LoweredStage& lowered = pending.lowered;
        CompiledPass& pass = passAt(pending.slot);
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
                if (first) reportCrossError(outcome.crossError, lowered);
                mFailed = true;
                continue;
            case Status::Crashed:
            case Status::WorkerFailed:
            case Status::SanitizerReport:
                if (first) error(outcome.fault, function, outcome.faultArguments);
                mFailed = true;
                continue;
            case Status::TimedOut: {
                CompileWorkers& workers = mOptions.workers ? *mOptions.workers : CompileWorkers::shared();
                if (first)
                    error(DiagId::HlslCompilerTimedOut, function, {std::to_string(workers.timeLimitMs())});
                mFailed = true;
                continue;
            }
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

}  // namespace fx::detail
