// FxcDirectives: rewrites of directive lines that fxc and D3DX's preprocessor accepted and glslang's
// refuses, applied to every source text before glslang preprocesses it. Private to fx.
//  - `#include "x.fxh" trailing text`: the text after the header name is dropped, with a warning (fxc,
//    like the Microsoft C preprocessor, warned about unexpected tokens after a directive and went on).
//  - `#if foo(X)` / `#elif foo(X)` where `foo` is no function-like macro when the condition is evaluated:
//    the call reads as 0, with a warning (MonoGame's effect preprocessor), where glslang stops with
//    "unexpected tokens following directive". Whether `foo` is defined is only known while glslang runs,
//    so each call is guarded by `#ifdef foo`, and the undefined branch emits a `#pragma` marker that
//    takeUndefinedCallMarkers() turns into the warning when (and only when) that condition was evaluated.
//  - `#define X ...` of a macro already defined with another body: the new definition replaces the old
//    one, with a warning (fxc's X1519, the Microsoft C preprocessor's C4005), where glslang stops with
//    "Macro redefined". Whether X is defined there, and by which #define, is only known while glslang
//    runs, so every #define is preceded by `#ifdef X`, a `#pragma` marker and `#undef X`, `#else` and
//    another marker: the markers in glslang's output say which definitions ran in which order, and so
//    which redefined a macro with another body.
#pragma once

#include <fx/Diagnostics.h>

#include <map>
#include <string>
#include <vector>

namespace fx::detail {

// A call in a preprocessor condition to a name that may not be a function-like macro.
struct ConditionCall {
    SourceLoc loc;     // the name in the user's file
    std::string name;  // "foo"
};

class FxcDirectives {
public:
    // The glslang-ready text of `text` (the user's file `file`, already through markStringizing). Lines
    // are added only where a condition needs guards; `#line` directives restore the user's numbering.
    // Warnings for trailing include text are reported at once.
    std::string rewrite(const std::string& text, const std::string& file, DiagnosticSink& diagnostics);

    // Removes the markers from glslang's output (the lines stay, empty) and reports a warning for each
    // call whose condition was evaluated with the name undefined.
    void takeUndefinedCallMarkers(std::string& preprocessed, DiagnosticSink& diagnostics) const;

    // Removes the definition markers from glslang's output (the lines stay, empty) and reports a warning
    // for each #define that ran where the macro was defined with another body.
    void takeRedefinitionMarkers(std::string& preprocessed, DiagnosticSink& diagnostics) const;

    // A macro defined before the first source (a command-line define): a #define of it with another body
    // is a redefinition.
    void predefine(const std::string& name, const std::string& body);

    // The glslang predefines an effect must not see (VULKAN, GL_SPIRV, GL_core_profile, the GL_*
    // extension names), as `#undef` lines for the preamble: fxc and D3DX predefined none of them.
    static std::string undefineGlslangPredefines();

private:
    std::vector<ConditionCall> mCalls;  // indexed by the marker's number
    // A #define: where its name stands, the name, and its parameters and body, comments dropped and blanks
    // collapsed (equal keys are the same definition).
    struct MacroDefinition {
        SourceLoc loc;
        std::string name;
        std::string key;
    };
    std::vector<MacroDefinition> mDefinitions;       // indexed by the marker's number / 2
    std::map<std::string, std::string> mPredefined;  // command-line defines: name -> key
};

}  // namespace fx::detail
