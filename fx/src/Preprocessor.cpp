// Preprocessor: glslang's preprocessor with an effect-aware includer; its errors become diagnostics.
#include "Preprocessor.h"

#include "CaseBlindPath.h"
#include "FxcDirectives.h"
#include "SourceText.h"
#include "StringEscapes.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>

namespace fx::detail {

namespace {

// glslang's preprocessor follows GLSL, which has no stringizing operator, but D3DX's has, and real FX
// Composer headers use it (NVIDIA's Quad.fxh: `string Format = #PixFmt;`). Inside #define bodies,
// `#param` becomes `__fx_stringize__ param`: glslang then substitutes the argument, and the lexer turns
// the marker and the token after it into one string literal. Token pasting (`##`) is left alone.
std::string markStringizing(const std::string& source) {
    std::string out;
    out.reserve(source.size());
    bool inDefine = false;
    bool lineStart = true;
    for (size_t i = 0; i < source.size(); ++i) {
        const char c = source[i];
        if (c == '\n') {
            // A define continues over backslash-newline.
            const bool continued = !out.empty() && out.back() == '\\';
            if (!continued) inDefine = false;
            lineStart = true;
            out += c;
            continue;
        }
        if (lineStart && c == '#') {
            size_t word = source.find_first_not_of(" \t", i + 1);
            inDefine = word != std::string::npos && source.compare(word, 6, "define") == 0;
            lineStart = false;
            out += c;
            continue;
        }
        if (lineStart && c != ' ' && c != '\t') lineStart = false;
        if (inDefine && c == '"') {  // copy string literals untouched
            size_t close = i + 1;
            while (close < source.size() && source[close] != '"' && source[close] != '\n')
                close += source[close] == '\\' ? 2 : 1;
            out.append(source, i, std::min(close + 1, source.size()) - i);
            i = std::min(close, source.size() - 1);
            continue;
        }
        if (inDefine && c == '#') {
            const bool pasting =
                (i + 1 < source.size() && source[i + 1] == '#') || (!out.empty() && out.back() == '#');
            const size_t next = source.find_first_not_of(" \t", i + 1);
            if (!pasting && next != std::string::npos &&
                (std::isalpha(static_cast<unsigned char>(source[next])) || source[next] == '_')) {
                out += "__fx_stringize__ ";
                continue;
            }
        }
        out += c;
    }
    return out;
}

// Bytes HLSL cannot contain outside comments and string literals: control characters, '@', '$', '`',
// and anything above ASCII (stray UTF-8 or Latin-1). glslang's preprocessor turned them into tokens such
// as "bad" or "<", so the user read "unknown type 'bad'" or "found '<'" instead of the character. Comments
// and strings may hold any bytes (FX Composer files have Latin-1 comments and UIName strings).
// Reports the first bad character of each line, at most 20, and returns false if there was any.
// A NUL byte is an error anywhere, comments and strings included: no text editor writes one, so the file
// is not what its author meant (a truncated save, a binary file).
bool checkCharacters(const std::string& text, const std::string& file, DiagnosticSink& diagnostics) {
    if (size_t nul = text.find('\0'); nul != std::string::npos) {
        const int nulLine = 1 + static_cast<int>(std::count(text.begin(), text.begin() + nul, '\n'));
        const size_t nulLineStart =
            text.rfind('\n', nul) == std::string::npos ? 0 : text.rfind('\n', nul) + 1;
        diagnostics.report(DiagId::InvalidCharacter,
                           SourceLoc{file, nulLine, static_cast<int>(nul - nulLineStart) + 1}, {"\\x00"});
        return false;
    }
    int line = 1, reported = 0, lastReportedLine = 0;
    size_t lineStart = 0;
    size_t i = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;  // a UTF-8 byte order mark is fine
    for (; i < text.size() && reported < 20; ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c == '\n') {
            ++line;
            lineStart = i + 1;
        } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
            while (i + 1 < text.size() && text[i + 1] != '\n') ++i;
        } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
            for (i += 2; i < text.size() && !(text[i] == '*' && i + 1 < text.size() && text[i + 1] == '/');
                 ++i)
                if (text[i] == '\n') ++line, lineStart = i + 1;
            ++i;  // the '/' (or past the end: the preprocessor reports the open comment)
        } else if (c == '"') {
            while (i + 1 < text.size() && text[i + 1] != '"' && text[i + 1] != '\n')
                i += text[i + 1] == '\\' ? 2 : 1;
            if (i + 1 < text.size() && text[i + 1] == '"') ++i;
        } else if ((c < 0x20 && c != '\t' && c != '\r' && c != '\f' && c != '\v') || c >= 0x7f || c == '@' ||
                   c == '$' || c == '`') {
            if (line != lastReportedLine) {
                char shown[8];
                if (c < 0x20 || c >= 0x7f)
                    std::snprintf(shown, sizeof shown, "\\x%02X", c);
                else
                    std::snprintf(shown, sizeof shown, "%c", c);
                diagnostics.report(DiagId::InvalidCharacter,
                                   SourceLoc{file, line, static_cast<int>(i - lineStart) + 1}, {shown});
                lastReportedLine = line;
                ++reported;
            }
        }
    }
    return reported == 0;
}

void initializeGlslang() {
    static std::once_flag once;
    std::call_once(once, [] { glslang::InitializeProcess(); });
}

std::optional<std::string> readFromDisk(const std::string& path) {
    // An ifstream opens a directory and reads it as empty: `#include "include"` would silently succeed.
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) return std::nullopt;
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) return std::nullopt;
    return text.str();
}

// "a/./b/../c" -> "a/c"; keeps leading "../" and a leading '/'.
std::string normalizePath(const std::string& path) {
    bool absolute = !path.empty() && path[0] == '/';
    std::vector<std::string> parts;
    std::string part;
    std::istringstream in(path);
    while (std::getline(in, part, '/')) {
        if (part.empty() || part == ".") continue;
        if (part == ".." && !parts.empty() && parts.back() != "..") {
            parts.pop_back();
            continue;
        }
        if (part == ".." && absolute) continue;
        parts.push_back(part);
    }
    std::string out = absolute ? "/" : "";
    for (size_t i = 0; i < parts.size(); ++i) out += (i ? "/" : "") + parts[i];
    return out;
}

std::string lineOf(const std::string& text, int line) {
    size_t start = 0;
    for (int i = 1; i < line; ++i) {
        start = text.find('\n', start);
        if (start == std::string::npos) return {};
        ++start;
    }
    size_t end = text.find('\n', start);
    return text.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

class EffectIncluder : public glslang::TShader::Includer {
public:
    EffectIncluder(const ParseOptions& options, PreprocessedSource& out, size_t totalBytes,
                   FxcDirectives& directives, DiagnosticSink& diagnostics)
        : mOptions(options),
          mOut(out),
          mTotalBytes(totalBytes),
          mDirectives(directives),
          mDiagnostics(diagnostics) {}

    IncludeResult* includeSystem(const char* headerName, const char* includerName, size_t depth) override {
        return include(headerName, includerName, depth, /*system*/ true);
    }
    IncludeResult* includeLocal(const char* headerName, const char* includerName, size_t depth) override {
        return include(headerName, includerName, depth, /*system*/ false);
    }
    void releaseInclude(IncludeResult* result) override { delete result; }

    // Why the include of `headerName` failed (for the "Could not process include" error), if it did: the
    // diagnostic and its arguments after the name as written.
    struct Failure {
        DiagId id;
        std::vector<std::string> args;
    };
    std::map<std::string, Failure> failures;
    // Includes found only by ignoring case: the including file, the name as written, the file opened.
    struct CaseMismatch {
        std::string includer, header, found;
    };
    std::vector<CaseMismatch> caseMismatches;

private:
    IncludeResult* include(const char* headerName, const char* includerName, size_t depth, bool system) {
        std::string header = headerName;
        for (char& c : header)
            if (c == '\\') c = '/';
        // "a\\b.fxh" written with an escaped backslash becomes "a//b.fxh": collapse.
        std::string collapsed;
        for (char c : header)
            if (!(c == '/' && !collapsed.empty() && collapsed.back() == '/')) collapsed += c;
        header = collapsed;
        std::string includer = includerName ? includerName : "";

        // glslang tries a "..." include as local first, then as system; resolve everything in one go.
        if (!system) return nullptr;

        if (header.empty()) {  // `#include ""` would otherwise resolve to the including file's folder
            failures[headerName] = {DiagId::IncludeFileNameEmpty, {}};
            return nullptr;
        }

        if (static_cast<int>(depth) > mOptions.maxIncludeDepth) {
            const std::string depthLimit = std::to_string(mOptions.maxIncludeDepth);
            failures[headerName] = isOnChain(header, includer)
                                       ? Failure{DiagId::IncludeRecursive, {depthLimit, header}}
                                       : Failure{DiagId::IncludeDepthExceeded, {depthLimit}};
            return nullptr;
        }
        // D3DX and FX Composer look beside the including file, then beside the root effect, then in the
        // include paths.
        std::vector<std::string> candidates;
        if (!header.empty() && header[0] == '/')
            candidates.push_back(header);
        else {
            candidates.push_back(normalizePath(folderOf(includer) + header));
            candidates.push_back(normalizePath(folderOf(mOut.includedFiles.front()) + header));
            for (const std::string& dir : mOptions.includeDirs)
                candidates.push_back(normalizePath(dir.empty() ? header : dir + "/" + header));
        }
        // The systems these effects were written on have case-blind file names: a name that differs
        // only in case is found too (on disk only), with a warning, after every exact candidate.
        const size_t exactCandidates = candidates.size();
        if (!mOptions.readFile)
            for (size_t i = 0; i < exactCandidates; ++i)
                if (std::optional<std::string> found = findPathIgnoringCase(candidates[i]))
                    candidates.push_back(*found);
        for (size_t i = 0; i < candidates.size(); ++i) {
            const std::string& candidate = candidates[i];
            std::optional<std::string> text =
                mOptions.readFile ? mOptions.readFile(candidate) : readFromDisk(candidate);
            if (!text) continue;
            text = decodeSourceText(*text);
            if (i >= exactCandidates) caseMismatches.push_back({includer, headerName, candidate});
            mTotalBytes += text->size();
            if (mTotalBytes > mOptions.maxSourceBytes) {
                failures[headerName] = {DiagId::IncludeSourcesTooLarge,
                                        {std::to_string(mOptions.maxSourceBytes)}};
                return nullptr;
            }
            mParents[candidate] = includer;
            auto stored = mOut.files.emplace(candidate, markStringizing(*text)).first;
            // What glslang reads: rewritten once per file, however often it is included.
            auto forGlslang = mGlslangTexts.find(candidate);
            if (forGlslang == mGlslangTexts.end())
                forGlslang =
                    mGlslangTexts
                        .emplace(candidate, mDirectives.rewrite(
                                                hideStringEscapes(stored->second, candidate, mDiagnostics),
                                                candidate, mDiagnostics))
                        .first;
            bool seen = false;
            for (const std::string& file : mOut.includedFiles) seen = seen || file == candidate;
            if (!seen) mOut.includedFiles.push_back(candidate);
            return new IncludeResult(candidate, forGlslang->second.data(), forGlslang->second.size(),
                                     nullptr);
        }
        failures[headerName] = {DiagId::IncludeNotFound, {}};
        return nullptr;
    }

    bool isOnChain(const std::string& header, std::string file) {
        for (int guard = 0; guard < 1000 && !file.empty(); ++guard) {
            bool endsWith = file.size() >= header.size() + 1 &&
                            file.compare(file.size() - header.size(), header.size(), header) == 0 &&
                            file[file.size() - header.size() - 1] == '/';
            if (file == header || endsWith) return true;
            auto parent = mParents.find(file);
            if (parent == mParents.end()) return false;
            file = parent->second;
        }
        return false;
    }

    const ParseOptions& mOptions;
    PreprocessedSource& mOut;
    size_t mTotalBytes;
    FxcDirectives& mDirectives;
    DiagnosticSink& mDiagnostics;
    std::map<std::string, std::string> mParents;
    std::map<std::string, std::string> mGlslangTexts;  // by file; glslang reads them until it is done
};

}  // namespace

std::string folderOf(const std::string& path) {
    size_t slash = path.find_last_of("/\\");
    return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

bool preprocessEffect(const std::string& bytes, const std::string& path, const ParseOptions& options,
                      DiagnosticSink& diagnostics, PreprocessedSource& out) {
    initializeGlslang();
    const std::string source = decodeSourceText(bytes);
    out.files[path] = markStringizing(source);
    out.includedFiles = {path};
    if (source.size() > options.maxSourceBytes) {
        diagnostics.report(DiagId::SourceTooLarge, SourceLoc{path, 0, 0},
                           {std::to_string(options.maxSourceBytes)});
        return false;
    }
    if (!checkCharacters(source, path, diagnostics)) return false;

    // An effect sees fxc's predefined macros, which are none (fxc and D3DX documented no predefined
    // macro; DXC's __SHADER_TARGET_* came after them), not glslang's: engines' shared headers branch on
    // `#if defined(VULKAN)`.
    std::string preamble = FxcDirectives::undefineGlslangPredefines();
    for (const auto& [name, value] : options.defines) preamble += "#define " + name + " " + value + "\n";

    FxcDirectives directives;
    for (const auto& [name, value] : options.defines) directives.predefine(name, value);
    glslang::TShader shader(EShLangFragment);
    const std::string mainText =
        directives.rewrite(hideStringEscapes(out.files[path], path, diagnostics), path, diagnostics);
    const char* strings[] = {mainText.c_str()};
    const int lengths[] = {static_cast<int>(mainText.size())};
    const char* names[] = {path.c_str()};
    shader.setStringsWithLengthsAndNames(strings, lengths, names, 1);
    shader.setEnvInput(glslang::EShSourceHlsl, EShLangFragment, glslang::EShClientVulkan, 100);
    shader.setEntryPoint("main");
    shader.setPreamble(preamble.c_str());

    EffectIncluder includer(options, out, source.size(), directives, diagnostics);
    std::string text;
    auto messages = static_cast<EShMessages>(EShMsgReadHlsl | EShMsgOnlyPreprocessor);
    bool ok =
        shader.preprocess(GetDefaultResources(), 100, ENoProfile, false, false, messages, &text, includer);

    // Log lines: "ERROR: file:line: 'token' : message" (also "WARNING: ..."); the summary line has no
    // location.
    bool reported = false;
    std::istringstream log(shader.getInfoLog());
    std::string line;
    while (std::getline(log, line)) {
        if (line.rfind("ERROR: ", 0) != 0) continue;
        std::string rest = line.substr(7);
        SourceLoc loc{path, 0, 0};
        std::string message = rest;
        // Find "file:line: " where line is digits; the file may itself contain ':'.
        for (size_t colon = rest.find(':'); colon != std::string::npos; colon = rest.find(':', colon + 1)) {
            size_t digits = colon + 1;
            while (digits < rest.size() && isdigit(static_cast<unsigned char>(rest[digits]))) ++digits;
            if (digits > colon + 1 && digits < rest.size() && rest[digits] == ':') {
                loc.file = rest.substr(0, colon);
                loc.line = std::atoi(rest.substr(colon + 1, digits - colon - 1).c_str());
                message = rest.substr(digits + 1);
                break;
            }
        }
        if (loc.line == 0 && rest.find("compilation error") != std::string::npos) continue;
        while (!message.empty() && (message.front() == ' ')) message.erase(0, 1);
        while (!message.empty() && (message.back() == ' ' || message.back() == '\r')) message.pop_back();

        // The column: the first non-blank character of the user's line (the directive's '#').
        std::string userLine;
        if (auto file = out.files.find(loc.file); file != out.files.end() && loc.line > 0)
            userLine = lineOf(file->second, loc.line);
        size_t first = userLine.find_first_not_of(" \t");
        loc.column = loc.line > 0 ? static_cast<int>(first == std::string::npos ? 0 : first) + 1 : 0;

        // Without the trailing blank, which the trimming above removes when the name is empty (`#include
        // ""`).
        const std::string kIncludeFailure = "Could not process include directive for header name:";
        size_t includeAt = message.find(kIncludeFailure);
        if (includeAt != std::string::npos) {
            std::string header = message.substr(includeAt + kIncludeFailure.size());
            if (!header.empty() && header.front() == ' ') header.erase(0, 1);
            // Point at the header name's opening quote or angle bracket.
            size_t quote = userLine.find_first_of("\"<", first == std::string::npos ? 0 : first);
            if (quote != std::string::npos) loc.column = static_cast<int>(quote) + 1;
            auto failure = includer.failures.find(header);
            if (failure != includer.failures.end()) {
                std::vector<std::string> args = failure->second.args;
                args.insert(args.begin(), header);
                diagnostics.report(failure->second.id, loc, args);
            } else {
                diagnostics.report(DiagId::IncludeNotFound, loc, {header});
            }
        } else {
            diagnostics.report(DiagId::PreprocessorError, loc, {message});
        }
        reported = true;
    }
    for (const EffectIncluder::CaseMismatch& mismatch : includer.caseMismatches) {
        // Point at the directive that named the file.
        SourceLoc loc{mismatch.includer, 0, 0};
        if (auto file = out.files.find(mismatch.includer); file != out.files.end()) {
            std::istringstream lines(file->second);
            std::string text;
            for (int number = 1; std::getline(lines, text); ++number) {
                const size_t at = text.find(mismatch.header);
                if (at != std::string::npos && text.find("include") != std::string::npos) {
                    loc.line = number;
                    loc.column = static_cast<int>(at);
                    break;
                }
            }
        }
        diagnostics.report(DiagId::IncludeCaseMismatch, loc, {mismatch.header, mismatch.found});
    }
    if (!ok && !reported) diagnostics.report(DiagId::PreprocessingFailed, SourceLoc{path, 0, 0}, {});
    restoreStringEscapes(text);
    directives.takeUndefinedCallMarkers(text, diagnostics);
    directives.takeRedefinitionMarkers(text, diagnostics);
    out.text = std::move(text);
    return ok && !reported;
}

}  // namespace fx::detail
