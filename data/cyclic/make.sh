#!/usr/bin/env bash
# The cyclic truth of issue 34 (README.md here): its sweeps in order of value, resumable, with each
# complete run's compact files copied into data/cyclic/<sweep>/ (and committed with COMMIT=1) as
# it completes, so that a campaign stopped anywhere resumes on another machine.
# Run from the repository root after building:  data/cyclic/make.sh [restore] [sweeps] [copy]
# (default: all three). Environment: JOBS runs at once (2) with NP ranks each (1): on 2 cores two
# one-rank runs finish 1.9 times as many runs per hour as one two-rank run; WORK (runs/cyclic);
# SWEEPS to run a subset; COMMIT=1 commits data/cyclic after every copy (only that path).
# Every cell of one wall and seed consolidates once: IWB_CONSOLIDATED_DIR is shared by the sweeps.
set -euo pipefail
IWB=${IWB:-build/iwb}
JOBS=${JOBS:-2}
NP=${NP:-1}
WORK=${WORK:-runs/cyclic}
DEST=data/cyclic
COMMIT=${COMMIT:-0}
COPY_EVERY_S=${COPY_EVERY_S:-120}
# In order of value: the headline cell (R_n 0.5, CNS, A 1 mm; its seed 1 is the inertial-number
# check's run, in cyclic_inertial/, made once before the campaign: README.md), the other BCs at
# R_n 0.5, the small amplitude, the flat wall; flat x CV is cut first.
read -r -a SWEEPS <<< "${SWEEPS:-cyclic_headline cyclic_rn05 cyclic_small cyclic_flat cyclic_flat_small cyclic_flat_cv}"
export IWB_CONSOLIDATED_DIR=${IWB_CONSOLIDATED_DIR:-$PWD/$WORK/consolidated}
stages=("$@")
[ ${#stages[@]} -eq 0 ] && stages=(restore sweeps copy)

copy_all() {
  for s in "${SWEEPS[@]}"; do
    [ -f "$WORK/$s/sweep.json" ] && data/copy_campaign.sh "$WORK/$s" "$DEST/$s"
  done
  if [ "$COMMIT" = 1 ] && [ -n "$(git status --porcelain -- "$DEST")" ]; then
    git add -- "$DEST" && git commit -q -m "data/cyclic: compact results of the runs complete so far" -- "$DEST" ||
      echo "make.sh: the commit of $DEST failed (tried again after the next copy)" >&2
  fi
  return 0
}

# Copies (and commits) every COPY_EVERY_S seconds while the sweeps run, and once more at the end.
copy_while_running() {
  while kill -0 "$1" 2>/dev/null; do
    sleep "$COPY_EVERY_S"
    copy_all
  done
}

for stage in "${stages[@]}"; do
  case $stage in
    restore)
      for s in "${SWEEPS[@]}"; do data/restore_campaign.sh "$DEST/$s" "$WORK/$s"; done ;;
    sweeps)
      (for s in "${SWEEPS[@]}"; do
         "$IWB" sweep "data/sweeps/$s.toml" --jobs "$JOBS" --np "$NP" -o "$WORK/$s"
       done) &
      runner=$!
      copy_while_running "$runner" &
      wait "$runner" ;;
    copy)
      copy_all ;;
    *)
      echo "make.sh: unknown stage '$stage'; stages: restore, sweeps, copy" >&2
      exit 2 ;;
  esac
done
