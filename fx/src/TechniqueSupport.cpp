// TechniqueSupport: see TechniqueSupport.h.
#include "TechniqueSupport.h"

#include <algorithm>

namespace fx::detail {

std::optional<std::string> unsupportedShaderValue(const Expr& value, const Effect& effect) {
    if (value.kind == Expr::Kind::Call && value.text == "BindInterfaces")
        return "dynamic shader linkage (BindInterfaces) is not supported: GLSL has no interfaces to bind at "
               "run time";
    // Stream output, inline or through a shader variable (`GeometryShader gsSO = ConstructGSWithSO(
    // CompileShader(gs_4_0, GS()), "POSITION.xyz; ...");`): only the techniques that use it are left out,
    // at the pass that sets it.
    const Parameter* variable =
        value.kind == Expr::Kind::Identifier ? effect.findParameter(value.text) : nullptr;
    if ((value.kind == Expr::Kind::Call && value.text == "ConstructGSWithSO") ||
        (variable && variable->initializer && variable->initializer->kind == Expr::Kind::Call &&
         variable->initializer->text == "ConstructGSWithSO"))
        return std::string("stream output (ConstructGSWithSO") +
               (variable ? ", held by '" + variable->name + "'" : "") +
               ") is not supported: shadowfx has no transform feedback";
    return std::nullopt;
}

bool TechniqueRefusals::leaveOut(const Technique& technique, DiagnosticSink& diagnostics,
                                 std::vector<RefusedTechnique>& leftOut) {
    if (!mCurrent) return false;
    const std::string name = technique.name.empty() ? "(unnamed)" : technique.name;
    diagnostics.report(DiagId::TechniqueRefused, mCurrent->loc, {name, mCurrent->reason});
    if (!mFirst) mFirst = Refused{name, mCurrent->reason, mCurrent->loc};
    leftOut.push_back({name, technique.group, mCurrent->reason, mCurrent->loc});
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
        diagnostics.report(DiagId::TechniqueRefused, first->loc, {name, first->message});
        leftOut.push_back({name, technique->group, first->message, first->loc});
    }
    return !reportedErrors;
}

}  // namespace fx::detail
