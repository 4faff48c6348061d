// Effect: helper methods of the effect syntax tree (expression spelling, source map, finders); the type
// names are Types.cpp's.
#include <fx/Effect.h>
#include <fx/RenderStates.h>

#include <algorithm>
#include <charconv>

namespace fx {

// [SECTION] Expr

namespace {

std::string numberText(double value, bool isInteger) {
    if (isInteger && value >= -9.2e18 && value <= 9.2e18)
        return std::to_string(static_cast<long long>(value));
    char buffer[64];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    std::string text(buffer, result.ptr);
    if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
    return text;
}

std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        if (c == '\n') {
            out += "\\n";
            continue;
        }
        out += c;
    }
    return out + "\"";
}

std::string argList(const std::vector<Expr>& args, size_t first = 0) {
    std::string out;
    for (size_t i = first; i < args.size(); ++i) {
        if (i > first) out += ", ";
        out += args[i].str();
    }
    return out;
}

std::string operand(const Expr& e) {
    bool wrap = e.kind == Expr::Kind::Binary || e.kind == Expr::Kind::Ternary;
    return wrap ? "(" + e.str() + ")" : e.str();
}

}  // namespace

std::string Expr::str() const {
    switch (kind) {
        case Kind::Number:
            return numberText(number, isInteger);
        case Kind::Bool:
            return number != 0 ? "true" : "false";
        case Kind::String:
            return quoted(text);
        case Kind::Identifier:
            return text;
        case Kind::Unary:
            return text + (args.empty() ? std::string() : operand(args[0]));
        case Kind::Binary:
            if (args.size() < 2) return text;
            return operand(args[0]) + " " + text + " " + operand(args[1]);
        case Kind::Ternary:
            if (args.size() < 3) return "?:";
            return operand(args[0]) + " ? " + operand(args[1]) + " : " + operand(args[2]);
        case Kind::Call:
            return text + "(" + argList(args) + ")";
        case Kind::Member:
            return (args.empty() ? std::string() : operand(args[0])) + "." + text;
        case Kind::Index:
            if (args.size() < 2) return "[]";
            return operand(args[0]) + "[" + args[1].str() + "]";
        case Kind::InitList:
            return "{" + argList(args) + "}";
        case Kind::TextureRef:
            return "<" + text + ">";
        case Kind::Compile:
            return "compile " + profile + " " + text + "(" + argList(args) + ")";
        case Kind::Cast:
            return "(" + castType.hlslName() + ")" + (args.empty() ? std::string() : operand(args[0]));
    }
    return "?";
}

// [SECTION] SourceMap

void SourceMap::add(const std::string& file, int line, int preprocessedColumn, int column, bool fromMacro) {
    auto& columns = mColumns[{file, line}];
    auto it = std::lower_bound(columns.begin(), columns.end(), preprocessedColumn,
                               [](const TokenColumn& entry, int p) { return entry.preprocessed < p; });
    if (it != columns.end() && it->preprocessed == preprocessedColumn)
        *it = TokenColumn{preprocessedColumn, column, fromMacro};
    else
        columns.insert(it, TokenColumn{preprocessedColumn, column, fromMacro});
}

SourceLoc SourceMap::map(const SourceLoc& preprocessed) const {
    SourceLoc out = preprocessed;
    auto found = mColumns.find({preprocessed.file, preprocessed.line});
    if (found == mColumns.end() || found->second.empty()) return out;
    const auto& columns = found->second;
    auto it =
        std::upper_bound(columns.begin(), columns.end(), preprocessed.column,
                         [](int column, const TokenColumn& entry) { return column < entry.preprocessed; });
    if (it == columns.begin()) return out;  // before the first token: leave as is
    --it;
    // Keep the offset inside a token the user wrote; a macro's expansion stands at the macro's name.
    out.column = it->fromMacro ? it->user : it->user + (preprocessed.column - it->preprocessed);
    return out;
}

void SourceMap::addExpansion(MacroExpansion expansion) {
    auto key = std::make_tuple(expansion.use.file, expansion.use.line, expansion.use.column);
    mExpansions.insert_or_assign(std::move(key), std::move(expansion));
}

const SourceMap::MacroExpansion* SourceMap::expansionAt(const SourceLoc& loc) const {
    auto found = mExpansions.find(std::make_tuple(loc.file, loc.line, loc.column));
    return found == mExpansions.end() ? nullptr : &found->second;
}

// [SECTION] Finders

namespace {
const Annotation* findAnnotation(const std::vector<Annotation>& annotations, const std::string& name) {
    for (const Annotation& annotation : annotations)
        if (equalsIgnoreCase(annotation.name, name)) return &annotation;
    return nullptr;
}
}  // namespace

const FunctionAttribute* FunctionDecl::attribute(const std::string& attributeName) const {
    for (const FunctionAttribute& a : attributes)
        if (equalsIgnoreCase(a.name, attributeName)) return &a;
    return nullptr;
}

const Annotation* Parameter::annotation(const std::string& annotationName) const {
    return findAnnotation(annotations, annotationName);
}
const Annotation* Pass::annotation(const std::string& annotationName) const {
    return findAnnotation(annotations, annotationName);
}
const Annotation* Technique::annotation(const std::string& annotationName) const {
    return findAnnotation(annotations, annotationName);
}

const Parameter* Effect::findParameter(const std::string& name) const {
    for (const Parameter& parameter : parameters)
        if (parameter.name == name) return &parameter;
    return nullptr;
}

const StructDecl* Effect::findStruct(const std::string& name) const {
    for (const StructDecl& decl : structs)
        if (decl.name == name) return &decl;
    return nullptr;
}

const Technique* Effect::findTechnique(const std::string& name) const {
    for (const Technique& technique : techniques)
        if (technique.name == name) return &technique;
    for (const Technique& technique : techniques)
        if (!technique.group.empty() && technique.group + "." + technique.name == name) return &technique;
    return nullptr;
}

std::vector<const FunctionDecl*> Effect::findFunctions(const std::string& name) const {
    std::vector<const FunctionDecl*> out;
    for (const FunctionDecl& function : functions)
        if (function.name == name) out.push_back(&function);
    return out;
}

}  // namespace fx
