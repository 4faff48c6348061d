#!/usr/bin/env python3
"""Frame-time ratios of the dual-depth techniques to constant bias, robust to a shared, noisy machine.

Wall-clock medians of one `shadowfx bench` run drift by 2x on a loaded machine because bench times one
technique after the other. Here each repetition runs the four techniques back to back (short bench runs),
takes each one's median frame time relative to constant bias's in the same repetition, and reports the
median [min-max] of those ratios over the repetitions (docs/techniques/depth-bias-and-layers.md).

usage: scripts/bench_paired_ratios.py [SCENE ...]   (default: dual-l double-torus; run from the repository
root after building build/samples/shadowfx/shadowfx)
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile

REPETITIONS = 5
MAP_SIZES = [256, 2048]
TECHNIQUES = [("bias", "constant"), ("dual_depth", "peel"), ("dual_depth", "peel_cull"),
              ("dual_depth", "single_pass")]


def median_frame_ms(effect, technique, scene, size, out):
    subprocess.run(["build/samples/shadowfx/shadowfx", "bench", "--effects", f"effects/{effect}.fx",
                    "--techniques", technique, "--scenes", scene, "--map-sizes", str(size),
                    "--width", "640", "--height", "480", "--warmup", "2", "--frames", "15", "--out", out],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   env=dict(os.environ, LP_NUM_THREADS=os.environ.get("LP_NUM_THREADS", "2")))
    with open(os.path.join(out, "results.json")) as f:
        # The full cost (every pass drawn): techniques compared as a moving light would see them.
        return json.load(f)["runs"][0]["full_cost"]["frame_time_ms"]["median"]


def main():
    scenes = sys.argv[1:] or ["dual-l", "double-torus"]
    with tempfile.TemporaryDirectory() as out:
        for scene in scenes:
            for size in MAP_SIZES:
                ratios = {technique: [] for _, technique in TECHNIQUES[1:]}
                constant = []
                for _ in range(REPETITIONS):
                    ms = {t: median_frame_ms(e, t, scene, size, out) for e, t in TECHNIQUES}
                    constant.append(ms["constant"])
                    for technique in ratios:
                        ratios[technique].append(ms[technique] / ms["constant"])
                print(f"{scene} {size}: constant {statistics.median(constant):.2f} ms; " + ", ".join(
                    f"{t} {statistics.median(r):.2f}x [{min(r):.2f}-{max(r):.2f}]" for t, r in ratios.items()),
                    flush=True)


if __name__ == "__main__":
    main()
