"""Peak friction and peak dilatancy rate d u_n / d u_x of the truth grains sheared three ways, from
the committed runs (README.md here): the soil cell (no wall) at the density of the truth's specimen
and at the calibration's dense and loose densities, between rough plates and fully periodic (issue
38: no plate, so no band beside one); the interface runs of the truth scene on the
flat, R_n 0.25 and R_n 0.5 walls; and vw3d with the calibrated set, started at each soil cell's own
void ratio. In simple shear d u_n / d u_x = d eps_n / d gamma, and at an interface whose dilation
happens in a band of thickness d_s it is d eps_n / d gamma of the band: the rate compares the three
whatever the band's thickness. Run from the repository root: /usr/bin/python3 data/dilatancy/table.py

Every DEM measure is the product's (issue 59: no table script re-implements a rule): the rate at
the peak and the peak friction from each run's summary (summary.json; a soil cell's manifest
cell_summary, both recomputed by `iwb dem summary`), the element span from cell_summary's
element_until_gamma (calibration's own rule). The rate is d u_n / d u_x over half a d50 either side
of the peak friction, the mean of 8 block slopes (src/dem/analysis/summary.hpp); until 2 Dec it was the
largest 1 mm windowed slope here, which grows with the noise.
"""
import csv
import glob
import math
import os
import subprocess
import sys
import tempfile

import json

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))  # data/seed_stats.py
from seed_stats import interval  # noqa: E402

# vw3d's calibrated sets: on the plate cells (issue 20) and on the periodic cells (issue 38), the
# latter where it exists
PARAMS = {"plates": "data/params/truth_grains_epsd2.toml",
          "periodic": "data/params/truth_grains_epsd2_periodic.toml"}
SETS = [k for k, f in PARAMS.items() if os.path.exists(f)]


def load(path):
    rows = list(csv.DictReader(open(path)))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def summary_of(run_dir):
    """The product's summary of a run: summary.json, or a soil cell's manifest cell_summary."""
    path = os.path.join(run_dir, "summary.json")
    if os.path.exists(path):
        return json.load(open(path))
    return json.load(open(os.path.join(run_dir, "manifest.json")))["cell_summary"]


def rate_at_peak(summary):
    """(rate, 95 % half-width over its blocks) of the summary's dilatancy rate at the peak."""
    r = summary["dilatancy_rate_at_peak"]
    return r["rate"], r["ci95"]


def model_run(e0, params, sigma_kPa=50.0, gamma=0.5):
    """vw3d with a calibrated set, CNL simple shear from e0 (iwb element; d_s 1 mm, so u = gamma mm)."""
    with tempfile.TemporaryDirectory() as tmp:
        test = os.path.join(tmp, "test.toml")
        with open(test, "w") as f:
            f.write(f'description = "dilatancy table"\n[model]\nname = "vw3d"\nparameters = "{os.path.abspath(params)}"\n'
                    f"[initial]\nsigma_n_kPa = {sigma_kPa}\ne0 = {e0}\n[shear_zone]\nd_s_mm = 1.0\n"
                    f'[boundary]\ntype = "CNL"\n[path]\nkind = "monotonic"\ngamma = {gamma}\nincrements = 2500\n')
        run = subprocess.run(["build/iwb", "element", test, "-o", os.path.join(tmp, "out")],
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        if run.returncode == 2:  # e0 outside the set's (e_d, e_i) at this stress: no prediction
            return math.nan, math.nan
        run.check_returncode()
        h = load(os.path.join(tmp, "out", "history.csv"))
    rate = np.gradient(h["u_n_mm"], h["u_x_mm"])  # u in mm of a 1 mm zone: the rate is d eps_n / d gamma
    return h["tau_over_sigma_n"].max(), rate.max()


def homogeneous_until(manifest_path):
    """A periodic cell's element span as the product records it (cell_summary.element_until_gamma:
    0 throughout, -1 not from the first window): "all", "none" or the gamma; "" for a plate cell."""
    m = json.load(open(manifest_path))
    if m.get("cell") != "periodic":
        return ""
    g = m["cell_summary"]["element_until_gamma"]
    return "all" if g == 0 else ("none" if g < 0 else f"{g:.2f}")


def soil_rows(pattern):
    out = []
    for f in sorted(glob.glob(pattern)):
        d = load(f)
        run = os.path.dirname(f)
        s = summary_of(run)
        height = d["u_x_mm"][-1] / d["gamma"][-1]
        rate, ci = rate_at_peak(s)
        models = [x for k in SETS for x in model_run(d["e"][0], PARAMS[k])]
        out.append((f.split("/")[-3], d["e"][0], s["peak_friction"], rate, ci, s["u_x_at_peak_mm"] / height,
                    homogeneous_until(os.path.join(run, "manifest.json")), *models))
    return out


def interface_rows(pattern):
    out = []
    for f in sorted(glob.glob(pattern)):
        d = load(f)
        s = summary_of(os.path.dirname(f))
        rate, ci = rate_at_peak(s)
        out.append((f.split("/")[-2], d["e_band"][0], d["e_specimen"][0], s["peak_friction"], rate, ci,
                    s["u_x_at_peak_mm"]))
    return out


def mean_sd(xs):
    """Mean +- the half-width of its 95 % Student-t interval (n - 1 degrees of freedom); "outside"
    when a model could not start from every e0 (below its e_d)."""
    xs = np.array(xs, dtype=float)
    if np.isnan(xs).any():
        return "outside (e_d, e_i)"
    return interval(list(xs), single="{:s}")


def main():
    print("## Soil cell, CNL 50 kPa (12 x 6 x 12 d50, I 3e-4), against vw3d from the cell's own e0\n")
    print("Periodic cells: homogeneous until gamma (the end of the last profile window whose velocity profile is")
    print("straight, R^2 >= 0.9; \"all\": every window). The rate is the summary's, at the peak friction's gamma.\n")
    sets = "".join(f" vw3d ({k} set) peak friction | rate |" for k in SETS)
    print("| cell | density | seed | e0 | DEM peak friction | DEM rate at the peak (95 %, blocks) | at gamma | homogeneous until |" + sets)
    print("|---|---|---|---|---|---|---|---|" + "---|---|" * len(SETS))
    groups = {}
    calib = "data/calibration/truth_grains_epsd2{}/seed*/simpleshear-CNL-{}-50/timeseries.csv"
    for cell, name, pattern in [
            ("plates", "as-scene", "data/dilatancy/seed*/simpleshear-CNL-as-scene-50/timeseries.csv"),
            ("plates", "dense", calib.format("", "dense")),
            ("plates", "loose", calib.format("", "loose")),
            ("periodic", "as-scene", "data/dilatancy/periodic/seed*/simpleshear-CNL-as-scene-50/timeseries.csv"),
            ("periodic", "dense", calib.format("_periodic", "dense")),
            ("periodic", "loose", calib.format("_periodic", "loose"))]:
        rows = soil_rows(pattern)
        groups[(cell, name)] = rows
        for seed, e0, mu, rate, ci, g, until, *models in rows:
            print(f"| {cell} | {name} | {seed} | {e0:.3f} | {mu:.3f} | {rate:.3f} +- {ci:.3f} | {g:.3f} | {until} |" +
                  "".join(f" {x:.3f} |" for x in models))
    print("\n## Interface runs of the truth scene, CNL 50 kPa\n")
    print("| wall | run | e_band at start | e_specimen at start | peak friction | rate at the peak (95 %, blocks) | at u_x (mm) |")
    print("|---|---|---|---|---|---|---|")
    iface = {}
    for wall, pattern in [("flat", "data/reference/truth2_rn/runs/flat_s*_cnl/timeseries.csv"),
                          ("R_n 0.25", "data/convergence/truth_clamped_rn025/runs/*/timeseries.csv"),
                          ("R_n 0.5", "data/convergence/truth_clamped/runs/*/timeseries.csv")]:
        rows = interface_rows(pattern)
        iface[wall] = rows
        for run, eb, es, mu, rate, ci, at in rows:
            print(f"| {wall} | {run} | {eb:.3f} | {es:.3f} | {mu:.3f} | {rate:.3f} +- {ci:.3f} | {at:.2f} |")
    print("\n## Means over the seeds (95 % t-intervals)\n")
    print("| what | e at start | peak friction | dilatancy rate at the peak |" + "".join(f" vw3d ({k} set) from the same e0: peak friction, rate |" for k in SETS))
    print("|---|---|---|---|" + "---|" * len(SETS))
    for (cell, name), rows in groups.items():
        if rows:
            models = "".join(f" {mean_sd([r[7 + 2 * k] for r in rows])}, {mean_sd([r[8 + 2 * k] for r in rows])} |"
                             for k in range(len(SETS)))
            print(f"| soil cell ({cell}), {name} | {mean_sd([r[1] for r in rows])} | {mean_sd([r[2] for r in rows])} | "
                  f"{mean_sd([r[3] for r in rows])} |" + models)
    for wall, rows in iface.items():
        if rows:
            print(f"| interface, {wall} | {mean_sd([r[2] for r in rows])} (band {mean_sd([r[1] for r in rows])}) | "
                  f"{mean_sd([r[3] for r in rows])} | {mean_sd([r[4] for r in rows])} |" + " |" * len(SETS))


if __name__ == "__main__":
    main()
