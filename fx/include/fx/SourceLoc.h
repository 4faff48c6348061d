// SourceLoc: where something came from in the user's files (after #include and #line mapping).
#pragma once

#include <string>

namespace fx {

struct SourceLoc {
    std::string file;  // path as the user named it (the main file, or an include resolved from it)
    int line = 0;      // 1-based; 0 = unknown
    int column = 0;    // 1-based; 0 = unknown

    bool valid() const { return line > 0; }
    // "file:line:column" (or "file:line" / "file" where the rest is unknown), as compilers print it.
    std::string str() const;
};

}  // namespace fx
