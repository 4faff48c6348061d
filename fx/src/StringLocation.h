// StringLocation: where a character of a string literal stands in the user's file. A literal may be
// several adjacent pieces ("a" "b"), each with its own location, so messages about a part of the string
// (a SAS script's command, a stream-output declaration's entry) point at that part. Private to fx.
#pragma once

#include <fx/Effect.h>

#include <cstddef>

namespace fx::detail {

// The source location of character `offset` of the concatenated string `literal`.
inline SourceLoc stringLocation(const Expr& literal, size_t offset) {
    if (literal.stringPieces.empty()) return literal.loc;
    const Expr::StringPiece* piece = &literal.stringPieces.front();
    for (const Expr::StringPiece& p : literal.stringPieces)
        if (p.offset <= offset) piece = &p;
    SourceLoc loc = piece->loc;
    // A piece a macro expanded to stands at the macro's name; its characters have no columns of their own.
    if (!piece->fromMacro) loc.column += static_cast<int>(offset - piece->offset);
    return loc;
}

}  // namespace fx::detail
