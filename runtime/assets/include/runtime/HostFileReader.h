// HostFileReader: host files (fx/HostFile.h, docs/host-files.md) from JSON, with every problem located at
// its line and column.
#pragma once

#include <fx/Diagnostics.h>
#include <fx/HostFile.h>

#include <memory>
#include <string>

namespace runtime {

// Reads a host file. Every problem is reported as `path:line:column: error: ...` (invalid JSON, a value of
// the wrong kind, a missing key; unknown keys are warnings); nullptr if there was an error. Never throws.
std::shared_ptr<const fx::HostFile> loadHostFile(const std::string& path, fx::DiagnosticSink& diagnostics);
// The same for JSON in memory; `path` names it in diagnostics.
std::shared_ptr<const fx::HostFile> parseHostJson(const std::string& text, const std::string& path,
                                                  fx::DiagnosticSink& diagnostics);

}  // namespace runtime
