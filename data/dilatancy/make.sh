#!/usr/bin/env bash
# Does a rough wall dilate more than the soil beside it? (issue 20 item 4, "which assumption is at
# fault"; README.md here.) DEM simple shear of the truth grains in a soil cell prepared as the truth
# scene's specimen (--density as-scene: its consolidation friction 0.1, so the cell starts at the
# interface specimen's density), CNL 50 kPa, three seeds, the calibration's cell and rate; then the
# table of peak dilatancy rates: soil cell, interface runs, and vw3d with the calibrated set from
# each cell's own start. Run from the repository root after building. Resumable.
#   data/dilatancy/make.sh            # run or continue, copy, table
#   data/dilatancy/make.sh copy table
#   CELL=periodic data/dilatancy/make.sh   # the same in the fully periodic cell (no plates; issue 38
#                                          # item 1), into periodic/seed<K>/
set -euo pipefail
IWB=${IWB:-build/iwb}
JOBS=${JOBS:-2}  # tests at once, one rank each
WORK=${WORK:-runs/dilatancy}
DEST=data/dilatancy
SCENES=data/calibration/truth_grains_epsd2/scenes  # the truth scene with seeds 1-3, as the calibration ran it
OPTS=(--test simpleshear --bc CNL --density as-scene --sigma 50 --gamma 0.5 --inertial-number 3e-4
      --length 12 --width 6 --height 12 --np 1)
CELL=${CELL:-plates}
case $CELL in
  plates) SUB= ;;
  periodic) SUB=periodic/; OPTS+=(--cell periodic) ;;
  *) echo "make.sh: CELL=$CELL: allowed plates or periodic" >&2; exit 2 ;;
esac

run_one() {
  local seed=$1 out=$WORK/${SUB}seed$1/simpleshear-CNL-as-scene-50 again=()
  grep -q '"status": "complete"' "$out/manifest.json" 2>/dev/null && return 0
  [ -f "$out/manifest.json" ] && again=(--resume)
  mkdir -p "$(dirname "$out")"
  "$IWB" dem soiltest "$SCENES/truth-seed$seed.toml" "${OPTS[@]}" --out "$out" "${again[@]}" > "$out.log" 2>&1 ||
    echo "dilatancy: $out failed, see $out.log" >&2
}

stages=("$@"); [ ${#stages[@]} -eq 0 ] && stages=(run copy table)
for stage in "${stages[@]}"; do
  case $stage in
  run)
    export -f run_one; export IWB WORK SCENES SUB OPTS_TEXT="${OPTS[*]}"
    printf '%s\n' 1 2 3 | xargs -P "$JOBS" -I{} bash -c 'OPTS=($OPTS_TEXT); run_one {}' ;;
  copy)
    for seed in 1 2 3; do
      from=$WORK/${SUB}seed$seed/simpleshear-CNL-as-scene-50 to=$DEST/${SUB}seed$seed/simpleshear-CNL-as-scene-50
      grep -q '"status": "complete"' "$from/manifest.json" 2>/dev/null || continue
      mkdir -p "$to"; cp "$from"/{manifest.json,timeseries.csv,profiles.csv} "$to/"
    done ;;
  table) /usr/bin/python3 "$DEST/table.py" > "$DEST/table.md"; cat "$DEST/table.md" ;;
  *) echo "make.sh: unknown stage '$stage' (run, copy, table)" >&2; exit 2 ;;
  esac
done
