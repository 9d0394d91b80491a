#!/usr/bin/env bash
# Reproduces data/reference/ (README.md there): the reference campaign on the truth scene (three
# sweeps, 51 LIGGGHTS runs), the copy of what is committed, the comparison of every run with hvwe
# and the hypothesis checks, and the report. Run from the repository root after building:  data/reference/make.sh
# Stages: restore | sweeps | crosscheck | copy | compare | report (default: all, in that order).
# crosscheck runs the truth (R_n 0.5, CNL) in LIGGGHTS and YADE with seeds 1-3 (YADE: ~40 min a run). restore puts the
# committed runs into WORK so that the sweeps reuse them on a new machine. The sweeps are
# resumable (run again to continue); the rest takes under a minute and can be rerun alone, e.g.
# with another parameter set:  PARAMS=data/params/other.toml data/reference/make.sh compare report
set -euo pipefail
IWB=${IWB:-build/iwb}
PARAMS=${PARAMS:-data/params/truth_grains_epsd2.toml}  # the hvwe set every run is compared with: calibrated on these grains (data/calibration/truth_grains_epsd2)
MODEL=${MODEL:-hvwe}
JOBS=${JOBS:-1}  # runs at once, NP ranks each
NP=${NP:-2}
WORK=${WORK:-runs/reference}  # the full campaigns (VTK, engine inputs and logs): not committed
DEST=data/reference
# The campaign on the converged truth (clamped plate, epsd2, 10 mm; issue 20 item 4). Its CNL runs
# at R_n 0.5 and 0.25 are the convergence study's (EXTRA_CNL), the sweeps hold the rest.
SWEEPS=(truth2_rn truth2_cns truth2_d50 truth2_stress truth2_seeds45)
EXTRA_CNL=(data/convergence/truth_clamped data/convergence/truth_clamped_rn025)
stages=("$@")
[ ${#stages[@]} -eq 0 ] && stages=(restore sweeps crosscheck copy compare report)

# The committed part of a campaign, copied afresh (../copy_campaign.sh says what it is).
copy_campaign() {
  rm -rf "$2"
  data/copy_campaign.sh "$1" "$2"
}

# The compact part of each complete seed run of the crosscheck, and its tables once every seed is
# done: a YADE run takes ~40 min, so seeds are committed one by one and a stopped crosscheck
# resumes from them on another machine (restore puts them back; the crosscheck reuses a complete
# run from its manifest and summary).
copy_crosscheck() {
  local from=$WORK/crosscheck to=$DEST/crosscheck
  [ -d "$from" ] || return 0
  mkdir -p "$to"
  [ -f "$from/crosscheck.json" ] && cp "$from"/crosscheck.{json,md} "$to/"
  for run in "$from"/*-seed*/; do
    grep -q '"status": "complete"' "$run/manifest.json" 2>/dev/null || continue
    rm -rf "$to/$(basename "$run")"; mkdir -p "$to/$(basename "$run")"
    cp "$run"/{manifest.json,summary.json,timeseries.csv,profiles.csv} "$to/$(basename "$run")/"
  done
}

restore_crosscheck() {
  local from=$DEST/crosscheck to=$WORK/crosscheck
  [ -d "$from" ] || return 0
  mkdir -p "$to"
  for run in "$from"/*-seed*/; do
    [ -d "$run" ] && [ ! -e "$to/$(basename "$run")" ] && cp -r "$run" "$to/"
  done
  return 0
}

# The committed runs of every sweep, or of one set: cnl (CNL at 50 kPa: names end _cnl), cns
# (names end _cns-<K>), cnl200 (CNL at 200 kPa: _cnl-200).
runs_of() {
  if [[ $1 == all || $1 == cnl ]]; then
    for d in "${EXTRA_CNL[@]}"; do for r in "$d"/runs/*; do [ -d "$r" ] && echo "$r"; done; done
  fi
  for s in "${SWEEPS[@]}"; do
    for r in "$DEST/$s"/runs/*; do
      [ -d "$r" ] || continue
      local n; n=$(basename "$r")
      case "$1" in
      all) echo "$r" ;;
      cnl) [[ $n == *_cnl || $n == *_cnl-50 ]] && echo "$r" ;;  # truth2_seeds45 names the stress
      cns) [[ $n == *_cns-* ]] && echo "$r" ;;
      cnl200) [[ $n == *_cnl-200 ]] && echo "$r" ;;
      esac
    done
  done
  return 0
}

for stage in "${stages[@]}"; do
  case $stage in
  restore)
    for s in "${SWEEPS[@]}"; do data/restore_campaign.sh "$DEST/$s" "$WORK/$s"; done
    restore_crosscheck ;;
  sweeps)
    for s in "${SWEEPS[@]}"; do "$IWB" sweep "data/sweeps/$s.toml" -j "$JOBS" --np "$NP" -o "$WORK/$s"; done ;;
  crosscheck)  # resumable: complete seed runs are reused
    "$IWB" dem crosscheck data/scenes/truth.toml --seeds 3 --np "$NP" -o "$WORK/crosscheck" ;;
  copy)
    for s in "${SWEEPS[@]}"; do [ -f "$WORK/$s/sweep.json" ] && copy_campaign "$WORK/$s" "$DEST/$s"; done
    copy_crosscheck ;;
  compare)
    # All runs together, and CNL 50, CNS and CNL 200 apart: the checks group runs by R_n and d50
    # only, and a CNS run dilates less than a CNL one, a run at 200 kPa less than one at 50, which
    # would widen the seed scatter of a mixed group.
    for set in all cnl cns cnl200; do
      mapfile -t runs < <(runs_of $set)
      if [ ${#runs[@]} -eq 0 ]; then echo "make.sh: no complete runs in set $set yet" >&2; continue; fi
      # afresh: a comparison of a run no longer in the set (an earlier campaign's) would stay beside
      rm -rf "$DEST/compare/$set"
      "$IWB" compare --runs "${runs[@]}" --model "$MODEL" --params "$PARAMS" -o "$DEST/compare/$set" --force
    done
    # the per-run comparisons of the CNL and CNS sets are those of the set of all runs (same DEM
    # run, parameters and model): keep them once
    for set in cnl cns cnl200; do
      [ -d "$DEST/compare/$set" ] && find "$DEST/compare/$set" -mindepth 1 -maxdepth 1 -type d -exec rm -r {} +
    done ;;
  report)
    # One page: the verdicts of the three sets, then every run (from the set of all runs) once.
    rm -rf "$DEST/report"
    sets=()
    for set in cnl cns cnl200; do [ -f "$DEST/compare/$set/hypotheses.json" ] && sets+=("$DEST/compare/$set/hypotheses.json"); done
    "$IWB" report "$DEST/compare/all" "${sets[@]}" -o "$DEST/report/report.html"
    # the PNGs repeat the SVGs (inline in the page, and beside their CSV and gnuplot script):
    # dropped to keep the committed campaign small; `gnuplot <figure>.gp` redraws any of them
    find "$DEST/report" -name '*.png' -delete ;;
  *) echo "make.sh: unknown stage '$stage' (restore, sweeps, crosscheck, copy, compare, report)" >&2; exit 2 ;;
  esac
done
