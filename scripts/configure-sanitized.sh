#!/usr/bin/env bash
# Configures build-asan/, the one sanitized build: clang with AddressSanitizer + UndefinedBehaviorSanitizer
# and libFuzzer's coverage instrumentation in every library. scripts/test-sanitized.sh runs the test suite
# from it and scripts/fuzz.sh the libFuzzer targets, so CI compiles the project twice (plain and
# sanitized), not three times. -O1 with line tables only, the flags fuzzing infrastructure (OSS-Fuzz) uses:
# reports keep file:line, at about half the compiler time of -O2 -g (the tests' time is llvmpipe's).
#   scripts/configure-sanitized.sh [CMAKE_ARGS...]
set -euo pipefail
cd "$(dirname "$0")/.."
# A build-asan/ of an earlier layout (GCC, without the fuzz targets) cannot change compiler in place.
if [ -f build-asan/CMakeCache.txt ] && ! grep -q '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang++' build-asan/CMakeCache.txt; then
  echo "configure-sanitized: build-asan/ was configured with another compiler; configuring it afresh"
  rm -rf build-asan/CMakeCache.txt build-asan/CMakeFiles
fi
opt="-O1 -gline-tables-only -DNDEBUG"
CC=clang CXX=clang++ cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DSHADOWFX_SANITIZE=ON -DSHADOWFX_FUZZ=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$opt" -DCMAKE_C_FLAGS_RELWITHDEBINFO="$opt" \
  -DSHADOWFX_BUILD_BENCHMARKS=OFF "$@" >/dev/null
