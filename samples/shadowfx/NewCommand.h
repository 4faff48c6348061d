// NewCommand: `shadowfx new NAME [--from pcf|vsm|minimal]`, a technique skeleton in the current folder.
#pragma once

#include "CommandLine.h"

namespace shadowfx::cli {

extern const char* const kNewUsage;
int newCommand(const Arguments& args);

}  // namespace shadowfx::cli
