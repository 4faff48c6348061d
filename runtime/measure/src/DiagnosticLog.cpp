// DiagnosticLog: see DiagnosticLog.h.
#include <runtime/DiagnosticLog.h>

namespace runtime {

DiagnosticLog::DiagnosticLog(std::function<void(const std::string&)> onFirstSight)
    : mOnFirstSight(std::move(onFirstSight)) {}

void DiagnosticLog::report(const fx::Diagnostic& diagnostic) {
    if (diagnostic.severity == fx::Severity::Note) return;
    if (diagnostic.severity == fx::Severity::Error) {
        ++mErrorCount;
        mRecent.push_back(fx::renderDiagnostic(diagnostic, false));
    }
    const std::string text = fx::renderDiagnostic(diagnostic);
    if (mSeen.insert(text).second && mOnFirstSight) mOnFirstSight(text);
}

std::string DiagnosticLog::firstError(const std::string& fallback) const {
    return mRecent.empty() ? fallback : mRecent.front();
}

std::string DiagnosticLog::takeErrors(size_t count) {
    std::string text;
    for (size_t i = 0; i < mRecent.size() && i < count; ++i) {
        const std::string& message = mRecent[i];
        text += (text.empty() ? "" : "; ") + message.substr(0, message.find('\n'));
    }
    mark();
    return text;
}

}  // namespace runtime
