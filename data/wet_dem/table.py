"""The wet DEM check's table (README.md here): per suction, peak and residual friction and total
dilation as mean +- SD over the seeds (each run's summary.json; friction is tau / sigma_n on the
wall, sigma_n the net load with the grains' weight), their change from the dry runs in percent and
in standard errors of the difference, and what Khalili's effective stress (seed eq. 6.31, the
stress of Masin & Khalili's model) predicts for the friction at the same net load:
tau / sigma_net = mu_dry (1 + chi s / sigma_net), chi = (s_e / s)^0.55 above s_e.
Usage: table.py RUN_DIR [S_E_KPA]   (RUN_DIR holds runs/s<suction>_s<seed>/)"""
import glob
import json
import math
import os
import re
import statistics
import sys

run_dir = sys.argv[1]
s_e = float(sys.argv[2]) if len(sys.argv) > 2 else 0.36  # kPa: 4 gamma / (0.4 d50), the pores' entry
QOIS = [("peak_friction", "peak friction"), ("residual_friction", "residual friction"), ("dilation_mm", "dilation (mm)")]

runs = {}
for path in sorted(glob.glob(os.path.join(run_dir, "runs", "s*_s*", "summary.json"))):
    suction = float(re.match(r"s([0-9.]+)_s", os.path.basename(os.path.dirname(path))).group(1))
    summary = json.load(open(path))
    summary["sigma_n_kPa"] = summary["sigma_n_mean_kPa"]
    runs.setdefault(suction, []).append(summary)


def stats(values):
    return statistics.mean(values), (statistics.stdev(values) if len(values) > 1 else float("nan"))


def change(a, b):
    """b against a: percent and standard errors of the difference."""
    (ma, sa), (mb, sb) = stats(a), stats(b)
    se = math.sqrt(sa ** 2 / len(a) + sb ** 2 / len(b)) if len(a) > 1 and len(b) > 1 else float("nan")
    return 100.0 * (mb / ma - 1.0), (mb - ma) / se if se > 0 else float("nan")


dry = runs.get(0.0, [])
print("| suction (kPa) | runs | " + " | ".join(label for _, label in QOIS) + " | Khalili: chi s (kPa), predicted residual friction |")
print("|---|---|" + "---|" * (len(QOIS) + 1))
for s in sorted(runs):
    cells = []
    for key, _ in QOIS:
        v = [r[key] for r in runs[s]]
        m, sd = stats(v)
        cell = f"{m:.3f} +- {sd:.3f}"
        if s > 0 and len(dry) > 0:
            pct, z = change([r[key] for r in dry], v)
            cell += f" ({pct:+.1f} %, {z:+.1f} SE)"
        cells.append(cell)
    model = ""
    if s > 0 and dry:
        chi = (s_e / s) ** 0.55 if s > s_e else 1.0
        sigma = statistics.mean(r["sigma_n_kPa"] for r in runs[s])
        mu = statistics.mean(r["residual_friction"] for r in dry)
        model = f"{chi * s:.2f}, {mu * (1.0 + chi * s / sigma):.3f}"
    print(f"| {s:g} | {len(runs[s])} | " + " | ".join(cells) + f" | {model} |")
