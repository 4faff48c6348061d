// InstancedPass: see InstancedPass.h.
//
// Why the GLSL and not the HLSL unit: which members are per object is the runtime's knowledge (its
// semantics and which parameters the application pinned), known after the effect compiled. Rewriting the
// HLSL would compile every batched pass a second time through glslang and SPIRV-Cross (worker processes,
// compile cache keys, a second set of reflection); the GLSL SPIRV-Cross writes names every block member
// one way (`<block>_.<member>`) and declares each on a line of its own, so the variant is a textual
// substitution over text the compiler itself produced, made in microseconds when a pass is first batched.
#include <fx/InstancedPass.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <utility>

namespace fx {

namespace {

bool isIdentChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// One member declaration of a uniform block as SPIRV-Cross writes it:
// "    layout(row_major) mat4 World;" or "    vec4 Rects[4];".
struct MemberDecl {
    std::string type;  // "mat4", "vec3", "uint"
    std::string dims;  // "[4]" or ""
};

std::map<std::string, MemberDecl> blockMembers(const std::string& glsl, const std::string& blockName) {
    std::map<std::string, MemberDecl> out;
    const std::string head = "uniform " + blockName + "\n{\n";
    size_t at = glsl.find(head);
    if (at == std::string::npos) return out;
    at += head.size();
    while (at < glsl.size() && glsl[at] != '}') {
        const size_t end = glsl.find('\n', at);
        if (end == std::string::npos) break;
        std::string line = glsl.substr(at, end - at);
        at = end + 1;
        size_t p = line.find_first_not_of(' ');
        if (p == std::string::npos) continue;
        if (line.compare(p, 7, "layout(") == 0) {
            p = line.find(')', p);
            if (p == std::string::npos) continue;
            p = line.find_first_not_of(' ', p + 1);
        }
        const size_t typeEnd = line.find(' ', p);
        if (typeEnd == std::string::npos) continue;
        const size_t nameEnd = line.find_first_of("[;", typeEnd + 1);
        if (nameEnd == std::string::npos) continue;
        const size_t semicolon = line.find(';', nameEnd);
        if (semicolon == std::string::npos) continue;
        out[line.substr(typeEnd + 1, nameEnd - typeEnd - 1)] =
            MemberDecl{line.substr(p, typeEnd - p), line.substr(nameEnd, semicolon - nameEnd)};
    }
    return out;
}

// std140 alignment and size of a GLSL type declared without a matrix layout qualifier (column major):
// false for types the record does not carry (doubles, structs).
bool std140Layout(const MemberDecl& decl, uint32_t& align, uint32_t& size, uint32_t& arrayStride) {
    const std::string& t = decl.type;
    uint32_t elementAlign = 0, elementSize = 0;
    if (t == "float" || t == "int" || t == "uint" || t == "bool") {
        elementAlign = elementSize = 4;
    } else if (t.size() == 4 && t.compare(0, 3, "vec") == 0 && t[3] >= '2' && t[3] <= '4') {
        const uint32_t n = static_cast<uint32_t>(t[3] - '0');
        elementAlign = n == 2 ? 8 : 16;
        elementSize = 4 * n;
    } else if (t.size() == 5 && (t[0] == 'i' || t[0] == 'u' || t[0] == 'b') && t.compare(1, 3, "vec") == 0 &&
               t[4] >= '2' && t[4] <= '4') {
        const uint32_t n = static_cast<uint32_t>(t[4] - '0');
        elementAlign = n == 2 ? 8 : 16;
        elementSize = 4 * n;
    } else if (t.compare(0, 3, "mat") == 0 && t.size() >= 4 && t[3] >= '2' && t[3] <= '4' &&
               (t.size() == 4 || (t.size() == 6 && t[4] == 'x' && t[5] >= '2' && t[5] <= '4'))) {
        elementAlign = 16;  // its columns, each rounded up to a vec4
        elementSize = 16 * static_cast<uint32_t>(t[3] - '0');
    } else {
        return false;
    }
    arrayStride = 0;
    uint32_t count = 1;
    for (size_t p = 0; p < decl.dims.size();) {
        if (decl.dims[p] != '[') return false;
        const size_t close = decl.dims.find(']', p);
        if (close == std::string::npos) return false;
        const std::string digits = decl.dims.substr(p + 1, close - p - 1);
        // Nine digits at most: a record far larger than any uniform block, and no overflow below.
        if (digits.empty() || digits.size() > 9 || !std::all_of(digits.begin(), digits.end(), ::isdigit))
            return false;
        count *= static_cast<uint32_t>(std::stoul(digits));
        if (count > (1u << 24)) return false;
        p = close + 1;
    }
    if (!decl.dims.empty()) {
        arrayStride = (elementSize + 15) / 16 * 16;
        align = 16;
        size = arrayStride * count;
    } else {
        align = elementAlign;
        size = elementSize;
    }
    return true;
}

// Replaces every `<instance>.<member>` whose member is in `names` by `fx_objects[fx_object].<member>`.
std::string redirectMembers(const std::string& glsl, const std::string& instance,
                            const std::map<std::string, bool>& names) {
    std::string out;
    const std::string prefix = instance + ".";
    size_t at = 0;
    while (true) {
        const size_t hit = glsl.find(prefix, at);
        if (hit == std::string::npos) break;
        size_t end = hit + prefix.size();
        while (end < glsl.size() && isIdentChar(glsl[end])) ++end;
        const std::string member = glsl.substr(hit + prefix.size(), end - hit - prefix.size());
        const bool standalone = hit == 0 || !isIdentChar(glsl[hit - 1]);
        out.append(glsl, at, hit - at);
        if (standalone && names.count(member))
            out += "fx_objects[fx_object]." + member;
        else
            out.append(glsl, hit, end - hit);
        at = end;
    }
    out.append(glsl, at, std::string::npos);
    return out;
}

// Where declarations can go: after #version and any #extension lines (GLSL wants those first).
size_t declarationPoint(const std::string& glsl) {
    size_t at = glsl.find("#version");
    if (at == std::string::npos) return std::string::npos;
    at = glsl.find('\n', at);
    if (at == std::string::npos) return std::string::npos;
    ++at;
    for (size_t ext = glsl.find("\n#extension", at - 1); ext != std::string::npos;
         ext = glsl.find("\n#extension", at - 1)) {
        const size_t end = glsl.find('\n', ext + 1);
        if (end == std::string::npos) return std::string::npos;
        at = end + 1;
    }
    return at;
}

}  // namespace

std::optional<InstancedPass> instancedPass(const CompiledPass& pass,
                                           const std::vector<bool>& perObjectParameter,
                                           const std::vector<bool>& perObjectArgument, std::string& whyNot) {
    if (pass.vertex.glsl.empty()) {
        whyNot = "the pass has no vertex shader";
        return std::nullopt;
    }
    // A geometry stage would need the object index passed through it and its own block's per-object
    // values from the records: not done, such passes draw object by object.
    if (!pass.geometry.glsl.empty()) {
        whyNot = "the pass has a geometry shader";
        return std::nullopt;
    }
    if (!pass.hull.glsl.empty()) {
        whyNot = "the pass has tessellation shaders";
        return std::nullopt;
    }
    const std::string varying = "layout(location = " + std::to_string(kObjectVaryingLocation) + ")";
    for (const StageProgram* stage : {&pass.vertex, &pass.fragment}) {
        // The effect's own instance ids would count this variant's instances; its own storage buffers
        // could take the bindings.
        for (const char* word : {"gl_InstanceID", "SPIRV_Cross_BaseInstance", "gl_BaseInstance", " buffer "})
            if (stage->glsl.find(word) != std::string::npos) {
                whyNot = std::string("the pass's GLSL uses '") + word + "'";
                return std::nullopt;
            }
        if (stage->glsl.find(varying) != std::string::npos) {
            whyNot = "varying location " + std::to_string(kObjectVaryingLocation) + " is taken";
            return std::nullopt;
        }
    }

    InstancedPass out;
    out.pass = pass;
    std::map<std::pair<int, size_t>, size_t> recordIndex;  // (source, index) -> out.record entry
    std::string recordFields;
    uint32_t cursor = 0;
    bool pixelReadsObject = false;
    std::map<std::string, bool> stageNames[2];
    StageProgram* stages[2] = {&out.pass.vertex, &out.pass.fragment};
    for (int s = 0; s < 2; ++s) {
        StageProgram& stage = *stages[s];
        if (stage.glsl.empty() || stage.uniformBlockName.empty()) continue;
        const std::map<std::string, MemberDecl> decls = blockMembers(stage.glsl, stage.uniformBlockName);
        for (UniformBinding& member : stage.uniforms) {
            if (!member.active) continue;
            const bool parameter = member.source == UniformBinding::Source::Parameter;
            const std::vector<bool>& flags = parameter ? perObjectParameter : perObjectArgument;
            if (member.index >= flags.size() || !flags[member.index]) continue;
            auto decl = decls.find(member.name);
            uint32_t align = 0, size = 0, arrayStride = 0;
            if (decl == decls.end() || !std140Layout(decl->second, align, size, arrayStride)) {
                whyNot =
                    "per-object member '" + member.name + "' has a type the object record does not carry";
                return std::nullopt;
            }
            member.active = false;  // packed into the object's record instead
            stageNames[s][member.name] = true;
            if (s == 1) pixelReadsObject = true;
            const std::pair<int, size_t> key{parameter ? 0 : 1, member.index};
            if (recordIndex.count(key)) {
                if (out.record[recordIndex[key]].name != member.name) {
                    whyNot = "per-object member '" + member.name + "' has another name in the other stage";
                    return std::nullopt;
                }
                continue;
            }
            UniformBinding field = member;
            field.active = true;
            field.offset = (cursor + align - 1) / align * align;
            field.size = size;
            field.arrayStride = arrayStride;
            if (field.type.shape == Shape::Matrix) {
                // Declared without row_major: each GLSL column (an HLSL row) is one vec4 slot.
                field.matrixStride = 16;
                field.hlslColumnsContiguous = false;
            }
            cursor = field.offset + size;
            recordIndex[key] = out.record.size();
            out.record.push_back(field);
            recordFields += "    " + decl->second.type + " " + member.name + decl->second.dims + ";\n";
        }
    }
    out.recordSize = (cursor + 15) / 16 * 16;

    const std::string objects =
        out.record.empty()
            ? std::string()
            : "struct fx_Object\n{\n" + recordFields +
                  "};\n\nlayout(binding = " + std::to_string(kObjectBufferBinding) +
                  ", std140) readonly buffer fx_ObjectBuffer\n{\n    fx_Object fx_objects[];\n};\n\n";
    // Vertex stage: the instance's object, for its own reads and (flat) for the pixel stage's.
    {
        StageProgram& vertex = out.pass.vertex;
        std::string glsl = redirectMembers(vertex.glsl, vertex.uniformBlockName + "_", stageNames[0]);
        const size_t declare = declarationPoint(glsl);
        const size_t main = glsl.find("void main()\n{\n");
        if (declare == std::string::npos || main == std::string::npos || main < declare) {
            whyNot = "the vertex GLSL has no main() where it was expected";
            return std::nullopt;
        }
        std::string entry = "    fx_object = fx_instances[gl_InstanceID];\n";
        if (pixelReadsObject) entry += "    fx_objectOut = fx_object;\n";
        glsl.insert(main + 14, entry);
        std::string declarations =
            objects + "layout(binding = " + std::to_string(kInstanceBufferBinding) +
            ", std430) readonly buffer fx_InstanceBuffer\n{\n    uint fx_instances[];\n};\n\n";
        if (pixelReadsObject) declarations += varying + " flat out uint fx_objectOut;\n";
        // main() assigns it first thing; the initializer keeps drivers from warning that the functions
        // above main() read it uninitialized (Mesa does).
        declarations += "uint fx_object = 0u;\n\n";
        glsl.insert(declare, declarations);
        vertex.glsl = std::move(glsl);
    }
    if (pixelReadsObject) {
        StageProgram& pixel = out.pass.fragment;
        std::string glsl = redirectMembers(pixel.glsl, pixel.uniformBlockName + "_", stageNames[1]);
        const size_t declare = declarationPoint(glsl);
        if (declare == std::string::npos) {
            whyNot = "the pixel GLSL has no #version line";
            return std::nullopt;
        }
        glsl.insert(declare, objects + varying + " flat in uint fx_object;\n\n");
        pixel.glsl = std::move(glsl);
    }
    return out;
}

}  // namespace fx
