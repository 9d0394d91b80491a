#!/usr/bin/python3
"""plan_shipped.py IWB REPO SCRATCH: `iwb plan` replays the shipped tradeoffs (data/tradeoff/*/)
from their committed compact runs and gives the plan committed beside them.

The committed plan.json was written when the full run directories (VTK, restarts) still existed;
its command line is replayed with --tradeoff pointing at the committed directory and -o at the
scratch directory. Every key of the new plan but the two naming those directories must equal the
committed one (numbers to 1e-9 relative): the DEM choice (from tradeoff.json) and each continuum model's calibrated errors
(from the base runs' time series, replayed through the models). Before that, each committed run
must be the tradeoff's own: its summary's quantities equal those tradeoff.json recorded for it.
"""
import json
import shlex
import subprocess
import sys
from pathlib import Path

iwb, repo, scratch = sys.argv[1], Path(sys.argv[2]), Path(sys.argv[3])
failures = []


def check_runs_are_the_tradeoffs(tradeoff_dir):
    tradeoff = json.loads((tradeoff_dir / "tradeoff.json").read_text())
    for run in tradeoff["runs"]:
        summary_file = tradeoff_dir / "runs" / run["name"] / "summary.json"
        if not summary_file.exists():
            continue  # plan needs the base seeds and the reference only; it says so if one is missing
        summary = json.loads(summary_file.read_text())
        for key in ("peak_friction", "residual_friction"):
            if run["qoi"].get(key) != summary.get(key):
                failures.append(f"{summary_file}: {key} {summary.get(key)} is not the tradeoff's "
                                f"{run['qoi'].get(key)} for {run['name']}")


def same(a, b):
    """Equal in structure and text, numbers to 1e-9 relative: on another processor the models'
    integrations over thousands of steps end 1e-11 apart (an AMD EPYC, 2026-12-02); a change of the
    code moves them by far more."""
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    if isinstance(a, float) or isinstance(b, float):
        return isinstance(a, (int, float)) and isinstance(b, (int, float)) and \
            abs(a - b) <= 1e-9 * max(1.0, abs(a), abs(b))
    return a == b


def replay(tradeoff_dir):
    committed = json.loads((tradeoff_dir / "plan.json").read_text())
    args = shlex.split(committed["command_line"])[1:]  # without the binary's path
    for option, value in (("--tradeoff", str(tradeoff_dir)), ("-o", str(scratch / tradeoff_dir.name))):
        if option in args:
            args[args.index(option) + 1] = value
        else:
            args += [option, value]
    done = subprocess.run([iwb] + args, cwd=repo, capture_output=True, text=True)
    if done.returncode != 0:
        failures.append(f"{tradeoff_dir}: iwb {' '.join(args)} exits {done.returncode}:\n{done.stderr}")
        return
    fresh = json.loads((scratch / tradeoff_dir.name / "plan.json").read_text())
    for key in sorted(set(committed) | set(fresh)):
        if key in ("command_line", "tradeoff"):
            continue
        if not same(committed.get(key), fresh.get(key)):
            failures.append(f"{tradeoff_dir}/plan.json: '{key}' differs from the replay:\n"
                            f"  committed {json.dumps(committed.get(key))[:300]}\n"
                            f"  replayed  {json.dumps(fresh.get(key))[:300]}")
    print(f"ok: iwb {' '.join(args)}")


shipped = sorted(p.parent for p in (repo / "data" / "tradeoff").glob("*/plan.json"))
if len(shipped) < 2:
    failures.append("data/tradeoff: fewer than two shipped tradeoffs with a plan.json")
for tradeoff_dir in shipped:
    check_runs_are_the_tradeoffs(tradeoff_dir)
    replay(tradeoff_dir)
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
