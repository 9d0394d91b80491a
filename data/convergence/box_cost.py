#!/usr/bin/python3
"""Issue 59 item 4: does the longer box (24 d50) buy more resolution per unit of engine work than more
seeds of the base box (12 d50)? For a target 95 % half-width h the seeds needed are n ~ (t sd / h)^2,
so the work of a cell is n times a run's work, proportional to sd^2 x work per run: the ratio
sd_12^2 w_12 / (sd_24^2 w_24) above 1 says the longer box is cheaper. Work is counted in particle-
steps (the engine's own count in each stage's facts, machine- and load-independent); the variance
ratio of two groups of three seeds is judged by the F test (2 and 2 degrees of freedom). Run from
the repository root: /usr/bin/python3 data/convergence/box_cost.py
"""
import glob
import json
import statistics

from scipy import stats

CELLS = {"12 d50": "data/convergence/stiffness/runs/E690000000_{wall}_s*",
         "24 d50": "data/convergence/box/runs/E690000000_box24-4-20-2560-0.1_{wall}_s*"}
QUANTITIES = ["peak_friction", "residual_friction", "dilation_mm"]


def group(pattern):
    runs = []
    for r in sorted(glob.glob(pattern)):
        summary = json.load(open(r + "/summary.json"))
        manifest = json.load(open(r + "/manifest.json"))
        work = sum(s.get("facts", {}).get("particle_steps", 0.0) for s in manifest["stages"].values())
        runs.append((summary, work))
    return runs


print("| wall | quantity | SD 12 d50 (3 seeds) | SD 24 d50 (3 seeds) | work per run 24 / 12 | "
      "work for equal resolution, 12 / 24 | F test p (variances equal) |")
print("|---|---|---|---|---|---|---|")
for wall in ["flat", "sawtooth-2-0.5"]:
    short, long_ = (group(CELLS[k].format(wall=wall)) for k in ("12 d50", "24 d50"))
    w12 = statistics.mean(w for _, w in short)
    w24 = statistics.mean(w for _, w in long_)
    for q in QUANTITIES:
        sd12 = statistics.stdev(s[q] for s, _ in short)
        sd24 = statistics.stdev(s[q] for s, _ in long_)
        f = (sd12 / sd24) ** 2
        p = 2 * min(stats.f.sf(f, 2, 2), stats.f.cdf(f, 2, 2))
        print(f"| {wall} | {q} | {sd12:.4f} | {sd24:.4f} | {w24 / w12:.2f} | "
              f"{sd12 ** 2 * w12 / (sd24 ** 2 * w24):.2g} | {p:.2g} |")
