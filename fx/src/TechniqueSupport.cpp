// TechniqueSupport: see TechniqueSupport.h.
#include "TechniqueSupport.h"

#include <algorithm>

namespace fx::detail {

std::optional<ShaderValueRefusal> unsupportedShaderValue(const Expr& value, const Effect&) {
    if (value.kind == Expr::Kind::Call && value.text == "BindInterfaces")
        return ShaderValueRefusal{DiagId::TechniqueRefusedDynamicLinkage,
                                  DiagId::AllTechniquesRefusedDynamicLinkage,
                                  "dynamic shader linkage (BindInterfaces) is not supported: GLSL has no "
                                  "interfaces to bind at run time"};
    return std::nullopt;
}

bool TechniqueRefusals::leaveOut(const Technique& technique, DiagnosticSink& diagnostics,
                                 std::vector<RefusedTechnique>& leftOut) {
    if (!mCurrent) return false;
    const std::string name = technique.name.empty() ? "(unnamed)" : technique.name;
    diagnostics.report(mCurrent->refusal.warning, mCurrent->loc, {name});
    if (!mFirst) mFirst = Refused{name, mCurrent->refusal, mCurrent->loc};
    leftOut.push_back({name, technique.group, mCurrent->refusal.reason, mCurrent->loc});
    mCurrent.reset();
    return true;
}

bool reportUnsupportedTechniques(
    const std::vector<std::pair<const Technique*, std::vector<Diagnostic>>>& techniques, bool anotherRuns,
    DiagnosticSink& diagnostics, std::vector<RefusedTechnique>& leftOut) {
    bool reportedErrors = false;
    for (const auto& [technique, reasons] : techniques) {
        const std::string name = technique->name.empty() ? "(unnamed)" : technique->name;
        if (!anotherRuns) {
            for (const Diagnostic& d : reasons) diagnostics.report(d);
            reportedErrors = true;
            continue;
        }
        const auto first = std::find_if(reasons.begin(), reasons.end(),
                                        [](const Diagnostic& d) { return d.severity == Severity::Error; });
        // The warning stands at the technique; the error that keeps it out follows as its note, with its id.
        Diagnostic refused{DiagId::TechniqueRefused, defaultSeverity(DiagId::TechniqueRefused),
                           technique->loc.valid() ? technique->loc : first->loc,
                           formatDiagnostic(DiagId::TechniqueRefused, {name})};
        Diagnostic cause = *first;
        cause.severity = Severity::Note;
        refused.notes.push_back(std::move(cause));
        diagnostics.report(refused);
        leftOut.push_back({name, technique->group, first->message, first->loc});
    }
    return !reportedErrors;
}

}  // namespace fx::detail
