// StageWrapper: the wrapper's shared parts (fields, uniform arguments) and the vertex and pixel shaders'
// wrappers (see StageWrapper.h).
#include "StageWrapper.h"
#include "CaseFolding.h"

#include "HlslSpelling.h"
#include "InstanceTransformRows.h"
#include "SemanticTables.h"

#include <algorithm>
#include <functional>

#include <fx/Preshader.h>

namespace fx {

// The value a field holds, for an output: the column of a matrix or the lvalue itself.
std::string fieldValue(const Field& f) {
    return f.column < 0 ? f.lvalue : "transpose(" + f.lvalue + ")[" + std::to_string(f.column) + "]";
}

void gatherFields(const Effect& effect, const TypeDesc& type, const std::string& semantic,
                  const std::string& interpolation, const std::string& lvalue, const SourceLoc& loc,
                  std::vector<Field>& out, int depth) {
    if (type.base == BaseType::Struct && type.arrayDims.empty()) {
        const StructDecl* decl = effect.findStruct(type.structName);
        if (!decl || depth > 8) return;
        for (const StructMember& m : decl->members)
            gatherFields(effect, m.type, m.semantic, m.interpolation, lvalue + "." + m.name, m.loc, out,
                         depth + 1);
        return;
    }
    if (semantic.empty()) return;  // left zero, as an unbound D3D9 register reads
    const std::string canonical = canonicalSemantic(semantic);
    const std::string upperSemantic = upperCase(semantic);
    const bool centroid =
        upperSemantic.size() > 9 && upperSemantic.compare(upperSemantic.size() - 9, 9, "_CENTROID") == 0;
    const std::string interp = centroid && interpolation.empty() ? std::string("centroid") : interpolation;
    auto [name, index] = splitSemantic(canonical);
    if (!type.arrayDims.empty() && depth <= 8) {
        // An array takes consecutive semantic indices, each element as many as it needs.
        TypeDesc element = type;
        element.arrayDims.erase(element.arrayDims.begin());
        int perElement = 1;
        for (int dim : element.arrayDims) perElement *= std::max(dim, 1);
        if (element.shape == Shape::Matrix) perElement *= element.cols;
        for (int i = 0; i < std::min(type.arrayDims.front(), 32); ++i)
            gatherFields(effect, element, name + std::to_string(index + i * perElement), interp,
                         lvalue + "[" + std::to_string(i) + "]", loc, out, depth + 1);
        return;
    }
    if (type.shape == Shape::Matrix) {
        TypeDesc column = type;
        column.shape = type.rows == 1 ? Shape::Scalar : Shape::Vector;
        column.cols = type.rows;
        column.rows = 1;
        for (int k = 0; k < type.cols; ++k)
            out.push_back(Field{lvalue, column, name + std::to_string(index + k), interp, loc, k});
        return;
    }
    out.push_back(Field{lvalue, type, canonical, interp, loc});
}

int fieldComponents(const Field& f) {
    return f.type.shape == Shape::Matrix ? f.type.rows * f.type.cols : f.type.cols;
}

// `expr` (a float4) narrowed to the field's type: ".x", ".xy", ".xyz", with a cast for ints/bools.
std::string narrowTo(const Field& f, const std::string& expr) {
    static const char* kSwizzle[] = {"", ".x", ".xy", ".xyz", ""};
    int n = std::clamp(f.type.cols, 1, 4);
    TypeDesc t = f.type;
    t.arrayDims.clear();
    return "(" + hlslTypeName(t) + ")(" + expr + kSwizzle[n] + ")";
}

// The statement that stores `source` (a float4) into a field: the whole lvalue, or each row's element of
// a matrix column.
std::string assignField(const Field& f, const std::string& source) {
    if (f.column < 0) return "    " + f.lvalue + " = " + narrowTo(f, source) + ";\n";
    std::string body;
    static const char kComponents[] = "xyzw";
    for (int r = 0; r < std::clamp(f.type.cols, 1, 4); ++r)
        body += "    " + f.lvalue + "[" + std::to_string(r) + "][" + std::to_string(f.column) + "] = (" +
                source + ")." + kComponents[r] + ";\n";
    return body;
}

// "float4(v, 0, 1)": a varying of n components read as the float4 the field assignments take.
std::string widenToFloat4(const std::string& name, int components) {
    switch (components) {
        case 1:
            return "float4(" + name + ", 0, 0, 1)";
        case 2:
            return "float4(" + name + ", 0, 1)";
        case 3:
            return "float4(" + name + ", 1)";
        default:
            return name;
    }
}

bool WrapperBuilder::everyArgumentTaken(size_t uniformCount) {
    if (uniformCount >= mCompile.args.size()) return true;
    return fail(DiagId::CompileTooManyArguments, mCompile.loc,
                {mFn.name, std::to_string(uniformCount), std::to_string(mCompile.args.size())});
}

bool WrapperBuilder::uniformArgument(const FunctionParam& p, size_t argIndex, std::string& value,
                                     std::string& globals) {
    const Expr* expr = nullptr;
    if (argIndex < mCompile.args.size())
        expr = &mCompile.args[argIndex];
    else if (p.defaultValue)
        expr = &*p.defaultValue;
    else
        return fail(DiagId::CompileArgumentMissing, mCompile.loc, {p.name, mFn.name});
    if (p.type.isSampler() || p.type.isTexture()) {
        const Parameter* s =
            expr->kind == Expr::Kind::Identifier ? mEffect.findParameter(expr->text) : nullptr;
        const bool fits =
            s && (p.type.isTexture() ? s->type.isTexture()
                  : p.type.base == BaseType::SamplerState || p.type.base == BaseType::SamplerComparisonState
                      ? s->type.base == p.type.base
                      : isSamplerType(s->type));
        if (!fits)
            return fail(p.type.isTexture() ? DiagId::CompileTextureArgumentNotTexture
                                           : DiagId::CompileSamplerArgumentNotSampler,
                        expr->loc, {p.name});
        value = s->name;
        return true;
    }
    if (!isNumericType(p.type))
        return fail(DiagId::CompileUniformTypeUnsupported, expr->loc, {p.name, hlslTypeName(p.type)});
    if (isLiteralOnly(*expr)) {
        // Folded, so that `if (PCF)` on a literal argument compiles away as in fxc.
        auto v = evaluate(*expr, nullptr, &p.type, &mDiagnostics);
        if (!v) return false;
        value = literalText(*v, p.type);
        return true;
    }
    // The runtime evaluates this expression at every draw: a name that is no effect parameter would only
    // fail there, once per frame, so report it here (NULL and true/false are the only bare words allowed).
    std::function<const Expr*(const Expr&)> unknownName = [&](const Expr& e) -> const Expr* {
        if (e.kind == Expr::Kind::Identifier && e.text != "true" && e.text != "false" && e.text != "NULL" &&
            !mEffect.findParameter(e.text))
            return &e;
        for (const Expr& a : e.args)
            if (const Expr* found = unknownName(a)) return found;
        return nullptr;
    };
    if (const Expr* unknown = unknownName(*expr))
        return fail(DiagId::UnknownIdentifier, unknown->loc, {unknown->text});
    std::string name = "fx_arg" + std::to_string(mArguments.size());
    mArguments.push_back(LoweredArgument{*expr, p.type, name});
    globals += hlslUniformTypeName(p.type) + " " + name + arraySuffix(p.type) + ";\n";
    value = name;
    return true;
}

namespace {

// The attribute location feeding a vertex input: D3D9's names exactly, D3D10's free input-layout names by
// their prefix; nullopt where the input reads a constant (D3D9 names no mesh supplies, unknown names).
std::optional<int> vertexInputAttribute(const std::string& semantic) {
    if (const std::optional<int> location = vertexInputLocation(semantic)) return location;
    if (vertexInputDefault(semantic)) return std::nullopt;
    return vertexStreamByName(semantic);
}

// What an input of a name no stream fits reads: 0, (0,0,0,1) for a position-like float4 (a w of 0 would
// put it at infinity), and the identity's column for a matrix (a per-instance transform, which the
// object's World already carries here).
// Row or column k of the identity matrix: "float4(0, 1, 0, 0)" for k = 1.
std::string identityVector(int k) {
    std::string v = "float4(";
    for (int i = 0; i < 4; ++i) v += std::string(i ? ", " : "") + (i == k ? "1" : "0");
    return v + ")";
}

std::string unmatchedVertexInput(const Field& f) {
    if (f.column >= 0) return identityVector(f.column);
    if (f.type.cols == 4 && f.semantic.find("POS") != std::string::npos) return "float4(0, 0, 0, 1)";
    return "float4(0, 0, 0, 0)";
}

}  // namespace

// A matrix-typed vertex input is a per-instance transform (XNA's `float4x4 instanceTransform :
// BLENDWEIGHT` or `: TEXCOORD1`, the SDK's `mTransform`): its columns take consecutive semantic indices, of
// which the meshes here hold one at most, so it reads the identity whatever its names. Inputs captured by
// stream output are the capture's.
bool WrapperBuilder::readsIdentity(const Field& f) const {
    return f.column >= 0 && !mStreamOut.capturedInputs;
}

int WrapperBuilder::instanceRow(const Field& f) const {
    if (f.column >= 0 || mStreamOut.capturedInputs) return -1;
    const auto row = mInstanceRows.find(f.lvalue);
    return row == mInstanceRows.end() ? -1 : row->second;
}

std::optional<int> WrapperBuilder::inputAttribute(const std::string& semantic) const {
    if (!mStreamOut.capturedInputs) return vertexInputAttribute(semantic);
    const std::vector<std::string>& captured = *mStreamOut.capturedInputs;
    const auto [name, index] = splitSemantic(semantic);
    const auto found = std::find(captured.begin(), captured.end(), name + std::to_string(index));
    if (found == captured.end()) return std::nullopt;
    return static_cast<int>(found - captured.begin());
}

bool WrapperBuilder::vertexInputs(const std::vector<Field>& fields, std::string& params, std::string& body) {
    // One attribute per location, as wide as its widest use. GL takes no bool attributes, and the runtime
    // feeds every stream as floats, so integer and bool inputs read a float attribute converted.
    std::map<int, TypeDesc> attributes;
    std::set<std::string> systemValues;
    for (const Field& f : fields) {
        if (f.semantic == "SV_VERTEXID" || f.semantic == "SV_INSTANCEID") {
            systemValues.insert(f.semantic);
            continue;
        }
        if (readsIdentity(f) || instanceRow(f) >= 0) continue;
        const std::optional<int> location = inputAttribute(f.semantic);
        if (!location) continue;
        if (!f.type.arrayDims.empty()) return fail(DiagId::VertexInputNestedTooDeeply, f.loc, {f.semantic});
        TypeDesc t = f.type;
        t.base = BaseType::Float;
        auto [it, inserted] = attributes.try_emplace(*location, t);
        if (!inserted && t.cols > it->second.cols) it->second = t;
    }
    for (auto& [location, type] : attributes) {
        TypeDesc t = type;
        t.shape = t.cols == 1 ? Shape::Scalar : Shape::Vector;
        if (!params.empty()) params += ",\n    ";
        params += "[[vk::location(" + std::to_string(location) + ")]] " + hlslTypeName(t) + " fx_in" +
                  std::to_string(location) + " : FX_IN" + std::to_string(location);
    }
    for (const std::string& s : systemValues) {
        if (!params.empty()) params += ",\n    ";
        params +=
            s == "SV_VERTEXID" ? "uint fx_vertexId : SV_VertexID" : "uint fx_instanceId : SV_InstanceID";
    }
    for (const Field& f : fields) {
        if (f.semantic == "SV_VERTEXID" || f.semantic == "SV_INSTANCEID") {
            const std::string id = f.semantic == "SV_VERTEXID" ? "fx_vertexId" : "fx_instanceId";
            body += "    " + f.lvalue + " = " + narrowTo(f, "uint4(" + id + ", 0, 0, 0)") + ";\n";
            continue;
        }
        if (readsIdentity(f)) {
            if (f.column == 0) mDiagnostics.report(DiagId::VertexInputMatrixIdentity, f.loc, {f.semantic});
            body += assignField(f, unmatchedVertexInput(f));
            continue;
        }
        if (const int row = instanceRow(f); row >= 0) {
            const std::string identityRow = identityVector(row);
            mDiagnostics.report(DiagId::VertexInputInstanceRow, f.loc,
                                {f.semantic, std::to_string(row), identityRow});
            body += assignField(f, identityRow);
            continue;
        }
        const std::optional<int> location = inputAttribute(f.semantic);
        if (!location) {
            if (std::optional<std::string> d3d9 = vertexInputDefault(f.semantic)) {
                body += assignField(f, *d3d9);
                continue;
            }
            const std::string constant = unmatchedVertexInput(f);
            if (f.column <= 0)  // a matrix once, not per column
                mDiagnostics.report(DiagId::VertexInputConstant, f.loc,
                                    {f.semantic, f.column == 0 ? "identity matrix" : constant});
            body += assignField(f, constant);
            continue;
        }
        std::string src = "fx_in" + std::to_string(*location);
        if (f.column >= 0) {
            body += assignField(f, src);  // the attribute is as wide as the column
            continue;
        }
        static const char* kSwizzle[] = {"", ".x", ".xy", ".xyz", ""};
        if (f.type.cols < attributes[*location].cols) src += kSwizzle[std::clamp(f.type.cols, 1, 4)];
        TypeDesc t = f.type;
        t.arrayDims.clear();
        body += "    " + f.lvalue + " = (" + hlslTypeName(t) + ")(" + src + ");\n";
    }
    return true;
}

bool WrapperBuilder::pixelInputs(const std::vector<Field>& fields, std::string& params, std::string& body) {
    // The integer system values a pixel shader reads, by canonical semantic: the wrapper's parameter and
    // its HLSL spelling (GL's gl_PrimitiveID, gl_SampleID, gl_Layer and gl_ViewportIndex).
    static const std::map<std::string, std::pair<std::string, std::string>> kPixelSystemValues = {
        {"SV_PRIMITIVEID", {"fx_primitiveId", "SV_PrimitiveID"}},
        {"SV_SAMPLEINDEX", {"fx_sampleIndex", "SV_SampleIndex"}},
        {"SV_RENDERTARGETARRAYINDEX", {"fx_layer", "SV_RenderTargetArrayIndex"}},
        {"SV_VIEWPORTARRAYINDEX", {"fx_viewportIndex", "SV_ViewportArrayIndex"}}};
    std::set<std::string> systemValues;
    std::vector<std::string> systemParams;
    std::set<int> varyings;
    std::map<int, std::string> interpolation;
    bool fragCoord = false, frontFace = false;
    for (const Field& f : fields) {
        const std::string& s = f.semantic;
        if (s == "VPOS0" || s == "VPOS") {
            // D3D9 VPOS is the pixel's integer top-left corner; SV_Position is its centre.
            fragCoord = true;
            int n = fieldComponents(f);
            std::string v = n == 1   ? "floor(fx_fragCoord.x)"
                            : n == 2 ? "floor(fx_fragCoord.xy)"
                                     : "float" + std::to_string(n) + "(floor(fx_fragCoord.xy)" +
                                           (n == 3 ? ", 0)" : ", 0, 1)");
            body += "    " + f.lvalue + " = " + v + ";\n";
        } else if (s == "POSITION0" || s == "SV_POSITION") {
            // ps_2_0 effects often reuse the vertex output struct; its POSITION reads the fragment position.
            fragCoord = true;
            body += "    " + f.lvalue + " = " + narrowTo(f, "fx_fragCoord") + ";\n";
        } else if (s == "VFACE" || s == "SV_ISFRONTFACE") {
            frontFace = true;
            body += "    " + f.lvalue + " = " +
                    (s == "VFACE" ? "(fx_frontFace ? 1.0 : -1.0)" : "fx_frontFace") + ";\n";
        } else if (s.rfind("PSIZE", 0) == 0) {
            // The point size goes to the rasterizer, not to the pixel stage: a pixel shader that reuses the
            // vertex output struct (XNA's particle effects) reads 0 there, D3D9's value for an input that no
            // earlier stage writes.
            body += assignField(f, "float4(0, 0, 0, 0)");
        } else if (const auto value = kPixelSystemValues.find(s); value != kPixelSystemValues.end()) {
            const auto& [name, spelling] = value->second;
            if (systemValues.insert(name).second) systemParams.push_back("uint " + name + " : " + spelling);
            body += "    " + f.lvalue + " = " + narrowTo(f, "uint4(" + name + ", 0, 0, 0)") + ";\n";
        } else if (auto location =
                       varyingLocation(s) ? varyingLocation(s) : customVaryingLocation(mEffect, s)) {
            std::string source = "fx_v" + std::to_string(*location);
            if (mPreviousOutputs) {
                auto written = mPreviousOutputs->find(*location);
                if (written == mPreviousOutputs->end()) {
                    // D3D9 and D3D10 link by register: an input the stage before does not write reads 0,
                    // where GL refuses to link the program.
                    body += assignField(f, "float4(0, 0, 0, 0)");
                    continue;
                }
                source = widenToFloat4(source, written->second.cols);
            }
            varyings.insert(*location);
            // An instance ID an earlier stage wrote is an integer: flat, as D3D10 passes integers.
            const bool instance = s == "SV_INSTANCEID" && f.interpolation.empty();
            if (!f.interpolation.empty() || instance)
                interpolation[*location] = instance ? "nointerpolation" : f.interpolation;
            body += assignField(f, source);
        } else {
            return fail(DiagId::PixelInputSemanticUnsupported, f.loc, {f.semantic});
        }
    }
    auto add = [&](const std::string& p) { params += (params.empty() ? "" : ",\n    ") + p; };
    // Varyings are float4 in both stages so that they link whatever width each stage declares; after a
    // geometry shader, they take the types its output struct declares.
    for (int location : varyings) {
        std::string interp = interpolation.count(location) ? interpolation[location] + " " : "";
        const std::string type =
            mPreviousOutputs ? hlslTypeName(mPreviousOutputs->at(location)) : std::string("float4");
        add("[[vk::location(" + std::to_string(location) + ")]] " + interp + type + " fx_v" +
            std::to_string(location) + " : FX_V" + std::to_string(location));
    }
    if (fragCoord) add("float4 fx_fragCoord : SV_Position");
    if (frontFace) add("bool fx_frontFace : SV_IsFrontFace");
    for (const std::string& p : systemParams) add(p);
    return true;
}

bool WrapperBuilder::vertexOutputs(const std::vector<Field>& fields, std::string& members,
                                   std::string& body) {
    bool position = false;
    std::set<int> used;
    const auto varying = [&](int location, const Field& f) {
        if (!used.insert(location).second) return;
        std::string name = "fx_v" + std::to_string(location);
        if (mStreamOut.captureOnly) {
            // Captured and never linked to a later stage: the output keeps its declared type, so that
            // transform feedback captures as many components as the declaration names.
            TypeDesc t = f.type;
            t.arrayDims.clear();
            const bool integer = t.base != BaseType::Float && t.base != BaseType::Half;
            mVaryingOutputs[location] = t;
            members += "    [[vk::location(" + std::to_string(location) + ")]] " +
                       (integer ? "nointerpolation " : "") + hlslTypeName(t) + " " + name + " : FX_V" +
                       std::to_string(location) + ";\n";
            body += "    fx_out." + name + " = " + fieldValue(f) + ";\n";
            return;
        }
        mVaryingOutputs[location] = float4Type();
        members += "    [[vk::location(" + std::to_string(location) + ")]] float4 " + name + " : FX_V" +
                   std::to_string(location) + ";\n";
        int n = std::clamp(f.type.cols, 1, 4);
        std::string v = "(float" + (n == 1 ? std::string() : std::to_string(n)) + ")(" + fieldValue(f) + ")";
        body += "    fx_out." + name + " = " +
                (n == 4 ? v
                        : "float4(" + v +
                              (n == 1   ? ", 0, 0, 1)"
                               : n == 2 ? ", 0, 1)"
                                        : ", 1)")) +
                ";\n";
    };
    for (const Field& f : fields) {
        const std::string& s = f.semantic;
        if (s == "POSITION0" || s == "SV_POSITION") {
            if (position) continue;
            position = true;
            members += "    float4 fx_position : SV_Position;\n";
            // A hull shader's control points often carry a float3 POSITION.
            body +=
                "    fx_out.fx_position = " + widenToFloat4(f.lvalue, std::clamp(f.type.cols, 1, 4)) + ";\n";
        } else if (s.rfind("PSIZE", 0) == 0) {
            // PSIZE0 is gl_PointSize (glslang reads no PSIZE semantic, but takes SPIR-V's builtin by name);
            // the runtime enables GL_PROGRAM_POINT_SIZE for a program that writes it (GpuProgram::bind).
            // PSIZE1..: D3D9 had one point size.
            if (s == "PSIZE0" && used.insert(2000).second) {
                members += "    [[vk::builtin(\"PointSize\")]] float fx_psize : PSIZE;\n";
                body += "    fx_out.fx_psize = " + fieldValue(f) +
                        (f.type.cols > 1 || f.type.rows > 1 ? ".x" : "") + ";\n";
            }
            // A geometry shader that reads it takes it as user data (SM4), through a varying.
            if (const std::optional<int> location = customVaryingLocation(mEffect, s)) varying(*location, f);
        } else if (s.rfind("SV_CLIPDISTANCE", 0) == 0 || s.rfind("SV_CULLDISTANCE", 0) == 0) {
            // gl_ClipDistance / gl_CullDistance; the runtime enables the clip planes the program writes.
            const bool clip = s[3] == 'C' && s[4] == 'L';
            const std::string index = s.substr(15).empty() ? "0" : s.substr(15);
            const std::string name = std::string(clip ? "fx_clip" : "fx_cull") + index;
            if (!used.insert(1000 + (clip ? 0 : 100) + splitSemantic(s).second).second) continue;
            TypeDesc t = f.type;
            t.arrayDims.clear();
            members += "    " + hlslTypeName(t) + " " + name +
                       (clip ? " : SV_ClipDistance" : " : SV_CullDistance") + index + ";\n";
            body += "    fx_out." + name + " = " + fieldValue(f) + ";\n";
        } else if (auto location =
                       varyingLocation(s) ? varyingLocation(s) : customVaryingLocation(mEffect, s)) {
            varying(*location, f);
        } else {
            return fail(DiagId::VertexOutputSemanticUnsupported, f.loc, {s});
        }
    }
    return true;
}

bool WrapperBuilder::pixelOutputs(const std::vector<Field>& fields, std::string& members, std::string& body) {
    std::set<std::string> used;
    for (const Field& f : fields) {
        auto [name, index] = splitSemantic(f.semantic);
        if (name == "COLOR" || name == "SV_TARGET") {
            if (!used.insert("c" + std::to_string(index)).second) continue;
            TypeDesc t = f.type;
            t.arrayDims.clear();
            members += "    " + hlslTypeName(t) + " fx_c" + std::to_string(index) + " : SV_Target" +
                       std::to_string(index) + ";\n";
            body += "    fx_out.fx_c" + std::to_string(index) + " = " + f.lvalue + ";\n";
        } else if (name == "DEPTH" || name == "SV_DEPTH") {
            if (!used.insert("depth").second) continue;
            members += "    float fx_depth : SV_Depth;\n";
            body += "    fx_out.fx_depth = (float)(" + f.lvalue + ");\n";
        } else {
            return fail(DiagId::PixelOutputSemanticUnsupported, f.loc, {f.semantic});
        }
    }
    return true;
}

bool WrapperBuilder::build(std::string& globals, std::string& wrapper) {
    if (mStage == ShaderStage::Geometry) return buildGeometry(globals, wrapper);
    if (mStage == ShaderStage::Hull) return buildHull(globals, wrapper);
    if (mStage == ShaderStage::Domain) return buildDomain(globals, wrapper);
    if (mStage == ShaderStage::Compute) return buildCompute(globals, wrapper);
    std::vector<Field> inputs, outputs;
    std::string locals, call, callArgs;
    size_t uniformIndex = 0;
    for (size_t i = 0; i < mFn.params.size(); ++i) {
        const FunctionParam& p = mFn.params[i];
        std::string arg;
        if (p.isUniform) {
            if (!uniformArgument(p, uniformIndex++, arg, globals)) return false;
        } else {
            arg = "fx_p" + std::to_string(i);
            TypeDesc t = p.type;
            std::string dims = arraySuffix(t);
            t.arrayDims.clear();
            if (p.type.arrayDims.empty()) {
                locals += "    " + hlslTypeName(t) + " " + arg + " = (" + hlslTypeName(t) + ")0;\n";
            } else {
                // glslang casts no scalar to an array (`(float2[5])0`, an array-typed input such as
                // `float2 JitterUV[5] : TEXCOORD1`): each element is zeroed on its own.
                locals += "    " + hlslTypeName(t) + " " + arg + dims + ";\n";
                for (int e = 0; p.type.arrayDims.size() == 1 && e < p.type.arrayDims.front(); ++e)
                    locals += "    " + arg + "[" + std::to_string(e) + "] = (" + hlslTypeName(t) + ")0;\n";
            }
            if (p.direction != FunctionParam::Direction::Out)
                gatherFields(mEffect, p.type, p.semantic, p.interpolation, arg, p.loc, inputs);
            if (p.direction != FunctionParam::Direction::In)
                gatherFields(mEffect, p.type, p.semantic, p.interpolation, arg, p.loc, outputs);
        }
        callArgs += (i ? ", " : "") + arg;
    }
    if (!everyArgumentTaken(uniformIndex)) return false;
    bool hasReturn = mFn.returnType.base != BaseType::Void;
    if (hasReturn) {
        TypeDesc t = mFn.returnType;
        locals += "    " + hlslTypeName(t) + " fx_r;\n";
        call = "    fx_r = " + mFn.name + "(" + callArgs + ");\n";
        gatherFields(mEffect, t, mFn.returnSemantic, "", "fx_r", mFn.loc, outputs);
    } else {
        call = "    " + mFn.name + "(" + callArgs + ");\n";
    }
    std::string params, inputBody, members, outputBody;
    bool vertex = mStage == ShaderStage::Vertex;
    if (vertex) {
        for (const auto& [path, row] : detail::instanceTransformRows(mEffect, mFn)) {
            const size_t dot = path.find('.');
            const std::string base = path.substr(0, dot);
            for (size_t i = 0; i < mFn.params.size(); ++i)
                if (mFn.params[i].name == base)
                    mInstanceRows["fx_p" + std::to_string(i) +
                                  (dot == std::string::npos ? "" : path.substr(dot))] = row;
        }
    }
    if (!(vertex ? vertexInputs(inputs, params, inputBody) : pixelInputs(inputs, params, inputBody)))
        return false;
    if (!(vertex ? vertexOutputs(outputs, members, outputBody) : pixelOutputs(outputs, members, outputBody)))
        return false;
    std::string outStruct = vertex ? "fx_VsOutput" : "fx_PsOutput";
    if (members.empty())
        members = vertex ? "    float4 fx_position : SV_Position;\n" : "    float4 fx_c0 : SV_Target0;\n";
    wrapper += "struct " + outStruct + " {\n" + members + "};\n";
    wrapper += outStruct + " " + std::string(kWrapperEntryPoint) + "(" +
               (params.empty() ? "" : "\n    " + params) + ")\n{\n";
    wrapper += "    " + outStruct + " fx_out = (" + outStruct + ")0;\n";
    wrapper += locals + inputBody + call + outputBody + "    return fx_out;\n}\n";
    return true;
}

}  // namespace fx
