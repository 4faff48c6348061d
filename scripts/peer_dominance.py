#!/usr/bin/env python3
"""Which peer runs shadowfx beats in `shadowfx bench --peers` outputs: for every peer run, the shadowfx runs
on the same scene with at most half its misclassified % at no more than its full-cost frame time (each side
at its own map size and settings), and the nearest miss where there is none.

usage: scripts/peer_dominance.py RESULTS.json [RESULTS.json ...]   (markdown on stdout)

The same run (scene, effect or peer, technique, map size, settings) in several files is one run measured
several times: its frame time is the median of the files' medians, its error the first file's (errors do
not depend on the machine's load). Give only outputs of one sitting on one machine together; alternating
repetitions of the two sides' benches in that sitting evens out a drifting load.
"""
import json
import statistics
import sys


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


def main(paths):
    runs = read_runs(paths)
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
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
