// GeometryWrapper: a geometry shader's wrapper: its input array rebuilt like a vertex shader's outputs, the
// user's function handed its output stream, the stream's element redeclared with varying locations (see
// StageWrapper.h).
#include "StageWrapper.h"

#include "HlslSpelling.h"
#include "SemanticTables.h"

#include <algorithm>

namespace fx {

// The stream's element struct, redeclared with the varying location of each member's semantic (glslang
// assigns the locations of a geometry shader's outputs from the struct it appends): members must be
// scalars or vectors with a POSITION/SV_Position or varying semantic, or a system value a geometry shader
// writes (SV_ClipDistance, SV_CullDistance, SV_RenderTargetArrayIndex, SV_ViewportArrayIndex,
// SV_PrimitiveID).
bool WrapperBuilder::streamElement(const FunctionParam& stream) {
    const StructDecl* decl =
        stream.type.base == BaseType::Struct ? mEffect.findStruct(stream.type.structName) : nullptr;
    if (!decl || !stream.type.arrayDims.empty())
        return fail(DiagId::GeometryStreamElementNotStruct, stream.loc, {stream.name});
    mStreamStruct = decl->name;
    // A captured and not rasterized stream keeps its POSITION as a varying (transform feedback captures
    // it by name, and a float3 one would not fit gl_Position), at the first location no other member takes.
    if (mStreamOut.captureOnly) {
        std::set<int> taken;
        for (const StructMember& m : decl->members) {
            const std::string semantic = canonicalSemantic(m.semantic);
            if (auto location = varyingLocation(semantic) ? varyingLocation(semantic)
                                                          : customVaryingLocation(mEffect, semantic))
                taken.insert(*location);
        }
        for (const StructMember& m : decl->members)
            if (canonicalSemantic(m.semantic) == "POSITION0")
                for (int location = 0; mPositionVarying < 0 && location < 32; ++location)
                    if (!taken.count(location)) mPositionVarying = location;
    }
    std::string members;
    for (const StructMember& m : decl->members) {
        const std::string semantic = canonicalSemantic(m.semantic);
        if (m.type.base == BaseType::Struct || m.type.arrayDims.size() > 1 || m.type.shape == Shape::Matrix)
            return fail(DiagId::GeometryOutputNotVector, m.loc, {m.name});
        TypeDesc element = m.type;
        element.arrayDims.clear();
        std::string declared = hlslTypeName(element) + " " + m.name;
        if (!m.type.arrayDims.empty()) {
            // `float3 Normals[6] : SIXNORMS` is SIXNORMS0..5, as fxc numbered them. The array keeps its
            // shape (the user's code indexes it) at its first element's location; glslang splits it into
            // one output per element at that location, which the GLSL step moves to the following ones
            // (SpirvToGlsl.cpp). So the elements' semantics must take consecutive locations: an array of
            // more than ten free-named elements has them apart (SIXNORMS10 sorts before SIXNORMS2), as has
            // one whose names run past the eight locations 24..31 into the D3D9 table's free ones.
            const int count = std::max(m.type.arrayDims[0], 1);
            // A pair, not a structured binding: clang 14 (the sanitized build's) cannot capture those.
            const std::pair<std::string, int> split = splitSemantic(semantic);
            const auto locationOf = [&](int k) {
                const std::string each = split.first + std::to_string(split.second + k);
                return varyingLocation(each) ? varyingLocation(each) : customVaryingLocation(mEffect, each);
            };
            const std::optional<int> start = locationOf(0);
            if (!start || semantic.rfind("SV_", 0) == 0 || semantic == "POSITION0")
                return fail(DiagId::GeometryOutputSemanticUnsupported, m.loc, {m.semantic});
            for (int k = 1; k < count; ++k)
                if (locationOf(k) != *start + k)
                    return fail(DiagId::GeometryOutputArrayLocationsApart, m.loc,
                                {m.name, split.first + std::to_string(split.second + k),
                                 split.first + std::to_string(split.second + k - 1)});
            const bool integer = element.base != BaseType::Float && element.base != BaseType::Half;
            if (integer && m.interpolation.empty())
                return fail(DiagId::GeometryIntegerOutputInterpolated, m.loc, {m.name});
            const std::string at = std::to_string(*start);
            members += "    [[vk::location(" + at + ")]] " +
                       (m.interpolation.empty() ? std::string() : m.interpolation + " ") + declared + "[" +
                       std::to_string(count) + "] : FX_V" + at + ";\n";
            for (int k = 0; k < count; ++k) mVaryingOutputs[*start + k] = element;
            continue;
        }
        const bool positionVarying = semantic == "POSITION0" && mPositionVarying >= 0;
        if (!positionVarying && (semantic == "POSITION0" || semantic == "SV_POSITION")) {
            members += "    " + declared + " : SV_Position;\n";
        } else if (semantic.rfind("SV_CLIPDISTANCE", 0) == 0 || semantic.rfind("SV_CULLDISTANCE", 0) == 0 ||
                   semantic == "SV_RENDERTARGETARRAYINDEX" || semantic == "SV_VIEWPORTARRAYINDEX" ||
                   semantic == "SV_PRIMITIVEID") {
            // GL's gl_ClipDistance, gl_CullDistance, gl_Layer, gl_ViewportIndex and gl_PrimitiveID: glslang
            // maps the system value to its built-in.
            members += "    " + declared + " : " + m.semantic + ";\n";
        } else if (auto location = positionVarying             ? std::optional<int>(mPositionVarying)
                                   : varyingLocation(semantic) ? varyingLocation(semantic)
                                                               : customVaryingLocation(mEffect, semantic)) {
            const bool integer = m.type.base != BaseType::Float && m.type.base != BaseType::Half;
            // Captured only, nothing interpolates it; GLSL still wants an integer output flat. An instance
            // ID is flat whatever it says, as D3D10 passes integers.
            const std::string interpolation =
                integer && m.interpolation.empty() && (mStreamOut.captureOnly || semantic == "SV_INSTANCEID")
                    ? "nointerpolation"
                    : m.interpolation;
            if (integer && interpolation.empty())
                return fail(DiagId::GeometryIntegerOutputInterpolated, m.loc, {m.name});
            const std::string at = std::to_string(*location);
            members += "    [[vk::location(" + at + ")]] " +
                       (interpolation.empty() ? std::string() : interpolation + " ") + declared + " : FX_V" +
                       at + ";\n";
            mVaryingOutputs[*location] = m.type;
        } else {
            return fail(DiagId::GeometryOutputSemanticUnsupported, m.loc, {m.semantic});
        }
    }
    mStreamStructText = "struct " + decl->name + "\n{\n" + members + "};\n";
    return true;
}

// A geometry shader: [maxvertexcount(n)] void GS(triangle In input[3], inout TriangleStream<Out> s).
// The wrapper is a geometry shader of the same primitive and vertex count that rebuilds `input` from the
// vertex stage's SV_Position and float4 varyings and passes its own stream through.
bool WrapperBuilder::buildGeometry(std::string& globals, std::string& wrapper) {
    if (mFn.maxVertexCount <= 0) return fail(DiagId::GeometryMaxVertexCountMissing, mFn.loc, {mFn.name});
    const FunctionParam* input = nullptr;
    const FunctionParam* stream = nullptr;
    std::string params, locals, body, callArgs;
    size_t uniformIndex = 0;
    bool primitiveId = false;
    for (size_t i = 0; i < mFn.params.size(); ++i) {
        const FunctionParam& p = mFn.params[i];
        std::string arg;
        if (p.isUniform) {
            if (!uniformArgument(p, uniformIndex++, arg, globals)) return false;
        } else if (!p.stream.empty()) {
            if (stream) return fail(DiagId::GeometryStreamRepeated, p.loc, {mFn.name});
            stream = &p;
            arg = "fx_stream";
        } else if (!p.primitive.empty()) {
            if (input) return fail(DiagId::GeometryInputPrimitiveRepeated, p.loc, {mFn.name});
            input = &p;
            arg = "fx_p" + std::to_string(i);
        } else if (canonicalSemantic(p.semantic) == "SV_PRIMITIVEID") {
            primitiveId = true;
            arg = "(" + hlslTypeName(p.type) + ")fx_primitiveId";
        } else {
            return fail(DiagId::GeometryParameterUnsupported, p.loc, {p.name});
        }
        callArgs += (i ? ", " : "") + arg;
    }
    if (!everyArgumentTaken(uniformIndex)) return false;
    if (!input || !stream) return fail(DiagId::GeometryInputOrStreamMissing, mFn.loc, {mFn.name});
    // What the pass's draws give each primitive: a mesh's triangles, its vertices, its edges or its
    // triangles with their neighbours (GpuMesh builds the edge and adjacency lists).
    using Primitive = CompiledPass::DrawPrimitive;
    static const std::map<std::string, std::pair<int, Primitive>> kInputs = {
        {"point", {1, Primitive::Points}},
        {"line", {2, Primitive::Lines}},
        {"triangle", {3, Primitive::Triangles}},
        {"triangleadj", {6, Primitive::TrianglesAdjacency}}};
    if (input->primitive == "lineadj") return fail(DiagId::GeometryLineAdjacencyInput, input->loc, {});
    const auto kind = kInputs.find(input->primitive);
    if (kind == kInputs.end())
        return fail(DiagId::GeometryInputPrimitiveUnsupported, input->loc, {input->primitive});
    const int count = kind->second.first;
    mPrimitive = kind->second.second;
    if (input->type.arrayDims.size() != 1 || input->type.arrayDims[0] != count)
        return fail(DiagId::GeometryInputArraySize, input->loc,
                    {input->name, std::to_string(count), input->primitive});
    if (stream->direction != FunctionParam::Direction::InOut)
        return fail(DiagId::GeometryStreamNotInout, stream->loc, {stream->name});
    mStreamType = stream->stream;
    if (!streamElement(*stream)) return false;

    TypeDesc vertex = input->type;
    vertex.arrayDims.clear();
    const std::string inputName = "fx_p" + std::to_string(input - mFn.params.data());
    locals += "    " + hlslTypeName(vertex) + " " + inputName + "[" + std::to_string(count) + "];\n";
    for (int k = 0; k < count; ++k)  // glslang has no zero cast of an array: element by element
        locals += "    " + inputName + "[" + std::to_string(k) + "] = (" + hlslTypeName(vertex) + ")0;\n";
    std::set<int> varyings;
    for (int k = 0; k < count; ++k) {
        std::vector<Field> fields;
        gatherFields(mEffect, vertex, input->semantic, input->interpolation,
                     inputName + "[" + std::to_string(k) + "]", input->loc, fields);
        const std::string from = "fx_in[" + std::to_string(k) + "].";
        for (const Field& f : fields) {
            if (f.semantic == "POSITION0" || f.semantic == "SV_POSITION") {
                body += assignField(f, from + "fx_position");
            } else if (auto location = varyingLocation(f.semantic)
                                           ? varyingLocation(f.semantic)
                                           : customVaryingLocation(mEffect, f.semantic)) {
                varyings.insert(*location);
                body += assignField(f, from + "fx_v" + std::to_string(*location));
            } else {
                return fail(DiagId::GeometryInputSemanticUnsupported, f.loc, {f.semantic});
            }
        }
    }
    std::string inputMembers = "    float4 fx_position : SV_Position;\n";
    for (int location : varyings)
        inputMembers += "    [[vk::location(" + std::to_string(location) + ")]] float4 fx_v" +
                        std::to_string(location) + " : FX_V" + std::to_string(location) + ";\n";
    params = input->primitive + " fx_GsInput fx_in[" + std::to_string(count) + "], inout " + stream->stream +
             "<" + mStreamStruct + "> fx_stream";
    if (primitiveId) params += ", uint fx_primitiveId : SV_PrimitiveID";
    wrapper += "struct fx_GsInput {\n" + inputMembers + "};\n";
    wrapper += "[maxvertexcount(" + std::to_string(mFn.maxVertexCount) + ")]\nvoid " +
               std::string(kWrapperEntryPoint) + "(" + params + ")\n{\n";
    wrapper += locals + body + "    " + mFn.name + "(" + callArgs + ");\n}\n";
    return true;
}

}  // namespace fx
