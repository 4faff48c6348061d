// DiagnosticLog: the diagnostics sink of the measuring tools (bench, check, stress). Many frames of many
// runs report the same warning again and again, and a failing step wants to name its first error in its
// result, so the log
//   - hands each distinct warning or error to `onFirstSight` once (the tool prints it; the library never
//     prints), notes dropped;
//   - counts every error, and keeps the errors reported since the last mark() for the step's result.
#pragma once

#include <fx/Diagnostics.h>

#include <functional>
#include <set>
#include <string>
#include <vector>

namespace runtime {

class DiagnosticLog : public fx::DiagnosticSink {
public:
    // `onFirstSight` gets fx::renderDiagnostic's text (with the source line and caret); may be empty.
    explicit DiagnosticLog(std::function<void(const std::string&)> onFirstSight = {});

    using fx::DiagnosticSink::report;
    void report(const fx::Diagnostic& diagnostic) override;

    int errors() const { return mErrorCount; }  // since construction
    // Errors since the last mark(), each "file:line:column: error: message" without the source line.
    void mark() { mRecent.clear(); }
    bool failed() const { return !mRecent.empty(); }
    std::string firstError(const std::string& fallback) const;
    // The first `count` errors since the last mark(), joined by "; " (a table cell); then mark().
    std::string takeErrors(size_t count = 4);

private:
    std::function<void(const std::string&)> mOnFirstSight;
    std::set<std::string> mSeen;
    std::vector<std::string> mRecent;
    int mErrorCount = 0;
};

}  // namespace runtime
