#!/usr/bin/env python3
"""Which peer runs shadowfx beats in `shadowfx bench --peers` outputs: for every peer run, the shadowfx runs
on the same scene with at most half its misclassified % at no more than its full-cost frame time (each side
at its own map size and settings), and the nearest miss where there is none.

usage: scripts/peer_dominance.py [--svg PREFIX] RESULTS.json [RESULTS.json ...]   (markdown on stdout)

--svg PREFIX also draws, per scene, PREFIX-SCENE.svg: every run's misclassified % against its full-cost frame
time (the same medians as the table), both axes logarithmic, the two sides in two colours, so that a plot of
repetitions shows what the table judges rather than one repetition's times.

The same run (scene, effect or peer, technique, map size, settings) in several files is one run measured
several times: its frame time is the median of the files' medians, its error the first file's (errors do
not depend on the machine's load). Give only outputs of one sitting on one machine together; alternating
repetitions of the two sides' benches in that sitting evens out a drifting load.
"""
import json
import math
import statistics
import sys
from xml.sax.saxutils import escape


def settings_of(document, run):
    # A --set with one value is recorded once, in the config; a sweep's value in each run's "setting".
    if run["peer"]:
        return ()
    fixed = dict(s.split("=", 1) for s in document["config"].get("set", []) if "," not in s)
    return tuple(sorted({**fixed, **(run.get("setting") or {})}.items()))


def label(run):
    name = run["peer"] or f'{run["effect_name"]}/{run["technique"]}'
    extra = " ".join(f"{k}={v}" for k, v in run["settings"])
    return f"`{name}` {run['map_size']}²" + (f" `{extra}`" if extra else "")


def read_runs(paths):
    merged = {}
    for path in paths:
        with open(path) as f:
            document = json.load(f)
        for run in document["runs"]:
            if not run.get("error"):
                continue
            run["settings"] = settings_of(document, run)
            key = (run["scene"], run["peer"] or f'{run["effect_name"]}/{run["technique"]}', run["map_size"],
                   run["settings"])
            entry = merged.setdefault(key, dict(run, times=[]))
            entry["times"].append(run["full_cost"]["frame_time_ms"]["median"])
    for run in merged.values():
        run["time"] = statistics.median(run["times"])
        run["misclassified"] = run["error"]["misclassified_percent"]
    return list(merged.values())


def log_ticks(log_span):
    """The 1, 2, 5 of each decade that lie within a logarithmic axis's span (log10 of its ends)."""
    lo, hi = log_span
    return [m * 10.0 ** decade for decade in range(math.floor(lo), math.ceil(hi) + 1) for m in (1, 2, 5)
            if lo <= math.log10(m * 10.0 ** decade) <= hi]


def draw_svg(runs, scene, path):
    points = [r for r in runs if r["scene"] == scene and r["misclassified"] > 0 and r["time"] > 0]
    width, height, left, right, top, bottom = 1000, 640, 80, 300, 40, 60

    def span(values):
        lo, hi = math.log10(min(values)), math.log10(max(values))
        pad = max(0.05 * (hi - lo), 0.05)
        return lo - pad, hi + pad

    tx, ty = span([r["time"] for r in points]), span([r["misclassified"] for r in points])
    x = lambda t: left + (math.log10(t) - tx[0]) / (tx[1] - tx[0]) * (width - left - right)
    y = lambda e: height - bottom - (math.log10(e) - ty[0]) / (ty[1] - ty[0]) * (height - top - bottom)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" font-family="sans-serif" '
           f'font-size="11"><rect width="100%" height="100%" fill="#fff"/>',
           f'<text x="{left}" y="20" font-size="14">{escape(scene)}: misclassified % against full-cost frame ms '
           f'(median of the repetitions; log-log)</text>']
    for v in log_ticks(tx):
        out.append(f'<line x1="{x(v):.1f}" y1="{top}" x2="{x(v):.1f}" y2="{height - bottom}" stroke="#ddd"/>'
                   f'<text x="{x(v):.1f}" y="{height - bottom + 15}" text-anchor="middle">{v:g}</text>')
    for v in log_ticks(ty):
        out.append(f'<line x1="{left}" y1="{y(v):.1f}" x2="{width - right}" y2="{y(v):.1f}" stroke="#ddd"/>'
                   f'<text x="{left - 5}" y="{y(v) + 4:.1f}" text-anchor="end">{v:g}</text>')
    out.append(f'<text x="{(left + width - right) / 2}" y="{height - 20}" text-anchor="middle">full-cost frame ms</text>')
    for r in sorted(points, key=lambda r: r["time"]):
        colour = "#d62728" if r["peer"] else "#1f77b4"
        name = label(r).replace("`", "").replace("²", "^2")
        out.append(f'<circle cx="{x(r["time"]):.1f}" cy="{y(r["misclassified"]):.1f}" r="4" fill="{colour}">'
                   f'<title>{escape(name)}: {r["misclassified"]:.3f} % in {r["time"]:.1f} ms</title></circle>')
    # A legend of every run beside the plot, in the order of error, since labels on the points would overlap.
    for i, r in enumerate(sorted(points, key=lambda r: r["misclassified"])):
        colour = "#d62728" if r["peer"] else "#1f77b4"
        name = label(r).replace("`", "").replace("²", "^2")
        out.append(f'<text x="{width - right + 10}" y="{top + 12 * (i + 1)}" fill="{colour}">'
                   f'{escape(name)} {r["misclassified"]:.3f} % {r["time"]:.0f} ms</text>')
    out.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def main(paths, svg_prefix=None):
    runs = read_runs(paths)
    if svg_prefix:
        for scene in sorted({r["scene"] for r in runs}):
            draw_svg(runs, scene, f"{svg_prefix}-{scene}.svg")
    print("| scene | peer run | misclassified % | full ms (reps) | shadowfx run with ≤ half the error in ≤ the time |")
    print("|---|---|---:|---:|---|")
    unbeaten = 0
    for peer in sorted((r for r in runs if r["peer"]), key=lambda r: (r["scene"], r["peer"], r["map_size"])):
        own = [r for r in runs if not r["peer"] and r["scene"] == peer["scene"]]
        winners = [r for r in own if r["misclassified"] <= 0.5 * peer["misclassified"] and r["time"] <= peer["time"]]
        if winners:
            best = min(winners, key=lambda r: r["time"])
            verdict = f'{label(best)}: {best["misclassified"]:.3f} % in {best["time"]:.1f} ms'
        else:
            unbeaten += 1
            fast = [r for r in own if r["time"] <= peer["time"]]
            if fast:
                near = min(fast, key=lambda r: r["misclassified"])
                verdict = f'**none**; least error in the time: {label(near)} {near["misclassified"]:.3f} %'
            else:
                verdict = "**none**; no shadowfx run is as fast"
        print(f'| {peer["scene"]} | {label(peer)} | {peer["misclassified"]:.3f} | {peer["time"]:.1f} '
              f'({len(peer["times"])}) | {verdict} |')
    print(f"\n{unbeaten} peer run(s) unbeaten.")


if __name__ == "__main__":
    arguments = sys.argv[1:]
    prefix = None
    if arguments[:1] == ["--svg"] and len(arguments) > 1:
        prefix, arguments = arguments[1], arguments[2:]
    if not arguments:
        sys.exit(__doc__)
    main(arguments, prefix)
