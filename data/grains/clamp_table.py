#!/usr/bin/python3
"""The deeper clamp against the truth's (README.md here, "A deeper clamp"): each run of
clamp_depth/ (9 d50 clamped) beside the run of the same seed with 6 d50 clamped, where the
committed campaigns have one, and the two sets compared (means +- 95 % t half-widths, n - 1
degrees of freedom; Welch's test). Not paired: the clamp-6 specimens were consolidated by earlier
builds (seed 1's specimen e 0.6564 there, 0.6546 here), so a seed is the same realisation only
in name. Run from the repository root:

    /usr/bin/python3 data/grains/clamp_table.py
"""
import glob
import json
import os
import re
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # data/seed_stats.py
from seed_stats import interval, welch  # noqa: E402

QUANTITIES = [("peak", "peak_friction"), ("residual", "residual_friction"), ("dilation (mm)", "dilation_mm"),
              ("wall band (d50)", "wall_band_d50")]


def clamp6_pair(name):
    """The same specimen sheared with 6 d50 clamped (dense: the truth cell; loose: the density sweep)."""
    cf, seed = re.match(r"cf([\d.]+)_s(\d+)", name).groups()
    if cf == "0.1":
        candidates = [f"data/convergence/truth_clamped/runs/s{seed}", f"data/reference/truth2_seeds45/runs/s{seed}_cnl-50"]
    else:
        candidates = [f"data/grains/density/runs/cf1_rn0.5_cnl-50_s{seed}"]
    return next((c for c in candidates if os.path.exists(f"{c}/summary.json")), None)


def summary(run):
    return json.load(open(f"{run}/summary.json"))


def mean_half(x):
    if len(x) < 2:
        return " / ".join(f"{v:.3g}" for v in x) + f" ({len(x)} run)"
    return interval(x) + f" ({len(x)} runs)"


def cell(values):
    return "-" if values is None else " / ".join("-" if v is None else f"{v:.3g}" for v in values)


def main():
    sets = {}
    print("| run | where it sheared, clamp 9 / 6 | " + " | ".join(f"{q}, 9 / 6" for q, _ in QUANTITIES) + " |")
    print("|---|---|" + "---|" * len(QUANTITIES))
    for run in sorted(glob.glob("data/grains/clamp_depth/runs/*")):
        name = os.path.basename(run)
        deep, pair = summary(run), clamp6_pair(name)
        shallow = summary(pair) if pair else None
        modes = deep["shear_mode"] + " / " + (shallow["shear_mode"] if shallow else "-")
        cols = [cell((deep.get(k), shallow.get(k) if shallow else None)) for _, k in QUANTITIES]
        print(f"| {name} | {modes} | " + " | ".join(cols) + " |")
        density = "dense" if name.startswith("cf0.1") else "loose"
        for q, k in QUANTITIES:
            for clamp, s in ((9, deep), (6, shallow)):
                if s is not None and s.get(k) is not None:
                    sets.setdefault((density, q, clamp), []).append(s[k])
    print("\nclamp 9 against clamp 6 (mean +- 95 % t, runs; Welch's p):")
    for density, q in sorted({(d, q) for d, q, _ in sets}):
        a, b = sets.get((density, q, 9), []), sets.get((density, q, 6), [])
        p = welch(b, a)[2] if len(a) > 1 and len(b) > 1 else float("nan")
        print(f"  {density} {q}: {mean_half(a)} against {mean_half(b)}, p {p:.2f}")


if __name__ == "__main__":
    main()
