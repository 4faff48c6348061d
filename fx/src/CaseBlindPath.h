// CaseBlindPath: effects written on Windows name their includes and textures without regard to case
// (`noise_2d.fxh` for `noise_2D.fxh`). Private to fx.
#pragma once

#include <optional>
#include <string>

namespace fx::detail {

// The existing path that equals `path` but for the case of its components, when `path` itself does not
// exist (the first match in directory order where several do); nullopt when there is none or `path`
// exists as written.
std::optional<std::string> findPathIgnoringCase(const std::string& path);

}  // namespace fx::detail
