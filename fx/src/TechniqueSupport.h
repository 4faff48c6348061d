// TechniqueSupport: which techniques GL can run, and how those it cannot are left out. D3DX offered the
// next valid technique where one did not validate (FindNextValidTechnique): a technique that uses what GL
// cannot run is left out with a located warning naming it while another technique can run; an effect none
// of whose techniques runs is an error. The parser finds some reasons in the syntax (dynamic
// linkage, compute shaders), the compiler the rest in the lowering's diagnostics. Private to fx.
#pragma once

#include <fx/Diagnostics.h>
#include <fx/Effect.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace fx::detail {

// Why GL cannot run a D3D10 pass's Set*Shader(value), where the value says so by itself: dynamic linkage
// (BindInterfaces). `warning` says it of the technique left out while another runs, `allLeftOut` of the
// first technique when every one is left out; `reason` is the warning's text after the technique's name.
struct ShaderValueRefusal {
    DiagId warning;
    DiagId allLeftOut;
    std::string reason;
};
std::optional<ShaderValueRefusal> unsupportedShaderValue(const Expr& value, const Effect& effect);

// The parser's refusals: the first reason of the technique being parsed, the first technique left out.
class TechniqueRefusals {
public:
    struct Refused {
        std::string name;
        ShaderValueRefusal refusal;
        SourceLoc loc;
    };
    void beginTechnique() { mCurrent.reset(); }
    // Something in the technique being parsed that GL cannot run: the first reason is reported.
    void refuse(const SourceLoc& loc, const ShaderValueRefusal& refusal) {
        if (!mCurrent) mCurrent = Refused{"", refusal, loc};
    }
    // At the technique's end: true when it is left out, reported (never silently: the technique is named,
    // with what GL cannot run and where it stands) and added to `leftOut`.
    bool leaveOut(const Technique& technique, DiagnosticSink& diagnostics,
                  std::vector<RefusedTechnique>& leftOut);
    const std::optional<Refused>& first() const { return mFirst; }

private:
    std::optional<Refused> mCurrent;  // of the technique being parsed
    std::optional<Refused> mFirst;    // the first technique left out
};

// The compiler's: techniques whose code uses what the lowering cannot express, with what it said (a
// stage form or a stream output GL has no counterpart for). Left out with a warning at the first error
// while `anotherRuns`, and added to `leftOut` with it; otherwise their diagnostics are reported as they
// stand and the result is false (the effect fails).
bool reportUnsupportedTechniques(
    const std::vector<std::pair<const Technique*, std::vector<Diagnostic>>>& techniques, bool anotherRuns,
    DiagnosticSink& diagnostics, std::vector<RefusedTechnique>& leftOut);

}  // namespace fx::detail
