#!/usr/bin/env bash
# The league of the interface models on the DEM truth (issue 17; README.md here): every interface
# model calibrated to the truth scene's runs (data/convergence/truth_clamped*: R_n 0.5 and 0.25,
# CNL 50 kPa, three seeds each) and judged by model, parameter and global uncertainty, with the
# Sobol indices about each calibrated set. Run from the repository root after building; resumable
# (a model whose record is there with the same inputs is reused). PARAMS: the hypoplastic models'
# set (default: the one iwb chooses for the truth scene's grains).
set -euo pipefail
IWB=${IWB:-build/iwb}
DEST=data/assessment/league
SAMPLES=${SAMPLES:-2000}
SOBOL=${SOBOL:-500}
extra=()
[ -n "${PARAMS:-}" ] && for m in hp1d ah ahe hvwe ahe-igs hvwe-igs; do extra+=(--params-for "$m=$PARAMS"); done
# issue 56's candidates with their deciding fits (the soil held, their own parameters fitted to
# the DEM walls of data/models_beyond/: README.md there)
extra+=(--params-for hvwe-rd=data/models_beyond/hvwe_rd_held_walls/form_limit.toml
        --params-for hvwe-pg=data/models_beyond/hvwe_pg_held_walls/form_limit.toml)
league() {  # name, run directories
  local name=$1; shift
  "$IWB" assess --reference "$@" --samples "$SAMPLES" --sobol-samples "$SOBOL" "${extra[@]}" \
    --form-limits data/reference/form_limit -o "$DEST/$name"
}
league truth_rn0.5 data/convergence/truth_clamped/runs/s{1,2,3}
league truth_rn0.25 data/convergence/truth_clamped_rn025/runs/Rn0.25_s{1,2,3}
