#!/usr/bin/env bash
# The main job: install what is missing, build, and render the thesis-style FX Composer effect headlessly.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
mkdir -p out
build/samples/shadowfx/shadowfx render effects/thesis_fxcomposer.fx --scene boxes --out out/thesis_fxcomposer.png \
  --width 800 --height 600 --verbose
echo "main: wrote $(pwd)/out/thesis_fxcomposer.png"
