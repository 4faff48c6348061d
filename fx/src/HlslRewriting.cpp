// HlslRewriting: see HlslRewriting.h.
#include "HlslRewriting.h"

#include <algorithm>
#include <cctype>
#include <vector>

namespace fx {

bool isIdentChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
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

// Rewrites, token by token (comments untouched), the intrinsic calls glslang gets wrong or cannot express:
// `lit(` -> `fx_lit(` (see kLitReplacement), and `tex2D(S,` (`tex2Dproj`, `tex2Dlod`, `tex2Dbias`) for
// the depth samplers S into calls of the comparison helpers. A depth sampler that a shader's compile
// argument names is bound into the entry point first (bindParameters), and one passed on to a function's
// sampler parameter into a copy of that function (bindCallArguments), so that every lookup names S.
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
        if (word == "tex2D" || word == "tex2Dproj" || word == "tex2Dlod" || word == "tex2Dbias") {
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
// the texel (filtered when the sampler filters linearly), in every component. A shadow map has one level,
// so tex2Dlod's level, tex2Dbias's bias and tex2D's gradients select nothing.
std::string depthSamplerHelpers(const std::string& s) {
    const std::string t = "fx_depth_" + s, c = "fx_cmp_" + s;
    auto compare = [&](const std::string& xy, const std::string& z) {
        return "{ return " + t + ".SampleCmpLevelZero(" + c + ", " + xy + ", " + z + ").xxxx; }\n";
    };
    return "Texture2D " + t + ";\nSamplerComparisonState " + c + ";\n" + "float4 fx_tex2D_" + s +
           "(float4 uv) " + compare("uv.xy", "uv.z") + "float4 fx_tex2D_" + s + "(float3 uv) " +
           compare("uv.xy", "uv.z") + "float4 fx_tex2D_" + s + "(float4 uv, float2 dx, float2 dy) " +
           compare("uv.xy", "uv.z") + "float4 fx_tex2D_" + s + "(float3 uv, float2 dx, float2 dy) " +
           compare("uv.xy", "uv.z") + "float4 fx_tex2Dproj_" + s + "(float4 uv) " +
           compare("uv.xy / uv.w", "uv.z / uv.w") + "float4 fx_tex2Dlod_" + s + "(float4 uv) " +
           compare("uv.xy", "uv.z") + "float4 fx_tex2Dbias_" + s + "(float4 uv) " + compare("uv.xy", "uv.z");
}

namespace {

// The end of the comment or string literal starting at `i`, or `i` where none starts there.
size_t skipCommentOrString(const std::string& text, size_t i) {
    if (text.compare(i, 2, "//") == 0) {
        size_t end = text.find('\n', i);
        return end == std::string::npos ? text.size() : end;
    }
    if (text.compare(i, 2, "/*") == 0) {
        size_t end = text.find("*/", i + 2);
        return end == std::string::npos ? text.size() : end + 2;
    }
    if (text[i] == '"') {
        size_t j = i + 1;
        while (j < text.size() && text[j] != '"') j += text[j] == '\\' ? 2 : 1;
        return std::min(j + 1, text.size());
    }
    return i;
}

}  // namespace

std::optional<std::string> bindParameters(const std::string& text, const std::string& name,
                                          const std::string& newName, size_t parameterCount,
                                          const std::map<std::string, std::string>& bound) {
    // The signature: the first `name (` outside comments; its parameters split at the commas outside
    // parentheses and template brackets (`InputPatch<VSOut, 3>`).
    size_t open = std::string::npos, nameAt = 0;
    for (size_t i = 0; i < text.size() && open == std::string::npos;) {
        if (size_t end = skipCommentOrString(text, i); end != i) {
            i = end;
        } else if (isIdentChar(text[i]) && (i == 0 || !isIdentChar(text[i - 1]))) {
            size_t start = i;
            while (i < text.size() && isIdentChar(text[i])) ++i;
            size_t j = i;
            while (j < text.size() && std::isspace(static_cast<unsigned char>(text[j]))) ++j;
            if (text.compare(start, i - start, name) == 0 && i - start == name.size() && j < text.size() &&
                text[j] == '(') {
                open = j;
                nameAt = start;
            }
        } else {
            ++i;
        }
    }
    if (open == std::string::npos) return std::nullopt;
    std::vector<std::string> chunks{""};
    size_t close = std::string::npos;
    int depth = 0;
    for (size_t i = open + 1; i < text.size() && close == std::string::npos;) {
        if (size_t end = skipCommentOrString(text, i); end != i) {
            chunks.back().append(text, i, end - i);
            i = end;
            continue;
        }
        const char c = text[i++];
        if (c == '(' || c == '<') ++depth;
        if ((c == ')' || c == '>') && depth > 0) {
            --depth;
        } else if (c == ')') {
            close = i - 1;
            break;
        } else if (c == ',' && depth == 0) {
            chunks.emplace_back();
            continue;
        }
        chunks.back() += c;
    }
    if (close == std::string::npos) return std::nullopt;
    if (chunks.size() == 1 && chunks[0].find_first_not_of(" \t\r\n") == std::string::npos) chunks.clear();
    if (chunks.size() != parameterCount) return std::nullopt;
    // A chunk's parameter name: its last identifier before a semantic, default value or array size.
    auto parameterName = [](const std::string& chunk) {
        std::string last;
        for (size_t i = 0; i < chunk.size();) {
            if (size_t end = skipCommentOrString(chunk, i); end != i) {
                i = end;
            } else if (chunk[i] == ':' || chunk[i] == '=' || chunk[i] == '[') {
                break;
            } else if (isIdentChar(chunk[i])) {
                size_t start = i;
                while (i < chunk.size() && isIdentChar(chunk[i])) ++i;
                last = chunk.substr(start, i - start);
            } else {
                ++i;
            }
        }
        return last;
    };
    std::string signature, lineBreaks;
    bool first = true;
    for (const std::string& chunk : chunks) {
        if (bound.count(parameterName(chunk))) {
            lineBreaks.append(static_cast<size_t>(std::count(chunk.begin(), chunk.end(), '\n')), '\n');
            continue;
        }
        signature += (first ? "" : ",") + lineBreaks + chunk;
        lineBreaks.clear();
        first = false;
    }
    std::string out = text.substr(0, nameAt) + newName +
                      text.substr(nameAt + name.size(), open + 1 - nameAt - name.size()) + signature +
                      lineBreaks;
    // The body: each use of a bound name (not a member `.name`) names the effect object.
    for (size_t i = close; i < text.size();) {
        if (size_t end = skipCommentOrString(text, i); end != i) {
            out.append(text, i, end - i);
            i = end;
        } else if (isIdentChar(text[i]) && (i == 0 || !isIdentChar(text[i - 1]))) {
            size_t start = i;
            while (i < text.size() && isIdentChar(text[i])) ++i;
            const std::string word = text.substr(start, i - start);
            size_t before = start;
            while (before > 0 && std::isspace(static_cast<unsigned char>(text[before - 1]))) --before;
            const auto found = bound.find(word);
            out += found != bound.end() && (before == 0 || text[before - 1] != '.') ? found->second : word;
        } else {
            out += text[i++];
        }
    }
    return out;
}

std::string bindCallArguments(const std::string& text, const std::set<std::string>& objects,
                              const CallBinder& binder) {
    std::string out;
    for (size_t i = 0; i < text.size();) {
        if (size_t end = skipCommentOrString(text, i); end != i) {
            out.append(text, i, end - i);
            i = end;
            continue;
        }
        if (!isIdentChar(text[i]) || (i > 0 && isIdentChar(text[i - 1]))) {
            out += text[i++];
            continue;
        }
        const size_t start = i;
        while (i < text.size() && isIdentChar(text[i])) ++i;
        const std::string word = text.substr(start, i - start);
        size_t before = start, open = i;
        while (before > 0 && std::isspace(static_cast<unsigned char>(text[before - 1]))) --before;
        while (open < text.size() && std::isspace(static_cast<unsigned char>(text[open]))) ++open;
        out += word;
        if (open >= text.size() || text[open] != '(' || (before > 0 && text[before - 1] == '.')) continue;
        // The arguments, split at the commas outside brackets.
        std::vector<std::string> arguments{""};
        size_t close = std::string::npos;
        int nesting = 0;
        for (size_t j = open + 1; j < text.size();) {
            if (size_t end = skipCommentOrString(text, j); end != j) {
                arguments.back().append(text, j, end - j);
                j = end;
                continue;
            }
            const char c = text[j++];
            if (c == '(' || c == '[' || c == '{') ++nesting;
            if ((c == ')' || c == ']' || c == '}') && nesting > 0) {
                --nesting;
            } else if (c == ')') {
                close = j - 1;
                break;
            } else if (c == ',' && nesting == 0) {
                arguments.emplace_back();
                continue;
            }
            arguments.back() += c;
        }
        if (close == std::string::npos) continue;
        if (arguments.size() == 1 && arguments[0].find_first_not_of(" \t\r\n") == std::string::npos)
            arguments.clear();
        std::map<size_t, std::string> passed;
        for (size_t a = 0; a < arguments.size(); ++a) {
            const size_t first = arguments[a].find_first_not_of(" \t\r\n");
            const size_t last = arguments[a].find_last_not_of(" \t\r\n");
            if (first == std::string::npos) continue;
            const std::string name = arguments[a].substr(first, last + 1 - first);
            if (objects.count(name)) passed[a] = name;
        }
        if (passed.empty()) continue;  // the arguments are scanned as the text goes on
        const std::optional<std::string> callee = binder(word, arguments.size(), passed);
        if (!callee) continue;
        out.resize(out.size() - word.size());
        out += *callee;
        out.append(text, i, open + 1 - i);
        std::string lineBreaks;
        bool firstKept = true;
        for (size_t a = 0; a < arguments.size(); ++a) {
            if (passed.count(a)) {
                lineBreaks.append(
                    static_cast<size_t>(std::count(arguments[a].begin(), arguments[a].end(), '\n')), '\n');
                continue;
            }
            out += (firstKept ? "" : ",") + lineBreaks + bindCallArguments(arguments[a], objects, binder);
            lineBreaks.clear();
            firstKept = false;
        }
        out += lineBreaks + ")";
        i = close + 1;
    }
    return out;
}

std::string regroupMatrixInitializer(const std::string& declaration, const TypeDesc& type) {
    if (type.shape != Shape::Matrix) return declaration;
    size_t count = static_cast<size_t>(type.rows * type.cols);
    for (int dim : type.arrayDims) count *= static_cast<size_t>(std::max(dim, 0));
    const size_t open = declaration.find('{');
    if (open == std::string::npos || declaration.find('=') > open) return declaration;
    // The values: the text between commas outside parentheses and brackets, braces left out.
    std::vector<std::string> values(1);
    int braces = 0, nesting = 0;
    size_t close = std::string::npos;
    for (size_t i = open; i < declaration.size() && close == std::string::npos; ++i) {
        const char c = declaration[i];
        if (nesting == 0 && (c == '{' || c == '}')) {
            braces += c == '{' ? 1 : -1;
            if (braces == 0) close = i;
            continue;
        }
        if (c == '(' || c == '[') ++nesting;
        if (c == ')' || c == ']') --nesting;
        if (c == ',' && nesting == 0)
            values.emplace_back();
        else
            values.back() += c;
    }
    if (close == std::string::npos) return declaration;
    // A trailing comma leaves blanks (and line breaks) after the last value.
    std::string trailing;
    if (values.back().find_first_not_of(" \t\r\n") == std::string::npos) {
        trailing = values.back();
        values.pop_back();
    }
    if (values.size() != count || values.size() == 1) return declaration;
    const size_t perMatrix = static_cast<size_t>(type.rows * type.cols);
    std::string list = "{";
    for (size_t i = 0; i < values.size(); ++i) {
        if (i % perMatrix == 0 && !type.arrayDims.empty()) list += i == 0 ? "{" : "}, {";
        list += values[i];
        if ((i + 1) % perMatrix != 0) list += ",";
    }
    list += type.arrayDims.empty() ? "" : "}";
    return declaration.substr(0, open) + list + trailing + "}" + declaration.substr(close + 1);
}

}  // namespace fx
