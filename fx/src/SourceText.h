// SourceText: the bytes of an effect or include file as Windows editors saved them, turned into the
// UTF-8 text with '\n' line ends that the preprocessor and lexer expect. Private to fx.
#pragma once

#include <string>

namespace fx::detail {

// Drops a UTF-8 byte-order mark, converts UTF-16 LE or BE (recognized by their byte-order mark) to UTF-8,
// turns CRLF line ends into LF, and ends the last line with one. Columns stay right: a mark is not a
// character of line 1, and a carriage return sits after the last one of its line. Unpaired UTF-16 surrogates
// become U+FFFD.
std::string decodeSourceText(const std::string& bytes);

}  // namespace fx::detail
