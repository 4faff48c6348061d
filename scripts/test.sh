#!/usr/bin/env bash
# Install what is missing, build, and run every test (CTest; real OpenGL through Mesa llvmpipe).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/phase-times.sh
phase install-deps scripts/install-deps.sh
phase "plain configure+build" scripts/build.sh
export LP_NUM_THREADS="${LP_NUM_THREADS:-2}"
phase "plain ctest" ctest --test-dir build --output-on-failure -j "$(nproc)" --timeout 600
