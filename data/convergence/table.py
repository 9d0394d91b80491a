"""Per level of one axis and wall: each quantity of interest as mean +- SD over the seeds (from each
run's summary.json), and its change to another level in percent and in units of the pooled
standard error of the difference, sqrt(SD_a^2/n_a + SD_b^2/n_b). A level is converged in a
quantity when that change is within 2 % or within 2 standard errors (a ✔).
Usage (as data/convergence/make.sh table calls it):
  table.py AXIS_DIR                       a chain of levels (stiffness): each against the next finer
  table.py AXIS_DIR BASE_AXIS_DIR LEVEL   one knob from the base (box, inertial, timestep): the runs
                                          of LEVEL in BASE_AXIS_DIR are the base, each level of
                                          AXIS_DIR is compared with it"""
import glob
import json
import math
import os
import statistics
import sys

QOIS = [("peak_friction", "peak friction"), ("residual_friction", "residual friction"),
        ("dilation_mm", "total dilation (mm)"), ("dilatancy_angle_deg", "dilatancy angle at residual (deg)"),
        ("u_x_at_peak_mm", "u_x at peak (mm)"), ("wall_band_d50", "wall band (d50)"),
        ("sigma_n_held_kPa", "mean sigma_n while shearing (kPa; CNL at 50)")]


def mean_sigma_n(run_dir):
    """How well CNL was held: the mean sigma_n on the wall over the rows after the first (the grains'
    weight adds ~0.6 kPa at 20 d50)."""
    import csv
    path = os.path.join(run_dir, "timeseries.csv")
    if not os.path.exists(path):
        return None
    rows = list(csv.DictReader(open(path)))[1:]
    return statistics.mean(float(r["sigma_n_kPa"]) for r in rows) if rows else None


def level_and_wall(name):
    """Job names read <level...>_<wall>_s<seed>: E100000000_sawtooth-2-0.5_s1, E690000000_I0.0003_flat_s2."""
    parts = name.split("_")
    return "_".join(parts[:-2]), parts[-2]


def number(level):
    digits = "".join(c for c in level.split("_")[0] if c.isdigit() or c in ".e-")
    return float(digits)


def read_groups(axis_dir):
    groups = {}
    for f in sorted(glob.glob(os.path.join(axis_dir, "runs", "*", "summary.json"))):
        name = os.path.basename(os.path.dirname(f))
        summary = json.load(open(f))
        summary["sigma_n_held_kPa"] = mean_sigma_n(os.path.dirname(f))
        groups.setdefault(level_and_wall(name), []).append(summary)
    return groups


def values(runs, key):
    return [r[key] for r in runs if isinstance(r.get(key), (int, float))]


def cell(xs, ys, direction):
    """mean +- SD of xs; with ys, the change from xs to ys (direction names it)."""
    if not xs:
        return "-"
    m, sd = statistics.mean(xs), statistics.stdev(xs) if len(xs) > 1 else float("nan")
    text = f"{m:.3g} ± {sd:.2g}"
    if len(xs) > 1 and len(ys) > 1:
        mo, sdo = statistics.mean(ys), statistics.stdev(ys)
        se = math.sqrt(sd ** 2 / len(xs) + sdo ** 2 / len(ys))
        change, rel = (m - mo, (m - mo) / abs(mo)) if direction == "from base" else (mo - m, (mo - m) / abs(m))
        ok = abs(rel) <= 0.02 or abs(change) <= 2 * se
        text += f"; {direction} {100 * rel:+.0f} % ({change / se if se else float('nan'):+.1f} SE){' ✔' if ok else ''}"
    return text


def row(wall, level, runs, other, direction):
    cells = [cell(values(runs, k), values(other, k) if other else [], direction) for k, _ in QOIS]
    return f"| {wall} | {level} | {len(runs)} | " + " | ".join(cells) + " |"


groups = read_groups(sys.argv[1])
base = None
if len(sys.argv) == 4:
    base_level = sys.argv[3]
    base = {w: runs for (l, w), runs in read_groups(sys.argv[2]).items() if l == base_level}

print("| wall | level | runs | " + " | ".join(label for _, label in QOIS) + " |")
print("|---|---|---|" + "---|" * len(QOIS))
for wall in sorted({w for _, w in groups}):
    levels = sorted((l for l, w in groups if w == wall), key=number)
    if base is not None:
        print(row(wall, f"base ({sys.argv[3]})", base.get(wall, []), None, ""))
        for level in levels:
            print(row(wall, level, groups[(level, wall)], base.get(wall, []), "from base"))
        continue
    for i, level in enumerate(levels):
        finer = groups.get((levels[i + 1], wall)) if i + 1 < len(levels) else None
        print(row(wall, level, groups[(level, wall)], finer, "to finer"))
