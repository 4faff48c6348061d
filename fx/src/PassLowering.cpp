// PassLowering: AST + compile expression -> HLSL unit (see PassLowering.h).
//
// [SECTION] Semantic tables
// [SECTION] Types and literals
// [SECTION] Effect declarations (verbatim, behind #line)
// [SECTION] Depth-compare samplers
// [SECTION] Entry-point wrapper
// [SECTION] lowerStage()
#include "PassLowering.h"

#include <fx/Preshader.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <functional>
#include <iterator>
#include <map>
#include <set>

namespace fx {

namespace {

std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

bool isIdentChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// Splits "TEXCOORD3" into ("TEXCOORD", 3); no trailing digits -> index 0.
std::pair<std::string, int> splitSemantic(const std::string& canonical) {
    size_t end = canonical.size();
    while (end > 0 && std::isdigit(static_cast<unsigned char>(canonical[end - 1]))) --end;
    if (end == canonical.size()) return {canonical, 0};
    return {canonical.substr(0, end), std::stoi(canonical.substr(end))};
}

}  // namespace

// [SECTION] Semantic tables

std::string canonicalSemantic(const std::string& semantic) {
    std::string s = upper(semantic);
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

// D3D10 lets a varying carry any semantic name ("WORLDPOS", "LIGHTDIR", the SDK's "TEXTURE0".."TEXTURE8").
// Such names get the locations above the D3D9 table's (24..31), then the table's locations no semantic of
// the effect uses, in the order of their sorted names over the whole effect, so that every stage of every
// pass agrees. The names of vertex inputs count too (a struct may be both), which only costs locations.
static std::optional<int> customVaryingLocation(const Effect& effect, const std::string& semantic) {
    std::set<std::string> names;
    std::set<int> tableUsed;
    auto add = [&](const std::string& s, const TypeDesc& type) {
        const std::string c = canonicalSemantic(s);
        // A matrix or an array takes consecutive indices (gatherFields): every one of them is used.
        int span = type.shape == Shape::Matrix ? std::max(type.cols, 1) : 1;
        for (int d : type.arrayDims) span *= std::clamp(d, 1, 32);
        const auto [name, first] = splitSemantic(c);
        for (int k = 0; k < std::min(span, 32); ++k)
            if (const std::optional<int> location = varyingLocation(name + std::to_string(first + k)))
                tableUsed.insert(*location);
        if (!c.empty() && c.rfind("SV_", 0) != 0 && !varyingLocation(c) && c != "POSITION0" && c != "VPOS" &&
            c != "VPOS0" && c != "VFACE" && c.rfind("PSIZE", 0) != 0 && c.rfind("DEPTH", 0) != 0 &&
            !vertexInputLocation(c))
            names.insert(splitSemantic(c).first + std::to_string(splitSemantic(c).second));
    };
    for (const StructDecl& s : effect.structs)
        for (const StructMember& m : s.members) add(m.semantic, m.type);
    for (const FunctionDecl& f : effect.functions) {
        add(f.returnSemantic, f.returnType);
        for (const FunctionParam& p : f.params) add(p.semantic, p.type);
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

// [SECTION] Types and literals

std::string hlslTypeName(const TypeDesc& type) {
    // glslang needs concrete types where D3D9 allows untyped ones (`sampler`, `texture`); types with no
    // HLSL counterpart in a shader (strings, shader variables) never reach a unit and read as float.
    TypeDesc concrete = type;
    switch (type.base) {
        case BaseType::Sampler:
            concrete.base = BaseType::Sampler2D;
            break;
        case BaseType::Texture:
            concrete.base = BaseType::Texture2D;
            break;
        case BaseType::Void:
        case BaseType::String:
            concrete.base = BaseType::Float;
            break;
        default:
            if (type.isShader() || type.isStateObject()) concrete.base = BaseType::Float;
            break;
    }
    const bool rowMajor = type.shape == Shape::Matrix && type.rowMajor;
    return (rowMajor ? "row_major " : "") + concrete.hlslName();
}

namespace {

TypeDesc float4Type() {
    TypeDesc t;
    t.base = BaseType::Float;
    t.shape = Shape::Vector;
    t.cols = 4;
    return t;
}

bool isNumericType(const TypeDesc& t) {
    return t.base == BaseType::Bool || t.base == BaseType::Int || t.base == BaseType::UInt ||
           t.base == BaseType::Half || t.base == BaseType::Float || t.base == BaseType::Double;
}

bool isSamplerType(const TypeDesc& t) {
    return t.base == BaseType::Sampler || t.base == BaseType::Sampler1D || t.base == BaseType::Sampler2D ||
           t.base == BaseType::Sampler3D || t.base == BaseType::SamplerCube;
}

std::string arraySuffix(const TypeDesc& t) {
    std::string out;
    for (int d : t.arrayDims) out += "[" + std::to_string(d) + "]";
    return out;
}

std::string formatFloat(float x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(x));
    std::string s = buf;
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
    return s;
}

// HLSL literal for a host value of type `type` ("float3(1.0, 2.0, 3.0)", "true", "4").
std::string literalText(const Value& v, const TypeDesc& type) {
    auto component = [&](float x) -> std::string {
        if (type.base == BaseType::Bool) return x != 0.0f ? "true" : "false";
        if (type.base == BaseType::Int || type.base == BaseType::UInt)
            return std::to_string(static_cast<long long>(x));
        return formatFloat(x);
    };
    if (v.data.size() == 1 && type.shape == Shape::Scalar && type.arrayDims.empty())
        return component(v.data[0]);
    TypeDesc plain = type;
    plain.rowMajor = false;
    plain.arrayDims.clear();
    std::string out = hlslTypeName(plain) + "(";
    for (size_t i = 0; i < v.data.size(); ++i) out += (i ? ", " : "") + component(v.data[i]);
    return out + ")";
}

// An expression with no parameter references: it can be folded into the HLSL as a literal.
bool isLiteralOnly(const Expr& e) {
    if (e.kind == Expr::Kind::Identifier) return e.text == "true" || e.text == "false";
    if (e.kind == Expr::Kind::String || e.kind == Expr::Kind::TextureRef || e.kind == Expr::Kind::Compile)
        return false;
    for (const Expr& a : e.args)
        if (!isLiteralOnly(a)) return false;
    return true;
}

const Parameter* findParam(const Effect& effect, const std::string& name) {
    for (const Parameter& p : effect.parameters)
        if (p.name == name) return &p;
    return nullptr;
}

const StructDecl* findStructDecl(const Effect& effect, const std::string& name) {
    for (const StructDecl& s : effect.structs)
        if (s.name == name) return &s;
    return nullptr;
}

// Identifiers of HLSL text, skipping comments and string literals.
std::set<std::string> identifiersIn(const std::string& text) {
    std::set<std::string> out;
    for (size_t i = 0; i < text.size();) {
        char c = text[i];
        if (c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
            while (i < text.size() && text[i] != '\n') ++i;
        } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
            size_t end = text.find("*/", i + 2);
            i = end == std::string::npos ? text.size() : end + 2;
        } else if (c == '"') {
            ++i;
            while (i < text.size() && text[i] != '"') i += text[i] == '\\' ? 2 : 1;
            ++i;
        } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
            size_t start = i;
            while (i < text.size() && isIdentChar(text[i])) ++i;
            out.insert(text.substr(start, i - start));
        } else {
            ++i;
        }
    }
    return out;
}

}  // namespace

// [SECTION] Depth-compare samplers

const Parameter* samplerTexture(const Effect& effect, const Parameter& sampler) {
    for (const StateAssignment& s : sampler.samplerState) {
        if (upper(s.name) != "TEXTURE") continue;
        if (s.value.kind == Expr::Kind::TextureRef || s.value.kind == Expr::Kind::Identifier)
            return findParam(effect, s.value.text);
    }
    return nullptr;
}

bool isDepthCompareSampler(const Effect& effect, const Parameter& sampler) {
    const Parameter* texture = samplerTexture(effect, sampler);
    if (!texture) return false;
    if (upper(texture->semantic) == "RENDERDEPTHSTENCILTARGET") return true;
    if (const Annotation* format = texture->annotation("Format");
        format && format->value.kind == Expr::Kind::String) {
        auto f = parseTextureFormat(format->value.text);
        return f && isDepthFormat(*f);
    }
    return false;
}

namespace {

// glslang 12.0 decomposes HLSL's lit() with n.h * m where HLSL specifies pow(n.h, m) (its specular term
// then grows linearly with the exponent and saturates everything lit). Every unit gets a correct lit and
// calls of lit( are renamed to it by rewriteIntrinsics. HLSL: lit(n.l, n.h, m) = (1, max(n.l, 0),
// (n.l < 0 || n.h < 0) ? 0 : pow(n.h, m), 1).
constexpr const char* kLitReplacement =
    "float4 fx_lit(float n_dot_l, float n_dot_h, float m)\n"
    "{ return float4(1, max(n_dot_l, 0), (n_dot_l < 0 || n_dot_h < 0) ? 0 : pow(max(n_dot_h, 0), m), 1); }\n";

// Rewrites, token by token (comments untouched), the intrinsic calls glslang gets wrong or cannot express:
// `lit(` -> `fx_lit(` (see kLitReplacement), and `tex2D(S,` / `tex2Dproj(S,` for the depth samplers S into
// calls of the comparison helpers. A depth sampler reaching a function through a parameter is not
// rewritten: the parameter's name is not S (and if it is, it names the global anyway).
std::string rewriteIntrinsics(const std::string& text, const std::set<std::string>& depthSamplers) {
    std::string out;
    size_t i = 0;
    auto skipSpace = [&](size_t j) {
        while (j < text.size() && std::isspace(static_cast<unsigned char>(text[j]))) ++j;
        return j;
    };
    while (i < text.size()) {
        char c = text[i];
        if (c == '/' && i + 1 < text.size() && (text[i + 1] == '/' || text[i + 1] == '*')) {
            size_t end = text[i + 1] == '/' ? text.find('\n', i) : text.find("*/", i + 2);
            end = end == std::string::npos ? text.size() : end + (text[i + 1] == '/' ? 0 : 2);
            out.append(text, i, end - i);
            i = end;
            continue;
        }
        if (!(std::isalpha(static_cast<unsigned char>(c)) || c == '_') ||
            (i > 0 && isIdentChar(text[i - 1]))) {
            out += c;
            ++i;
            continue;
        }
        size_t start = i;
        while (i < text.size() && isIdentChar(text[i])) ++i;
        std::string word = text.substr(start, i - start);
        if (word == "lit" && skipSpace(i) < text.size() && text[skipSpace(i)] == '(') {
            out += "fx_lit";
            continue;
        }
        if (word == "tex2D" || word == "tex2Dproj") {
            size_t p = skipSpace(i);
            if (p < text.size() && text[p] == '(') {
                size_t s = skipSpace(p + 1), e = s;
                while (e < text.size() && isIdentChar(text[e])) ++e;
                std::string name = text.substr(s, e - s);
                size_t comma = skipSpace(e);
                if (depthSamplers.count(name) && comma < text.size() && text[comma] == ',') {
                    out += "fx_" + word + "_" + name + "(";
                    i = comma + 1;
                    continue;
                }
            }
        }
        out += word;
    }
    return out;
}

// The D3D9 shadow-map lookups on a comparison sampler: the result of comparing the reference depth with
// the texel (filtered when the sampler filters linearly), in every component.
std::string depthSamplerHelpers(const std::string& s) {
    std::string t = "fx_depth_" + s, c = "fx_cmp_" + s;
    return "Texture2D " + t + ";\nSamplerComparisonState " + c + ";\n" + "float4 fx_tex2D_" + s +
           "(float4 uv) { return " + t + ".SampleCmpLevelZero(" + c + ", uv.xy, uv.z).xxxx; }\n" +
           "float4 fx_tex2D_" + s + "(float3 uv) { return " + t + ".SampleCmpLevelZero(" + c +
           ", uv.xy, uv.z).xxxx; }\n" + "float4 fx_tex2Dproj_" + s + "(float4 uv) { return " + t +
           ".SampleCmpLevelZero(" + c + ", uv.xy / uv.w, uv.z / uv.w).xxxx; }\n";
}

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

// [SECTION] Entry-point wrapper

// One leaf of a (possibly nested) struct: where it lives and what semantic it carries.
struct Field {
    std::string lvalue;  // "fx_p0.Position"
    TypeDesc type;
    std::string semantic;  // canonical
    std::string interpolation;
    SourceLoc loc;
    // A matrix's column: D3D9 gives a matrix varying or input one register per column (its default
    // column_major packing), at consecutive semantic indices. lvalue names the whole matrix then, and
    // type is the column's vector.
    int column = -1;
};

// The value a field holds, for an output: the column of a matrix or the lvalue itself.
std::string fieldValue(const Field& f) {
    return f.column < 0 ? f.lvalue : "transpose(" + f.lvalue + ")[" + std::to_string(f.column) + "]";
}

void gatherFields(const Effect& effect, const TypeDesc& type, const std::string& semantic,
                  const std::string& interpolation, const std::string& lvalue, const SourceLoc& loc,
                  std::vector<Field>& out, int depth = 0) {
    if (type.base == BaseType::Struct && type.arrayDims.empty()) {
        const StructDecl* decl = findStructDecl(effect, type.structName);
        if (!decl || depth > 8) return;
        for (const StructMember& m : decl->members)
            gatherFields(effect, m.type, m.semantic, m.interpolation, lvalue + "." + m.name, m.loc, out,
                         depth + 1);
        return;
    }
    if (semantic.empty()) return;  // left zero, as an unbound D3D9 register reads
    const std::string canonical = canonicalSemantic(semantic);
    const std::string upperSemantic = upper(semantic);
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

class WrapperBuilder {
public:
    WrapperBuilder(const Effect& effect, const FunctionDecl& fn, const Expr& compile, ShaderStage stage,
                   std::vector<LoweredArgument>& arguments, DiagnosticSink& diagnostics,
                   const std::map<int, TypeDesc>* previousOutputs, const FunctionDecl* hull)
        : mEffect(effect),
          mFn(fn),
          mCompile(compile),
          mStage(stage),
          mArguments(arguments),
          mDiagnostics(diagnostics),
          mPreviousOutputs(previousOutputs),
          mHull(hull) {}

    bool build(std::string& globals, std::string& wrapper);

    // A geometry shader's output stream element: its name and its redeclaration with varying locations.
    const std::string& streamStruct() const { return mStreamStruct; }
    const std::string& streamStructText() const { return mStreamStructText; }
    const std::map<int, TypeDesc>& varyingOutputs() const { return mVaryingOutputs; }
    // A hull shader's control points per input patch and its patch-constant function.
    int patchVertices() const { return mPatchVertices; }
    CompiledPass::DrawPrimitive primitive() const { return mPrimitive; }
    const std::string& patchConstantFunction() const { return mPatchConstantFunction; }

private:
    bool fail(DiagId id, const SourceLoc& loc, const std::vector<std::string>& args) {
        mDiagnostics.report(id, loc, args);
        return false;
    }
    bool uniformArgument(const FunctionParam& p, size_t argIndex, std::string& value, std::string& globals);
    // False (reported at CompileShader) when the call gives more arguments than the `uniformCount`
    // uniform parameters of the function took.
    bool everyArgumentTaken(size_t uniformCount);
    bool vertexInputs(const std::vector<Field>& fields, std::string& params, std::string& body);
    bool pixelInputs(const std::vector<Field>& fields, std::string& params, std::string& body);
    bool vertexOutputs(const std::vector<Field>& fields, std::string& members, std::string& body);
    bool pixelOutputs(const std::vector<Field>& fields, std::string& members, std::string& body);
    bool buildGeometry(std::string& globals, std::string& wrapper);
    bool streamElement(const FunctionParam& stream);
    bool buildHull(std::string& globals, std::string& wrapper);
    bool buildDomain(std::string& globals, std::string& wrapper);
    bool readControlPoints(const FunctionParam& patch, const std::string& local, const std::string& source,
                           std::set<int>& varyings, std::string& locals, std::string& body);
    bool patchConstants(const TypeDesc& type, const SourceLoc& loc, bool write, const std::string& value,
                        std::string& members, std::string& body);

    const Effect& mEffect;
    const FunctionDecl& mFn;
    const Expr& mCompile;
    ShaderStage mStage;
    std::vector<LoweredArgument>& mArguments;
    DiagnosticSink& mDiagnostics;
    const std::map<int, TypeDesc>* mPreviousOutputs;
    const FunctionDecl* mHull;
    int mPatchVertices = 0;
    CompiledPass::DrawPrimitive mPrimitive = CompiledPass::DrawPrimitive::Triangles;
    std::string mPatchConstantFunction;
    std::string mStreamStruct;
    std::string mStreamStructText;
    std::map<int, TypeDesc> mVaryingOutputs;
};

bool WrapperBuilder::everyArgumentTaken(size_t uniformCount) {
    if (uniformCount >= mCompile.args.size()) return true;
    return fail(DiagId::InvalidCompileExpression, mCompile.loc,
                {"'" + mFn.name + "' has " + std::to_string(uniformCount) + " uniform parameter(s), " +
                 std::to_string(mCompile.args.size()) + " argument(s) given"});
}

bool WrapperBuilder::uniformArgument(const FunctionParam& p, size_t argIndex, std::string& value,
                                     std::string& globals) {
    const Expr* expr = nullptr;
    if (argIndex < mCompile.args.size())
        expr = &mCompile.args[argIndex];
    else if (p.defaultValue)
        expr = &*p.defaultValue;
    else
        return fail(DiagId::InvalidCompileExpression, mCompile.loc,
                    {"no argument for uniform parameter '" + p.name + "' of '" + mFn.name + "'"});
    if (p.type.isSampler() || p.type.isTexture()) {
        const Parameter* s = expr->kind == Expr::Kind::Identifier ? findParam(mEffect, expr->text) : nullptr;
        const bool fits =
            s && (p.type.isTexture() ? s->type.isTexture()
                  : p.type.base == BaseType::SamplerState || p.type.base == BaseType::SamplerComparisonState
                      ? s->type.base == p.type.base
                      : isSamplerType(s->type));
        if (!fits)
            return fail(
                DiagId::InvalidCompileExpression, expr->loc,
                {"argument for " + std::string(p.type.isTexture() ? "texture" : "sampler") + " parameter '" +
                 p.name + "' must name an effect " + (p.type.isTexture() ? "texture" : "sampler")});
        value = s->name;
        return true;
    }
    if (!isNumericType(p.type))
        return fail(
            DiagId::InvalidCompileExpression, expr->loc,
            {"uniform parameter '" + p.name + "' of type " + hlslTypeName(p.type) + " is not supported"});
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
            !findParam(mEffect, e.text))
            return &e;
        for (const Expr& a : e.args)
            if (const Expr* found = unknownName(a)) return found;
        return nullptr;
    };
    if (const Expr* unknown = unknownName(*expr))
        return fail(DiagId::UnknownIdentifier, unknown->loc, {unknown->text});
    std::string name = "fx_arg" + std::to_string(mArguments.size());
    mArguments.push_back(LoweredArgument{*expr, p.type, name});
    globals += hlslTypeName(p.type) + " " + name + arraySuffix(p.type) + ";\n";
    value = name;
    return true;
}

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
std::string unmatchedVertexInput(const Field& f) {
    if (f.column >= 0) {
        std::string v = "float4(";
        for (int k = 0; k < 4; ++k) v += std::string(k ? ", " : "") + (k == f.column ? "1" : "0");
        return v + ")";
    }
    if (f.type.cols == 4 && f.semantic.find("POS") != std::string::npos) return "float4(0, 0, 0, 1)";
    return "float4(0, 0, 0, 0)";
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
        const std::optional<int> location = vertexInputAttribute(f.semantic);
        if (!location) continue;
        if (!f.type.arrayDims.empty())
            return fail(DiagId::UnsupportedFeature, f.loc,
                        {"vertex input '" + f.semantic + "' is nested too deeply"});
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
        const std::optional<int> location = vertexInputAttribute(f.semantic);
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
        } else if (s == "SV_PRIMITIVEID" || s == "SV_SAMPLEINDEX") {
            const std::string name = s == "SV_PRIMITIVEID" ? "fx_primitiveId" : "fx_sampleIndex";
            if (systemValues.insert(name).second)
                systemParams.push_back("uint " + name +
                                       (s == "SV_PRIMITIVEID" ? " : SV_PrimitiveID" : " : SV_SampleIndex"));
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
            if (!f.interpolation.empty()) interpolation[*location] = f.interpolation;
            body += assignField(f, source);
        } else {
            return fail(DiagId::UnsupportedFeature, f.loc,
                        {"pixel input semantic '" + f.semantic + "' is not supported"});
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
            continue;  // point size: GL takes it from gl_PointSize only when enabled; D3D9 effects rarely
                       // rely on it
        } else if (s.rfind("SV_CLIPDISTANCE", 0) == 0 || s.rfind("SV_CULLDISTANCE", 0) == 0) {
            // gl_ClipDistance / gl_CullDistance; the runtime enables the clip planes the program writes.
            const bool clip = s[3] == 'C' && s[4] == 'L';
            const std::string index = s.substr(15).empty() ? "0" : s.substr(15);
            const std::string name = std::string(clip ? "fx_clip" : "fx_cull") + index;
            if (!used.insert(1000 + (clip ? 0 : 100) + std::stoi(index)).second) continue;
            TypeDesc t = f.type;
            t.arrayDims.clear();
            members += "    " + hlslTypeName(t) + " " + name +
                       (clip ? " : SV_ClipDistance" : " : SV_CullDistance") + index + ";\n";
            body += "    fx_out." + name + " = " + fieldValue(f) + ";\n";
        } else if (auto location =
                       varyingLocation(s) ? varyingLocation(s) : customVaryingLocation(mEffect, s)) {
            if (!used.insert(*location).second) continue;
            std::string name = "fx_v" + std::to_string(*location);
            mVaryingOutputs[*location] = float4Type();
            members += "    [[vk::location(" + std::to_string(*location) + ")]] float4 " + name + " : FX_V" +
                       std::to_string(*location) + ";\n";
            int n = std::clamp(f.type.cols, 1, 4);
            std::string v =
                "(float" + (n == 1 ? std::string() : std::to_string(n)) + ")(" + fieldValue(f) + ")";
            body += "    fx_out." + name + " = " +
                    (n == 4 ? v
                            : "float4(" + v +
                                  (n == 1   ? ", 0, 0, 1)"
                                   : n == 2 ? ", 0, 1)"
                                            : ", 1)")) +
                    ";\n";
        } else {
            return fail(DiagId::UnsupportedFeature, f.loc,
                        {"vertex output semantic '" + s + "' is not supported"});
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
            return fail(DiagId::UnsupportedFeature, f.loc,
                        {"pixel output semantic '" + f.semantic + "' is not supported"});
        }
    }
    return true;
}

// The stream's element struct, redeclared with the varying location of each member's semantic (glslang
// assigns the locations of a geometry shader's outputs from the struct it appends): members must be
// scalars or vectors with a POSITION/SV_Position, varying or SV_ClipDistance semantic.
bool WrapperBuilder::streamElement(const FunctionParam& stream) {
    const StructDecl* decl =
        stream.type.base == BaseType::Struct ? findStructDecl(mEffect, stream.type.structName) : nullptr;
    if (!decl || !stream.type.arrayDims.empty())
        return fail(DiagId::UnsupportedFeature, stream.loc,
                    {"the element of geometry shader stream '" + stream.name + "' must be a struct"});
    mStreamStruct = decl->name;
    std::string members;
    for (const StructMember& m : decl->members) {
        const std::string semantic = canonicalSemantic(m.semantic);
        if (m.type.base == BaseType::Struct || !m.type.arrayDims.empty() || m.type.shape == Shape::Matrix)
            return fail(DiagId::UnsupportedFeature, m.loc,
                        {"geometry shader output '" + m.name +
                         "' must be a scalar or a vector (structs, arrays and matrices are not supported)"});
        std::string declared = hlslTypeName(m.type) + " " + m.name;
        if (semantic == "POSITION0" || semantic == "SV_POSITION") {
            members += "    " + declared + " : SV_Position;\n";
        } else if (semantic.rfind("SV_CLIPDISTANCE", 0) == 0 || semantic.rfind("SV_CULLDISTANCE", 0) == 0) {
            members += "    " + declared + " : " + m.semantic + ";\n";
        } else if (auto location = varyingLocation(semantic) ? varyingLocation(semantic)
                                                             : customVaryingLocation(mEffect, semantic)) {
            if (m.type.base != BaseType::Float && m.type.base != BaseType::Half && m.interpolation.empty())
                return fail(
                    DiagId::UnsupportedFeature, m.loc,
                    {"geometry shader output '" + m.name + "' of an integer type must be 'nointerpolation'"});
            const std::string at = std::to_string(*location);
            members += "    [[vk::location(" + at + ")]] " +
                       (m.interpolation.empty() ? std::string() : m.interpolation + " ") + declared +
                       " : FX_V" + at + ";\n";
            mVaryingOutputs[*location] = m.type;
        } else {
            return fail(DiagId::UnsupportedFeature, m.loc,
                        {"geometry shader output semantic '" + m.semantic + "' is not supported"});
        }
    }
    mStreamStructText = "struct " + decl->name + "\n{\n" + members + "};\n";
    return true;
}

// A geometry shader: [maxvertexcount(n)] void GS(triangle In input[3], inout TriangleStream<Out> s).
// The wrapper is a geometry shader of the same primitive and vertex count that rebuilds `input` from the
// vertex stage's SV_Position and float4 varyings and passes its own stream through.
bool WrapperBuilder::buildGeometry(std::string& globals, std::string& wrapper) {
    if (mFn.maxVertexCount <= 0)
        return fail(DiagId::UnsupportedFeature, mFn.loc,
                    {"geometry shader '" + mFn.name + "' has no [maxvertexcount(n)] attribute"});
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
            if (stream)
                return fail(DiagId::UnsupportedFeature, p.loc,
                            {"geometry shader '" + mFn.name + "' has more than one output stream"});
            stream = &p;
            arg = "fx_stream";
        } else if (!p.primitive.empty()) {
            if (input)
                return fail(DiagId::UnsupportedFeature, p.loc,
                            {"geometry shader '" + mFn.name + "' has more than one input primitive"});
            input = &p;
            arg = "fx_p" + std::to_string(i);
        } else if (canonicalSemantic(p.semantic) == "SV_PRIMITIVEID") {
            primitiveId = true;
            arg = "(" + hlslTypeName(p.type) + ")fx_primitiveId";
        } else {
            return fail(DiagId::UnsupportedFeature, p.loc,
                        {"geometry shader parameter '" + p.name +
                         "' is not supported (expected the input primitive, the output stream, "
                         "SV_PrimitiveID or a uniform)"});
        }
        callArgs += (i ? ", " : "") + arg;
    }
    if (!everyArgumentTaken(uniformIndex)) return false;
    if (!input || !stream)
        return fail(DiagId::UnsupportedFeature, mFn.loc,
                    {"geometry shader '" + mFn.name +
                     "' needs an input primitive ('triangle T input[3]') and an output stream "
                     "('inout TriangleStream<T> stream')"});
    // What the pass's draws give each primitive: a mesh's triangles, its vertices, its edges or its
    // triangles with their neighbours (GpuMesh builds the edge and adjacency lists).
    using Primitive = CompiledPass::DrawPrimitive;
    static const std::map<std::string, std::pair<int, Primitive>> kInputs = {
        {"point", {1, Primitive::Points}},
        {"line", {2, Primitive::Lines}},
        {"triangle", {3, Primitive::Triangles}},
        {"triangleadj", {6, Primitive::TrianglesAdjacency}}};
    if (input->primitive == "lineadj")
        return fail(
            DiagId::UnsupportedFeature, input->loc,
            {"geometry shader input primitive 'lineadj' is not supported: a mesh's triangles define no "
             "line strips, so an edge has no single continuation at either end"});
    const auto kind = kInputs.find(input->primitive);
    if (kind == kInputs.end())
        return fail(DiagId::UnsupportedFeature, input->loc,
                    {"geometry shader input primitive '" + input->primitive + "' is not supported"});
    const int count = kind->second.first;
    mPrimitive = kind->second.second;
    if (input->type.arrayDims.size() != 1 || input->type.arrayDims[0] != count)
        return fail(
            DiagId::UnsupportedFeature, input->loc,
            {"geometry shader input '" + input->name + "' must be an array of " + std::to_string(count) +
             " vertices ('" + input->primitive + " T " + input->name + "[" + std::to_string(count) + "]')"});
    if (stream->direction != FunctionParam::Direction::InOut)
        return fail(DiagId::UnsupportedFeature, stream->loc,
                    {"geometry shader stream '" + stream->name + "' must be 'inout'"});
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
                return fail(DiagId::UnsupportedFeature, f.loc,
                            {"geometry shader input semantic '" + f.semantic + "' is not supported"});
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
                return fail(DiagId::UnsupportedFeature, f.loc,
                            {"control point semantic '" + f.semantic + "' is not supported"});
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
                                 ? findStructDecl(mEffect, type.structName)
                                 : nullptr;
    if (!decl)
        return fail(
            DiagId::UnsupportedFeature, loc,
            {"the patch constants must be a struct with SV_TessFactor and SV_InsideTessFactor members"});
    bool outer = false;
    std::set<int> used;
    for (const StructMember& m : decl->members) {
        const std::string semantic = upper(m.semantic);
        if (semantic == "SV_TESSFACTOR" || semantic == "SV_INSIDETESSFACTOR") {
            const std::string name = semantic == "SV_TESSFACTOR" ? "fx_outer" : "fx_inner";
            outer |= semantic == "SV_TESSFACTOR";
            if (!used.insert(semantic == "SV_TESSFACTOR" ? -1 : -2).second)
                return fail(DiagId::UnsupportedFeature, m.loc,
                            {"semantic '" + m.semantic + "' is used twice"});
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
            if (!location)
                return fail(DiagId::UnsupportedFeature, f.loc,
                            {"patch constant semantic '" + f.semantic + "' is not supported"});
            const std::string name = "fx_k" + std::to_string(*location);
            if (used.insert(*location).second)
                members += "    [[vk::location(" + std::to_string(*location) + ")]] float4 " + name +
                           " : FX_K" + std::to_string(*location) + ";\n";
            body +=
                write ? "    fx_out." + name + " = " + float4Of(f) + ";\n" : assignField(f, "fx_c." + name);
        }
    }
    if (!outer)
        return fail(DiagId::UnsupportedFeature, decl->loc,
                    {"the patch constants '" + decl->name + "' have no SV_TessFactor member"});
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
            return fail(DiagId::UnsupportedFeature, mFn.loc,
                        {"hull shader '" + mFn.name + "' has no [" + required + "(...)] attribute"});
    const FunctionAttribute& pcfAttribute = *mFn.attribute("patchconstantfunc");
    const FunctionDecl* pcf = nullptr;
    for (const FunctionDecl& f : mEffect.functions)
        if (f.name == pcfAttribute.argument && f.hasBody) pcf = &f;
    if (!pcf)
        return fail(DiagId::UnsupportedFeature, pcfAttribute.loc,
                    {"patch-constant function '" + pcfAttribute.argument + "' of hull shader '" + mFn.name +
                     "' is not defined"});
    mPatchConstantFunction = pcf->name;
    const std::string& pointsText = mFn.attribute("outputcontrolpoints")->argument;
    const int outputPoints = std::all_of(pointsText.begin(), pointsText.end(), ::isdigit) &&
                                     !pointsText.empty() && pointsText.size() < 3
                                 ? std::stoi(pointsText)
                                 : 0;
    if (outputPoints < 1 || outputPoints > 32)
        return fail(DiagId::UnsupportedFeature, mFn.attribute("outputcontrolpoints")->loc,
                    {"[outputcontrolpoints] takes a number 1..32"});

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
            return fail(DiagId::UnsupportedFeature, p.loc,
                        {"hull shader parameter '" + p.name +
                         "' is not supported (expected one InputPatch<T, 3>, SV_OutputControlPointID, "
                         "SV_PrimitiveID or a uniform)"});
        }
        callArgs += (i ? ", " : "") + arg;
    }
    if (!everyArgumentTaken(uniformIndex)) return false;
    if (!input)
        return fail(DiagId::UnsupportedFeature, mFn.loc,
                    {"hull shader '" + mFn.name + "' needs an input patch ('InputPatch<T, 3> patch')"});
    if (input->patchSize != 3)
        return fail(DiagId::UnsupportedFeature, input->loc,
                    {"an input patch of " + std::to_string(input->patchSize) +
                     " control points is not supported: shadowfx draws a mesh's triangles as patches, which "
                     "'InputPatch<T, 3>' takes"});
    mPatchVertices = input->patchSize;
    if (mFn.returnType.base == BaseType::Void)
        return fail(DiagId::UnsupportedFeature, mFn.loc,
                    {"hull shader '" + mFn.name + "' must return its output control point"});
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
    std::string pcfLocals, pcfBody, pcfArgs, pcfParams = "InputPatch<fx_HsInput, 3> fx_in";
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
                    return fail(DiagId::UnsupportedFeature, p.loc,
                                {"the output patch '" + p.name + "' of '" + pcf->name +
                                 "' reads a semantic that hull shader '" + mFn.name + "' does not write"});
            pcfParams += ", OutputPatch<fx_HsOutput, " + std::to_string(outputPoints) + "> fx_op";
        } else if (semantic == "SV_PRIMITIVEID" && !p.isUniform) {
            arg = "(" + hlslTypeName(p.type) + ")fx_primitiveId";
        } else {
            return fail(
                DiagId::UnsupportedFeature, p.loc,
                {"patch-constant function parameter '" + p.name +
                 "' is not supported (expected the hull shader's InputPatch<T, 3>, an OutputPatch<T, " +
                 std::to_string(outputPoints) + "> or SV_PrimitiveID)"});
        }
        pcfArgs += (i ? ", " : "") + arg;
    }
    pcfParams += ", uint fx_primitiveId : SV_PrimitiveID";
    if (pcf->returnType.base == BaseType::Void)
        return fail(
            DiagId::UnsupportedFeature, pcf->loc,
            {"patch-constant function '" + pcf->name + "' must return its patch constants as a struct"});
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
    wrapper +=
        "fx_HsOutput " + std::string(kWrapperEntryPoint) +
        "(InputPatch<fx_HsInput, 3> fx_in, uint fx_id : SV_OutputControlPointID, uint fx_primitiveId : "
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
    if (!domain)
        return fail(DiagId::UnsupportedFeature, mFn.loc,
                    {"domain shader '" + mFn.name + "' has no [domain(...)] attribute"});
    if (!mHull || !mHull->attribute("domain"))
        return fail(DiagId::UnsupportedFeature, mCompile.loc,
                    {"a domain shader needs a hull shader in the same pass (SetHullShader)"});
    if (!equalsIgnoreCase(domain->argument, mHull->attribute("domain")->argument))
        return fail(
            DiagId::UnsupportedFeature, domain->loc,
            {"domain shader '" + mFn.name + "' is for the '" + domain->argument + "' domain, hull shader '" +
             mHull->name + "' for '" + mHull->attribute("domain")->argument + "'"});
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
                return fail(DiagId::UnsupportedFeature, p.loc,
                            {"the output patch of domain shader '" + mFn.name + "' has " +
                             std::to_string(p.patchSize) + " control points, hull shader '" + mHull->name +
                             "' writes " + (points ? points->argument : std::string("?"))});
            if (!readControlPoints(p, arg, "fx_patch", varyings, locals, body)) return false;
            addParam("const OutputPatch<fx_DsPoint, " + std::to_string(p.patchSize) + "> fx_patch");
        } else if (semantic == "SV_DOMAINLOCATION") {
            TypeDesc t = p.type;
            addParam(hlslTypeName(t) + " fx_domain : SV_DomainLocation");
            arg = "fx_domain";
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
            return fail(
                DiagId::UnsupportedFeature, p.loc,
                {"domain shader parameter '" + p.name +
                 "' is not supported (expected the patch constants, SV_DomainLocation, an OutputPatch, "
                 "SV_PrimitiveID, an output or a uniform)"});
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

bool WrapperBuilder::build(std::string& globals, std::string& wrapper) {
    if (mStage == ShaderStage::Geometry) return buildGeometry(globals, wrapper);
    if (mStage == ShaderStage::Hull) return buildHull(globals, wrapper);
    if (mStage == ShaderStage::Domain) return buildDomain(globals, wrapper);
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
                                                          : "ds_";
    std::string p = profile;
    for (char& c : p) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (p.rfind(prefix, 0) != 0) return false;
    std::string version = p.substr(3);
    if (stage == ShaderStage::Hull || stage == ShaderStage::Domain) return modern(version);
    if (stage == ShaderStage::Geometry) return version == "4_0" || version == "4_1" || modern(version);
    if (stage == ShaderStage::Vertex && (version == "1_2" || version == "1_3" || version == "1_4"))
        return false;
    if (stage == ShaderStage::Fragment && version == "1_1") return true;
    return std::any_of(std::begin(kVersions), std::end(kVersions),
                       [&](const char* v) { return version == v; });
}

}  // namespace

// [SECTION] lowerStage()

std::optional<LoweredStage> lowerStage(const Effect& effect, const Expr& compile, ShaderStage stage,
                                       std::vector<LoweredArgument>& arguments, DiagnosticSink& diagnostics,
                                       const std::map<int, TypeDesc>* previousOutputs,
                                       const FunctionDecl* hull) {
    auto stageName = [](ShaderStage s) {
        return s == ShaderStage::Vertex     ? "vertex"
               : s == ShaderStage::Fragment ? "pixel"
               : s == ShaderStage::Geometry ? "geometry"
               : s == ShaderStage::Hull     ? "hull"
                                            : "domain";
    };
    if (!profileMatches(compile.profile, stage)) {
        // `VertexShader = compile ps_3_0 VS()` read "unsupported shader profile 'ps_3_0'": say what is wrong.
        for (ShaderStage other : {ShaderStage::Vertex, ShaderStage::Fragment, ShaderStage::Geometry,
                                  ShaderStage::Hull, ShaderStage::Domain})
            if (other != stage && profileMatches(compile.profile, other)) {
                diagnostics.report(DiagId::InvalidCompileExpression, compile.loc,
                                   {"'" + compile.profile + "' is a " + stageName(other) +
                                    "-shader profile, used for the " + stageName(stage) + " shader"});
                return std::nullopt;
            }
        diagnostics.report(DiagId::UnsupportedProfile, compile.loc, {compile.profile});
        return std::nullopt;
    }
    const FunctionDecl* fn = nullptr;
    for (const FunctionDecl& f : effect.functions)
        if (f.name == compile.text && f.hasBody) {
            fn = &f;
            break;
        }
    if (!fn) {
        diagnostics.report(DiagId::MissingEntryPoint, compile.loc, {compile.text});
        return std::nullopt;
    }

    LoweredStage out;
    out.stage = stage;
    out.entryPoint = fn->name;
    out.profile = compile.profile;
    out.compileLoc = compile.loc;

    std::set<std::string> depth;
    for (const Parameter& p : effect.parameters)
        if (isSamplerType(p.type) && isDepthCompareSampler(effect, p)) depth.insert(p.name);

    // Wrapper first (it may fail on arguments) but emitted last.
    size_t firstArgument = arguments.size();
    std::string argumentGlobals, wrapper;
    WrapperBuilder builder(effect, *fn, compile, stage, arguments, diagnostics,
                           stage == ShaderStage::Fragment ? previousOutputs : nullptr,
                           stage == ShaderStage::Domain ? hull : nullptr);
    if (!builder.build(argumentGlobals, wrapper)) {
        arguments.resize(firstArgument);
        return std::nullopt;
    }
    out.varyingOutputs = builder.varyingOutputs();
    out.patchVertices = builder.patchVertices();
    out.primitive = builder.primitive();

    std::set<std::string> reached = reachableFunctions(effect, fn->name);
    if (!builder.patchConstantFunction().empty())  // named in an attribute's string, so not found as a call
        reached.merge(reachableFunctions(effect, builder.patchConstantFunction()));
    // D3D10 textures and sampler objects are declared only where the unit's code names them: a D3D9
    // effect's `texture2D` is reached through its sampler_state alone.
    std::set<std::string> named;
    auto nameAll = [&](const std::string& text) {
        for (const std::string& id : identifiersIn(text)) named.insert(id);
    };
    for (const FunctionDecl& f : effect.functions)
        if (reached.count(f.name)) nameAll(f.hlslText);
    for (const Parameter& p : effect.parameters)
        if (p.isStatic) nameAll(p.hlslText);
    for (const VerbatimDecl& v : effect.verbatim) nameAll(v.hlslText);
    nameAll(wrapper);
    std::set<std::string> usedDepth;
    std::string staticAssignments;  // what the entry point assigns first (splitStaticInitializer)
    std::string& hlsl = out.hlsl;
    hlsl += "// shadowfx: " + std::string(stageName(stage)) + " shader " + fn->name + " (" + compile.profile +
            ")\n";
    hlsl += "#line 1 \"" + std::string(kGeneratedFile) + "\"\n" + kLitReplacement;
    for (const DeclRef& ref : effect.order) {
        switch (ref.kind) {
            case DeclRef::Kind::Parameter: {
                const Parameter& p = effect.parameters[ref.index];
                if (p.isStatic) {
                    const SplitStatic split = splitStaticInitializer(effect, p);
                    if (split.declaration.empty()) {
                        emitAt(hlsl, rewriteIntrinsics(p.hlslText, depth), p.hlslLoc);
                    } else {
                        emitAt(hlsl, split.declaration, p.hlslLoc);
                        emitAt(staticAssignments, rewriteIntrinsics(split.assignment, depth), p.hlslLoc);
                    }
                } else if (isNumericType(p.type) && p.type.base != BaseType::String) {
                    // A plain global: it lands in the $Global block; the runtime fills it.
                    hlsl += hlslTypeName(p.type) + " " + p.name + arraySuffix(p.type) + ";\n";
                } else if (p.type.base == BaseType::Struct && named.count(p.name)) {
                    // A struct-typed global (D3D10 effects keep lights and materials in cbuffers so): in
                    // the block too, zero as an application that never set it leaves it.
                    hlsl += p.type.structName + " " + p.name + arraySuffix(p.type) + ";\n";
                } else if (((p.type.isTexture() && p.type.base != BaseType::Texture) || p.type.isBuffer() ||
                            p.type.base == BaseType::SamplerState ||
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
                            const std::string resourceType =
                                kind && kind->value.kind == Expr::Kind::String ? upper(kind->value.text) : "";
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
                const bool stream = !builder.streamStruct().empty() && s.name == builder.streamStruct();
                emitAt(hlsl, stream ? builder.streamStructText() : s.hlslText, s.hlslLoc);
                break;
            }
            case DeclRef::Kind::Function: {
                const FunctionDecl& f = effect.functions[ref.index];
                if (reached.count(f.name)) emitAt(hlsl, rewriteIntrinsics(f.hlslText, depth), f.hlslLoc);
                break;
            }
            case DeclRef::Kind::Verbatim: {
                const VerbatimDecl& v = effect.verbatim[ref.index];
                emitAt(hlsl, rewriteIntrinsics(v.hlslText, depth), v.hlslLoc);
                break;
            }
        }
    }
    if (!staticAssignments.empty()) {
        const size_t entry = wrapper.find(std::string(kWrapperEntryPoint) + "(");
        const size_t body = entry == std::string::npos ? entry : wrapper.find(")\n{\n", entry);
        if (body != std::string::npos)
            wrapper.insert(body + 4, staticAssignments + "#line 1 \"" + std::string(kGeneratedFile) + "\"\n");
    }
    hlsl += "#line 1 \"" + std::string(kGeneratedFile) + "\"\n" + argumentGlobals + wrapper;
    out.depthSamplers.assign(usedDepth.begin(), usedDepth.end());
    return out;
}

}  // namespace fx
