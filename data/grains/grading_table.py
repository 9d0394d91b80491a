#!/usr/bin/python3
"""Does d50 normalise roughness across gradings, or does d10 or d60 do better? (README.md here)

Each wall's roughness R_max (over a gauge length of d50: for the sawtooth of pitch 2 d50 its whole
height) is normalised by d10, d50 or d60 of the run's own grading (mass-cumulative curve, linear
between the classes, clamped at the smallest class as README.md's table). The uniform grains'
cells (C_u ~1.2) give a curve of each quantity's seed mean against R_max/d_x; each graded cell is
read against that curve at its own R_max/d_x (linear between the uniform cells; '-' outside them).
A descriptor collapses the gradings where the graded cell's mean lies on the uniform curve: the
difference is printed with the graded cell's 95 % t half-width. Run from the repository root:

    /usr/bin/python3 data/grains/grading_table.py [UNIFORM_GLOB GRADED_GLOB]
"""
import glob
import json
import statistics as st
import sys
import tomllib
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # data/seed_stats.py
from seed_stats import mean_half  # noqa: E402

UNIFORM = ["data/convergence/truth_clamped/runs/*", "data/convergence/truth_clamped_rn025/runs/*",
           "data/reference/truth2_seeds45/runs/*_cnl-50", "data/reference/truth2_rn/runs/sawtooth-*_cnl"]
GRADED = ["data/grains/grains_cu2/runs/*", "data/grains/grains_cu3/runs/*", "data/grains/grains_cu3_rn025/runs/*",
          "data/grains/grains_cu4/runs/*"]
QUANTITIES = [("peak friction", "peak_friction"), ("residual friction", "residual_friction"),
              ("total dilation (mm)", "dilation_mm"), ("first-layer slip", "wall_slip")]


def passing(sizes, fractions, share):
    """d at which `share` of the mass passes, in d50 (linear between the classes)."""
    cum, acc = [], 0.0
    for f in fractions:
        acc += f
        cum.append(acc)
    if share <= cum[0]:
        return sizes[0]
    for (d0, c0), (d1, c1) in zip(zip(sizes, cum), zip(sizes[1:], cum[1:])):
        if share <= c1:
            return d0 + (share - c0) / (c1 - c0) * (d1 - d0)
    return sizes[-1]


def run_of(directory):
    manifest = json.load(open(f"{directory}/manifest.json"))
    scene = tomllib.loads(manifest["scene"]["text"])
    sizes, fractions = scene["particles"]["d_over_d50"], scene["particles"]["mass_fraction"]
    grading = {"d10": passing(sizes, fractions, 0.1), "d50": 1.0, "d60": passing(sizes, fractions, 0.6)}
    # runs made before the descriptors were recorded carry R_n alone: for every wall read here (a
    # sawtooth of pitch 2 d50) it equals R_max over the gauge length d50
    r_max = manifest["roughness"]["wall"]["R_max_d50"] if "roughness" in manifest else manifest["R_n"]
    return {"grading": tuple(sizes), "d": grading, "R_max_d50": r_max,
            "summary": json.load(open(f"{directory}/summary.json"))}


def cells(patterns):
    """{(grading, R_max_d50): [runs]} of the CNL 50 kPa runs matching the patterns."""
    out = {}
    for pattern in patterns:
        for d in sorted(glob.glob(pattern)):
            r = run_of(d)
            out.setdefault((r["grading"], round(r["R_max_d50"], 6)), []).append(r)
    return out


def interpolate(curve, x):
    for (x0, y0), (x1, y1) in zip(curve, curve[1:]):
        if x0 <= x <= x1:
            return y0 + (x - x0) / (x1 - x0) * (y1 - y0)
    return None


def main(args):
    uniform, graded = cells(args[:1] or UNIFORM), cells(args[1:2] or GRADED)
    for name, key in QUANTITIES:
        print(f"\n{name}\n")
        print("| grading (d10, d60 in d50) | R_max/d50 | runs | graded | uniform at equal R_max/d10 | at R_max/d50 | at R_max/d60 |")
        print("|---|---|---|---|---|---|---|")
        for (sizes, r_max), runs in sorted(graded.items()):
            m, h = mean_half([r["summary"][key] for r in runs])
            cols = []
            for dx in ("d10", "d50", "d60"):
                x = r_max / runs[0]["d"][dx]
                curve = sorted((rm / us[0]["d"][dx], st.mean(u["summary"][key] for u in us))
                               for (_, rm), us in uniform.items())
                y = interpolate(curve, x)
                cols.append("-" if y is None else f"{y:.3f} (R {x:.2f}; graded {m - y:+.3f})")
            d = runs[0]["d"]
            print(f"| {d['d10']:.2f}, {d['d60']:.2f} | {r_max:.2f} | {len(runs)} | {m:.3f} +- {h:.3f} | " + " | ".join(cols) + " |")


if __name__ == "__main__":
    main(sys.argv[1:])
