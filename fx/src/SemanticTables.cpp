// SemanticTables: see SemanticTables.h.
#include "SemanticTables.h"
#include "CaseFolding.h"
#include "SemanticIndex.h"

#include <fx/RenderStates.h>

#include <algorithm>
#include <cctype>
#include <iterator>
#include <set>

namespace fx {

std::pair<std::string, int> splitSemantic(const std::string& canonical) {
    return splitSemanticIndex(canonical);
}

std::string canonicalSemantic(const std::string& semantic) {
    std::string s = upperCase(semantic);
    // D3D9's `TEXCOORD0_centroid` modifier: the interpolation is taken in gatherFields().
    if (s.size() > 9 && s.compare(s.size() - 9, 9, "_CENTROID") == 0) s.resize(s.size() - 9);
    // Indexed semantics get their index spelled out so that TEXCOORD and TEXCOORD0 are one key.
    static const char* kIndexed[] = {"TEXCOORD", "COLOR",       "NORMAL",       "TANGENT",
                                     "BINORMAL", "BLENDWEIGHT", "BLENDINDICES", "POSITION",
                                     "PSIZE",    "FOG",         "DEPTH",        "SV_TARGET"};
    for (const char* name : kIndexed)
        if (s == name) return s + "0";
    // fxc reads a system value with index 0 as the system value (`SV_Position0`, `SV_Depth0`,
    // `SV_IsFrontFace0`); only SV_Target and the clip and cull distances are indexed.
    if (s.size() > 4 && s.rfind("SV_", 0) == 0 && s.back() == '0' &&
        !std::isdigit(static_cast<unsigned char>(s[s.size() - 2])) && s.rfind("SV_TARGET", 0) != 0 &&
        s.rfind("SV_CLIPDISTANCE", 0) != 0 && s.rfind("SV_CULLDISTANCE", 0) != 0)
        s.pop_back();
    return s;
}

// Vertex inputs D3D9 declared that no mesh here supplies (a second tangent frame, more blend weights,
// point size, fog): they read a constant, as an unbound D3D9 stream reads its default.
std::optional<std::string> vertexInputDefault(const std::string& semantic) {
    auto [name, index] = splitSemantic(canonicalSemantic(semantic));
    if (name == "PSIZE") return "float4(1, 1, 1, 1)";
    if (name == "FOG" || name == "TESSFACTOR" || name == "DEPTH" || name == "SAMPLE")
        return "float4(0, 0, 0, 0)";
    for (const char* known : {"POSITION", "NORMAL", "TEXCOORD", "COLOR", "TANGENT", "BINORMAL", "BLENDWEIGHT",
                              "BLENDINDICES", "POSITIONT"})
        if (name == known && index < 16) return name == "COLOR" ? "float4(1, 1, 1, 1)" : "float4(0, 0, 0, 1)";
    return std::nullopt;
}

std::optional<int> varyingLocation(const std::string& semantic) {
    auto [name, index] = splitSemantic(canonicalSemantic(semantic));
    if (name == "TEXCOORD" && index < 8) return index;
    if (name == "COLOR" && index < 2) return 8 + index;
    if (name == "NORMAL" && index == 0) return 10;
    if (name == "TANGENT" && index == 0) return 11;
    if (name == "BINORMAL" && index == 0) return 12;
    if (name == "FOG" && index == 0) return 13;
    // vs_3_0 has ten texture-coordinate outputs; matrix varyings spill into the indices above them.
    if (name == "TEXCOORD" && index < 16) return 14 + index - 8;
    if (name == "COLOR" && index < 4) return 22 + index - 2;
    return std::nullopt;
}

namespace {

// The functions a pass or a shader variable compiles: as vertex shaders, and as any other stage.
struct Entries {
    std::set<std::string> vertex, other;
};

void collectEntries(const Expr& e, Entries& entries) {
    if (e.kind == Expr::Kind::Compile)
        (upperCase(e.profile).rfind("VS_", 0) == 0 ? entries.vertex : entries.other).insert(e.text);
    for (const Expr& a : e.args) collectEntries(a, entries);
}

// The structs that only ever stand as a vertex shader's input (or a helper function's input, where
// semantics mean nothing): a return type, an output, another stage's input or a member makes a struct's
// semantics varyings as well.
std::set<std::string> vertexInputOnlyStructs(const Effect& effect, const Entries& entries) {
    std::set<std::string> inputs, elsewhere;
    for (const StructDecl& s : effect.structs)
        for (const StructMember& m : s.members)
            if (m.type.base == BaseType::Struct) elsewhere.insert(m.type.structName);
    for (const FunctionDecl& f : effect.functions) {
        if (f.returnType.base == BaseType::Struct) elsewhere.insert(f.returnType.structName);
        for (const FunctionParam& p : f.params) {
            if (p.type.base != BaseType::Struct) continue;
            if (p.direction != FunctionParam::Direction::In || entries.other.count(f.name))
                elsewhere.insert(p.type.structName);
            else if (entries.vertex.count(f.name))
                inputs.insert(p.type.structName);
        }
    }
    std::set<std::string> only;
    std::set_difference(inputs.begin(), inputs.end(), elsewhere.begin(), elsewhere.end(),
                        std::inserter(only, only.end()));
    return only;
}

}  // namespace

// D3D10 lets a varying carry any semantic name ("WORLDPOS", "LIGHTDIR", the SDK's "TEXTURE0".."TEXTURE8").
// Such names get the locations above the D3D9 table's (24..31), then the table's locations no semantic of
// the effect uses, in the order of their sorted names over the whole effect, so that every stage of every
// pass agrees. An array or a matrix takes one name per element (`Points[16] : POINTS` is POINTS0..15).
// A vertex shader's inputs are attributes, not varyings: a name that only ever stands there takes none.
namespace {

Entries effectEntries(const Effect& effect) {
    Entries entries;
    for (const Parameter& p : effect.parameters)
        if (p.initializer) collectEntries(*p.initializer, entries);
    for (const Technique& t : effect.techniques)
        for (const Pass& pass : t.passes)
            for (const StateAssignment& state : pass.states) collectEntries(state.value, entries);
    return entries;
}

}  // namespace

std::set<std::string> vertexInputStructs(const Effect& effect) {
    const Entries entries = effectEntries(effect);
    std::set<std::string> inputs;
    for (const FunctionDecl& f : effect.functions)
        for (const FunctionParam& p : f.params)
            if (p.type.base == BaseType::Struct && p.direction == FunctionParam::Direction::In &&
                entries.vertex.count(f.name))
                inputs.insert(p.type.structName);
    return inputs;
}

std::optional<int> customVaryingLocation(const Effect& effect, const std::string& semantic) {
    const Entries entries = effectEntries(effect);
    const std::set<std::string> inputStructs = vertexInputOnlyStructs(effect, entries);
    // SM4's PSIZE is user data between a vertex and a geometry shader (point-sprite particles carry each
    // sprite's size to the geometry shader that expands it): a geometry shader's input names it a varying.
    std::set<std::string> geometryInputStructs;
    for (const FunctionDecl& f : effect.functions)
        for (const FunctionParam& p : f.params)
            if (!p.primitive.empty() && p.type.base == BaseType::Struct)
                geometryInputStructs.insert(p.type.structName);
    std::set<std::string> names;
    std::set<int> tableUsed;
    auto add = [&](const std::string& s, const TypeDesc& type, bool vertexInput, bool geometryInput) {
        const std::string c = canonicalSemantic(s);
        // A matrix or an array takes consecutive indices (gatherFields): every one of them is used.
        int span = type.shape == Shape::Matrix ? std::max(type.cols, 1) : 1;
        for (int d : type.arrayDims) span *= std::clamp(d, 1, 32);
        span = std::min(span, 32);
        const auto [name, first] = splitSemantic(c);
        for (int k = 0; k < span; ++k)
            if (const std::optional<int> location = varyingLocation(name + std::to_string(first + k)))
                tableUsed.insert(*location);
        // SV_InstanceID a vertex shader writes is user data to the stages after it, as in D3D10 (a
        // vertex input SV_InstanceID stays the draw's instance, gl_InstanceID).
        if (vertexInput || c.empty() || (c.rfind("SV_", 0) == 0 && c != "SV_INSTANCEID") ||
            c == "POSITION0" || c == "VPOS" || c == "VPOS0" || c == "VFACE" ||
            (c.rfind("PSIZE", 0) == 0 && !geometryInput) || c.rfind("DEPTH", 0) == 0)
            return;
        // Each element the table has no location for is free-named: `float3x3 Tangent : TANGENT0` is
        // TANGENT0 (the table's) and TANGENT1..2, and a vertex-input name written as an output
        // (`BLENDWEIGHT0`) is a varying like any other.
        for (int k = 0; k < span; ++k)
            if (!varyingLocation(name + std::to_string(first + k)))
                names.insert(name + std::to_string(first + k));
    };
    for (const StructDecl& s : effect.structs)
        for (const StructMember& m : s.members)
            add(m.semantic, m.type, inputStructs.count(s.name) > 0, geometryInputStructs.count(s.name) > 0);
    for (const FunctionDecl& f : effect.functions) {
        add(f.returnSemantic, f.returnType, false, false);
        for (const FunctionParam& p : f.params)
            add(p.semantic, p.type,
                entries.vertex.count(f.name) && !entries.other.count(f.name) &&
                    p.direction == FunctionParam::Direction::In,
                !p.primitive.empty());
    }
    const std::string key = splitSemantic(canonicalSemantic(semantic)).first +
                            std::to_string(splitSemantic(canonicalSemantic(semantic)).second);
    auto it = names.find(key);
    if (it == names.end()) return std::nullopt;
    const int index = static_cast<int>(std::distance(names.begin(), it));
    if (index < 8) return 24 + index;
    int free = index - 8;
    for (int location = 0; location < 24; ++location)
        if (!tableUsed.count(location) && free-- == 0) return location;
    return std::nullopt;
}

}  // namespace fx
