// PointSprites: see PointSprites.h.
#include "PointSprites.h"

#include <regex>

namespace fx::detail {

int readPointSpriteCoordinates(std::string& glsl) {
    // SPIRV-Cross declares each pixel-shader input on a line of its own; TEXCOORDn is location n
    // (SemanticTables.h).
    static const std::regex kInput(
        R"(^layout\(location = ([0-7])\) (?:(?:flat|noperspective|centroid|sample) )*in (float|vec2|vec3|vec4) (\w+);$)");
    std::string assignments, out;
    int replaced = 0;
    size_t start = 0;
    while (start < glsl.size()) {
        size_t end = glsl.find('\n', start);
        if (end == std::string::npos) end = glsl.size();
        const std::string line = glsl.substr(start, end - start);
        std::smatch m;
        if (std::regex_match(line, m, kInput)) {
            const std::string type = m[2], name = m[3];
            // GL puts gl_PointCoord's origin at the top of GL's window coordinates; under the runtime's
            // glClipControl(GL_UPPER_LEFT) that is the bottom of the image D3D sees, so v is flipped.
            const std::string uv = "vec2(gl_PointCoord.x, 1.0 - gl_PointCoord.y)";
            const std::string value = type == "float"  ? "gl_PointCoord.x"
                                      : type == "vec2" ? uv
                                      : type == "vec3" ? "vec3(" + uv + ", 0.0)"
                                                       : "vec4(" + uv + ", 0.0, 1.0)";
            out += type + " " + name + ";";
            assignments += "    " + name + " = " + value + ";\n";
            ++replaced;
        } else {
            out += line;
        }
        if (end < glsl.size()) out += '\n';
        start = end + 1;
    }
    const std::string main = "void main()\n{\n";
    const size_t at = out.find(main);
    if (replaced == 0 || at == std::string::npos) return 0;
    out.insert(at + main.size(), assignments);
    glsl = std::move(out);
    return replaced;
}

}  // namespace fx::detail
