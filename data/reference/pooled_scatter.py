"""Issue 36, item 4: may the seed scatter be pooled across the truth campaign's cells? Per quantity,
each run's value relative to its cell's mean (the verdicts' tolerances are relative), tested for
equal scatter across the cells of at least 3 seeds with Levene's test about the median
(Brown-Forsythe: robust to the skewed, small samples here) and, for reference, Bartlett's; where
Levene does not reject at 5 %, the pooled relative SD with its sum(n_i - 1) degrees of freedom and
the 95 % t half-width it gives a cell of n seeds, beside the cell's own. Runs that did not shear at
the wall are kept (the verdicts keep them, flagged); the same test on wall-localised runs only is the
second block. Run from the repository root:  /usr/bin/python3 data/reference/pooled_scatter.py"""
import statistics as st
import sys
from itertools import groupby

from scipy import stats

sys.path.insert(0, "data/reference")
from campaign_runs import campaign_runs  # noqa: E402

QUANTITIES = [("peak_friction", "peak friction"), ("residual_friction", "residual friction"),
              ("dilation_mm", "total dilation")]


def cells(wall_only):
    out = {}
    for group, rows in groupby(campaign_runs(), key=lambda r: r[0]):
        ss = [r[2] for r in rows if not wall_only or r[2].get("shear_mode") == "localised at the wall"]
        out[group] = ss
    return out


def block(wall_only):
    print(f"\n{'Wall-localised runs only' if wall_only else 'Every complete run'}:\n")
    print("| quantity | cells (runs) | Levene p | Bartlett p | pooled relative SD | dof | 95 % half-width, n = 3: pooled | own (median over cells) | n = 5: pooled |")
    print("|---|---|---|---|---|---|---|---|---|")
    for key, name in QUANTITIES:
        rel = []
        for group, ss in cells(wall_only).items():
            v = [s[key] for s in ss if s.get(key) is not None]
            if len(v) < 3 or st.mean(v) == 0:
                continue
            m = st.mean(v)
            rel.append([x / m for x in v])
        runs = sum(len(r) for r in rel)
        lev = stats.levene(*rel, center="median").pvalue
        bart = stats.bartlett(*rel).pvalue
        dof = sum(len(r) - 1 for r in rel)
        sp = (sum((len(r) - 1) * st.variance(r) for r in rel) / dof) ** 0.5
        own = st.median(stats.t.ppf(0.975, len(r) - 1) * st.stdev(r) / len(r) ** 0.5 for r in rel)
        pooled = lambda n: stats.t.ppf(0.975, dof) * sp / n ** 0.5
        verdict = "" if lev > 0.05 else " (not pooled: Levene rejects)"
        print(f"| {name}{verdict} | {len(rel)} ({runs}) | {lev:.2f} | {bart:.2g} | {100 * sp:.1f} % | {dof} | "
              f"{100 * pooled(3):.1f} % | {100 * own:.1f} % | {100 * pooled(5):.1f} % |")


block(False)
block(True)
