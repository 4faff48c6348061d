// MacroNoteSink: forwards to another sink, adding to a diagnostic at a macro's use the note where the
// macro was defined, as C compilers do ("in expansion of macro 'NAME' defined here"): the error is in the
// macro's body, which the use alone does not show. Private to fx; the parser and the compiler wrap their
// sinks in it.
#pragma once

#include <fx/Diagnostics.h>
#include <fx/Effect.h>

namespace fx::detail {

class MacroNoteSink : public DiagnosticSink {
public:
    using DiagnosticSink::report;
    // `sourceMap` may still be filling (the lexer records expansions as it goes).
    MacroNoteSink(DiagnosticSink& inner, const SourceMap& sourceMap) : mInner(inner), mSourceMap(sourceMap) {}

    void report(const Diagnostic& diagnostic) override {
        const SourceMap::MacroExpansion* expansion = mSourceMap.expansionAt(diagnostic.loc);
        if (!expansion) return mInner.report(diagnostic);
        Diagnostic noted = diagnostic;
        noted.notes.push_back(Diagnostic{DiagId::InMacroExpansion, defaultSeverity(DiagId::InMacroExpansion),
                                         expansion->definition,
                                         formatDiagnostic(DiagId::InMacroExpansion, {expansion->name})});
        mInner.report(noted);
    }

private:
    DiagnosticSink& mInner;
    const SourceMap& mSourceMap;
};

}  // namespace fx::detail
