#!/usr/bin/python3
"""Twice the travel (README.md here, "Twice the travel"): each 20 mm run of truth_travel20/ read
in two windows of its own time series, 8-10 mm (where a 10 mm run reads its residual: the last
fifth) and 16-20 mm (the last fifth of 20 mm): the mean friction tau/sigma_n, its drift over the
window (the linear fit's change, shown, not judged), u_n at the window's end and the dilation rate
du_n/du_x; whether the residual at 20 mm is steady is the product's rule (summary.json residual_is,
statistics/steady_state.hpp), not re-derived here (until 2 Dec a drift below 0.02 was counted). Per wall, the means over the seeds +- 95 % t, the change from the
first window to the second (paired: the same runs), and the seeds the residual's 5 % tolerance
needs at the scatter each window shows (half-width at most half the tolerance, as `iwb compare`).
Run from the repository root:

    /usr/bin/python3 data/grains/travel_table.py [RUN ...]
"""
import csv
import glob
import json
import statistics as st
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # data/seed_stats.py
from seed_stats import interval, mean_half, seeds_needed  # noqa: E402

WINDOWS = [(8.0, 10.0), (16.0, 20.0)]
TOLERANCE = 0.05  # the residual's default tolerance (src/comparison/replay/quantities.cpp)


def slope(xs, ys):
    mx, my = st.mean(xs), st.mean(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def window(rows, lo, hi):
    w = [r for r in rows if lo <= r["u_x"] <= hi]
    ux = [r["u_x"] for r in w]
    mu = [r["tau"] / r["sigma"] for r in w]
    return {"residual": st.mean(mu), "drift": slope(ux, mu) * (hi - lo), "u_n": w[-1]["u_n"],
            "rate": slope(ux, [r["u_n"] for r in w])}


def read(run):
    rows = [{"u_x": float(r["u_x_mm"]), "u_n": float(r["u_n_mm"]), "tau": float(r["tau_kPa"]),
             "sigma": float(r["sigma_n_kPa"])} for r in csv.DictReader(open(f"{run}/timeseries.csv"))]
    summary = json.load(open(f"{run}/summary.json"))
    return [window(rows, lo, hi) for lo, hi in WINDOWS], summary


def main(runs):
    cells = {}
    print("| run | where it sheared | residual 8-10 / 16-20 mm | drift | u_n (mm) | du_n/du_x | residual at 20 mm (summary.json) |")
    print("|---|---|---|---|---|---|---|")
    for run in runs:
        if not Path(f"{run}/summary.json").exists():
            continue
        (a, b), summary = read(run)
        name = Path(run).name
        print(f"| {name} | {summary['shear_mode']} | {a['residual']:.3f} / {b['residual']:.3f} | "
              f"{a['drift']:+.3f} / {b['drift']:+.3f} | {a['u_n']:.2f} / {b['u_n']:.2f} | "
              f"{a['rate']:.3f} / {b['rate']:.3f} | {summary['residual_is']} |")
        cells.setdefault(name.rsplit("_s", 1)[0], []).append((a, b, summary["residual_is"]))
    for cell, pairs in sorted(cells.items()):
        print(f"\n{cell}, {len(pairs)} run(s), mean +- 95 % t:")
        for k, what in (("residual", "residual"), ("u_n", "u_n (mm)"), ("rate", "du_n/du_x")):
            first, second = [p[0][k] for p in pairs], [p[1][k] for p in pairs]
            change = interval([y - x for x, y in zip(first, second)], "+.3f")
            print(f"  {what}: {interval(first)} at 8-10 mm, {interval(second)} at 16-20 mm; change {change}")
        steady = sum(p[2] == "steady" for p in pairs)
        print(f"  steady at 20 mm (summary.json, the product's rule): {steady} of {len(pairs)}")
        for i, label in ((0, "8-10"), (1, "16-20")):
            values = [p[i]["residual"] for p in pairs]
            if len(values) > 1:
                mean, _ = mean_half(values)
                sd = st.stdev(values)
                n = seeds_needed(sd, 0.5 * TOLERANCE * mean)
                need = n if n else ("2 (no scatter)" if sd == 0 else "more than 1000")
                print(f"  residual at {label} mm: SD {sd:.4f}; the 5 % tolerance needs {need} seeds")


if __name__ == "__main__":
    main(sys.argv[1:] or sorted(glob.glob("data/grains/truth_travel20/runs/*")))
