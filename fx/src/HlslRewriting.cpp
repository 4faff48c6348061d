// HlslRewriting: see HlslRewriting.h.
#include "HlslRewriting.h"

#include <cctype>

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

}  // namespace fx
