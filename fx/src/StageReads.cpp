// StageReads: see fx/StageReads.h.
#include <fx/StageReads.h>

#include <cctype>

namespace fx {

bool stageReads(const StageProgram& stage, const std::string& identifier) {
    const std::string& glsl = stage.glsl;
    const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    int mentions = 0;
    for (size_t at = glsl.find(identifier); at != std::string::npos; at = glsl.find(identifier, at + 1)) {
        const size_t end = at + identifier.size();
        if ((at == 0 || !word(glsl[at - 1])) && (end == glsl.size() || !word(glsl[end])) && ++mentions > 1)
            return true;
    }
    return false;
}

}  // namespace fx
