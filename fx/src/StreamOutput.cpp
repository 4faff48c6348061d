// StreamOutput: D3D10's stream output (ConstructGSWithSO) lowered to GL transform feedback (see Compiler.h
// and docs/d3d10.md, "Stream output"). The pass lowering keeps every captured output a varying of the
// capturing stage; once the stages are compiled, each declaration entry becomes the name SPIRV-Cross gave
// that output, with gl_SkipComponentsN for a `$SKIP` and gl_NextBuffer between output slots, the list
// glTransformFeedbackVaryings takes (GL_INTERLEAVED_ATTRIBS, GL 4.0's ARB_transform_feedback3).

#include "Compiler.h"

#include "CaseFolding.h"
#include "SemanticTables.h"

#include <regex>

namespace fx::detail {

namespace {

// The entry's semantic as the pass lowering keys varyings ("POSITION0", "TIMER", "SV_POSITION").
std::string entrySemantic(const StreamOutEntry& e) {
    return canonicalSemantic(e.semantic + (e.semanticIndex ? std::to_string(e.semanticIndex) : ""));
}

// The key capture elements and vertex inputs are matched by: the name with its index spelled out.
std::string elementKey(const std::string& canonical) {
    const auto [name, index] = splitSemantic(canonical);
    return name + std::to_string(index);
}

bool isPosition(const std::string& canonical) {
    return canonical == "POSITION0" || canonical == "SV_POSITION";
}

// A pixel shader that is set: a compile expression or a variable holding one (not NULL, 0 or a variable
// holding nothing).
bool setsShader(const StateAssignment& s, const Effect& effect) {
    if (s.value.kind == Expr::Kind::Compile || s.value.kind == Expr::Kind::Index) return true;
    if (s.value.kind != Expr::Kind::Identifier) return false;
    const Parameter* p = effect.findParameter(s.value.text);
    return p && p->initializer && p->initializer->kind == Expr::Kind::Compile;
}

// One stage output as SPIRV-Cross declares it: `layout(location = 3) flat out uint name;`.
struct GlslOutput {
    std::string name;
    std::string type;
};

std::map<int, GlslOutput> glslOutputs(const std::string& glsl) {
    static const std::regex kOutput(
        R"(layout\(location = (\d+)\)\s+(?:(?:flat|noperspective|centroid|sample|smooth)\s+)*out\s+(\w+)\s+(\w+)\s*;)");
    std::map<int, GlslOutput> outputs;
    for (auto it = std::sregex_iterator(glsl.begin(), glsl.end(), kOutput); it != std::sregex_iterator();
         ++it)
        outputs[std::stoi((*it)[1])] = GlslOutput{(*it)[3], (*it)[2]};
    return outputs;
}

// Components and component type of a GLSL scalar or vector type; 0 components for anything else.
std::pair<int, StreamOutElement::Component> glslShape(const std::string& type) {
    using Component = StreamOutElement::Component;
    if (type == "float") return {1, Component::Float};
    if (type == "int") return {1, Component::Int};
    if (type == "uint") return {1, Component::UInt};
    if (type.size() == 4 && type.compare(0, 3, "vec") == 0) return {type[3] - '0', Component::Float};
    if (type.size() == 5 && type.compare(0, 4, "ivec") == 0) return {type[4] - '0', Component::Int};
    if (type.size() == 5 && type.compare(0, 4, "uvec") == 0) return {type[4] - '0', Component::UInt};
    return {0, Component::Float};
}

}  // namespace

void Compiler::unsupported(DiagId id, const SourceLoc& loc, const std::vector<std::string>& args) {
    mTechniqueUnsupported.push_back(Diagnostic{id, Severity::Error, loc, formatDiagnostic(id, args)});
}

const Expr* Compiler::streamOutCall(const StateAssignment& s) const {
    if (s.value.kind == Expr::Kind::Call && s.value.text == "ConstructGSWithSO") return &s.value;
    if (s.value.kind != Expr::Kind::Identifier) return nullptr;
    const Parameter* variable = mEffect.findParameter(s.value.text);
    if (variable && variable->initializer && variable->initializer->kind == Expr::Kind::Call &&
        variable->initializer->text == "ConstructGSWithSO")
        return &*variable->initializer;
    return nullptr;
}

void Compiler::streamOutStage(const Expr& call, const Pass& p, CompiledPass& pass, PassSlot slot) {
    std::optional<StreamOutCall> so = readConstructGSWithSO(call);
    if (!so) return;  // the parser said what is wrong with its form
    StateAssignment shader;
    shader.name = "GeometryShader";
    shader.loc = call.loc;
    shader.value = *so->shader;
    const Expr* compile = shaderExpr(shader);
    if (!compile) return;
    StreamOutRequest request;
    request.slot = slot;
    request.loc = call.loc;
    request.entries = so->entries;
    request.fromVertex = compile->profile.rfind("vs_", 0) == 0;
    request.rasterizes = false;
    for (const StateAssignment& s : p.states)
        if (findRenderState(s.name) == RenderStateId::PixelShader)
            request.rasterizes = setsShader(s, mEffect);
    if (const Annotation* a = p.annotation("StreamOutVertices")) {
        const std::optional<Value> value = eval(a->value, nullptr);
        const float vertices = value && value->data.size() == 1 ? value->asFloat() : 0.0f;
        if (vertices >= 1.0f && vertices <= float(1 << 24) && vertices == float(int(vertices)))
            request.capacity = int(vertices);
        else
            error(DiagId::StreamOutVerticesInvalid, a->loc, {});
    }

    if (so->otherStreams) return unsupported(DiagId::StreamOutOtherStreams, call.loc, {});
    if (request.entries.empty()) return unsupported(DiagId::StreamOutEmpty, call.loc, {});
    // GL captures whole outputs: an entry must name all of an output's components, as every SDK
    // declaration does. A vertex shader's outputs are float4 varyings (the pass lowering widens them).
    std::string function;
    const std::optional<OutputSignature> outputs = streamOutputSignature(*so->shader, mEffect, function);
    for (const StreamOutEntry& e : request.entries) {
        if (e.semantic == "$SKIP") continue;
        const std::string canonical = entrySemantic(e);
        const bool builtIn = canonical == "SV_POSITION" ||
                             (canonical == "POSITION0" && (request.fromVertex || request.rasterizes));
        // A vertex shader's outputs are float4 varyings where a pixel shader reads them.
        const bool float4Varying = request.fromVertex && request.rasterizes;
        int components = builtIn || float4Varying ? 4 : 0;
        if (!components && outputs) {
            auto found = outputs->find({upperCase(e.semantic), e.semanticIndex});
            if (found != outputs->end()) components = found->second;
        }
        if (components && (e.startComponent != 0 || e.componentCount != components))
            return unsupported(builtIn         ? DiagId::StreamOutPartialPosition
                               : float4Varying ? DiagId::StreamOutPartialFloat4Varying
                                               : DiagId::StreamOutPartialOutput,
                               e.loc, {e.text, std::to_string(components)});
    }
    if (request.fromVertex) {
        // Not rasterized: the vertex stage's outputs keep their declared types (reset after the vertex
        // shader's compile in compilePass).
        mStageStreamOut.captureOnly = !request.rasterizes;
        // D3D10 streams out the pass's own vertex shader when ConstructGSWithSO is given one.
        for (const StateAssignment& s : p.states)
            if (findRenderState(s.name) == RenderStateId::VertexShader)
                if (const Expr* vertex = shaderExpr(s); vertex && vertex->text != compile->text)
                    return unsupported(DiagId::StreamOutOtherVertexShader, call.loc,
                                       {compile->text, vertex->text});
    } else {
        mStageStreamOut.captureOnly = !request.rasterizes;
        mLastPositionVarying = -1;
        mLastStreamType.clear();
        const bool compiled = compileStage(*compile, ShaderStage::Geometry, pass, slot);
        mStageStreamOut.captureOnly = false;
        if (!compiled) return;
        request.positionVarying = mLastPositionVarying;
        request.streamType = mLastStreamType;
    }
    mStreamOutRequests.push_back(std::move(request));
}

void Compiler::drawAutoSource(const Pass& p, CompiledPass& pass) {
    const Annotation* a = p.annotation("DrawAuto");
    if (!a || !mTechnique) return;
    if (a->value.kind != Expr::Kind::String)
        return error(DiagId::DrawAutoNotString, a->loc, {mTechnique->name});
    for (size_t i = 0; i < mTechnique->passes.size(); ++i) {
        const Pass& source = mTechnique->passes[i];
        if (!equalsIgnoreCase(source.name, a->value.text)) continue;
        for (const StateAssignment& s : source.states) {
            if (findRenderState(s.name) != RenderStateId::GeometryShader) continue;
            const Expr* call = streamOutCall(s);
            const std::optional<StreamOutCall> so = call ? readConstructGSWithSO(*call) : std::nullopt;
            if (!so) continue;
            pass.drawAuto = static_cast<int>(i);
            std::vector<std::string> captured;
            for (const StreamOutEntry& e : so->entries)
                if (e.semantic != "$SKIP") captured.push_back(elementKey(entrySemantic(e)));
            mStageStreamOut.capturedInputs = std::move(captured);
            return;
        }
    }
    error(DiagId::DrawAutoNotStreamingPass, a->loc, {mTechnique->name, a->value.text});
}

void Compiler::resolveStreamOutputs() {
    for (const StreamOutRequest& request : mStreamOutRequests) {
        CompiledPass& pass = mOut->techniques[request.slot.technique].passes[request.slot.pass];
        const StageProgram& stage = request.fromVertex ? pass.vertex : pass.geometry;
        if (stage.glsl.empty()) continue;  // it failed to compile, and said so
        const std::map<int, GlslOutput> outputs = glslOutputs(stage.glsl);
        StreamOutput out;
        out.rasterizes = request.rasterizes;
        out.capacity = request.capacity;
        using Primitive = StreamOutput::Primitive;
        out.primitive = request.streamType == "TriangleStream" ? Primitive::Triangles
                        : request.streamType == "LineStream"   ? Primitive::Lines
                        : request.streamType == "PointStream"  ? Primitive::Points
                        : pass.drawAuto >= 0                   ? Primitive::Points  // a capture's vertices
                                                               : Primitive::Triangles;                // the meshes
        int slot = 0;
        bool resolved = true;
        for (const StreamOutEntry& e : request.entries) {
            for (; slot < e.slot; ++slot) out.varyings.push_back("gl_NextBuffer");
            uint32_t& stride = out.strides[slot];
            if (e.semantic == "$SKIP") {
                out.varyings.push_back("gl_SkipComponents" + std::to_string(e.componentCount));
                stride += 4u * static_cast<uint32_t>(e.componentCount);
                continue;
            }
            const std::string canonical = entrySemantic(e);
            StreamOutElement element;
            element.semantic = elementKey(canonical);
            element.slot = slot;
            element.offset = stride;
            if (isPosition(canonical) && (canonical == "SV_POSITION" || request.positionVarying < 0)) {
                out.varyings.push_back("gl_Position");
                element.components = 4;
            } else {
                const std::optional<int> location =
                    canonical == "POSITION0"     ? std::optional<int>(request.positionVarying)
                    : varyingLocation(canonical) ? varyingLocation(canonical)
                                                 : customVaryingLocation(mEffect, canonical);
                auto found = location ? outputs.find(*location) : outputs.end();
                const auto [components, component] = found == outputs.end()
                                                         ? std::pair(0, StreamOutElement::Component::Float)
                                                         : glslShape(found->second.type);
                if (components == 0 || components != e.componentCount) {
                    error(DiagId::StreamOutEntryNotCapturable, e.loc,
                          {e.text, request.fromVertex ? "vertex" : "geometry"});
                    resolved = false;
                    break;
                }
                out.varyings.push_back(found->second.name);
                element.components = components;
                element.component = component;
            }
            stride += 4u * static_cast<uint32_t>(element.components);
            out.elements.push_back(element);
        }
        if (resolved) pass.streamOut = std::move(out);
    }
}

}  // namespace fx::detail
