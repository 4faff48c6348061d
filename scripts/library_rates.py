#!/usr/bin/env python3
"""How much of a folder of effects shadowfx compiles and renders.

    scripts/library_rates.py run TOOL LIBRARY_ROOT FOLDER... --out RESULTS.jsonl [--timeout 60]
    scripts/library_rates.py summary RESULTS.jsonl [OLD_RESULTS.jsonl]

`run` runs `TOOL compile EFFECT` and `TOOL render EFFECT --scene teapot` on every .fx under each FOLDER
(relative to LIBRARY_ROOT), one effect at a time, and writes one JSON line per effect: its exit statuses,
the first error line of each (paths relative to LIBRARY_ROOT, so that results of two machines or two
checkouts compare) and the number of distinct colours of the rendered frame. A frame with fewer than
BLANK_BELOW colours is blank: a clear colour, or one flat shade over the teapot.

`summary` prints, per folder, the effects, compiled, rendered and non-blank counts (beside OLD's when
given, with every effect whose outcome differs), and the new results' failure classes: the first error
line with its names and numbers taken out, counted, one example each.
"""
import argparse
import collections
import json
import os
import pathlib
import re
import subprocess
import sys
import tempfile

from png_pixels import read_png

BLANK_BELOW = 8


def png_colours(path):
    """Distinct RGB colours of a frame `shadowfx render` wrote (alpha ignored, as `shadowfx check` judges a
    frame)."""
    return len({pixel[:3] for row in read_png(pathlib.Path(path)) for pixel in row})


def first_error(text, root):
    """The first line that reports an error, else the first line printed; paths relative to `root`."""
    lines = text.replace(str(root) + os.sep, "").splitlines()
    for line in lines:
        if "error:" in line:
            return line.strip()
    return next((line.strip() for line in lines if line.strip()), "")


def run_tool(command, timeout):
    # One llvmpipe rasterizer thread per run: the effects run one at a time on a machine shared with builds.
    environment = dict(os.environ, LP_NUM_THREADS="1")
    try:
        done = subprocess.run(command, capture_output=True, text=True, errors="replace", timeout=timeout,
                              env=environment)
        return done.returncode, done.stdout + done.stderr
    except subprocess.TimeoutExpired:
        return 124, f"timed out after {timeout} s"


def run(args):
    root = pathlib.Path(args.library_root).resolve()
    with open(args.out, "w") as out, tempfile.TemporaryDirectory() as scratch:
        frame = pathlib.Path(scratch) / "frame.png"
        for folder in args.folders:
            for effect in sorted((root / folder).rglob("*.fx")):
                record = {"folder": folder, "effect": str(effect.relative_to(root))}
                status, text = run_tool([args.tool, "compile", str(effect)], args.timeout)
                record.update(compile=status, compile_error="" if status == 0 else first_error(text, root))
                frame.unlink(missing_ok=True)
                render = [args.tool, "render", str(effect), "--scene", "teapot", "--out", str(frame)]
                status, text = run_tool(render, args.timeout)
                record.update(render=status, render_error="" if status == 0 else first_error(text, root))
                record["colours"] = png_colours(frame) if status == 0 and frame.exists() else 0
                out.write(json.dumps(record) + "\n")
                out.flush()


def load(path):
    with open(path) as f:
        return [json.loads(line) for line in f]


def error_line(record, stage):
    """The stage's first error line; a run killed by a signal printed none."""
    status = record[stage]
    if status < 0:
        return f"killed by signal {-status}"
    return record[f"{stage}_error"] or (f"exit status {status}" if status else "")


def outcome(record):
    if record["compile"] != 0:
        return "compile fails"
    if record["render"] != 0:
        return "render fails"
    return "blank" if record["colours"] < BLANK_BELOW else "drawn"


def counts(records):
    table = collections.OrderedDict()
    for r in records:
        row = table.setdefault(r["folder"], [0, 0, 0, 0])
        row[0] += 1
        row[1] += r["compile"] == 0
        row[2] += r["render"] == 0
        row[3] += r["render"] == 0 and r["colours"] >= BLANK_BELOW
    return table


def failure_class(line):
    """The error line without what names this effect: quoted names, numbers, the location."""
    line = re.sub(r"^\S+?:\d+:\d+: ", "", line)
    line = re.sub(r"'[^']*'", "'X'", line)
    return re.sub(r"\b\d+\b", "N", line)


def summary(args):
    new = load(args.results)
    old = load(args.old) if args.old else None
    print("| folder | effects | compile OK | render OK | not blank |")
    print("|---|---|---|---|---|")
    old_counts = counts(old) if old else {}
    for folder, row in counts(new).items():
        before = old_counts.get(folder)
        cells = [str(v) if before is None or before[i] == v else f"{before[i]} -> {v}"
                 for i, v in enumerate(row)]
        print(f"| {folder} | " + " | ".join(cells) + " |")
    if old:
        print("\nChanged outcomes (old -> new):")
        before = {r["effect"]: r for r in old}
        changes = 0
        for r in new:
            was = before.get(r["effect"])
            if not was:
                continue
            changed = [stage for stage in ("compile", "render")
                       if error_line(was, stage) != error_line(r, stage)]
            if outcome(was) != outcome(r) or changed:
                changes += 1
                print(f"- {r['effect']}: {outcome(was)} -> {outcome(r)}")
                for stage in changed:
                    print(f"    {stage}: {error_line(was, stage)!r} -> {error_line(r, stage)!r}")
        if not changes:
            print("- none")
    classes = collections.Counter()
    example = {}
    for r in new:
        line = error_line(r, "compile") or error_line(r, "render")
        if not line and outcome(r) == "blank":
            line = "blank frame"
        if line:
            key = failure_class(line)
            classes[key] += 1
            example.setdefault(key, f"{r['effect']}: {line}")
    print("\nFailure classes of the new results:")
    for key, n in classes.most_common():
        print(f"- {n}: {key}\n    e.g. {example[key]}")


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    commands = parser.add_subparsers(dest="command", required=True)
    run_parser = commands.add_parser("run")
    run_parser.add_argument("tool")
    run_parser.add_argument("library_root")
    run_parser.add_argument("folders", nargs="+")
    run_parser.add_argument("--out", required=True)
    run_parser.add_argument("--timeout", type=int, default=60)
    summary_parser = commands.add_parser("summary")
    summary_parser.add_argument("results")
    summary_parser.add_argument("old", nargs="?")
    args = parser.parse_args()
    run(args) if args.command == "run" else summary(args)


if __name__ == "__main__":
    sys.exit(main())
