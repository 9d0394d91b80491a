"""The wall band of the re-run campaign (campaign_runs.py) by four measures, mean +- SD over the seeds, in d50:
- window: the summary's measures on the velocity profile averaged over the last profile window
  (2 mm of travel; the 10 % of the drop from the far field, hypothesis check 2's; the 0.9 -> 0.1
  width relative to the first layer; an erfc fitted to the lower half);
- snapshot: the 0.9 -> 0.1 width of the grains' velocities (binned by centre) in the snapshots of
  the second half of the travel (fields/band.csv; relative to the wall's speed, so only where the
  wall does not slip, slip < 0.1).
The band breathes in a stick-slip residual: a 2 mm average is wider than an instant.
Run from the repository root:  /usr/bin/python3 data/reference/band_table.py"""
import csv, os, statistics as st

from campaign_runs import campaign_runs

groups = {}
for group, d, s in campaign_runs():
    snap = []
    if os.path.exists(f"{d}/fields/band.csv") and (s.get("wall_slip") or 0) < 0.1:
        rows = list(csv.DictReader(open(f"{d}/fields/band.csv")))
        travel = max(float(r["u_x_mm"]) for r in rows)
        snap = [float(r["band_width_grains_d50"]) for r in rows
                if "band_width_grains_d50" in r and float(r["u_x_mm"]) >= 0.5 * travel and float(r["band_width_grains_d50"]) > 0]
    groups.setdefault(group, []).append(
        (s.get("wall_band_d50"), s.get("band_thickness_d50"), s.get("band_thickness_erfc_fit_d50"),
         st.mean(snap) if snap else None, s.get("wall_slip")))


def ms(v):
    v = [x for x in v if x is not None]
    if not v:
        return "-"
    return f"{st.mean(v):.1f} +- {st.stdev(v):.1f} ({len(v)})" if len(v) > 1 else f"{v[0]:.1f} (1)"


print("| wall | boundary | window: 10 % of the drop | window: 0.9 -> 0.1 | window: erfc fit | snapshots: 0.9 -> 0.1 | wall slip |")
print("|---|---|---|---|---|---|---|")
for (wall, bc), rows in groups.items():
    cols = list(zip(*rows))
    print(f"| {wall} | {bc} | {ms(cols[0])} | {ms(cols[1])} | {ms(cols[2])} | {ms(cols[3])} | {ms(cols[4])} |")
