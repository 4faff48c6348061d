// TessellationWrappers: the hull shader's wrapper (its input patch rebuilt, control points and patch
// constants written as float4 varyings through a generated patch-constant function around the user's) and
// the domain shader's (reading them back into the user's structs); see StageWrapper.h.
#include "StageWrapper.h"
#include "CaseFolding.h"

#include "HlslSpelling.h"
#include "SemanticTables.h"

#include <algorithm>

namespace fx {

namespace {

// The float4 a varying carries for a field (narrower values widened as vertexOutputs() widens them).
std::string float4Of(const Field& f) {
    const int n = std::clamp(f.type.cols, 1, 4);
    return widenToFloat4("(float" + (n == 1 ? std::string() : std::to_string(n)) + ")(" + fieldValue(f) + ")",
                         n);
}

// A control point struct of float4 varyings: SV_Position (gl_Position) and one member per location.
std::string controlPointStruct(const std::string& name, const std::set<int>& varyings, bool position) {
    std::string members = position ? "    float4 fx_position : SV_Position;\n" : "";
    for (int location : varyings)
        members += "    [[vk::location(" + std::to_string(location) + ")]] float4 fx_v" +
                   std::to_string(location) + " : FX_V" + std::to_string(location) + ";\n";
    if (members.empty()) members = "    float4 fx_position : SV_Position;\n";
    return "struct " + name + " {\n" + members + "};\n";
}

}  // namespace

// `local[k]` (the user's control point struct) from `source[k]`'s float4 varyings, for every control point
// of an InputPatch/OutputPatch parameter; collects the locations read (-1: SV_Position).
bool WrapperBuilder::readControlPoints(const FunctionParam& patch, const std::string& local,
                                       const std::string& source, std::set<int>& varyings,
                                       std::string& locals, std::string& body) {
    TypeDesc point = patch.type;
    point.arrayDims.clear();
    const std::string count = std::to_string(patch.patchSize);
    locals += "    " + hlslTypeName(point) + " " + local + "[" + count + "];\n";
    for (int k = 0; k < patch.patchSize; ++k) {  // glslang has no zero cast of an array: element by element
        const std::string at = "[" + std::to_string(k) + "]";
        locals += "    " + local + at + " = (" + hlslTypeName(point) + ")0;\n";
        std::vector<Field> fields;
        gatherFields(mEffect, point, patch.semantic, patch.interpolation, local + at, patch.loc, fields);
        for (const Field& f : fields) {
            if (f.semantic == "POSITION0" || f.semantic == "SV_POSITION") {
                varyings.insert(-1);
                body += assignField(f, source + at + ".fx_position");
            } else if (auto location = varyingLocation(f.semantic)
                                           ? varyingLocation(f.semantic)
                                           : customVaryingLocation(mEffect, f.semantic)) {
                varyings.insert(*location);
                body += assignField(f, source + at + ".fx_v" + std::to_string(*location));
            } else {
                return fail(DiagId::ControlPointSemanticUnsupported, f.loc, {f.semantic});
            }
        }
    }
    return true;
}

// The patch constants between a hull and a domain shader: the tessellation factors as glslang maps them
// (SV_TessFactor, SV_InsideTessFactor), every other member a float4 `patch` varying at its semantic's
// location. `write`: the hull side (fx_out.* = value.*), else the domain side (value.* = fx_c.*).
bool WrapperBuilder::patchConstants(const TypeDesc& type, const SourceLoc& loc, bool write,
                                    const std::string& value, std::string& members, std::string& body) {
    const StructDecl* decl = type.base == BaseType::Struct && type.arrayDims.empty()
                                 ? mEffect.findStruct(type.structName)
                                 : nullptr;
    if (!decl) return fail(DiagId::PatchConstantsNotStruct, loc, {});
    bool outer = false;
    std::set<int> used;
    for (const StructMember& m : decl->members) {
        const std::string semantic = upperCase(m.semantic);
        if (semantic == "SV_TESSFACTOR" || semantic == "SV_INSIDETESSFACTOR") {
            const std::string name = semantic == "SV_TESSFACTOR" ? "fx_outer" : "fx_inner";
            outer |= semantic == "SV_TESSFACTOR";
            if (!used.insert(semantic == "SV_TESSFACTOR" ? -1 : -2).second)
                return fail(DiagId::PatchConstantSemanticRepeated, m.loc, {m.semantic});
            TypeDesc element = m.type;
            element.arrayDims.clear();
            members += "    " + hlslTypeName(element) + " " + name + arraySuffix(m.type) + " : " +
                       (semantic == "SV_TESSFACTOR" ? "SV_TessFactor" : "SV_InsideTessFactor") + ";\n";
            body += write ? "    fx_out." + name + " = " + value + "." + m.name + ";\n"
                          : "    " + value + "." + m.name + " = fx_c." + name + ";\n";
            continue;
        }
        std::vector<Field> fields;
        gatherFields(mEffect, m.type, m.semantic, m.interpolation, value + "." + m.name, m.loc, fields);
        for (const Field& f : fields) {
            auto location = varyingLocation(f.semantic) ? varyingLocation(f.semantic)
                                                        : customVaryingLocation(mEffect, f.semantic);
            if (!location) return fail(DiagId::PatchConstantSemanticUnsupported, f.loc, {f.semantic});
            const std::string name = "fx_k" + std::to_string(*location);
            if (used.insert(*location).second)
                members += "    [[vk::location(" + std::to_string(*location) + ")]] float4 " + name +
                           " : FX_K" + std::to_string(*location) + ";\n";
            body +=
                write ? "    fx_out." + name + " = " + float4Of(f) + ";\n" : assignField(f, "fx_c." + name);
        }
    }
    if (!outer) return fail(DiagId::PatchConstantsWithoutTessFactor, decl->loc, {decl->name});
    return true;
}

// A hull shader: [domain][partitioning][outputtopology][outputcontrolpoints][patchconstantfunc("PCF")]
// HsOut HS(InputPatch<VsOut, 3> ip, uint i : SV_OutputControlPointID). The wrapper is a hull shader with the
// same attributes over an input patch of the vertex stage's float4 varyings; its patch-constant function
// fx_pcf rebuilds the user's patch (and output patch) and calls the user's PCF.
bool WrapperBuilder::buildHull(std::string& globals, std::string& wrapper) {
    for (const char* required :
         {"domain", "partitioning", "outputtopology", "outputcontrolpoints", "patchconstantfunc"})
        if (!mFn.attribute(required))
            return fail(DiagId::HullAttributeMissing, mFn.loc, {mFn.name, required});
    const FunctionAttribute& pcfAttribute = *mFn.attribute("patchconstantfunc");
    const FunctionDecl* pcf = nullptr;
    for (const FunctionDecl& f : mEffect.functions)
        if (f.name == pcfAttribute.argument && f.hasBody) pcf = &f;
    if (!pcf)
        return fail(DiagId::PatchConstantFunctionUndefined, pcfAttribute.loc,
                    {pcfAttribute.argument, mFn.name});
    mPatchConstantFunction = pcf->name;
    const std::string& pointsText = mFn.attribute("outputcontrolpoints")->argument;
    const int outputPoints = std::all_of(pointsText.begin(), pointsText.end(), ::isdigit) &&
                                     !pointsText.empty() && pointsText.size() < 3
                                 ? std::stoi(pointsText)
                                 : 0;
    if (outputPoints < 1 || outputPoints > 32)
        return fail(DiagId::OutputControlPointsInvalid, mFn.attribute("outputcontrolpoints")->loc, {});

    const FunctionParam* input = nullptr;
    std::string locals, body, callArgs;
    std::set<int> inputVaryings;
    size_t uniformIndex = 0;
    for (size_t i = 0; i < mFn.params.size(); ++i) {
        const FunctionParam& p = mFn.params[i];
        const std::string semantic = canonicalSemantic(p.semantic);
        std::string arg;
        if (p.isUniform) {
            if (!uniformArgument(p, uniformIndex++, arg, globals)) return false;
        } else if (p.patch == "InputPatch" && !input) {
            input = &p;
            arg = "fx_p" + std::to_string(i);
            if (!readControlPoints(p, arg, "fx_in", inputVaryings, locals, body)) return false;
        } else if (semantic == "SV_OUTPUTCONTROLPOINTID" || semantic == "SV_PRIMITIVEID") {
            arg = "(" + hlslTypeName(p.type) + ")" +
                  (semantic == "SV_PRIMITIVEID" ? "fx_primitiveId" : "fx_id");
        } else {
            return fail(DiagId::HullParameterUnsupported, p.loc, {p.name});
        }
        callArgs += (i ? ", " : "") + arg;
    }
    if (!everyArgumentTaken(uniformIndex)) return false;
    if (!input) return fail(DiagId::HullInputPatchMissing, mFn.loc, {mFn.name});
    if (input->patchSize != 3 && input->patchSize != 4)
        return fail(DiagId::InputPatchSizeUnsupported, input->loc, {std::to_string(input->patchSize)});
    mPatchVertices = input->patchSize;
    if (mFn.returnType.base == BaseType::Void)
        return fail(DiagId::HullReturnsNoControlPoint, mFn.loc, {mFn.name});
    std::vector<Field> outputs;
    locals += "    " + hlslTypeName(mFn.returnType) + " fx_r;\n";
    gatherFields(mEffect, mFn.returnType, mFn.returnSemantic, "", "fx_r", mFn.loc, outputs);
    std::string outputMembers, outputBody;
    if (!vertexOutputs(outputs, outputMembers, outputBody)) return false;
    if (outputMembers.empty()) outputMembers = "    float4 fx_position : SV_Position;\n";
    std::set<int> written;  // what the domain shader and the patch-constant function may read
    for (const Field& f : outputs) {
        if (f.semantic == "POSITION0" || f.semantic == "SV_POSITION") written.insert(-1);
        if (auto location = varyingLocation(f.semantic) ? varyingLocation(f.semantic)
                                                        : customVaryingLocation(mEffect, f.semantic))
            written.insert(*location);
    }

    // The patch-constant function's wrapper.
    std::string pcfLocals, pcfBody, pcfArgs,
        pcfParams = "InputPatch<fx_HsInput, " + std::to_string(mPatchVertices) + "> fx_in";
    bool outputPatch = false;
    for (size_t i = 0; i < pcf->params.size(); ++i) {
        const FunctionParam& p = pcf->params[i];
        const std::string semantic = canonicalSemantic(p.semantic);
        std::string arg = "fx_q" + std::to_string(i);
        if (p.patch == "InputPatch" && p.patchSize == input->patchSize && !p.isUniform) {
            if (!readControlPoints(p, arg, "fx_in", inputVaryings, pcfLocals, pcfBody)) return false;
        } else if (p.patch == "OutputPatch" && p.patchSize == outputPoints && !outputPatch && !p.isUniform) {
            outputPatch = true;
            std::set<int> read;
            if (!readControlPoints(p, arg, "fx_op", read, pcfLocals, pcfBody)) return false;
            for (int location : read)
                if (!written.count(location))
                    return fail(DiagId::OutputPatchReadsUnwritten, p.loc, {p.name, pcf->name, mFn.name});
            pcfParams += ", OutputPatch<fx_HsOutput, " + std::to_string(outputPoints) + "> fx_op";
        } else if (semantic == "SV_PRIMITIVEID" && !p.isUniform) {
            arg = "(" + hlslTypeName(p.type) + ")fx_primitiveId";
        } else {
            return fail(DiagId::PatchConstantParameterUnsupported, p.loc,
                        {p.name, std::to_string(outputPoints)});
        }
        pcfArgs += (i ? ", " : "") + arg;
    }
    pcfParams += ", uint fx_primitiveId : SV_PrimitiveID";
    if (pcf->returnType.base == BaseType::Void)
        return fail(DiagId::PatchConstantsNotReturnedAsStruct, pcf->loc, {pcf->name});
    std::string constantMembers, constantBody;
    if (!patchConstants(pcf->returnType, pcf->loc, true, "fx_r", constantMembers, constantBody)) return false;

    inputVaryings.erase(-1);
    wrapper += controlPointStruct("fx_HsInput", inputVaryings, true);
    wrapper += "struct fx_HsOutput {\n" + outputMembers + "};\n";
    wrapper += "struct fx_HsConstants {\n" + constantMembers + "};\n";
    wrapper += "fx_HsConstants fx_pcf(" + pcfParams +
               ")\n{\n    fx_HsConstants fx_out = (fx_HsConstants)0;\n    " + hlslTypeName(pcf->returnType) +
               " fx_r;\n" + pcfLocals + pcfBody + "    fx_r = " + pcf->name + "(" + pcfArgs + ");\n" +
               constantBody + "    return fx_out;\n}\n";
    for (const FunctionAttribute& a : mFn.attributes)
        wrapper +=
            (equalsIgnoreCase(a.name, "patchconstantfunc") ? std::string("[patchconstantfunc(\"fx_pcf\")]")
                                                           : a.text) +
            "\n";
    wrapper += "fx_HsOutput " + std::string(kWrapperEntryPoint) + "(InputPatch<fx_HsInput, " +
               std::to_string(mPatchVertices) +
               "> fx_in, uint fx_id : SV_OutputControlPointID, uint fx_primitiveId : "
               "SV_PrimitiveID)\n{\n    fx_HsOutput fx_out = (fx_HsOutput)0;\n" +
               locals + body + "    fx_r = " + mFn.name + "(" + callArgs + ");\n" + outputBody +
               "    return fx_out;\n}\n";
    return true;
}

// A domain shader: [domain("tri")] DsOut DS(HsConstants c, float3 uvw : SV_DomainLocation,
// const OutputPatch<HsOut, 3> patch). The wrapper reads the hull wrapper's control points and patch
// constants back into the user's structs and writes its results as a vertex shader does; it takes the
// hull shader's partitioning and output topology, which GL declares in this stage.
bool WrapperBuilder::buildDomain(std::string& globals, std::string& wrapper) {
    const FunctionAttribute* domain = mFn.attribute("domain");
    if (!domain) return fail(DiagId::DomainAttributeMissing, mFn.loc, {mFn.name});
    if (!mHull || !mHull->attribute("domain")) return fail(DiagId::DomainWithoutHull, mCompile.loc, {});
    if (!equalsIgnoreCase(domain->argument, mHull->attribute("domain")->argument))
        return fail(DiagId::DomainMismatch, domain->loc,
                    {mFn.name, domain->argument, mHull->name, mHull->attribute("domain")->argument});
    const FunctionAttribute* points = mHull->attribute("outputcontrolpoints");
    std::string locals, body, callArgs, params, constantMembers, constantBody;
    std::vector<Field> outputs;
    std::set<int> varyings;
    bool constants = false, patch = false;
    size_t uniformIndex = 0;
    auto addParam = [&](const std::string& p) { params += (params.empty() ? "" : ", ") + p; };
    for (size_t i = 0; i < mFn.params.size(); ++i) {
        const FunctionParam& p = mFn.params[i];
        const std::string semantic = canonicalSemantic(p.semantic);
        std::string arg = "fx_p" + std::to_string(i);
        if (p.isUniform) {
            if (!uniformArgument(p, uniformIndex++, arg, globals)) return false;
        } else if (p.patch == "OutputPatch" && !patch) {
            patch = true;
            if (!points || std::to_string(p.patchSize) != points->argument)
                return fail(DiagId::OutputPatchSizeMismatch, p.loc,
                            {mFn.name, std::to_string(p.patchSize), mHull->name,
                             points ? points->argument : std::string("?")});
            if (!readControlPoints(p, arg, "fx_patch", varyings, locals, body)) return false;
            addParam("const OutputPatch<fx_DsPoint, " + std::to_string(p.patchSize) + "> fx_patch");
        } else if (semantic == "SV_DOMAINLOCATION") {
            // GL's tessellation coordinate has three components in every domain; a quad's reads two.
            addParam("float3 fx_domain : SV_DomainLocation");
            arg = p.type.cols == 2 ? "fx_domain.xy" : "fx_domain";
        } else if (semantic == "SV_PRIMITIVEID") {
            addParam("uint fx_primitiveId : SV_PrimitiveID");
            arg = "(" + hlslTypeName(p.type) + ")fx_primitiveId";
        } else if (p.semantic.empty() && p.type.base == BaseType::Struct && !constants &&
                   p.direction == FunctionParam::Direction::In) {
            constants = true;
            locals += "    " + hlslTypeName(p.type) + " " + arg + " = (" + hlslTypeName(p.type) + ")0;\n";
            if (!patchConstants(p.type, p.loc, false, arg, constantMembers, constantBody)) return false;
            addParam("fx_DsConstants fx_c");
        } else if (p.direction == FunctionParam::Direction::Out) {
            TypeDesc t = p.type;
            const std::string dims = arraySuffix(t);
            t.arrayDims.clear();
            locals += "    " + hlslTypeName(t) + " " + arg + dims + ";\n";
            gatherFields(mEffect, p.type, p.semantic, p.interpolation, arg, p.loc, outputs);
        } else {
            return fail(DiagId::DomainParameterUnsupported, p.loc, {p.name});
        }
        callArgs += (i ? ", " : "") + arg;
    }
    if (!everyArgumentTaken(uniformIndex)) return false;
    std::string call = "    " + mFn.name + "(" + callArgs + ");\n";
    if (mFn.returnType.base != BaseType::Void) {
        locals += "    " + hlslTypeName(mFn.returnType) + " fx_r;\n";
        call = "    fx_r = " + mFn.name + "(" + callArgs + ");\n";
        gatherFields(mEffect, mFn.returnType, mFn.returnSemantic, "", "fx_r", mFn.loc, outputs);
    }
    std::string members, outputBody;
    if (!vertexOutputs(outputs, members, outputBody)) return false;
    if (members.empty()) members = "    float4 fx_position : SV_Position;\n";
    const bool position = varyings.erase(-1) > 0;
    if (patch) wrapper += controlPointStruct("fx_DsPoint", varyings, position);
    if (constants) wrapper += "struct fx_DsConstants {\n" + constantMembers + "};\n";
    wrapper += "struct fx_DsOutput {\n" + members + "};\n";
    // glslang writes D3D's triangle_cw as SPIR-V's VertexOrderCw for Vulkan, whose tessellation domain
    // has its origin at the upper left; GL's has it at the lower left, which reverses the winding that
    // order produces. So the GL stage gets the other order, and the tessellated triangles face as the
    // mesh's do.
    std::string topology = mHull->attribute("outputtopology")->argument;
    topology = equalsIgnoreCase(topology, "triangle_cw")    ? "triangle_ccw"
               : equalsIgnoreCase(topology, "triangle_ccw") ? "triangle_cw"
                                                            : topology;
    wrapper += domain->text + "\n" + mHull->attribute("partitioning")->text + "\n[outputtopology(\"" +
               topology + "\")]\n";
    wrapper += "fx_DsOutput " + std::string(kWrapperEntryPoint) + "(" + params + ")\n{\n" +
               "    fx_DsOutput fx_out = (fx_DsOutput)0;\n" + locals + constantBody + body + call +
               outputBody + "    return fx_out;\n}\n";
    return true;
}

}  // namespace fx
