#!/usr/bin/python3
"""Which verdicts a re-run of `make.sh compare` changed: every (run, variant, quantity) verdict of
compare/all/*/compare.json in the working tree against the same file at a git revision (default
HEAD), counted by transition; quantities new to the re-run are counted apart, by verdict. Run from
the repository root after `data/reference/make.sh compare`:

    /usr/bin/python3 data/reference/verdict_changes.py [REV]
"""
import collections
import glob
import json
import subprocess
import sys

ROOT = "data/reference/compare/all"


def verdicts(compare):
    """{(variant, quantity): verdict} of one compare.json."""
    return {(variant["label"], v["quantity"]): v["verdict"]
            for variant in compare["variants"] for v in variant["verdicts"]}


def at_revision(rev, path):
    shown = subprocess.run(["git", "show", f"{rev}:{path}"], capture_output=True, text=True)
    return json.loads(shown.stdout) if shown.returncode == 0 else None


def main(rev):
    changed, new, same = collections.Counter(), collections.Counter(), 0
    runs = sorted(glob.glob(f"{ROOT}/*/compare.json"))
    for path in runs:
        before = at_revision(rev, path)
        after = verdicts(json.load(open(path)))
        old = verdicts(before) if before else {}
        for key, verdict in after.items():
            if key not in old:
                new[(key[1], verdict)] += 1
            elif old[key] != verdict:
                changed[(key[0], key[1], old[key], verdict)] += 1
            else:
                same += 1
    print(f"{len(runs)} runs; {same} verdicts unchanged against {rev}")
    for (variant, quantity, a, b), n in sorted(changed.items()):
        print(f"changed: {n} {variant} {quantity}: {a} -> {b}")
    for (quantity, verdict), n in sorted(new.items()):
        print(f"new: {n} {quantity} {verdict}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "HEAD")
