#!/usr/bin/env bash
# Convergence study of the DEM truth (issue 20 item 1; README.md here). Run from the repository
# root after building. Stages: restore | sweeps | copy | table (default: all; restore puts the
# committed runs into WORK so that the sweeps reuse them on a new machine). The sweeps are resumable (run again
# to continue, e.g. in the next session); `copy` commits the compact part of every complete run.
#   data/convergence/make.sh            # run (or continue) every axis, then copy
#   data/convergence/make.sh copy       # only copy what has completed
set -euo pipefail
IWB=${IWB:-build/iwb}
WORK=${WORK:-runs/convergence-v2}  # the full runs (VTK, engine inputs, restarts): not committed; -v2: with the loop-number servo gain
DEST=data/convergence
AXES=(stiffness box inertial timestep damping slow rolling epsd2)
STALE_AXES=(box)  # committed runs that must be re-run, not restored (drop an axis once its re-run is committed)
# The one-knob axes start from this level of the stiffness axis (converged within the seed
# scatter there): their tables compare each of their levels with its runs.
BASE_LEVEL=E690000000
stages=("$@")
[ ${#stages[@]} -eq 0 ] && stages=(restore sweeps copy table)

# sweep.json, the job scenes, and per complete run its contract files without VTK or engine files
# (and its coarse-grained fields/band.csv and band_profile.csv, not the .vti images).
copy_axis() {
  local from=$1 to=$2
  [ -f "$from/sweep.json" ] || return 0  # an axis not started yet
  mkdir -p "$to/scenes" "$to/runs"
  cp "$from/sweep.json" "$to/"
  cp "$from"/scenes/*.toml "$to/scenes/"
  for run in "$from"/runs/*/; do
    local name; name=$(basename "$run")
    grep -q '"status": "complete"' "$run/manifest.json" 2>/dev/null || continue
    mkdir -p "$to/runs/$name"
    cp "$run"/{manifest.json,summary.json,timeseries.csv,profiles.csv} "$to/runs/$name/"
    # the coarse-grained balances and the band's mean profile (issue 21), where the run has them
    if [ -f "$run/fields/band.csv" ]; then
      mkdir -p "$to/runs/$name/fields"
      cp "$run"/fields/{band.csv,band_profile.csv} "$to/runs/$name/fields/"
    fi
  done
}

for stage in "${stages[@]}"; do
  case $stage in
  restore) for a in "${AXES[@]}"; do
             # the committed box runs predate the loop-number servo gain, which the binary chooses and
             # the scene hash does not record: restored, they would be reused instead of re-run
             [[ " ${STALE_AXES[*]} " == *" $a "* ]] && continue
             data/restore_campaign.sh "$DEST/$a" "$WORK/$a"
           done ;;
  sweeps) for a in "${AXES[@]}"; do "$IWB" sweep "data/sweeps/convergence_$a.toml" -j 1 --np 2 -o "$WORK/$a"; done ;;
  copy) for a in "${AXES[@]}"; do copy_axis "$WORK/$a" "$DEST/$a"; done ;;
  table) for a in "${AXES[@]}"; do
           [ -d "$DEST/$a/runs" ] || continue
           base=(); [ "$a" = stiffness ] || base=("$DEST/stiffness" "$BASE_LEVEL")
           # the damping axis asks whether the rate effect is the damping's: against I = 3e-4 at e = 0.5
           [ "$a" = damping ] && base=("$DEST/inertial" "${BASE_LEVEL}_I0.0003")
           # the slow axis against the inertial axis's slowest level
           [ "$a" = slow ] && base=("$DEST/inertial" "${BASE_LEVEL}_I0.0001")
           # the rolling axis (rolling resistance off) against I = 3e-4 with it
           [ "$a" = rolling ] && base=("$DEST/inertial" "${BASE_LEVEL}_I0.0003")
           [ "$a" = epsd2 ] && base=("$DEST/inertial" "${BASE_LEVEL}_I0.0003")
           /usr/bin/python3 "$DEST/table.py" "$DEST/$a" "${base[@]}" > "$DEST/$a/table.md"
         done ;;
  *) echo "make.sh: unknown stage '$stage' (restore, sweeps, copy, table)" >&2; exit 2 ;;
  esac
done
