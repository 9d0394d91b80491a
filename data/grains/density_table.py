#!/usr/bin/python3
"""Per run of the density cells: where the specimen changes volume.

For each run directory given (default: density/runs/* and density_rolling/runs/* here):
the void ratio when shear starts (specimen, and the coarse-grained wall band of fields/band.csv),
the wall band's void ratio at 5 and 10 mm, u_n and sigma_n at the end, where it sheared, and the
void ratio of 4-d50 slabs of the profiles (fixed heights above the wall base) in the first and
the last profile window: which part of the specimen made the plate move.

    data/grains/density_table.py [RUN ...]
"""
import csv
import glob
import json
import os
import sys


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def slabs(run, slab_d50=4.0, top_d50=20.0):
    """Void ratio of each slab [lo, lo + slab) in the first and last profile window."""
    prof = rows(os.path.join(run, "profiles.csv"))
    windows = sorted({float(r["u_x_mm_window"]) for r in prof})
    out = []
    lo = 0.0
    while lo < top_d50:
        pair = []
        for w in (windows[0], windows[-1]):
            solid = [1.0 - float(r["porosity"]) for r in prof
                     if float(r["u_x_mm_window"]) == w and lo <= float(r["z_over_d50"]) < lo + slab_d50]
            n = sum(solid) / len(solid)
            pair.append((1.0 - n) / n)
        out.append((lo, pair))
        lo += slab_d50
    return out


def lowest(ts):
    """The row of the lowest sigma_n (a CNS run's dip before it dilates; a raw row, where `iwb
    compare`'s sigma_n_lowest takes an 11-row running mean)."""
    low = min(ts, key=lambda r: float(r["sigma_n_kPa"]))
    return (f"lowest {float(low['sigma_n_kPa']):.1f} kPa at u_x {float(low['u_x_mm']):.2f} mm "
            f"(u_n {float(low['u_n_mm']):+.3f})")


def describe(run):
    s = json.load(open(os.path.join(run, "summary.json")))
    ts = rows(os.path.join(run, "timeseries.csv"))
    band = rows(os.path.join(run, "fields", "band.csv"))
    e_band = " -> ".join(f"{float(r['e_band_cg']):.3f}" for r in band)
    line = (f"{os.path.basename(run):28s} e_specimen {float(ts[0]['e_specimen']):.3f}  "
            f"wall band e (0, 5, 10 mm) {e_band}  u_n {float(ts[-1]['u_n_mm']):+.2f} mm  "
            f"sigma_n {float(ts[0]['sigma_n_kPa']):.1f} -> {float(ts[-1]['sigma_n_kPa']):.1f} kPa, "
            f"{lowest(ts)}  {s['shear_mode']}")
    slab = "  ".join(f"{lo:.0f}-{lo + 4:.0f}: {a:.3f}->{b:.3f}" for lo, (a, b) in slabs(run))
    return line + "\n    slabs (d50 above the wall base), e first -> last window: " + slab


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    runs = argv or sorted(glob.glob(os.path.join(here, "density*", "runs", "*")))
    for run in runs:
        if os.path.exists(os.path.join(run, "summary.json")):
            print(describe(run))


if __name__ == "__main__":
    main(sys.argv[1:])
