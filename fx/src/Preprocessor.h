// Preprocessor: runs glslang's HLSL preprocessor over an effect file with an includer that resolves
// "a/b.fxh" and <a\b.fxh> relative to the including file, then the include directories. Private to fx.
#pragma once

#include <fx/Diagnostics.h>
#include <fx/EffectParser.h>

#include <map>
#include <string>
#include <vector>

namespace fx::detail {

// Forwards to another sink and counts the errors; the parser stops after a bounded number.
class CountingSink : public DiagnosticSink {
public:
    using DiagnosticSink::report;
    explicit CountingSink(DiagnosticSink& inner) : mInner(inner) {}
    void report(const Diagnostic& diagnostic) override {
        if (diagnostic.severity == Severity::Error) ++mErrors;
        mInner.report(diagnostic);
    }
    size_t errors() const { return mErrors; }

private:
    DiagnosticSink& mInner;
    size_t mErrors = 0;
};

struct PreprocessedSource {
    std::string text;                          // glslang's output: lines kept, #line for includes
    std::map<std::string, std::string> files;  // every file read, by the name #line uses
    std::vector<std::string> includedFiles;    // main file first, in the order opened
};

// Returns false if an error was reported.
bool preprocessEffect(const std::string& source, const std::string& path, const ParseOptions& options,
                      DiagnosticSink& diagnostics, PreprocessedSource& out);

// The folder part of a path ("a/b/c.fx" -> "a/b/", "c.fx" -> "").
std::string folderOf(const std::string& path);

}  // namespace fx::detail
