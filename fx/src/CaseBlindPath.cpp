// CaseBlindPath: file names as the Windows systems FX Composer effects were written on saw them.
#include "CaseBlindPath.h"

#include <cctype>
#include <filesystem>
#include <sstream>

namespace fx::detail {

std::optional<std::string> findPathIgnoringCase(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code error;
    if (fs::exists(path, error)) return std::nullopt;
    auto lower = [](std::string text) {
        for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return text;
    };
    std::string resolved = !path.empty() && path[0] == '/' ? "/" : "";
    std::istringstream parts(path);
    std::string part;
    while (std::getline(parts, part, '/')) {
        if (part.empty()) continue;
        const std::string next = resolved + (resolved.empty() || resolved.back() == '/' ? "" : "/") + part;
        if (part == "." || part == ".." || fs::exists(next, error)) {
            resolved = next;
            continue;
        }
        std::optional<std::string> match;
        for (fs::directory_iterator it(resolved.empty() ? "." : resolved, error), end; !error && it != end;
             it.increment(error)) {
            const std::string name = it->path().filename().string();
            if (lower(name) == lower(part)) {
                match = name;
                break;
            }
        }
        if (!match) return std::nullopt;
        resolved += (resolved.empty() || resolved.back() == '/' ? "" : "/") + *match;
    }
    return resolved;
}

}  // namespace fx::detail
