// StringEscapes: string literals kept out of glslang's escape handling. glslang's preprocessor decodes the
// escapes of every string it reads and refuses an unknown one (`"C:\Users\Desktop"`: `\D` stops the
// file), where fxc kept the character and went on. So before glslang reads a source, each backslash in a
// string literal (and a quote a backslash escapes) becomes a placeholder byte of the same width, so that
// no column moves; its output gets them back, and the effect's lexer decodes the escapes once, as the
// user wrote them. Private to fx.
#pragma once

#include <fx/Diagnostics.h>

#include <optional>
#include <string>

namespace fx::detail {

// The character the escape `\e` stands for (`n`: a newline, `\\`: a backslash), or nullopt where `\e`
// is no escape: the lexer keeps the backslash and `e` as they stand.
std::optional<char> decodeEscape(char e);

// `text` (the user's file `file`) with the backslashes of its string literals, and the quotes they
// escape, replaced by placeholders: in code and in #define lines, not in other directives (an
// #include's header name is glslang's to read, backslashes and all). Each unknown escape gets a
// warning at its backslash.
std::string hideStringEscapes(const std::string& text, const std::string& file, DiagnosticSink& diagnostics);

// Puts back what hideStringEscapes() replaced, in glslang's output.
void restoreStringEscapes(std::string& text);

}  // namespace fx::detail
