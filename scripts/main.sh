#!/usr/bin/env bash
# The main job: install what is missing, build, render the thesis-style FX Composer effect headlessly, and
# measure it: `shadowfx bench` scores each technique's shadows against the ray-cast ground truth and times
# its frames (a default set that takes a minute or two on two cores); then the γ sweep of every light-space
# parameterization on the forest (a few minutes) and the stress set.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
mkdir -p out
build/samples/shadowfx/shadowfx render effects/thesis_fxcomposer.fx --scene boxes --out out/thesis_fxcomposer.png \
  --width 800 --height 600 --verbose
echo "main: wrote $(pwd)/out/thesis_fxcomposer.png"
LP_NUM_THREADS="${LP_NUM_THREADS:-2}" build/samples/shadowfx/shadowfx bench --effects effects/thesis_fxcomposer.fx \
  --techniques main,hardware --scenes boxes,teapot --map-sizes 512,1024 --frames 5 --warmup 2 \
  --width 640 --height 480 --out out/bench
echo "main: bench report $(pwd)/out/bench/report.md (results.json, error_vs_time.png, errors/*.png beside it)"
LP_NUM_THREADS="${LP_NUM_THREADS:-2}" python3 scripts/gamma_sweep.py --scene forest --out out/gamma > out/gamma.txt
echo "main: γ sweep $(pwd)/out/gamma/report.md (gamma.json, gamma.png beside it)"
LP_NUM_THREADS="${LP_NUM_THREADS:-2}" build/samples/shadowfx/shadowfx stress --out out/stress > out/stress.txt || true
echo "main: stress report $(pwd)/out/stress/report.md (stress.json beside it; failures also in out/stress.txt)"
