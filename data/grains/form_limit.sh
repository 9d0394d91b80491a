#!/usr/bin/env bash
# Form or calibration on the graded cells (README.md here, "Form or calibration on the graded
# cells"): `iwb form-limit` fits every material parameter hvwe declares a calibration box for, and
# each wall's kappa_r and d_s, jointly to a grading's runs at its walls, starting from the set
# scaled by the dense packing (scaled_set.py). A break of the scaled set's prediction that the form
# limit meets is the calibration's; one it still breaks, the form's. No soil tests of the graded
# grains exist, so nothing says what the form-limit set would cost there (the uniform grains'
# ../reference/form_limit/ does). Writes data/grains/form_limit/<model>_<grading>/ (form_limit.json,
# .md, .toml, manifest.json); 11-154 s a fit on a shared core (measured). Run from the repository
# root:
#   data/grains/form_limit.sh [GRADING...]     (default: cu2 cu3)
set -euo pipefail
IWB=${IWB:-build/iwb}
MODEL=${MODEL:-hvwe}
gradings=("$@")
[ ${#gradings[@]} -eq 0 ] && gradings=(cu2 cu3)
for g in "${gradings[@]}"; do
  case $g in
    cu2) runs=(data/grains/grains_cu2/runs/rn0.25_s{1,2,3} data/grains/grains_cu2/runs/rn0.5_s{1,2,3}) ;;
    cu3) runs=(data/grains/grains_cu3_rn025/runs/rn0.25_s{1,2,3} data/grains/grains_cu3/runs/rn0.5_s{1,2,3}) ;;
    *) echo "form_limit.sh: unknown grading '$g' (cu2, cu3)" >&2; exit 2 ;;
  esac
  "$IWB" form-limit --runs "${runs[@]}" --model "$MODEL" --params "data/params/grains_${g}_scaled.toml" \
    -o "data/grains/form_limit/${MODEL}_${g}" --force
done
