// DispatchTerms: the terms of a `Dispatch=x,y,z` script command (fx/SasScript.h), as the compiler checks
// them and the runtime resolves them: split at commas, blanks around each removed. Each is a parameter's
// name or a whole number; the compiler says which are neither.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace fx {

inline std::vector<std::string> dispatchTerms(std::string_view value) {
    std::vector<std::string> terms;
    for (size_t from = 0; from <= value.size();) {
        size_t comma = value.find(',', from);
        if (comma == std::string_view::npos) comma = value.size();
        std::string term(value.substr(from, comma - from));
        term.erase(0, term.find_first_not_of(" \t"));
        term.erase(term.find_last_not_of(" \t") + 1);
        terms.push_back(std::move(term));
        from = comma + 1;
    }
    return terms;
}

}  // namespace fx
