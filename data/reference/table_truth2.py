"""The re-run reference campaign on the converged truth (campaign_runs.py): per wall and boundary,
mean +- SD over the seeds of each run's summary.json. Run from the repository root:
    /usr/bin/python3 data/reference/table_truth2.py"""
import statistics as st
from itertools import groupby

from campaign_runs import campaign_runs


def ms(v):
    v = [x for x in v if x is not None]
    return f"{st.mean(v):.3f} +- {st.stdev(v):.3f}" if len(v) > 1 else (f"{v[0]:.3f}" if v else "-")


print("| wall | boundary | runs | peak friction | residual friction | total dilation (mm) | wall slip | band (d50, last 2 mm, 0.9 -> 0.1) | shear mode |")
print("|---|---|---|---|---|---|---|---|---|")
for (wall, bc), rows in groupby(campaign_runs(), key=lambda r: r[0]):
    ss = [r[2] for r in rows]
    q = lambda k: ms([s.get(k) for s in ss])
    print(f"| {wall} | {bc} | {len(ss)} | {q('peak_friction')} | {q('residual_friction')} | {q('dilation_mm')} | "
          f"{q('wall_slip')} | {q('band_thickness_d50')} | {', '.join(s['shear_mode'] for s in ss)} |")
