// HlslLegalization: see HlslLegalization.h.
//
// [SECTION] Edits of the preprocessed text
// [SECTION] Token walking
// [SECTION] The rewrites
// [SECTION] Helpers the rewrites call
// [SECTION] legalizeFunctions()
#include "HlslLegalization.h"

#include "HlslSpelling.h"
#include "TypeNames.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>

namespace fx::detail {

namespace {

// [SECTION] Edits of the preprocessed text

// Replaces text[begin, end) (an insertion where begin == end); offsets into the preprocessed text.
struct Edit {
    size_t begin = 0;
    size_t end = 0;
    std::string text;
};

// The text of text[begin, end) with the edits inside it applied (edits never overlap; insertions at one
// offset keep the order they were made in).
std::string applyEdits(const std::string& text, size_t begin, size_t end, std::vector<Edit> edits) {
    std::stable_sort(edits.begin(), edits.end(),
                     [](const Edit& a, const Edit& b) { return a.begin < b.begin; });
    std::string out;
    size_t at = begin;
    for (const Edit& e : edits) {
        if (e.begin < at || e.end > end) continue;  // overlapping: the first one made wins
        out.append(text, at, e.begin - at);
        out += e.text;
        at = e.end;
    }
    out.append(text, at, end - at);
    return out;
}

// [SECTION] Token walking

class FunctionTokens {
public:
    FunctionTokens(const std::vector<Token>& tokens, const FunctionTokenRange& range)
        : mTokens(tokens), mRange(range) {}

    size_t first() const { return mRange.first; }
    size_t last() const { return mRange.last; }
    const Token& at(size_t i) const { return mTokens[std::min(i, mRange.last)]; }
    bool is(size_t i, const char* spelling) const { return i <= mRange.last && mTokens[i].is(spelling); }
    bool isIdentifier(size_t i) const {
        return i <= mRange.last && mTokens[i].kind == Token::Kind::Identifier;
    }

    // The index of the bracket closing the one at `open` ('(', '[' or '{'), or last() + 1.
    size_t closing(size_t open) const {
        int depth = 0;
        for (size_t i = open; i <= mRange.last; ++i) {
            const Token& t = mTokens[i];
            if (t.is("(") || t.is("[") || t.is("{")) ++depth;
            if (t.is(")") || t.is("]") || t.is("}")) {
                if (--depth == 0) return i;
            }
        }
        return mRange.last + 1;
    }

    // The first and last token of each argument of the call whose '(' is at `open`; empty where the call
    // has no arguments, is not closed, or has an empty argument.
    std::vector<std::pair<size_t, size_t>> arguments(size_t open) const {
        const size_t close = closing(open);
        if (close > mRange.last || close == open + 1) return {};
        std::vector<std::pair<size_t, size_t>> args;
        size_t start = open + 1;
        for (size_t i = open + 1; i <= close; ++i) {
            if (is(i, "(") || is(i, "[")) i = closing(i);
            if (is(i, ",") || i == close) {
                if (i == start) return {};
                args.push_back({start, i - 1});
                start = i + 1;
            }
        }
        return args;
    }

    // After a postfix chain that starts at `i` (`.member`, `[index]`, `(arguments)`): the next token.
    size_t afterPostfix(size_t i) const {
        for (;;) {
            if (is(i, ".") && isIdentifier(i + 1))
                i += 2;
            else if (is(i, "[") || is(i, "("))
                i = closing(i) + 1;
            else
                return i;
        }
    }

    // After the unary expression that starts at `i`: a name or a parenthesized expression with its postfix
    // chain, a call, a literal; a prefix operator with its operand.
    size_t afterUnary(size_t i) const {
        if (is(i, "-") || is(i, "+") || is(i, "!") || is(i, "~")) return afterUnary(i + 1);
        if (is(i, "(")) return afterPostfix(closing(i) + 1);
        if (i > mRange.last) return i;
        return afterPostfix(i + 1);
    }

    // Whether a statement may start at `i`.
    bool startsStatement(size_t i) const {
        return i > mRange.first &&
               (is(i - 1, ";") || is(i - 1, "{") || is(i - 1, "}") || is(i - 1, ")") || is(i - 1, "else"));
    }

private:
    const std::vector<Token>& mTokens;
    const FunctionTokenRange& mRange;
};

bool isAssignmentOperator(const Token& t) {
    static const char* kOperators[] = {"=", "+=", "-=", "*=", "/=", "%=", "<<=", ">>=", "&=", "|=", "^="};
    return std::any_of(std::begin(kOperators), std::end(kOperators),
                       [&](const char* op) { return t.is(op); });
}

// A scalar or vector type name ("float", "half3"): its base's spelling and component count.
bool vectorTypeName(const std::string& name, std::string& base, int& components) {
    TypeDesc type;
    if (!parseScalarTypeName(name, type) || type.shape == Shape::Matrix) return false;
    components = type.shape == Shape::Vector ? type.cols : 1;
    base = components == 1 ? name : name.substr(0, name.size() - 1);
    return true;
}

// [SECTION] Helpers the rewrites call

std::string arrayCastName(const std::string& base, int n) {
    return "fx_to_array_" + base + "_" + std::to_string(n);
}

// `(T[N])v`: an array of the vector's first N components (an array type cannot be returned unnamed). One
// overload per vector size from N to 4, so that the cast's operand is no implicit truncation.
std::string arrayCastHelper(const std::string& base, int n) {
    const std::string array = "fx_array_" + base + "_" + std::to_string(n);
    std::string helper = "typedef " + base + " " + array + "[" + std::to_string(n) + "];\n";
    for (int size = n; size <= 4; ++size) {
        std::string components;
        for (int i = 0; i < n; ++i) components += (i ? ", v." : "v.") + std::string(1, "xyzw"[i]);
        if (size == 1) components = "v";
        helper += array + " " + arrayCastName(base, n) + "(" + base + (size > 1 ? std::to_string(size) : "") +
                  " v) { " + array + " a = { " + components + " }; return a; }\n";
    }
    return helper;
}

// `T(a, b) = e;`: one overload per way of splitting T's components among two or more l-values.
std::string lvalueConstructorHelper(const std::string& base, int n) {
    std::string out;
    const std::string vector = base + std::to_string(n);
    // Every composition of n into two or more parts: bit i of `cuts` set cuts after component i.
    for (unsigned cuts = 1; cuts < (1u << (n - 1)); ++cuts) {
        std::string params, body;
        int start = 0, part = 0;
        for (int i = 0; i < n; ++i) {
            if (i + 1 < n && !(cuts & (1u << i))) continue;
            const int size = i + 1 - start;
            const std::string name = "a" + std::to_string(part++);
            params += "out " + base + (size > 1 ? std::to_string(size) : "") + " " + name + ", ";
            body += name + " = v." +
                    std::string("xyzw").substr(static_cast<size_t>(start), static_cast<size_t>(size)) + "; ";
            start = i + 1;
        }
        out += "void fx_assign_" + vector + "(" + params + vector + " v) { " + body + "}\n";
    }
    return out;
}

// [SECTION] The rewrites

// What the rewrites of one effect need and produce.
class Legalizer {
public:
    Legalizer(const std::string& text, const std::function<bool(const Token&)>& isTypeName, Effect& effect,
              DiagnosticSink& diagnostics)
        : mText(text), mIsTypeName(isTypeName), mEffect(effect), mDiagnostics(diagnostics) {}

    void rewriteLocally(const FunctionTokens& f, std::vector<Edit>& edits) {
        for (size_t i = f.first(); i <= f.last(); ++i) {
            const Token& t = f.at(i);
            if (t.is("unsigned")) {
                // `unsigned int` and `unsigned` alone are both uint; `unsigned` was a reserved word to
                // glslang.
                edits.push_back({t.begin, t.end, "uint"});
                if (f.is(i + 1, "int")) edits.push_back({f.at(i + 1).begin, f.at(i + 1).end, ""});
            } else if (isKeywordUsedAsName(f, i)) {
                edits.push_back({t.begin, t.end, "fx_" + t.text});
            } else if (t.is("(") && f.isIdentifier(i + 1) && f.is(i + 2, "[") &&
                       f.at(i + 3).kind == Token::Kind::Number && f.is(i + 4, "]") && f.is(i + 5, ")")) {
                rewriteArrayCast(f, i, edits);
            } else if (f.isIdentifier(i) && f.isIdentifier(i + 1) && f.is(i + 2, "[") &&
                       f.at(i + 3).kind == Token::Kind::Number && f.is(i + 4, "]") && f.is(i + 5, "=") &&
                       f.is(i + 6, "{")) {
                regroupFlatInitializer(f, i, edits);
            } else if (t.is(".") && i > f.first() && f.isIdentifier(i - 1) && f.isIdentifier(i + 1) &&
                       f.is(i + 2, "(")) {
                rewriteVariableOffset(f, i - 1, edits);
            } else if (t.is(".") && i > f.first() && f.isIdentifier(i - 1) && f.is(i + 1, "Length") &&
                       !(i - 1 > f.first() && f.is(i - 2, "."))) {
                rewriteLength(f, i - 1, edits);
            } else if (t.is("for") && f.is(i + 1, "(") && mIsTypeName(f.at(i + 2)) && f.isIdentifier(i + 3)) {
                hoistLoopVariable(f, i, edits);
            } else if (f.isIdentifier(i) && f.is(i + 1, "(") && !mEffect.findFunctions(t.text).empty() &&
                       !(i > f.first() && (f.is(i - 1, ".") || mIsTypeName(f.at(i - 1))))) {
                truncateVectorArguments(f, i, edits);
            } else if (mIsTypeName(t) && f.isIdentifier(i + 1) && !mIsTypeName(f.at(i + 1)) &&
                       f.is(i + 2, "{")) {
                rewriteBraceInitializer(f, i, edits);
            } else if (f.startsStatement(i)) {
                rewriteLvalueConstructor(f, i, edits);
            }
        }
    }

    // The uniform parameters some function writes (they are not declared again in that function).
    std::set<std::string> writtenUniforms(const FunctionTokens& f) const {
        std::set<std::string> declared, written;
        for (size_t i = f.first() + 1; i <= f.last(); ++i)
            if (f.isIdentifier(i) && mIsTypeName(f.at(i - 1))) declared.insert(f.at(i).text);
        for (size_t i = f.first(); i <= f.last(); ++i) {
            const Token& t = f.at(i);
            if (t.kind != Token::Kind::Identifier || (i > f.first() && f.is(i - 1, ".")) ||
                declared.count(t.text) || !isUniform(t.text))
                continue;
            const size_t after = f.afterPostfix(i + 1);
            const bool prefixed = i > f.first() && (f.is(i - 1, "++") || f.is(i - 1, "--"));
            if (prefixed || f.is(after, "++") || f.is(after, "--") ||
                (after <= f.last() && isAssignmentOperator(f.at(after))))
                written.insert(t.text);
        }
        return written;
    }

    // Every mention of a written uniform, in every function, names its static copy.
    void renameWritten(const FunctionTokens& f, const std::set<std::string>& written,
                       std::vector<Edit>& edits) const {
        for (size_t i = f.first(); i <= f.last(); ++i) {
            const Token& t = f.at(i);
            if (t.kind == Token::Kind::Identifier && written.count(t.text) &&
                !(i > f.first() && f.is(i - 1, ".")))
                edits.push_back({t.begin, t.end, copyName(t.text)});
        }
    }

    static std::string copyName(const std::string& uniform) { return "fx_mutable_" + uniform; }

    // The declarations the rewrites call, each once, in the order first needed: those that name nothing
    // of the effect's, and by parameter those that must follow its declaration.
    const std::vector<std::string>& helpers() const { return mHelpers; }
    std::map<std::string, std::vector<std::string>>& afterParameter() { return mAfterParameter; }

private:
    bool isUniform(const std::string& name) const {
        const Parameter* p = mEffect.findParameter(name);
        return p && !p->isStatic && !p->isConst && p->type.base != BaseType::String &&
               (isNumericType(p->type) || p->type.base == BaseType::Struct);
    }

    // `line`, `point`, `linear` and the other words glslang reserves as modifiers, where fxc let a
    // program name a variable so: a modifier is always followed by a type or another modifier, a name never.
    bool isKeywordUsedAsName(const FunctionTokens& f, size_t i) const {
        static const std::set<std::string> kModifiers = {
            "line",   "point",    "triangle",        "lineadj",       "triangleadj",
            "linear", "centroid", "nointerpolation", "noperspective", "precise"};
        const Token& t = f.at(i);
        return t.kind == Token::Kind::Identifier && kModifiers.count(t.text) && !f.isIdentifier(i + 1) &&
               !(i > f.first() && f.is(i - 1, "."));
    }

    // `(T[N]) operand` -> `fx_to_array_T_N(operand)`.
    void rewriteArrayCast(const FunctionTokens& f, size_t open, std::vector<Edit>& edits) {
        std::string base;
        int components = 0;
        const Token& count = f.at(open + 3);
        if (!vectorTypeName(f.at(open + 1).text, base, components) || components != 1 || !count.isInteger ||
            count.number < 1 || count.number > 4)
            return;
        const int n = static_cast<int>(count.number);
        const size_t operand = open + 6, after = f.afterUnary(operand);
        if (operand > f.last() || after > f.last() + 1) return;
        const std::string name = arrayCastName(base, n);
        edits.push_back({f.at(open).begin, f.at(open + 5).end, name + "("});
        edits.push_back({f.at(after - 1).end, f.at(after - 1).end, ")"});
        need(name, [&] { return arrayCastHelper(base, n); });
    }

    // `float4 v[3] = { 0, 0, ... };` with 12 scalars -> `{ float4(0, 0, 0, 0), ... }`: fxc filled an array
    // of vectors from a flat list, glslang wants one constructor per element.
    void regroupFlatInitializer(const FunctionTokens& f, size_t type, std::vector<Edit>& edits) const {
        std::string base;
        int components = 0;
        const Token& count = f.at(type + 3);
        if (!vectorTypeName(f.at(type).text, base, components) || components < 2 || !count.isInteger) return;
        const size_t open = type + 6, close = f.closing(open);
        std::vector<std::pair<size_t, size_t>> elements;  // first and last token of each
        size_t start = open + 1;
        for (size_t i = open + 1; i <= close && close <= f.last(); ++i) {
            if (f.is(i, "{")) return;  // already grouped
            if (f.is(i, "(") || f.is(i, "[")) i = f.closing(i);
            if (f.is(i, ",") || i == close) {
                if (i > start) elements.push_back({start, i - 1});
                start = i + 1;
            }
        }
        if (elements.size() != static_cast<size_t>(count.number) * static_cast<size_t>(components) ||
            count.number < 2)
            return;
        for (size_t e = 0; e < elements.size(); e += static_cast<size_t>(components)) {
            edits.push_back(
                {f.at(elements[e].first).begin, f.at(elements[e].first).begin, f.at(type).text + "("});
            const Token& last = f.at(elements[e + static_cast<size_t>(components) - 1].second);
            edits.push_back({last.end, last.end, ")"});
        }
    }

    // `T(a, b) = e;` -> `fx_assign_T(a, b, e);`.
    // `for (int i = 0; ...) body ... i` -> `int i; for ( i = 0; ...) body ... i`: fxc declared a `for`'s
    // variable in the enclosing block, so code after the loop may read it; glslang scopes it to the loop.
    // Only where the block reads the name after the loop (before declaring it again), and the loop
    // declares one variable.
    void hoistLoopVariable(const FunctionTokens& f, size_t loop, std::vector<Edit>& edits) {
        const size_t close = f.closing(loop + 1);
        const std::string& name = f.at(loop + 3).text;
        int depth = 0;
        for (size_t i = loop + 4; i < close; ++i) {
            if (f.is(i, "(") || f.is(i, "[") || f.is(i, "{")) ++depth;
            if (f.is(i, ")") || f.is(i, "]") || f.is(i, "}")) --depth;
            if (depth == 0 && f.is(i, ";")) break;
            if (depth == 0 && f.is(i, ",")) return;
        }
        // The body: a block, or one simple statement.
        size_t bodyEnd = close + 1;
        if (f.is(bodyEnd, "{")) {
            bodyEnd = f.closing(bodyEnd);
        } else {
            if (f.is(bodyEnd, "for") || f.is(bodyEnd, "if") || f.is(bodyEnd, "while") || f.is(bodyEnd, "do"))
                return;
            for (depth = 0; bodyEnd <= f.last() && !(depth == 0 && f.is(bodyEnd, ";")); ++bodyEnd) {
                if (f.is(bodyEnd, "(") || f.is(bodyEnd, "[") || f.is(bodyEnd, "{")) ++depth;
                if (f.is(bodyEnd, ")") || f.is(bodyEnd, "]") || f.is(bodyEnd, "}")) --depth;
            }
        }
        bool readAfter = false;
        depth = 0;
        for (size_t i = bodyEnd + 1; i <= f.last() && !readAfter; ++i) {
            if (f.is(i, "{")) ++depth;
            if (f.is(i, "}") && --depth < 0) break;
            if (!f.isIdentifier(i) || f.at(i).text != name || f.is(i - 1, ".")) continue;
            if (mIsTypeName(f.at(i - 1))) break;  // declared again: a name of its own from here
            readAfter = true;
        }
        if (!readAfter) return;
        // Before the loop's attributes (`[unroll(8)] for`), which belong to the loop.
        size_t start = loop;
        while (start > f.first() && f.is(start - 1, "]")) {
            size_t open = start - 1;
            for (int nesting = 0; open > f.first(); --open) {
                if (f.is(open, "]")) ++nesting;
                if (f.is(open, "[") && --nesting == 0) break;
            }
            start = open;
        }
        const Token& type = f.at(loop + 2);
        edits.push_back({f.at(start).begin, f.at(start).begin, type.text + " " + name + "; "});
        edits.push_back({type.begin, type.end, ""});
    }

    // C++'s brace initialization of a local, which fxc accepted: `float x{};` -> `float x = (float)0;`
    // (zero, as `{}` value-initializes), `float3 v{1, 2, 3}` -> `float3 v = float3(1, 2, 3)` and, for a
    // struct or a list with braces inside, `S s{a, b}` -> `S s = {a, b}`. The braces are replaced token by
    // token, so that a line break inside them stays.
    void rewriteBraceInitializer(const FunctionTokens& f, size_t type, std::vector<Edit>& edits) const {
        const size_t open = type + 2, close = f.closing(open);
        if (close > f.last() || !(f.is(close + 1, ";") || f.is(close + 1, ","))) return;
        const Token& name = f.at(type + 1);
        const std::string& spelling = f.at(type).text;
        if (close == open + 1) {
            edits.push_back({name.end, f.at(close).end, " = (" + spelling + ")0"});
            return;
        }
        TypeDesc numeric;
        bool constructor = parseScalarTypeName(spelling, numeric);
        for (size_t i = open + 1; i < close; ++i) constructor = constructor && !f.is(i, "{");
        edits.push_back({name.end, f.at(open).end, constructor ? " = " + spelling + "(" : " = {"});
        edits.push_back({f.at(close).begin, f.at(close).end, constructor ? ")" : "}"});
    }

    void rewriteLvalueConstructor(const FunctionTokens& f, size_t i, std::vector<Edit>& edits) {
        std::string base;
        int components = 0;
        if (!f.isIdentifier(i) || !f.is(i + 1, "(") || !vectorTypeName(f.at(i).text, base, components) ||
            components < 2)
            return;
        const size_t close = f.closing(i + 1);
        if (!f.is(close + 1, "=")) return;
        size_t end = close + 2;
        while (end <= f.last() && !f.is(end, ";"))
            end = f.is(end, "(") || f.is(end, "[") ? f.closing(end) + 1 : end + 1;
        if (end > f.last()) return;
        const std::string name = "fx_assign_" + f.at(i).text;
        edits.push_back({f.at(i).begin, f.at(i + 1).end, name + "("});
        // Token by token, so that a line break between them stays.
        edits.push_back({f.at(close).begin, f.at(close).end, ""});
        edits.push_back({f.at(close + 1).begin, f.at(close + 1).end, ","});
        edits.push_back({f.at(end).begin, f.at(end).begin, ")"});
        need(name, [&] { return lvalueConstructorHelper(base, components); });
    }

    // `T.Sample(S, uv, offset)` (and the other methods of kOffsetArguments) with an offset GLSL would
    // refuse as not constant -> `T.Sample(S, fx_offset_uv_T(uv, offset))`: the offset in texels of level 0
    // added to the coordinate; `T.Load(location, offset)` -> `T.Load(fx_offset_texel_int3_int2(location,
    // offset))`, the offset added to the integer location (its mip level untouched).
    void rewriteVariableOffset(const FunctionTokens& f, size_t receiver, std::vector<Edit>& edits) {
        // Per method: the coordinate's argument, the offset's, and how many arguments may follow it
        // (a clamp, SampleGrad's included).
        struct OffsetArguments {
            size_t coordinate, offset, trailing;
        };
        static const std::map<std::string, OffsetArguments> kOffsetArguments = {
            {"Sample", {1, 2, 1}},     {"SampleLevel", {1, 3, 0}}, {"SampleBias", {1, 3, 1}},
            {"SampleGrad", {1, 4, 1}}, {"SampleCmp", {1, 3, 1}},   {"SampleCmpLevelZero", {1, 3, 0}},
            {"Load", {0, 1, 0}}};
        struct TextureShape {
            const char* coordinate;  // Sample's
            const char* location;    // Load's: the texel, then the layer, then the mip level
            const char* offset;
            const char* sizes;  // GetDimensions' outputs at level 0
            const char* step;   // the offset `o` in Sample's coordinate units
            const char* texel;  // the offset `o` as Load's location
        };
        static const std::map<BaseType, TextureShape> kShapes = {
            {BaseType::Texture1D, {"float", "int2", "int", "w", "float(o) / float(w)", "int2(o, 0)"}},
            {BaseType::Texture1DArray,
             {"float2", "int3", "int", "w, layers", "float2(float(o) / float(w), 0)", "int3(o, 0, 0)"}},
            {BaseType::Texture2D,
             {"float2", "int3", "int2", "w, h", "float2(o) / float2(w, h)", "int3(o, 0)"}},
            {BaseType::Texture2DArray,
             {"float3", "int4", "int2", "w, h, layers", "float3(float2(o) / float2(w, h), 0)",
              "int4(o, 0, 0)"}},
            {BaseType::Texture3D,
             {"float3", "int4", "int3", "w, h, d", "float3(o) / float3(w, h, d)", "int4(o, 0)"}}};
        const Parameter* texture = mEffect.findParameter(f.at(receiver).text);
        const auto method = kOffsetArguments.find(f.at(receiver + 2).text);
        if (!texture || !texture->type.arrayDims.empty() || !kShapes.count(texture->type.base) ||
            method == kOffsetArguments.end())
            return;
        const OffsetArguments& arguments = method->second;
        const TextureShape& shape = kShapes.at(texture->type.base);
        const std::vector<std::pair<size_t, size_t>> args = f.arguments(receiver + 3);
        if (args.size() <= arguments.offset || args.size() > arguments.offset + 1 + arguments.trailing)
            return;
        const auto [offsetFirst, offsetLast] = args[arguments.offset];
        bool constant = true;
        for (size_t i = offsetFirst; i <= offsetLast; ++i) {
            const Token& t = f.at(i);
            const Parameter* named =
                t.kind == Token::Kind::Identifier ? mEffect.findParameter(t.text) : nullptr;
            std::string base;
            int components = 0;
            if (t.kind == Token::Kind::Identifier && !vectorTypeName(t.text, base, components) &&
                !(named && named->isStatic && named->isConst))
                constant = false;
        }
        if (constant) return;
        const bool load = method->first == "Load";
        const std::string name = load ? std::string("fx_offset_texel_") + shape.location + "_" + shape.offset
                                      : "fx_offset_uv_" + texture->name;
        // The offset moves next to the coordinate on one line; the lines it spanned stay as line breaks.
        const auto [coordinateFirst, coordinateLast] = args[arguments.coordinate];
        const size_t removedBegin = f.at(offsetFirst - 1).begin, removedEnd = f.at(offsetLast).end;
        std::string offset = mText.substr(f.at(offsetFirst).begin, removedEnd - f.at(offsetFirst).begin);
        std::replace(offset.begin(), offset.end(), '\n', ' ');
        const std::string lineBreaks(
            static_cast<size_t>(std::count(mText.begin() + static_cast<std::ptrdiff_t>(removedBegin),
                                           mText.begin() + static_cast<std::ptrdiff_t>(removedEnd), '\n')),
            '\n');
        edits.push_back({f.at(coordinateFirst).begin, f.at(coordinateFirst).begin, name + "("});
        edits.push_back({f.at(coordinateLast).end, f.at(coordinateLast).end, ", " + offset + ")"});
        edits.push_back({removedBegin, removedEnd, lineBreaks});
        if (load) {
            need(name, [&] {
                return std::string(shape.location) + " " + name + "(" + shape.location + " location, " +
                       shape.offset + " o) { return location + " + shape.texel + "; }\n";
            });
            return;
        }
        if (!mNeeded.insert(name).second) return;
        mAfterParameter[texture->name].push_back(std::string(shape.coordinate) + " " + name + "(" +
                                                 shape.coordinate + " uv, " + shape.offset + " o) { uint " +
                                                 shape.sizes + "; " + texture->name + ".GetDimensions(" +
                                                 shape.sizes + "); return uv + " + shape.step + "; }");
    }

    // `F(v, ...)` where F is one of the effect's functions, of one signature, whose `in` parameter there is a
    // scalar, and `v` a vector -> `F(v.x, ...)`, with fxc's warning X3206: fxc passed the first component,
    // glslang finds no overload. Only where the argument is evidently a vector: a swizzle of two or more
    // components, or a name the calling function (before the call) or the effect declares with a vector
    // type. Any other argument is left to glslang, so a line's columns move only where fxc would have
    // truncated.
    void truncateVectorArguments(const FunctionTokens& f, size_t name, std::vector<Edit>& edits) {
        const std::vector<const FunctionDecl*> overloads = mEffect.findFunctions(f.at(name).text);
        const auto signature = [](const FunctionDecl& d) {
            std::string s;
            for (const FunctionParam& p : d.params)
                s += hlslTypeName(p.type) + arraySuffix(p.type) + static_cast<char>('0' + int(p.direction)) +
                     ",";
            return s;
        };
        for (const FunctionDecl* d : overloads)
            if (signature(*d) != signature(*overloads.front())) return;  // overloads: glslang chooses
        const FunctionDecl& callee = *overloads.front();
        const std::vector<std::pair<size_t, size_t>> args = f.arguments(name + 1);
        if (args.size() > callee.params.size()) return;
        for (size_t k = 0; k < args.size(); ++k) {
            const FunctionParam& p = callee.params[k];
            if (p.direction != FunctionParam::Direction::In || p.isUniform || p.type.shape != Shape::Scalar ||
                !p.type.arrayDims.empty() || !isNumericType(p.type))
                continue;
            const std::optional<std::string> vector = vectorOf(f, args[k].first, args[k].second, name);
            if (!vector) continue;
            const Token& last = f.at(args[k].second);
            edits.push_back({last.end, last.end, ".x"});
            mDiagnostics.report(DiagId::ImplicitVectorTruncation, f.at(args[k].first).loc,
                                {"'" + *vector + "' to '" + hlslTypeName(p.type) + "'"});
        }
    }

    // The vector type of the argument made of tokens first..last, where it is evidently one (see above).
    std::optional<std::string> vectorOf(const FunctionTokens& f, size_t first, size_t last,
                                        size_t call) const {
        const Token& t = f.at(first);
        if (t.kind != Token::Kind::Identifier) return std::nullopt;
        if (last == first + 2 && f.is(first + 1, ".") && f.isIdentifier(last)) {
            const std::string& swizzle = f.at(last).text;
            const bool components = swizzle.size() >= 2 && swizzle.size() <= 4 &&
                                    (swizzle.find_first_not_of("xyzw") == std::string::npos ||
                                     swizzle.find_first_not_of("rgba") == std::string::npos);
            const std::optional<std::string> swizzled = vectorOf(f, first, first, call);
            std::string base;
            int size = 0;
            if (!components || !swizzled || !vectorTypeName(*swizzled, base, size)) return std::nullopt;
            return base + std::to_string(swizzle.size());
        }
        if (last != first) return std::nullopt;
        // The nearest declaration before the call in a scope that encloses it: `T name` (a parameter or a
        // local); one inside a block closed before the call is another variable.
        int closedBlocks = 0;
        for (size_t i = call; i-- > f.first() + 1;) {
            if (f.is(i, "}")) ++closedBlocks;
            if (f.is(i, "{") && closedBlocks > 0) --closedBlocks;
            if (closedBlocks > 0 || !f.is(i, t.text.c_str()) || !f.isIdentifier(i) ||
                !mIsTypeName(f.at(i - 1)))
                continue;
            std::string base;
            int size = 0;
            if (f.is(i + 1, "[") || !vectorTypeName(f.at(i - 1).text, base, size) || size < 2)
                return std::nullopt;
            return f.at(i - 1).text;
        }
        const Parameter* global = mEffect.findParameter(t.text);
        if (global && global->type.shape == Shape::Vector && global->type.arrayDims.empty() &&
            isNumericType(global->type))
            return hlslTypeName(global->type);
        return std::nullopt;
    }

    // `T.Length` -> `fx_length_T()`: D3D10's size of a texture or buffer object, which fxc read as
    // GetDimensions without a mip level (level 0's size) and glslang refuses ("unexpected operator on
    // texture type"): a uint for Buffer and the 1D textures, uint2 for 2D and 1D arrays (the element count
    // last), uint3 for 3D and 2D arrays.
    void rewriteLength(const FunctionTokens& f, size_t receiver, std::vector<Edit>& edits) {
        struct LengthShape {
            const char* type;
            const char* sizes;  // GetDimensions' outputs
        };
        static const std::map<BaseType, LengthShape> kShapes = {
            {BaseType::Buffer, {"uint", "w"}},
            {BaseType::RWBuffer, {"uint", "w"}},
            {BaseType::Texture1D, {"uint", "w"}},
            {BaseType::RWTexture1D, {"uint", "w"}},
            {BaseType::Texture1DArray, {"uint2", "w, layers"}},
            {BaseType::Texture2D, {"uint2", "w, h"}},
            {BaseType::RWTexture2D, {"uint2", "w, h"}},
            {BaseType::Texture2DArray, {"uint3", "w, h, layers"}},
            {BaseType::RWTexture2DArray, {"uint3", "w, h, layers"}},
            {BaseType::Texture3D, {"uint3", "w, h, d"}},
            {BaseType::RWTexture3D, {"uint3", "w, h, d"}}};
        const Parameter* texture = mEffect.findParameter(f.at(receiver).text);
        if (!texture || !texture->type.arrayDims.empty() || !kShapes.count(texture->type.base)) return;
        // A parameter or local of the function by the same name hides the effect's texture; its size is
        // not known here.
        for (size_t i = f.first() + 1; i <= f.last(); ++i)
            if (f.at(i).text == texture->name && (mIsTypeName(f.at(i - 1)) || f.is(i - 1, ">"))) return;
        const LengthShape& shape = kShapes.at(texture->type.base);
        const std::string name = "fx_length_" + texture->name;
        edits.push_back({f.at(receiver).begin, f.at(receiver + 2).end, name + "()"});
        if (!mNeeded.insert(name).second) return;
        mAfterParameter[texture->name].push_back(
            std::string(shape.type) + " " + name + "() { uint " + shape.sizes + "; " + texture->name +
            ".GetDimensions(" + shape.sizes + "); return " + shape.type + "(" + shape.sizes + "); }");
    }

    template <typename Make>
    void need(const std::string& name, Make make) {
        if (mNeeded.insert(name).second) mHelpers.push_back(make());
    }

    const std::string& mText;  // the preprocessed text the tokens' offsets are into
    const std::function<bool(const Token&)>& mIsTypeName;
    Effect& mEffect;
    DiagnosticSink& mDiagnostics;
    std::set<std::string> mNeeded;
    std::vector<std::string> mHelpers;
    std::map<std::string, std::vector<std::string>> mAfterParameter;
};

}  // namespace

// [SECTION] legalizeFunctions()

void legalizeFunctions(const std::vector<Token>& tokens, const std::string& text,
                       const std::vector<FunctionTokenRange>& ranges,
                       const std::function<bool(const Token&)>& isTypeName, Effect& effect,
                       DiagnosticSink& diagnostics) {
    Legalizer legalizer(text, isTypeName, effect, diagnostics);
    std::set<std::string> written;
    for (const FunctionTokenRange& range : ranges) written.merge(legalizer.writtenUniforms({tokens, range}));
    for (const FunctionTokenRange& range : ranges) {
        const FunctionTokens f(tokens, range);
        std::vector<Edit> edits;
        legalizer.rewriteLocally(f, edits);
        legalizer.renameWritten(f, written, edits);
        if (!edits.empty())
            effect.functions[range.function].hlslText =
                applyEdits(text, tokens[range.first].begin, tokens[range.last].end, std::move(edits));
    }
    // fxc's backward-compatibility mode gave each shader its own modifiable copy of a uniform it writes:
    // a static initialized from the uniform, declared right after it.
    for (const std::string& name : written) {
        const Parameter& p = *effect.findParameter(name);
        const std::string type = p.type.base == BaseType::Struct ? p.type.structName : hlslTypeName(p.type);
        legalizer.afterParameter()[name].push_back("static " + type + " " + Legalizer::copyName(name) +
                                                   arraySuffix(p.type) + " = " + name + ";");
    }
    std::vector<DeclRef> order;
    for (const DeclRef& ref : effect.order) {
        order.push_back(ref);
        if (ref.kind != DeclRef::Kind::Parameter) continue;
        for (std::string& declaration : legalizer.afterParameter()[effect.parameters[ref.index].name]) {
            effect.verbatim.push_back({std::move(declaration), SourceLoc{}});
            order.push_back({DeclRef::Kind::Verbatim, effect.verbatim.size() - 1});
        }
    }
    // The helpers use no type of the effect's: first of all.
    std::vector<DeclRef> helpers;
    for (const std::string& helper : legalizer.helpers()) {
        effect.verbatim.push_back({helper, SourceLoc{}});
        helpers.push_back({DeclRef::Kind::Verbatim, effect.verbatim.size() - 1});
    }
    order.insert(order.begin(), helpers.begin(), helpers.end());
    effect.order = std::move(order);
}

}  // namespace fx::detail
