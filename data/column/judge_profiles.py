#!/usr/bin/python3
"""The column's profiles against the DEM's coarse-grained fields (issue 57, item 3), field by
field at the DEM's windows, judged as `iwb compare` judges a model: per quantity the DEM's seed
mean +- its 95 % Student's t-interval, the column's value, the error against the tolerance, and a
verdict (holds / breaks / not resolved, judge_truth.py's rule). Beside each verdict the p of the
prediction-interval test "one column run differs from the DEM seeds' mean" (t = (column - mean) /
(s sqrt(1 + 1/n)), n - 1 degrees of freedom) and its Benjamini-Hochberg q over every test of the
table: the README states a difference only where q < 0.05. Where a verdict is not resolved, the
seeds whose interval at the seeds' scatter would resolve it.

    data/column/judge_profiles.py [--out DIR]   # after judge_truth.py: reads data/column/runs/<cell>

Stated before the first judged run (README.md, "The profiles"), per cell whose column wall does
not slide (on a sliding wall no band forms: not judged), with the column written at the DEM's
windows (`iwb column --dem` takes the first run's profile windows):
  band_centre_d50     the height above the wall where vx / v_wall first falls to 0.5, at each
                      profile window; tolerance 1 d50 (absolute: the width the DEM's profiles are
                      averaged over)
  zone_dilation_mm    the wall zone's dilation from its void ratio, h (e - e0) / (1 + e), h the
                      DEM's zone (min(10 d50, H / 2) above the wall's mean height), the mean over
                      each fifth of the travel, from the time series (the DEM's e_band, the
                      column's e_wall_zone); compare's wall_zone_dilation: 20 %, at least 0.02 d50
  interior_friction   tau_zx / sigma_zz averaged over the interior (2 d50 from the wall and from
                      the clamp) at each profile window; tolerance 10 % (the peak's: the windows
                      span the peak and the softening)
  band_fwhm_mid_d50   the band's FWHM at the DEM's snapshot halfway along the travel (its end is
                      verdicts.md's band_fwhm_d50), the column's interpolated in the travel; 25 %
  peak_spin           the grains' spin d50 / v_wall at its largest magnitude over the lower half,
                      in the DEM's last snapshot (fields/band_profile.csv, grain_spin_y) and the
                      column's last profile; the column's sense is turned to the DEM's axes (y
                      = z x x: a wall moving along +x below spins the grains negative); 25 %
Writes data/column/profile_verdicts.md and profile_verdicts.json."""
import csv
import glob
import json
import math
import os
import sys

from scipy import stats

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import judge_truth as jt  # noqa: E402  (the cells, the DEM runs' selection, the verdict rule)

HERE = jt.HERE
TOL = {"band_centre_d50": ("absolute", 1.0), "zone_dilation_mm": ("relative", 0.20),
       "interior_friction": ("relative", 0.10), "band_fwhm_mid_d50": ("relative", 0.25),
       "peak_spin": ("relative", 0.25)}
WINDOW_MATCH_MM = 0.5  # a seed's window farther than this from the first seed's is not the same window


def rows_of(path):
    return list(csv.DictReader(open(path)))


def windows(rows):
    """profiles.csv rows by window, in the order of the travel: [(u_x, [row, ...]), ...]."""
    out = {}
    for r in rows:
        out.setdefault(float(r["u_x_mm_window"]), []).append(r)
    return sorted(out.items())


def band_centre(rows):
    z = [float(r["z_over_d50"]) for r in rows]
    v = [float(r["vx_over_vwall"]) for r in rows]
    for k in range(1, len(z)):
        if v[k - 1] > 0.5 >= v[k]:
            return z[k - 1] + (v[k - 1] - 0.5) / (v[k - 1] - v[k]) * (z[k] - z[k - 1])
    return None


def interior_friction(rows, top_d50):
    r = [float(x["tau_zx_kPa"]) / float(x["sigma_zz_kPa"]) for x in rows
         if 2.0 <= float(x["z_over_d50"]) <= top_d50 - 2.0 and float(x["sigma_zz_kPa"]) > 0.0]
    return sum(r) / len(r) if r else None


def zone_dilation_by_fifth(u, e, zone_mm):
    """compare's wall_zone_dilation over each fifth of the travel (quantities.cpp, zone_dilation)."""
    d = [zone_mm * (x - e[0]) / (1.0 + x) for x in e]
    out = []
    for k in range(5):
        lo, hi = u[-1] * k / 5.0, u[-1] * (k + 1) / 5.0
        part = [d[i] for i in range(1, len(u)) if lo < u[i] <= hi]
        out.append(sum(part) / len(part) if part else None)
    return out


def nearest(u, by_travel):
    return min(by_travel, key=lambda x: abs(x - u))


def interpolate(x, xs, ys):
    for k in range(1, len(xs)):
        if xs[k - 1] <= x <= xs[k]:
            return ys[k - 1] + (x - xs[k - 1]) / (xs[k] - xs[k - 1]) * (ys[k] - ys[k - 1])
    return None


def peak_signed(z, s, top):
    pairs = [(abs(v), v) for h, v in zip(z, s) if 0.0 <= h <= top]
    return max(pairs)[1] if pairs else None


def dem_quantities(run, top_d50):
    m = json.load(open(os.path.join(run, "manifest.json")))["scene"]["resolved"]
    d50, height = m["particles"]["d50_mm"], m["specimen"]["height_mm"]
    zone = min(10.0 * d50, 0.5 * height)  # common/band_zone.hpp's wall_zone_thickness
    ts = rows_of(os.path.join(run, "timeseries.csv"))
    prof = windows(rows_of(os.path.join(run, "profiles.csv")))
    band = rows_of(os.path.join(run, "fields", "band.csv"))
    spin_rows = rows_of(os.path.join(run, "fields", "band_profile.csv"))
    scale = d50 / m["shear"]["velocity_mm_s"]
    q = {"profiles": {u: {"band_centre_d50": band_centre(r),
                          "interior_friction": interior_friction(r, top_d50)} for u, r in prof},
         "zone_dilation_mm": zone_dilation_by_fifth([float(r["u_x_mm"]) for r in ts],
                                                    [float(r["e_band"]) for r in ts], zone),
         "band_mid": (float(band[1]["u_x_mm"]), float(band[1]["band_fwhm_d50"])),
         "peak_spin": peak_signed([float(r["z_over_d50"]) for r in spin_rows],
                                  [float(r["grain_spin_y_rad_s"]) * scale for r in spin_rows],
                                  0.5 * top_d50),
         "d50_mm": d50}
    return q


def column_quantities(out, top_d50, zone_mm):
    ts = rows_of(os.path.join(out, "timeseries.csv"))
    prof = windows(rows_of(os.path.join(out, "profiles.csv")))
    band = rows_of(os.path.join(out, "band.csv"))
    last = prof[-1][1]
    return {"profiles": {u: {"band_centre_d50": band_centre(r),
                             "interior_friction": interior_friction(r, top_d50)} for u, r in prof},
            "zone_dilation_mm": zone_dilation_by_fifth([float(r["u_x_mm"]) for r in ts],
                                                       [float(r["e_wall_zone"]) for r in ts], zone_mm),
            "band": ([float(r["u_x_mm"]) for r in band], [float(r["band_fwhm_d50"]) for r in band]),
            # the column's spin turns about -y in the DEM's axes
            "peak_spin": peak_signed([float(r["z_over_d50"]) for r in last],
                                     [-float(r["spin_d50_over_vwall"]) for r in last], 0.5 * top_d50)}


def judge(key, col, dem_values, scale_floor=0.0):
    values = [v for v in dem_values if v is not None]
    if col is None or len(values) < 1:
        return None
    mean, half, n = jt.interval(values)
    kind, tol = TOL[key]
    limit = tol if kind == "absolute" else tol * max(abs(mean), scale_floor)
    miss = abs(col - mean)
    if miss <= limit:
        v = "holds"
    elif math.isfinite(half) and miss - limit > half:
        v = "breaks"
    else:
        v = "not resolved"
    p = needed = None
    if n >= 2:
        sd = math.sqrt(sum((x - mean) ** 2 for x in values) / (n - 1))
        if sd > 0.0:
            p = 2.0 * stats.t.sf(miss / (sd * math.sqrt(1.0 + 1.0 / n)), n - 1)
            needed = seeds_to_decide(sd, abs(miss - limit)) if v == "not resolved" else n
    return {"dem_mean": mean, "dem_half_width": half, "n": n, "column": col,
            "error": col - mean, "limit": limit, "verdict": v, "p": p, "seeds_to_decide": needed}


def seeds_to_decide(sd, gap):
    """The seeds whose 95 % t-interval, at this scatter, would be narrower than the gap between the
    miss and the tolerance's edge (the verdict then holds or breaks); None beyond 50."""
    for m in range(2, 51):
        if stats.t.ppf(0.975, m - 1) * sd / math.sqrt(m) < gap:
            return m
    return None


def cell_rows(name):
    out = os.path.join(HERE, "runs", name)
    summary = json.load(open(os.path.join(out, "summary.json")))
    if summary.get("status") != "complete":
        return [], "the column stopped"
    if summary["wall_slip_share"] > 0.5:
        return [], (f"the column's wall slides ({100 * summary['wall_slip_share']:.0f} % of the last "
                    "fifth's travel): no band forms")
    spec = json.load(open(os.path.join(out, "manifest.json")))["spec"]
    top = spec["height_mm"] / spec["d50_mm"]
    pattern, _ = jt.CELLS[name]
    runs = [r for p in pattern.split() for r in sorted(glob.glob(os.path.join(jt.ROOT, p)))]
    dem = [dem_quantities(r, top) for r in runs if jt.dem_run(r) is not None]
    col = column_quantities(out, top, spec["wall_zone_mm"])
    d50 = spec["d50_mm"]
    rows = []
    # the DEM's windows (the column wrote its profiles at the first run's and at the end): each
    # run's window nearest the column's, within half a window's spacing of the seeds' others
    for u in sorted(dem[0]["profiles"]):
        cu = nearest(u, col["profiles"])
        for key in ("band_centre_d50", "interior_friction"):
            values = [q["profiles"][nearest(u, q["profiles"])][key] for q in dem
                      if abs(nearest(u, q["profiles"]) - u) < WINDOW_MATCH_MM]
            j = judge(key, col["profiles"][cu][key], values)
            if j:
                rows.append((f"{key} @ {u:.2g} mm", j))
    for k in range(5):
        j = judge("zone_dilation_mm", col["zone_dilation_mm"][k], [q["zone_dilation_mm"][k] for q in dem],
                  0.02 * d50)
        if j:
            rows.append((f"zone_dilation_mm, fifth {k + 1}", j))
    u_mid = sum(q["band_mid"][0] for q in dem) / len(dem)
    j = judge("band_fwhm_mid_d50", interpolate(u_mid, *col["band"]), [q["band_mid"][1] for q in dem])
    if j:
        rows.append((f"band_fwhm_d50 @ {u_mid:.2g} mm", j))
    j = judge("peak_spin", col["peak_spin"], [q["peak_spin"] for q in dem])
    if j:
        rows.append(("peak_spin (end)", j))
    return rows, ""


def bh(ps):
    """Benjamini-Hochberg q-values of a list of p-values (None stays None)."""
    idx = sorted((p, i) for i, p in enumerate(ps) if p is not None)
    m = len(idx)
    q = [None] * len(ps)
    running = 1.0
    for rank in range(m, 0, -1):
        p, i = idx[rank - 1]
        running = min(running, p * m / rank)
        q[i] = running
    return q


def decide(j):
    if j["verdict"] != "not resolved":
        return ""
    return "> 50" if j["seeds_to_decide"] is None and j["n"] >= 2 else str(j["seeds_to_decide"] or "")


def main():
    import argparse
    a = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    a.add_argument("--out", default=HERE, help="where profile_verdicts.md and .json go (default: here)")
    out = os.path.abspath(a.parse_args().out)
    os.makedirs(out, exist_ok=True)
    os.chdir(jt.ROOT)
    table = []
    notes = {}
    for name in jt.CELLS:
        if not os.path.exists(os.path.join(HERE, "runs", name, "summary.json")):
            continue
        rows, why = cell_rows(name)
        if why:
            notes[name] = why
        table += [(name, label, j) for label, j in rows]
    qs = bh([j["p"] for _, _, j in table])
    for (name, label, j), q in zip(table, qs):
        j["q"] = q
    lines = [f"Tests: {sum(1 for *_, j in table if j['p'] is not None)} with a p (Benjamini-Hochberg "
             "over all of them); verdicts: " + ", ".join(
                 f"{v} {sum(1 for *_, j in table if j['verdict'] == v)}"
                 for v in ("holds", "not resolved", "breaks")), "",
             "| cell | quantity | seeds | DEM mean +- 95 % t | column | column - DEM | tolerance | verdict | p | q (BH) | seeds to decide |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    def f(x):
        return "" if x is None else f"{x:.2g}"
    for name, label, j in table:
        lines.append(f"| {name} | {label} | {j['n']} | {j['dem_mean']:.4g} +- {j['dem_half_width']:.2g} | "
                     f"{j['column']:.4g} | {j['error']:+.3g} | {j['limit']:.3g} | {j['verdict']} | "
                     f"{f(j['p'])} | {f(j['q'])} | {decide(j)} |")
    for name, why in notes.items():
        lines.append(f"| {name} | all | | | | | | not judged: {why} | | | |")
    open(os.path.join(out, "profile_verdicts.md"), "w").write("\n".join(lines) + "\n")
    json.dump([{"cell": n, "quantity": l, **j} for n, l, j in table] +
              [{"cell": n, "not_judged": w} for n, w in notes.items()],
              open(os.path.join(out, "profile_verdicts.json"), "w"), indent=1)
    print("\n".join(lines[:1]))


if __name__ == "__main__":
    main()
