// HostOption: see HostOption.h.
#include "HostOption.h"

namespace shadowfx::cli {

std::shared_ptr<const fx::HostFile> readHostOption(const Arguments& args, fx::DiagnosticSink& sink,
                                                   bool& ok) {
    const std::string path = args.value("--host");
    ok = true;
    if (path.empty()) return nullptr;
    std::shared_ptr<const fx::HostFile> host = runtime::loadHostFile(path, sink);
    ok = host != nullptr;
    return host;
}

bool useHostFile(runtime::EffectRenderer& renderer, const std::shared_ptr<const fx::HostFile>& host,
                 fx::DiagnosticSink& sink) {
    return !host || renderer.setHostFile(host, sink);
}

}  // namespace shadowfx::cli
