#!/usr/bin/env bash
# ERRATA 9 (data/reference/README.md): which reading of Arnold & Herle's rate factor f_c the truth
# runs support. Every CNL and CNS run of the flat wall and of R_n 0.1 and 0.25 (where the fits put
# kappa_r below or at 1) replayed through hvwe with Arnold & Herle's scheme, f_c = 1/kappa_r (eq.
# 5.40 as printed) and f_c = kappa_r, each with its seeds, and the fitted variants tabulated beside
# Gutjahr's scheme (compare/all). Run from the repository root after building:
#   data/reference/errata9.sh > data/reference/errata9.md
set -euo pipefail
IWB=${IWB:-build/iwb}
WORK=${WORK:-runs/errata9}
RUNS=data/reference/truth_rn/runs
for wall in flat sawtooth-2-0.1 sawtooth-2-0.25; do
  for bc in cnl cns-50; do
    for s in 1 2 3; do
      seeds=()
      for o in 1 2 3; do [ "$o" != "$s" ] && seeds+=("$RUNS/${wall}_s${o}_${bc}"); done
      for fc in 1/kappa_r kappa_r; do
        "$IWB" compare "$RUNS/${wall}_s${s}_${bc}" --seeds "${seeds[@]}" --model hvwe \
          --params data/params/truth_grains.toml --roughness-scheme arnold-herle --f-c "$fc" \
          -o "$WORK/${wall}_s${s}_${bc}_${fc//\//_}" --force > /dev/null
      done
    done
  done
done
/usr/bin/python3 - "$WORK" <<'PY'
import json, sys, glob, os, statistics as st
work = sys.argv[1]
def fitted(path):
    c = json.load(open(path)); v = c["variants"][c["verdicts"]["fitted_variant"]]
    q = {x["quantity"]: x for x in v["verdicts"]}
    return v["kappa_r"], q
print("| wall | boundary | scheme, f_c | fitted kappa_r | peak error | residual error | total dilation error | quantities that hold or are within scatter, per seed (of 5 under CNL, 6 under CNS) |")
print("|---|---|---|---|---|---|---|---|")
for wall in ["flat", "sawtooth-2-0.1", "sawtooth-2-0.25"]:
    for bc in ["cnl", "cns-50"]:
        for label, pattern in [("Gutjahr", f"data/reference/compare/all/{wall}_s*_{bc}/compare.json"),
                               ("Arnold & Herle, 1/kappa_r", f"{work}/{wall}_s*_{bc}_1_kappa_r/compare.json"),
                               ("Arnold & Herle, kappa_r", f"{work}/{wall}_s*_{bc}_kappa_r/compare.json")]:
            files = sorted(f for f in glob.glob(pattern) if not f.endswith("_1_kappa_r/compare.json") or "1_kappa_r" in pattern)
            rows = [fitted(f) for f in files]
            if not rows: continue
            def rng(k):
                e = [r[1][k]["relative_error"] * 100 for r in rows]
                return f"{min(e):+.0f} to {max(e):+.0f} %"
            ok = [sum(1 for x in r[1].values() if x["verdict"] != "breaks") for r in rows]
            print(f"| {wall} | {bc} | {label} | {min(r[0] for r in rows):.2f}-{max(r[0] for r in rows):.2f} | {rng('peak_friction')} | "
                  f"{rng('residual_friction')} | {rng('total_dilation')} | {', '.join(map(str, ok))} |")
PY
