#!/usr/bin/python3
"""What d_s the thin-layer model needs to be the column (issue 57, item 4): for each judged cell of
verdicts.json, the hvwe shear-zone thickness d_s whose u_n at the column's travel equals the
column's, found by bisection over `iwb element` runs (hvwe, the same soil set, the same e0,
sigma_n0 and boundary, kappa_r from the wall's R_n by eq. 5.35, simple shear to the column's
travel over d_s), and the hvwe tau/sigma_n at the end with that d_s beside the column's.
Compared with the column's band (FWHM) and the DEM's. Writes thin_layer_ds.md and .json.

    /usr/bin/python3 data/column/thin_layer_ds.py [--iwb build/iwb]"""
import argparse
import csv
import json
import math
import os
import subprocess
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
R_N = {"rn0.5": 0.5, "rn1": 1.0, "d1_rn1": 1.0}


def hvwe(iwb, cell, d_s_mm, work):
    spec = cell["spec"]
    bc = spec["top"]
    travel = spec["travel_mm"]
    text = f"""description = "thin layer of the column's cell"
[model]
name = "hvwe"
parameters = "{os.path.join(ROOT, 'data/params/truth_grains_epsd2.toml')}"
[roughness]
R_n = {cell['R_n']}
[initial]
sigma_n_kPa = {spec['sigma_n0_kPa']}
e0 = {spec['e0']}
[shear_zone]
d_s_mm = {d_s_mm}
[boundary]
type = "{bc}"
"""
    if bc == "CNS":
        text += f"K_kPa_per_mm = {spec['stiffness_kPa_per_mm']}\n"
    text += f"""[path]
kind = "monotonic"
gamma = {travel / d_s_mm}
increments = 2000
"""
    path = os.path.join(work, "t.toml")
    open(path, "w").write(text)
    out = os.path.join(work, "run")
    r = subprocess.run([iwb, "element", path, "--out", out, "--force"], capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit(r.stderr)
    rows = list(csv.DictReader(open(os.path.join(out, "history.csv"))))
    return rows[-1]


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--iwb", default=os.path.join(ROOT, "build", "iwb"))
    a = p.parse_args()
    verdicts = json.load(open(os.path.join(HERE, "verdicts.json")))
    results = {}
    with tempfile.TemporaryDirectory() as work:
        for name, v in verdicts.items():
            if v["status"] != "complete" or v["column"]["slip_share"] > 0.5:
                continue  # a stopped column, or one whose wall slides under unsheared soil
            prefix = name.rsplit("_", 1)[0]
            manifest = json.load(open(os.path.join(HERE, "runs", name, "manifest.json")))
            cell = {"spec": manifest["spec"], "R_n": R_N[prefix]}
            target = v["column"]["dilation_mm"]
            d50 = cell["spec"]["d50_mm"]
            lo, hi = 0.5 * d50, 60.0 * d50  # u_n grows with d_s
            first = hvwe(a.iwb, cell, lo, work)
            for _ in range(30):
                mid = math.sqrt(lo * hi)
                row = hvwe(a.iwb, cell, mid, work)
                if float(row["u_n_mm"]) < target:
                    lo = mid
                else:
                    hi = mid
                if hi / lo < 1.002:
                    break
            row = hvwe(a.iwb, cell, math.sqrt(lo * hi), work)
            results[name] = {"d_s_d50": math.sqrt(lo * hi) / d50, "column_u_n_mm": target,
                             "hvwe_u_n_mm": float(row["u_n_mm"]),
                             "hvwe_end_friction": float(row["tau_x_kPa"]) / float(row["sigma_n_kPa"]),
                             "column_end_friction": v["column"]["end_friction"],
                             "column_band_fwhm_d50": v["column"]["band_fwhm_d50"],
                             "dem_band_fwhm_d50": v["quantities"]["band_fwhm_d50"]["dem_mean"],
                             "dem_dilation_mm": v["quantities"]["dilation_mm"]["dem_mean"]}
    json.dump(results, open(os.path.join(HERE, "thin_layer_ds.json"), "w"), indent=1)
    lines = ["| cell | column band FWHM (d50) | DEM band FWHM (d50) | hvwe d_s giving the column's u_n (d50) | u_n column / hvwe / DEM (mm) | tau/sigma_n at the end, column / hvwe |",
             "|---|---|---|---|---|---|"]
    for name, r in results.items():
        lines.append(f"| {name} | {r['column_band_fwhm_d50']:.2f} | {r['dem_band_fwhm_d50']:.2f} | {r['d_s_d50']:.2f} | "
                     f"{r['column_u_n_mm']:.3f} / {r['hvwe_u_n_mm']:.3f} / {r['dem_dilation_mm']:.3f} | "
                     f"{r['column_end_friction']:.3f} / {r['hvwe_end_friction']:.3f} |")
    open(os.path.join(HERE, "thin_layer_ds.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
