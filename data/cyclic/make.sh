#!/usr/bin/env bash
# The cyclic truth of issue 34 (README.md here): its sweeps in order of value, resumable, each
# complete run's compact files copied into data/cyclic/<sweep>/ (and committed with COMMIT=1) as it
# completes, so that a campaign stopped anywhere resumes on another machine (../run_campaign.sh
# does the work). Run from the repository root after building:
#   data/cyclic/make.sh [restore] [sweeps] [copy]   (default: all three)
# Environment as ../run_campaign.sh's (IWB, JOBS, NP, COMMIT, COPY_EVERY_S); SWEEPS to run a subset;
# WORK (runs/cyclic). Every cell of one wall and seed consolidates once (WORK/consolidated).
set -euo pipefail
# In order of value: the headline cell (R_n 0.5, CNS, A 1 mm; its seed 1 is the inertial-number
# check's run, in cyclic_inertial/, made once before the campaign: README.md), the other BCs at
# R_n 0.5, the small amplitude, the flat wall, the virgin peaks under CNS (monotonic, for the
# post-cyclic ones), the medium-dense cell, the check at I = 1e-4 (its
# shear stage checkpoints, so it spans sessions); flat x CV is cut first.
export DEST=data/cyclic
export SWEEPS=${SWEEPS:-cyclic_headline cyclic_rn05 cyclic_small cyclic_flat cyclic_virgin cyclic_medium cyclic_k50 cyclic_flat_small cyclic_inertial_fine cyclic_flat_cv}
export WORK=${WORK:-runs/cyclic}
exec data/run_campaign.sh "$@"
