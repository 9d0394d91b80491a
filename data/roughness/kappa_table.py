"""Issue 36 item 3: hvwe against the shapes, per wall (README.md here, "hvwe on the shapes"): the
kappa_r and d_s its joint fit finds (mean +- 95 % t half-width over the seeds), kappa_r from
eq. 5.35 with the wall's R_n (log base 10) and from eq. 5.36, tan(delta) / tan(phi_c) with delta the
DEM's residual interface friction angle and phi_c the calibrated set's, and the predicted
variant's total-dilation error and verdict. Reads a comparison directory of `iwb compare --runs`:
  build/iwb compare --runs data/roughness/roughness_shapes/runs/* data/convergence/truth_clamped/runs/s{1,2,3} \\
      data/reference/truth2_rn/runs/sawtooth-2-0.1_s{1,2,3}_cnl --model hvwe \\
      --params data/params/truth_grains_epsd2.toml -o runs/cmp_shapes
  /usr/bin/python3 data/roughness/kappa_table.py runs/cmp_shapes"""
import collections
import json
import math
import os
import sys
import tomllib
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # data/seed_stats.py
from seed_stats import interval  # noqa: E402

PHI_C_DEG = tomllib.load(open("data/params/truth_grains_epsd2.toml", "rb"))["hypoplastic"]["phi_c_deg"]


def mean_t(values):
    return interval(values, single="{:s}")


def shape_of(run):
    m = json.load(open(f"{run}/manifest.json"))
    return tomllib.loads(m["scene"]["text"])["wall"]["profile"], m["R_n"]


def main(cmp_dir):
    cells = collections.defaultdict(list)
    for name in sorted(os.listdir(cmp_dir)):
        f = f"{cmp_dir}/{name}/compare.json"
        if not os.path.exists(f):
            continue
        c = json.load(open(f))
        wall, rn = shape_of(c["dem"]["dir"])
        summary = json.load(open(f"{c['dem']['dir']}/summary.json"))
        pred = {v["quantity"]: v for v in c["variants"][c["verdicts"]["predicted_variant"]]["verdicts"]}
        cells[(round(rn, 3), wall)].append((c["fit"]["kappa_r"], c["fit"]["d_s_over_d50"],
                                             c["variants"][0]["kappa_r"], summary["residual_friction"],
                                             pred["total_dilation"]))
    print(f"phi_c of the calibrated set: {PHI_C_DEG:.2f} deg (tan {math.tan(math.radians(PHI_C_DEG)):.3f})\n")
    print("| R_n | wall | runs | fitted kappa_r | fitted d_s (d50) | eq. 5.35 | eq. 5.36 (DEM residual) | predicted total dilation: error, verdicts |")
    print("|---|---|---|---|---|---|---|---|")
    for (rn, wall), rows in sorted(cells.items()):
        k536 = [min(1.0, r[3] / math.tan(math.radians(PHI_C_DEG))) for r in rows]
        dil = ", ".join(f"{100 * r[4]['relative_error']:+.0f} % {r[4]['verdict']}" for r in rows)
        print(f"| {rn:g} | {wall} | {len(rows)} | {mean_t([r[0] for r in rows])} | {mean_t([r[1] for r in rows])} | "
              f"{rows[0][2]:.3f} | {mean_t(k536)} | {dil} |")


main(sys.argv[1] if len(sys.argv) > 1 else "runs/cmp_shapes")
