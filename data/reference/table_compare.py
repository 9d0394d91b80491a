"""The comparisons of the reference campaign per wall and boundary: hvwe fitted jointly to tau and
u_n (CNL) or tau and sigma_n (CNS), from compare/all/<run>/compare.json (the fitted variant), with
the error ranges over the three seeds. Run from the repository root after `make.sh compare`:
    /usr/bin/python3 data/reference/table_compare.py [COMPARE_DIR]"""
import glob, json, statistics as st, sys

from campaign_runs import campaign_runs, group_of

root = sys.argv[1] if len(sys.argv) > 1 else "data/reference/compare/all"
order = {group: i for i, group in enumerate(dict.fromkeys(g for g, _, _ in campaign_runs()))}
groups = {}
for f in sorted(glob.glob(f"{root}/*/compare.json")):
    c = json.load(open(f))
    group = group_of(json.load(open(f"{c['dem']['dir']}/manifest.json")))
    v = c["variants"][c["verdicts"]["fitted_variant"]]
    groups.setdefault(group, []).append((v, {x["quantity"]: x for x in v["verdicts"]}, c["dem"]["d50_mm"]))


def rng(values, fmt="{:+.0f}"):
    lo, hi = min(values), max(values)
    return fmt.format(lo) if fmt.format(lo) == fmt.format(hi) else f"{fmt.format(lo)} to {fmt.format(hi)}"


print("| wall | boundary | runs | DEM total dilation (mm) | hvwe fitted (mm) | dilation error % | peak error % | residual error % | fitted kappa_r | fitted d_s (d50) | quantities holding or within scatter |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for (wall, bc), rows in sorted(groups.items(), key=lambda kv: order.get(kv[0], len(order))):
    dil = [r[1]["total_dilation"] for r in rows]
    err = lambda q: rng([r[1][q]["relative_error"] * 100 for r in rows])
    ok = [f"{sum(1 for x in r[1].values() if x['verdict'] != 'breaks')}/{len(r[1])}" for r in rows]
    print(f"| {wall} | {bc} | {len(rows)} | {st.mean(x['dem'] for x in dil):.3f} | "
          f"{st.mean(x['model'] for x in dil):.3f} | {err('total_dilation')} | {err('peak_friction')} | "
          f"{err('residual_friction')} | {rng([r[0]['kappa_r'] for r in rows], '{:.2f}')} | "
          f"{rng([r[0]['d_s_mm'] / r[2] for r in rows], '{:.1f}')} | {', '.join(ok)} |")
