#!/usr/bin/env python3
"""Every figure in docs/results/ can be reproduced: each results file cites at least one commit, and every
commit it cites (a 7-40 digit hexadecimal name in backquotes) is in the history of the checked-out commit.

  results_commits.py SOURCE_DIR

A commit that was rebased away before it landed is not in the history: cite the landed commit that carries
the same code, or say that the figure is not reproducible at a landed commit and cite none for it.
A source tree without git history (an exported archive) cannot show this: the check then fails and says
so, rather than passing without having looked. A shallow clone holds the history of its last commits only:
the check then exits 77, which CTest reports as a skip with this script's reason (SKIP_RETURN_CODE), since
its answer there would say how the tree was cloned, not whether a figure is reproducible.
"""
import os
import re
import subprocess
import sys

COMMIT = re.compile(r"`([0-9a-f]{7,40})`")
SKIPPED = 77  # CTest's SKIP_RETURN_CODE for this test


def git(source_dir, *args):
    return subprocess.run(["git", "-C", source_dir, *args], capture_output=True, text=True)


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    source_dir = sys.argv[1]
    results_dir = os.path.join(source_dir, "docs", "results")
    try:
        inside = git(source_dir, "rev-parse", "--is-inside-work-tree")
    except FileNotFoundError:
        print("results_commits: git is not installed: the cited commits cannot be checked", file=sys.stderr)
        return 1
    toplevel = git(source_dir, "rev-parse", "--show-toplevel").stdout.strip()
    if inside.returncode != 0 or os.path.realpath(toplevel) != os.path.realpath(source_dir):
        print(f"results_commits: {source_dir} has no git history (an exported tree?): the commits "
              "docs/results/ cites cannot be checked; run this test from a clone", file=sys.stderr)
        return 1
    if git(source_dir, "rev-parse", "--is-shallow-repository").stdout.strip() == "true":
        print(f"results_commits: skipped: {source_dir} is a shallow clone, older cited commits are not in "
              "it; run `git fetch --unshallow` first")
        return SKIPPED

    failures = []
    files = sorted(f for f in os.listdir(results_dir) if f.endswith(".md") and f != "README.md")
    for name in files:
        with open(os.path.join(results_dir, name), encoding="utf-8") as f:
            lines = f.read().splitlines()
        cited = [(number, commit) for number, line in enumerate(lines, 1) for commit in COMMIT.findall(line)]
        if not cited:
            failures.append(f"docs/results/{name}: cites no commit its figures were measured at")
        for number, commit in cited:
            resolved = git(source_dir, "rev-parse", "--verify", "--quiet", commit + "^{commit}")
            if resolved.returncode != 0:
                failures.append(f"docs/results/{name}:{number}: commit {commit} is not in this repository")
            elif git(source_dir, "merge-base", "--is-ancestor", resolved.stdout.strip(), "HEAD").returncode != 0:
                failures.append(f"docs/results/{name}:{number}: commit {commit} is not in the history of HEAD")
    for failure in failures:
        print(failure, file=sys.stderr)
    print(f"results_commits: {len(files)} results files, {len(failures)} problems")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
