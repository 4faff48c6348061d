// Preprocessor: glslang's preprocessor with an effect-aware includer; its errors become diagnostics.
#include "Preprocessor.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <fstream>
#include <mutex>
#include <sstream>

namespace fx::detail {

namespace {

void initializeGlslang() {
    static std::once_flag once;
    std::call_once(once, [] { glslang::InitializeProcess(); });
}

std::optional<std::string> readFromDisk(const std::string& path) {
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
    EffectIncluder(const ParseOptions& options, PreprocessedSource& out, size_t totalBytes)
        : mOptions(options), mOut(out), mTotalBytes(totalBytes) {}

    IncludeResult* includeSystem(const char* headerName, const char* includerName, size_t depth) override {
        return include(headerName, includerName, depth, /*system*/ true);
    }
    IncludeResult* includeLocal(const char* headerName, const char* includerName, size_t depth) override {
        return include(headerName, includerName, depth, /*system*/ false);
    }
    void releaseInclude(IncludeResult* result) override { delete result; }

    // Why the include of `headerName` failed (for the "Could not process include" error), if it did.
    std::map<std::string, std::string> failures;

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

        if (static_cast<int>(depth) > mOptions.maxIncludeDepth) {
            failures[headerName] = "include depth exceeds " + std::to_string(mOptions.maxIncludeDepth) +
                                   (isOnChain(header, includer) ? " (recursive include of '" + header + "')" : "");
            return nullptr;
        }
        std::vector<std::string> candidates;
        if (!header.empty() && header[0] == '/')
            candidates.push_back(header);
        else {
            candidates.push_back(normalizePath(folderOf(includer) + header));
            for (const std::string& dir : mOptions.includeDirs)
                candidates.push_back(normalizePath(dir.empty() ? header : dir + "/" + header));
        }
        for (const std::string& candidate : candidates) {
            std::optional<std::string> text =
                mOptions.readFile ? mOptions.readFile(candidate) : readFromDisk(candidate);
            if (!text) continue;
            mTotalBytes += text->size();
            if (mTotalBytes > mOptions.maxSourceBytes) {
                failures[headerName] = "sources exceed " + std::to_string(mOptions.maxSourceBytes) + " bytes in total";
                return nullptr;
            }
            mParents[candidate] = includer;
            auto stored = mOut.files.emplace(candidate, std::move(*text)).first;
            bool seen = false;
            for (const std::string& file : mOut.includedFiles) seen = seen || file == candidate;
            if (!seen) mOut.includedFiles.push_back(candidate);
            return new IncludeResult(candidate, stored->second.data(), stored->second.size(), nullptr);
        }
        failures[headerName] = "";
        return nullptr;
    }

    bool isOnChain(const std::string& header, std::string file) {
        for (int guard = 0; guard < 1000 && !file.empty(); ++guard) {
            bool endsWith = file.size() >= header.size() + 1 &&
                            file.compare(file.size() - header.size(), header.size(), header) == 0 &&
                            file[file.size() - header.size() - 1] == '/';
            if (file == header || endsWith)
                return true;
            auto parent = mParents.find(file);
            if (parent == mParents.end()) return false;
            file = parent->second;
        }
        return false;
    }

    const ParseOptions& mOptions;
    PreprocessedSource& mOut;
    size_t mTotalBytes;
    std::map<std::string, std::string> mParents;
};

}  // namespace

std::string folderOf(const std::string& path) {
    size_t slash = path.find_last_of("/\\");
    return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

bool preprocessEffect(const std::string& source, const std::string& path, const ParseOptions& options,
                      DiagnosticSink& diagnostics, PreprocessedSource& out) {
    initializeGlslang();
    out.files[path] = source;
    out.includedFiles = {path};
    if (source.size() > options.maxSourceBytes) {
        diagnostics.report(DiagId::PreprocessorError, SourceLoc{path, 0, 0},
                           {"source exceeds " + std::to_string(options.maxSourceBytes) + " bytes"});
        return false;
    }

    std::string preamble;
    for (const auto& [name, value] : options.defines) preamble += "#define " + name + " " + value + "\n";

    glslang::TShader shader(EShLangFragment);
    const std::string& mainText = out.files[path];
    const char* strings[] = {mainText.c_str()};
    const int lengths[] = {static_cast<int>(mainText.size())};
    const char* names[] = {path.c_str()};
    shader.setStringsWithLengthsAndNames(strings, lengths, names, 1);
    shader.setEnvInput(glslang::EShSourceHlsl, EShLangFragment, glslang::EShClientVulkan, 100);
    shader.setEntryPoint("main");
    if (!preamble.empty()) shader.setPreamble(preamble.c_str());

    EffectIncluder includer(options, out, source.size());
    std::string text;
    auto messages = static_cast<EShMessages>(EShMsgReadHlsl | EShMsgOnlyPreprocessor);
    bool ok = shader.preprocess(GetDefaultResources(), 100, ENoProfile, false, false, messages, &text, includer);

    // Log lines: "ERROR: file:line: 'token' : message" (also "WARNING: ..."); the summary line has no location.
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

        const std::string kIncludeFailure = "Could not process include directive for header name: ";
        size_t includeAt = message.find(kIncludeFailure);
        if (includeAt != std::string::npos) {
            std::string header = message.substr(includeAt + kIncludeFailure.size());
            // Point at the header name's opening quote or angle bracket.
            size_t quote = userLine.find_first_of("\"<", first == std::string::npos ? 0 : first);
            if (quote != std::string::npos) loc.column = static_cast<int>(quote) + 1;
            auto failure = includer.failures.find(header);
            if (failure != includer.failures.end() && !failure->second.empty())
                diagnostics.report(DiagId::PreprocessorError, loc,
                                   {"cannot include '" + header + "': " + failure->second});
            else
                diagnostics.report(DiagId::IncludeNotFound, loc, {header});
        } else {
            diagnostics.report(DiagId::PreprocessorError, loc, {message});
        }
        reported = true;
    }
    if (!ok && !reported) diagnostics.report(DiagId::PreprocessorError, SourceLoc{path, 0, 0}, {"preprocessing failed"});
    out.text = std::move(text);
    return ok && !reported;
}

}  // namespace fx::detail
