// HostOption: `--host FILE.json` on render, bench, check and view: the host file (fx/HostFile.h,
// docs/host-files.md) that draws an effect written for an application, given to every renderer a command
// makes.
#pragma once

#include "CommandLine.h"

#include <runtime/EffectRenderer.h>
#include <runtime/HostFileReader.h>

#include <memory>

namespace shadowfx::cli {

// The lines each command's --help gives the option (a literal, joined to the command's usage text).
#define SHADOWFX_HOST_OPTION_HELP                                                                        \
    "  --host FILE.json      draw an effect without SAS scripts as the host file says its application\n" \
    "                        drew it: targets, parameters, techniques and passes (docs/host-files.md)\n"

// The host file --host names: null when the option is absent; `ok` false (with the errors reported) when
// the file cannot be read.
std::shared_ptr<const fx::HostFile> readHostOption(const Arguments& args, fx::DiagnosticSink& sink, bool& ok);

// Gives `renderer` the host file, if any. False (with the errors at the file's lines) where the file names
// what the effect does not have.
bool useHostFile(runtime::EffectRenderer& renderer, const std::shared_ptr<const fx::HostFile>& host,
                 fx::DiagnosticSink& sink);

}  // namespace shadowfx::cli
