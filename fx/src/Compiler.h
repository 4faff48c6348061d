// Compiler: the effect compiler's state over one effect (EffectCompiler.h's compileEffect), its stages
// defined in the files named after them:
//   EffectCompiler.cpp       initial values, parameter info, passes and techniques, run()
//   ResourceDescriptors.cpp  textures, samplers and their units
//   PassSamplerStates.cpp    a D3D9 pass's sampler-register states on the samplers they reach
//   ScriptValidation.cpp     SAS scripts checked and resolved against the effect
//   StageCompilation.cpp     lowering, the cache, glslang and SPIRV-Cross (in workers or here), reflection
//   ComputePass.cpp          passes that set a compute shader
//   HlslMessages.cpp         glslang's and SPIRV-Cross's messages said at the user's source
//   TextureFunction.cpp      FX Composer's texture functions, lowered to a fill pass per texture
#pragma once

#include <fx/CompileCache.h>
#include <fx/CompileWorkers.h>
#include <fx/EffectCompiler.h>
#include <fx/Preshader.h>

#include "PassLowering.h"
#include "StreamOutDeclaration.h"
#include "StageCompile.h"

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace fx::detail {

class Compiler {
public:
    Compiler(const Effect& effect, const CompileOptions& options, DiagnosticSink& diagnostics)
        : mEffect(effect), mOptions(options), mDiagnostics(diagnostics) {
        mOut = std::make_unique<CompiledEffect>();
        mOut->maxScriptLoopCount = options.maxScriptLoopCount;
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

    void structTable();
    void initialValues();
    void parameterInfo();
    static Annotations annotationValues(const std::vector<Annotation>& annotations);
    void passAnnotations(const Pass& source, CompiledPass& pass);
    void textures();
    void procedural(const Parameter& p, const Annotation& annotation, TextureDesc& t);
    void resourceShape(const Parameter& p, TextureDesc& t);
    void samplers();
    void storageBindings();
    void storageResources();
    // The texel format of each image parameter a pass uses (ParameterInfo::imageFormat), once the stages
    // compiled.
    void imageFormats();
    void applySamplerState(const StateAssignment& a, BaseType samplerType, SamplerDesc& s,
                           bool& hasComparison);
    // The D3D9 sampler-register states of every pass (`MinFilter[0] = LINEAR;`), once its stages compiled.
    void passSamplerStates();
    void passSamplerStates(const Pass& source, CompiledPass& pass);
    // SamplerBinding::hostPicture of the full-screen passes' samplers, once their sampler states are known.
    void hostPictureSamplers();
    void pointSprites(CompiledPass& pass);
    // The units of a pass's D3D10 pairs and images, once every stage of the pass compiled, written into
    // its stages' GLSL (layout(binding)) so that the runtime sets no unit by name.
    void assignPairUnits();
    void assignImageUnits();
    void unboundResource(const std::string& name);
    // Each pass's CompiledPass::readParameters, once its units and sampler states are known.
    void passReads();
    void scripts();
    // ParameterInfo::memberBindings of the light and material structs without a semantic, and the
    // constants of their members in their initial values, once the parameters' semantics are classified.
    void structMemberBindings(const std::vector<bool>& hasInitializer);
    std::vector<ScriptCommand> script(const std::vector<Annotation>& annotations, bool& has);
    // Checks a script and resolves its operands (ScriptCommand::parameter, literal, light, dispatch, pass).
    void validateScript(std::vector<ScriptCommand>& commands, const Technique* technique);
    // The index of a light in CompiledEffect::lights, added if new.
    int lightIndex(const std::string& name);
    // The global script's Technique= commands resolved to CompiledEffect::techniques indices, once the
    // techniques that run are compiled.
    void resolveTechniqueSelection();
    // A stage's place in mOut: technique and pass index, or (technique kTextureFill) the texture whose
    // fill pass it belongs to.
    struct PassSlot {
        static constexpr size_t kTextureFill = static_cast<size_t>(-1);
        size_t technique = 0;
        size_t pass = 0;
    };
    CompiledPass& passAt(PassSlot slot) {
        return slot.technique == PassSlot::kTextureFill ? *mOut->textures[slot.pass].fill
                                                        : mOut->techniques[slot.technique].passes[slot.pass];
    }
    // A stage the cache did not have: compiled with all the others once every pass is lowered, so that
    // the stages of an effect compile concurrently across the worker pool.
    struct PendingStage {
        PassSlot slot;
        LoweredStage lowered;
        uint64_t key = 0;
        size_t job = 0;  // index into mJobs (identical units share one job)
    };
    bool compileStage(const Expr& compile, ShaderStage stage, CompiledPass& pass, PassSlot slot);
    // A lowered stage looked up in the cache, else queued for the compilers.
    void enqueueStage(LoweredStage&& lowered, CompiledPass& pass, PassSlot slot);
    std::vector<StageOutcome> runJobs();
    void finishPendingStages();
    SourceLoc functionLocation(const LoweredStage& lowered) const;
    void reportHlslMessages(const std::vector<HlslMessage>& messages, const LoweredStage& lowered);
    // SPIRV-Cross's message about a stage it could not write, said in the effect's terms.
    void reportCrossError(const std::string& message, const LoweredStage& lowered);
    SourceLoc userLocation(const HlslMessage& m, const LoweredStage& lowered) const;
    void resolveReflection(StageProgram& program, const CompiledPass& pass);
    void resolveStructFields(UniformBinding& u) const;
    const Expr* shaderExpr(const StateAssignment& s);
    // The vertex shader `compile` names hands its input position to the rasterizer unchanged
    // (PositionPassThrough.h); false where the name is overloaded.
    bool vertexShaderPassesPosition(const Expr& compile) const;
    CompiledPass compilePass(const Pass& p, PassSlot slot);
    // [SECTION] Compute passes (ComputePass.cpp)
    // Compiles the compute stage of a pass that sets a compute shader. True where the pass is a compute
    // pass alone (no other stage, no render states); false where it sets none or also sets graphics
    // stages, which compilePass then compiles as for any pass.
    bool computePass(const Pass& p, CompiledPass& pass, PassSlot slot);
    // [SECTION] Stream output (StreamOutput.cpp)
    // A stream-output pass, from the pass's lowering to the varyings resolved in its compiled GLSL.
    struct StreamOutRequest {
        PassSlot slot;
        std::vector<StreamOutEntry> entries;
        bool fromVertex = false;  // ConstructGSWithSO of a vertex shader: the pass's vertex stage captures
        bool rasterizes = true;
        int capacity = 65536;
        int positionVarying = -1;  // LoweredStage::positionVarying of the capturing geometry shader
        std::string streamType;    // its output stream's type
        SourceLoc loc;             // SetGeometryShader's value
    };
    // The ConstructGSWithSO a pass's geometry-shader state names, inline or through a shader variable.
    const Expr* streamOutCall(const StateAssignment& s) const;
    // Lowers the pass's stream output: its geometry shader compiled for capture (or, for a vertex shader's
    // output, a note that the vertex stage captures), what GL cannot capture left for the technique.
    void streamOutStage(const Expr& call, const Pass& p, CompiledPass& pass, PassSlot slot);
    // `string DrawAuto = "pass";`: the pass index drawn and what its capture feeds the vertex shader.
    void drawAutoSource(const Pass& p, CompiledPass& pass);
    // After every stage compiled: each request's varyings named as the GLSL declares the outputs.
    void resolveStreamOutputs();
    void unsupported(DiagId id, const SourceLoc& loc, const std::vector<std::string>& args);
    // [SECTION] Texture functions (TextureFunction.cpp)
    struct TextureFunctionRequest {
        size_t texture;  // mOut->textures index
        const FunctionDecl* function;
        SourceLoc loc;  // the `function` annotation
    };
    void textureFunction(const Parameter& p, const Annotation& annotation, TextureDesc& t);
    void lowerTextureFunctions();

    const Effect& mEffect;
    const CompileOptions& mOptions;
    DiagnosticSink& mDiagnostics;
    std::unique_ptr<CompiledEffect> mOut;
    std::map<std::string, size_t> mIndex;  // parameter name -> index
    std::map<std::string, int> mSamplerUnits;
    std::set<std::string> mUnboundResources;  // reported by unboundResource()
    // Storage-block parameters' binding points, and their counters' (storageBindings()).
    std::map<std::string, int> mStorageBindings;
    std::map<std::string, int> mCounterBindings;
    std::vector<LoweredArgument> mPassArguments;  // the current pass's, as lowering numbers them
    // The outputs (by varying location) of the current pass's stage before its pixel shader: its geometry
    // shader's, else its vertex shader's (none after tessellation), which the pixel shader reads.
    std::optional<std::map<int, TypeDesc>> mPreviousOutputs;
    // The current pass's hull shader, whose partitioning and output topology its domain shader takes.
    const FunctionDecl* mHull = nullptr;
    const Technique* mTechnique = nullptr;  // the technique being compiled
    StageStreamOut mStageStreamOut;         // what the next compileStage's lowering needs of stream output
    int mLastPositionVarying = -1;          // of the last geometry stage compileStage lowered
    std::string mLastStreamType;
    std::vector<StreamOutRequest> mStreamOutRequests;
    std::vector<TextureFunctionRequest> mTextureFunctions;
    bool mFailed = false;
    // The diagnostics of the current technique's stages that the lowering could not express (a stage
    // form or a stream output GL has no counterpart for), held back until run() knows whether another
    // technique can run.
    std::vector<Diagnostic> mTechniqueUnsupported;
    std::vector<PendingStage> mPending;
    // The passes that set sampler-register states, by where they stand in mOut.
    std::vector<std::pair<PassSlot, const Pass*>> mSamplerRegisterPasses;
    // The passes that draw the full-screen quad (Pass::drawsScreenQuad, or a vertex shader that passes the
    // position through), by where they stand in mOut.
    std::vector<PassSlot> mScreenQuadPasses;
    std::vector<StageJob> mJobs;
    std::map<uint64_t, size_t> mJobByKey;
};

}  // namespace fx::detail
