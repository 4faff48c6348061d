#!/usr/bin/env python3
"""The γ sweep (docs/techniques/light-space-parameterizations.md): every light-space parameterization's
shadow error, texel footprint and frame time as the light turns from along the view (γ = 0°) to across it
(γ = 90°), on one scene, at equal total shadow-map texels.

Each (γ, method) is one `shadowfx bench --light-angle-to-view γ` run; methods that need the same parameter
settings share one run per γ, so their frame times are measured back to back. Writes, under --out:
  gamma.json   every run's numbers (one record per γ and method)
  report.md    misclassified % and texel footprint against γ, the ratios to the uniform map at the largest
               γ, and error against frame time per γ (the methods side by side)
  gamma.png    misclassified % and mean texel footprint against γ (when gnuplot is installed)
  bench/g<γ>_<group>/   the bench runs themselves (report.md, error images)

usage: scripts/gamma_sweep.py [--scene forest] [--gammas 0,15,30,45,60,75,90] [--methods a,b,...]
                              [--frames 3] [--warmup 1] [--width 320] [--height 240] [--out out/gamma]
                              [--camera-orbit 0] [--shadowfx build/samples/shadowfx/shadowfx]
Run from the repository root after building.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys


# label -> (effect, technique, parameter settings). Every method's maps hold 1024² texels in all: one
# 1024² map, or four 512² cascades or the used cube faces in one 1024² atlas. `uniform` is pcf.fx's
# `bilinear`: the same 2x2 PCF as the light-space effects (lightspace.fxh) on the view-independent map.
METHODS = {
    "uniform": ("effects/pcf.fx", "bilinear", ()),
    "focused": ("effects/focused.fx", "bilinear", ()),
    "lispsm": ("effects/lispsm.fx", "bilinear", ()),
    "lispsm-middle": ("effects/lispsm.fx", "bilinear", ("MiddleVector=1",)),
    "lispsm-n4": ("effects/lispsm.fx", "bilinear", ("NScale=4",)),
    "lispsm-wimmer": ("effects/lispsm.fx", "bilinear", ("NOpt=Wimmer2004",)),
    "lispsm-scherzer": ("effects/lispsm.fx", "bilinear", ("NOpt=Scherzer2005",)),
    "lispsm-lloyd": ("effects/lispsm.fx", "bilinear", ("NOpt=Lloyd2006",)),
    "lispsm-visible": ("effects/lispsm.fx", "bilinear", ("FitVisible=true",)),
    "tsm": ("effects/tsm.fx", "bilinear", ()),
    "psm": ("effects/psm.fx", "bilinear", ()),
    "psm-cube": ("effects/psm_cube.fx", "bilinear", ()),
    "cascades": ("effects/cascades.fx", "blended", ()),
}
DEFAULT_METHODS = list(METHODS)


def run_group(args, gamma, settings, methods, out):
    """One bench run of `methods` (same settings) at `gamma`; returns {label: run record}."""
    effects = sorted({METHODS[m][0] for m in methods})
    techniques = sorted({METHODS[m][1] for m in methods})
    command = [args.shadowfx, "bench", "--effects", ",".join(effects), "--techniques", ",".join(techniques),
               "--scenes", args.scene, "--width", str(args.width), "--height", str(args.height),
               "--frames", str(args.frames), "--warmup", str(args.warmup),
               "--light-angle-to-view", str(gamma), "--camera-orbit", str(args.camera_orbit), "--out", out]
    for setting in settings:
        command += ["--set", setting]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL,
                   env=dict(os.environ, LP_NUM_THREADS=os.environ.get("LP_NUM_THREADS", "2")))
    with open(os.path.join(out, "results.json")) as f:
        runs = json.load(f)["runs"]
    records = {}
    for label in methods:
        effect, technique, _ = METHODS[label]
        run = next(r for r in runs if r["effect"] == effect and r["technique"] == technique)
        records[label] = {
            "gamma": gamma,
            "method": label,
            "effect": effect,
            "technique": technique,
            "settings": list(settings),
            "misclassified_percent": run["error"]["misclassified_percent"],
            "false_shadow_percent": run["error"]["false_shadow_percent"],
            "false_light_percent": run["error"]["false_light_percent"],
            "mean_footprint_px": run["aliasing"]["mean_texel_footprint_px"],
            "p95_footprint_px": run["aliasing"]["p95_texel_footprint_px"],
            # Techniques are compared at their full cost: every map drawn, as for a moving light.
            "frame_ms": run["full_cost"]["frame_time_ms"]["median"],
            "draws": run["work"]["draws"],
        }
    return records


def write_report(args, methods, gammas, records, path):
    by = {(r["gamma"], r["method"]): r for r in records}
    lines = ["# γ sweep: light-space parameterizations", "",
             f"Scene `{args.scene}`, {args.width}x{args.height}, 1024² texels per method, hard ray-cast truth; "
             f"frame times are medians of {args.frames} frames after {args.warmup} warm-up at full cost (every "
             "map drawn every frame, as for a moving light; llvmpipe: compare them within one γ, not across γ); "
             + (f"the camera orbits {args.camera_orbit}° a frame." if args.camera_orbit else "a still camera."), "",
             "## Misclassified % (false shadow + false light over receiver pixels)", "",
             "| γ | " + " | ".join(methods) + " |", "|---:|" + "---:|" * len(methods)]
    for g in gammas:
        lines.append(f"| {g}° | " + " | ".join(f"{by[(g, m)]['misclassified_percent']:.2f}" for m in methods) + " |")
    lines += ["", "## Texel footprint, mean / p95 (screen pixels per shadow-map texel; > 1 undersamples)", "",
              "| γ | " + " | ".join(methods) + " |", "|---:|" + "---|" * len(methods)]
    for g in gammas:
        lines.append(f"| {g}° | " + " | ".join(
            f"{by[(g, m)]['mean_footprint_px']:.2f} / {by[(g, m)]['p95_footprint_px']:.1f}" for m in methods) + " |")
    last = gammas[-1]
    if "uniform" in methods:
        base = by[(last, "uniform")]
        lines += ["", f"## Ratios to the uniform map at γ = {last}°", "",
                  "| method | misclassified | mean footprint | p95 footprint |", "|---|---:|---:|---:|"]
        for m in methods:
            r = by[(last, m)]
            ratio = lambda key: r[key] / base[key] if base[key] > 0 else float("nan")
            lines.append(f"| {m} | {ratio('misclassified_percent'):.3f}× | {ratio('mean_footprint_px'):.3f}× | "
                         f"{ratio('p95_footprint_px'):.3f}× |")
    lines += ["", "## Error against frame time, per γ", "",
              "| γ | " + " | ".join(methods) + " |", "|---:|" + "---|" * len(methods)]
    for g in gammas:
        lines.append(f"| {g}° | " + " | ".join(
            f"{by[(g, m)]['misclassified_percent']:.2f} % @ {by[(g, m)]['frame_ms']:.0f} ms" for m in methods) + " |")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def plot(methods, gammas, records, out):
    if not shutil.which("gnuplot"):
        return
    data = os.path.join(out, "gamma.dat")
    with open(data, "w") as f:
        for m in methods:
            f.write(f'"{m}"\n')
            for r in sorted((r for r in records if r["method"] == m), key=lambda r: r["gamma"]):
                f.write(f"{r['gamma']} {r['misclassified_percent']} {r['mean_footprint_px']}\n")
            f.write("\n\n")
    script = f"""set terminal pngcairo size 1200,480
set output '{os.path.join(out, "gamma.png")}'
set multiplot layout 1,2
set xlabel 'gamma (degrees between light and view)'
set key top right
set ylabel 'misclassified %'
plot for [i=0:{len(methods) - 1}] '{data}' index i using 1:2 with linespoints title columnheader(1)
set ylabel 'mean texel footprint (px)'
set logscale y
plot for [i=0:{len(methods) - 1}] '{data}' index i using 1:3 with linespoints title columnheader(1)
unset multiplot
"""
    subprocess.run(["gnuplot"], input=script, text=True, check=False)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default="forest")
    parser.add_argument("--gammas", default="0,15,30,45,60,75,90")
    parser.add_argument("--methods", default=",".join(DEFAULT_METHODS))
    parser.add_argument("--frames", type=int, default=3)
    parser.add_argument("--warmup", type=int, default=1)
    parser.add_argument("--width", type=int, default=320)
    parser.add_argument("--height", type=int, default=240)
    parser.add_argument("--out", default="out/gamma")
    parser.add_argument("--camera-orbit", type=float, default=0.0,
                        help="degrees the camera turns per frame (bench --camera-orbit): frame times then "
                             "include redrawing every view-dependent map, as in a walk-through")
    parser.add_argument("--shadowfx", default="build/samples/shadowfx/shadowfx", help="the tool to run")
    args = parser.parse_args()
    gammas = [int(g) for g in args.gammas.split(",")]
    methods = args.methods.split(",")
    unknown = [m for m in methods if m not in METHODS]
    if unknown:
        sys.exit(f"gamma_sweep: unknown method(s) {', '.join(unknown)}; known: {', '.join(METHODS)}")
    groups = {}
    for m in methods:
        groups.setdefault(METHODS[m][2], []).append(m)
    records = []
    for g in gammas:
        for index, (settings, members) in enumerate(groups.items()):
            print(f"gamma_sweep: γ = {g}°: {', '.join(members)}", flush=True)
            out = os.path.join(args.out, "bench", f"g{g}_{index}")
            records += run_group(args, g, settings, members, out).values()
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "gamma.json"), "w") as f:
        json.dump({"scene": args.scene, "width": args.width, "height": args.height, "runs": records}, f, indent=1)
    write_report(args, methods, gammas, records, os.path.join(args.out, "report.md"))
    plot(methods, gammas, records, args.out)
    print(os.path.join(args.out, "report.md"))


if __name__ == "__main__":
    main()
