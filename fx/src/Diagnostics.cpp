#include <fx/Diagnostics.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace fx {

std::string SourceLoc::str() const {
    std::string out = file.empty() ? std::string("<input>") : file;
    if (line > 0) {
        out += ":" + std::to_string(line);
        if (column > 0) out += ":" + std::to_string(column);
    }
    return out;
}

namespace {
struct DiagInfo {
    std::string_view name;
    Severity severity;
    std::string_view text;
};
constexpr DiagInfo kDiagInfo[] = {
#define FX_DIAGNOSTIC(id, severity, text) {#id, Severity::severity, text},
#include <fx/DiagnosticDefs.h>
};
}  // namespace

std::string_view diagnosticName(DiagId id) {
    return kDiagInfo[static_cast<size_t>(id)].name;
}
Severity defaultSeverity(DiagId id) {
    return kDiagInfo[static_cast<size_t>(id)].severity;
}
std::string_view diagnosticTemplate(DiagId id) {
    return kDiagInfo[static_cast<size_t>(id)].text;
}
std::optional<DiagId> findDiagnostic(std::string_view name) {
    for (size_t i = 0; i < std::size(kDiagInfo); ++i)
        if (kDiagInfo[i].name == name) return static_cast<DiagId>(i);
    return std::nullopt;
}

std::string_view severityName(Severity severity) {
    switch (severity) {
        case Severity::Note:
            return "note";
        case Severity::Warning:
            return "warning";
        case Severity::Error:
            return "error";
    }
    return "error";
}

std::string formatDiagnostic(DiagId id, const std::vector<std::string>& args) {
    std::string_view text = diagnosticTemplate(id);
    std::string out;
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '{' && i + 2 < text.size() && text[i + 2] == '}' && text[i + 1] >= '0' &&
            text[i + 1] <= '9') {
            size_t arg = static_cast<size_t>(text[i + 1] - '0');
            out += arg < args.size() ? args[arg] : std::string();
            i += 2;
        } else {
            out += text[i];
        }
    }
    return out;
}

void DiagnosticSink::report(DiagId id, const SourceLoc& loc, const std::vector<std::string>& args) {
    report(Diagnostic{id, defaultSeverity(id), loc, formatDiagnostic(id, args)});
}

bool DiagnosticList::hasErrors() const {
    return errorCount() > 0;
}

size_t DiagnosticList::errorCount() const {
    return static_cast<size_t>(std::count_if(
        mItems.begin(), mItems.end(), [](const Diagnostic& d) { return d.severity == Severity::Error; }));
}

std::string DiagnosticList::str() const {
    std::string out;
    for (const Diagnostic& d : mItems) out += renderDiagnostic(d, false) + "\n";
    return out;
}

namespace {
std::string renderOne(const Diagnostic& diagnostic, bool withSourceLine);
}

std::string renderDiagnostic(const Diagnostic& diagnostic, bool withSourceLine) {
    std::string out = renderOne(diagnostic, withSourceLine);
    for (const Diagnostic& note : diagnostic.notes) out += "\n" + renderDiagnostic(note, withSourceLine);
    return out;
}

namespace {
std::string renderOne(const Diagnostic& diagnostic, bool withSourceLine) {
    // A diagnostic about no file in particular (an unknown scene name) reads "error: message".
    std::string out = (diagnostic.loc.file.empty() ? std::string() : diagnostic.loc.str() + ": ") +
                      std::string(severityName(diagnostic.severity)) + ": " + diagnostic.message;
    if (!withSourceLine || diagnostic.loc.line <= 0 || diagnostic.loc.file.empty()) return out;
    std::ifstream in(diagnostic.loc.file, std::ios::binary);
    if (!in) return out;
    std::string line;
    for (int i = 0; i < diagnostic.loc.line && std::getline(in, line); ++i) {
    }
    if (!in) return out;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    out += "\n    " + line;
    if (diagnostic.loc.column > 0) {
        std::string caret;
        for (int i = 0; i + 1 < diagnostic.loc.column && i < static_cast<int>(line.size()); ++i)
            caret += line[static_cast<size_t>(i)] == '\t' ? '\t' : ' ';
        out += "\n    " + caret + "^";
    }
    return out;
}
}  // namespace

}  // namespace fx
