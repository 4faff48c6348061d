// Diagnostics: the library never prints and never exits. Every stage reports into a DiagnosticSink the
// caller passes in; the CLI prints "path:line:column: error: message" with the source line and a caret.
#pragma once

#include <fx/SourceLoc.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fx {

enum class Severity { Note, Warning, Error };

enum class DiagId {
#define FX_DIAGNOSTIC(id, severity, text) id,
#include <fx/DiagnosticDefs.h>
};

struct Diagnostic {
    DiagId id;
    Severity severity;
    SourceLoc loc;
    std::string message;  // the filled-in template
    // Notes that belong to this diagnostic and are printed after it, whatever a sink does with notes on
    // their own: where the macro expanded at `loc` was defined.
    std::vector<Diagnostic> notes = {};
};

// The stable name of an id ("UnknownState"), its default severity and its message template.
std::string_view diagnosticName(DiagId id);
Severity defaultSeverity(DiagId id);
std::string_view diagnosticTemplate(DiagId id);
// The id of a stable name; none if this shadowfx has no such id.
std::optional<DiagId> findDiagnostic(std::string_view name);
std::string_view severityName(Severity severity);  // "error", "warning", "note"

// Fills {0}, {1}, ... in the id's template.
std::string formatDiagnostic(DiagId id, const std::vector<std::string>& args);

class DiagnosticSink {
public:
    virtual ~DiagnosticSink() = default;
    virtual void report(const Diagnostic& diagnostic) = 0;

    // Convenience: build the message from the id's template and report it with its default severity.
    void report(DiagId id, const SourceLoc& loc, const std::vector<std::string>& args = {});
};

// Collects diagnostics in order; what tests and the CLI use.
class DiagnosticList : public DiagnosticSink {
public:
    using DiagnosticSink::report;
    void report(const Diagnostic& diagnostic) override { mItems.push_back(diagnostic); }

    const std::vector<Diagnostic>& items() const { return mItems; }
    bool hasErrors() const;
    size_t errorCount() const;
    void clear() { mItems.clear(); }
    // All diagnostics, one per line, as "file:line:column: severity: message".
    std::string str() const;

private:
    std::vector<Diagnostic> mItems;
};

// "file:line:column: error: message" plus, when the file can be read, the source line and a caret under
// the column; then its notes, each the same way. What the CLI prints.
std::string renderDiagnostic(const Diagnostic& diagnostic, bool withSourceLine = true);

}  // namespace fx
