#!/usr/bin/env bash
# Install what is missing, build, and run every test (CTest; real OpenGL through Mesa llvmpipe).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
export LP_NUM_THREADS="${LP_NUM_THREADS:-2}"
ctest --test-dir build --output-on-failure -j "$(nproc)" --timeout 600
