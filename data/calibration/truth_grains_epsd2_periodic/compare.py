"""The truth grains' simple-shear designs in the plate cell (../truth_grains_epsd2/) and in the
periodic cell (here, issue 38 item 1), side by side: per design the mean and 95 % Student-t
interval over the seeds of e0, peak tau/sigma_n, the peak dilatancy rate d eps_n / d gamma (CNL;
the summary's rate at the peak friction, as ../../dilatancy/table.py reads it), tau/sigma_n
over the last fifth, and sigma_n at the end (CV); for the periodic cells how far they sheared
homogeneously (the gamma calibrate reads them to). Run from the repository root:
/usr/bin/python3 data/calibration/truth_grains_epsd2_periodic/compare.py > data/calibration/truth_grains_epsd2_periodic/compare.md
"""
import csv
import glob
import json
import math
import os
import sys

import numpy as np

sys.path.insert(0, "data/dilatancy")
sys.path.insert(0, "data")
import seed_stats  # noqa: E402
from table import homogeneous_until, rate_at_peak, summary_of  # noqa: E402  the dilatancy table's reads

DESIGNS = ["CNL-dense-50", "CNL-loose-50", "CV-dense-50", "CV-loose-50",
           "CNL-dense-200", "CNL-loose-200", "CV-dense-200", "CV-loose-200"]
CELLS = [("plates", "data/calibration/truth_grains_epsd2"), ("periodic", "data/calibration/truth_grains_epsd2_periodic")]


def interval(xs):
    return seed_stats.interval([x for x in xs if x is not None and math.isfinite(x)], single="{:s} (1 seed)")


def measures(run):
    rows = list(csv.DictReader(open(os.path.join(run, "timeseries.csv"))))
    col = lambda k: np.array([float(r[k]) for r in rows])
    gamma, tau, sn, e = col("gamma"), col("tau_kPa"), col("sigma_n_kPa"), col("e")
    ratio = tau / sn
    last = gamma >= 0.8 * gamma[-1]
    rate = rate_at_peak(summary_of(run))[0] if "CNL" in run else None
    return {"e0": e[0], "peak": ratio.max(), "rate": rate, "residual": ratio[last].mean(),
            "sigma_end": sn[-1], "until": homogeneous_until(os.path.join(run, "manifest.json"))}


def main():
    print("| design | cell | seeds | e0 | peak tau/sigma_n | peak d eps_n/d gamma | tau/sigma_n, last fifth | sigma_n at the end (kPa) | homogeneous until gamma |")
    print("|---|---|---|---|---|---|---|---|---|")
    for design in DESIGNS:
        for cell, root in CELLS:
            runs = sorted(d for d in glob.glob(f"{root}/seed*/simpleshear-{design}") if os.path.exists(f"{d}/timeseries.csv"))
            if not runs:
                continue
            m = [measures(r) for r in runs]
            until = ", ".join(x["until"] for x in m) if cell == "periodic" else ""
            print(f"| {design} | {cell} | {len(m)} | {interval([x['e0'] for x in m])} | {interval([x['peak'] for x in m])} | "
                  f"{interval([x['rate'] for x in m]) if 'CNL' in design else ''} | {interval([x['residual'] for x in m])} | "
                  f"{interval([x['sigma_end'] for x in m]) if 'CV' in design else ''} | {until} |")


if __name__ == "__main__":
    main()
