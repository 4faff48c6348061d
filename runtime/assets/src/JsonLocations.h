// JsonLocations: where each value of a JSON text starts, by its JSON pointer ("/frame/0/technique"), so that
// a reader that validates values after nlohmann parsed them can report `file:line:column` at the value
// itself. nlohmann's values carry no positions; this scans the text once more, which is valid JSON by then.
#pragma once

#include <fx/Diagnostics.h>
#include <fx/SourceLoc.h>

#include <cstddef>
#include <string>
#include <unordered_map>

namespace runtime {

class JsonLocations {
public:
    // `text` must be JSON that nlohmann accepted; `path` names it in locations.
    JsonLocations(std::string path, const std::string& text);

    // The value at `pointer` (nlohmann's json_pointer::to_string() spelling); the file's start if the scan
    // did not record it.
    fx::SourceLoc at(const std::string& pointer) const;
    // Line and column of a byte offset (1-based).
    static fx::SourceLoc locationOf(const std::string& path, const std::string& text, size_t offset);
    // Where a reader looks for a syntax error nlohmann reports at `byte` (json::parse_error::byte, one past
    // the offending character): the start of the offending token ("name" in {"a": 1 "name": 2}, not its
    // closing quote).
    static fx::SourceLoc syntaxErrorLocation(const std::string& path, const std::string& text, size_t byte);
    // SceneSyntaxError at syntaxErrorLocation() with nlohmann's message (json::parse_error::what()) less the
    // position it repeats ("syntax error while parsing ... - ").
    static void reportSyntaxError(const std::string& path, const std::string& text, size_t byte,
                                  const std::string& what, fx::DiagnosticSink& diagnostics);

private:
    // Values nested deeper than any file this reads are skipped whole, so that a hostile file cannot
    // exhaust the stack (nlohmann parses them without recursion).
    static constexpr int kMaxDepth = 64;
    void scanValue(const std::string& pointer, int depth);
    void skipNested();
    void skipSpace();
    std::string scanString();  // at '"'; returns the key as nlohmann spells it in a pointer

    std::string mPath;
    const std::string& mText;
    size_t mAt = 0;
    std::unordered_map<std::string, fx::SourceLoc> mStarts;
    int mLine = 1;
    size_t mLineStart = 0;
};

}  // namespace runtime
