"""Per level of one axis and wall: each quantity of interest as mean +- SD over the seeds (from each
run's summary.json), and its change from the next finer level in percent and in units of the
pooled standard error of the difference, sqrt(SD_a^2/n_a + SD_b^2/n_b). A level is converged in a
quantity when the change to the next finer level is within 2 % or within 2 standard errors.
Usage: table.py AXIS_DIR  (as data/convergence/make.sh table calls it)."""
import glob
import json
import math
import os
import statistics
import sys

QOIS = [("peak_friction", "peak friction"), ("residual_friction", "residual friction"),
        ("dilation_mm", "total dilation (mm)"), ("dilatancy_angle_deg", "dilatancy angle at residual (deg)"),
        ("u_x_at_peak_mm", "u_x at peak (mm)"), ("wall_band_d50", "wall band (d50)")]


def level_and_wall(name):
    """Job names read <level>_<wall>_s<seed>: E100000000_sawtooth-2-0.5_s1."""
    parts = name.split("_")
    return parts[0], "_".join(parts[1:-1])


def number(level):
    digits = "".join(c for c in level if c.isdigit() or c in ".e-")
    return float(digits)


groups = {}
for f in sorted(glob.glob(os.path.join(sys.argv[1], "runs", "*", "summary.json"))):
    name = os.path.basename(os.path.dirname(f))
    groups.setdefault(level_and_wall(name), []).append(json.load(open(f)))

print("| wall | level | runs | " + " | ".join(label for _, label in QOIS) + " |")
print("|---|---|---|" + "---|" * len(QOIS))
walls = sorted({w for _, w in groups})
for wall in walls:
    levels = sorted((l for l, w in groups if w == wall), key=number)
    for i, level in enumerate(levels):
        runs = groups[(level, wall)]
        cells = []
        for key, _ in QOIS:
            xs = [r[key] for r in runs if isinstance(r.get(key), (int, float))]
            if not xs:
                cells.append("-")
                continue
            m, sd = statistics.mean(xs), statistics.stdev(xs) if len(xs) > 1 else float("nan")
            cell = f"{m:.3g} ± {sd:.2g}"
            finer = groups.get((levels[i + 1], wall)) if i + 1 < len(levels) else None
            ys = [r[key] for r in finer if isinstance(r.get(key), (int, float))] if finer else []
            if len(xs) > 1 and len(ys) > 1:
                mf, sdf = statistics.mean(ys), statistics.stdev(ys)
                se = math.sqrt(sd ** 2 / len(xs) + sdf ** 2 / len(ys))
                rel = (mf - m) / abs(m) if m else float("nan")
                ok = abs(rel) <= 0.02 or abs(mf - m) <= 2 * se
                cell += f"; to finer {100 * rel:+.0f} % ({(mf - m) / se if se else float('nan'):+.1f} SE){' ✔' if ok else ''}"
            cells.append(cell)
        print(f"| {wall} | {level} | {len(runs)} | " + " | ".join(cells) + " |")
