#!/usr/bin/env bash
# The Fortran test model through `--model-lib` against the workbench's own mc (tests/external): the
# same law written twice, independently. CNL, CNS and CV element tests of both models, every stress
# of every row equal to 1e-12 of the largest.
# Usage: against_mc.sh IWB LIBRARY WORK_DIR
set -euo pipefail
iwb=$1 lib=$2 work=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work"
for bc in CNL CNS CV; do
  for model in ep_mohr_coulomb mc; do
    extra=""; [ $bc = CNS ] && extra=$'\nK_kPa_per_mm = 2000'
    cat > "$work/${model}_$bc.toml" <<TOML
description = "$model $bc"
[model]
name = "$model"
parameters = "$here/ep_mohr_coulomb.toml"
[initial]
sigma_n_kPa = 100
[boundary]
type = "$bc"$extra
[path]
kind = "monotonic"
gamma = 0.05
increments = 200
TOML
    "$iwb" element "$work/${model}_$bc.toml" -o "$work/${model}_$bc" --model-lib "$lib" --entry ep_mohr_coulomb > /dev/null
  done
  /usr/bin/python3 - "$work/ep_mohr_coulomb_$bc/history.csv" "$work/mc_$bc/history.csv" "$bc" <<'PY'
import csv, sys
a, b = (list(csv.DictReader(open(f))) for f in sys.argv[1:3])
cols = ("sigma_n_kPa", "tau_x_kPa", "u_n_mm")
scale = max(abs(float(r[c])) for r in b for c in cols[:2])
worst = max(abs(float(x[c]) - float(y[c])) for x, y in zip(a, b) for c in cols) / scale
print(f"{sys.argv[3]}: {len(a)} rows, largest difference {worst:.1e} of {scale:.4g}")
sys.exit(0 if len(a) == len(b) and worst <= 1e-12 else 1)
PY
done
