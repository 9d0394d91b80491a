#!/usr/bin/env bash
# The form limits of issue 38 item 4 on the truth campaign (README.md here, "Form or
# calibration"): per model and wall, every material parameter with a declared calibration box and
# the wall's kappa_r and d_s fitted to seeds 1-3 under CNL and CNS 50 kPa together; R_n 0.5 holds
# seeds 4 and 5 out and predicts them. The soil tests of the calibration say what each form limit
# costs there. Writes data/reference/form_limit/<model>_<wall>/ (form_limit.json, .md, .toml,
# manifest.json). Run from the repository root after building:
#   data/reference/form_limit.sh [MODEL...]        (default: hvwe ahe hp1d)
# IWB (build/iwb). Models on the [hypoplastic] table only (the soil-test set is a vw3d set); each fit is 1-4 minutes on one core; rerunning replaces its directory.
set -euo pipefail
IWB=${IWB:-build/iwb}
PARAMS=data/params/truth_grains_epsd2.toml
CAL=data/calibration/truth_grains_epsd2
SOIL=("$CAL"/seed*/*)
models=("$@")
[ ${#models[@]} -eq 0 ] && models=(hvwe ahe hp1d)
RN05=(data/convergence/truth_clamped/runs/s{1,2,3} data/reference/truth2_cns/runs/sawtooth-2-0.5_s{1,2,3}_cns-50)
RN05_HELD=(data/reference/truth2_seeds45/runs/s{4,5}_cnl-50 data/reference/truth2_seeds45/runs/s{4,5}_cns-50-50)
RN01=(data/reference/truth2_rn/runs/sawtooth-2-0.1_s{1,2,3}_cnl data/reference/truth2_rn/runs/sawtooth-2-0.1_s{1,2,3}_cns-50)
for model in "${models[@]}"; do
  "$IWB" form-limit --runs "${RN05[@]}" --held-out "${RN05_HELD[@]}" --model "$model" --params "$PARAMS" \
    --calibration "$CAL/calibration.json" --soil-tests "${SOIL[@]}" -o "data/reference/form_limit/${model}_rn05" --force
  "$IWB" form-limit --runs "${RN01[@]}" --model "$model" --params "$PARAMS" \
    --calibration "$CAL/calibration.json" --soil-tests "${SOIL[@]}" -o "data/reference/form_limit/${model}_rn01" --force
done
