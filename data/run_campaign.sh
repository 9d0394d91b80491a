#!/usr/bin/env bash
# Runs a campaign of sweeps resumably and commits its compact results as each run completes, so
# that a campaign stopped anywhere resumes on another machine (a session may end at any time).
# Usage, from the repository root after building:
#   DEST=data/roughness SWEEPS="a b" data/run_campaign.sh [restore] [sweeps] [copy]   (default: all three)
# restore puts DEST's committed runs into WORK (so `iwb sweep` reuses them), sweeps runs
# data/sweeps/<s>.toml for each s into WORK/<s>, copy puts each sweep's compact files into DEST/<s>
# (data/copy_campaign.sh; also every COPY_EVERY_S seconds while the sweeps run).
# Environment: DEST, SWEEPS (required, in order of value: a name of data/sweeps/ or a sweep file's
# path, e.g. a plan of `iwb claims --plan-seeds` committed under DEST; its name is the file's); IWB (build/iwb: give a copy, so that a
# rebuild does not change the binary under a running campaign); JOBS runs at once (2) with NP
# ranks each (1): on 2 cores two one-rank runs finish 1.9 times as many runs per hour as one
# two-rank run; WORK (runs/<DEST's name>); COMMIT=1 commits DEST/<sweep> after every copy (only
# those paths);
# IWB_CONSOLIDATED_DIR (WORK/consolidated: every cell of one wall and seed consolidates once).
set -euo pipefail
: "${DEST:?DEST=data/<campaign> is required}" "${SWEEPS:?SWEEPS=\"sweep names\" is required}"
IWB=${IWB:-build/iwb}
JOBS=${JOBS:-2}
NP=${NP:-1}
WORK=${WORK:-runs/$(basename "$DEST")}
COMMIT=${COMMIT:-0}
COPY_EVERY_S=${COPY_EVERY_S:-120}
read -r -a sweeps <<< "$SWEEPS"
export IWB_CONSOLIDATED_DIR=${IWB_CONSOLIDATED_DIR:-$PWD/$WORK/consolidated}
stages=("$@")
[ ${#stages[@]} -eq 0 ] && stages=(restore sweeps copy)

sweep_name() { local s=${1##*/}; echo "${s%.toml}"; }
sweep_file() { case $1 in */* | *.toml) echo "$1" ;; *) echo "data/sweeps/$1.toml" ;; esac; }

# Commits the sweeps' directories only: a file edited by hand elsewhere under DEST (its README, a
# script) is the editor's to commit, under its own message.
copy_all() {
  local copied=()
  local s
  for s in "${sweeps[@]}"; do
    s=$(sweep_name "$s")
    [ -f "$WORK/$s/sweep.json" ] && data/copy_campaign.sh "$WORK/$s" "$DEST/$s" && copied+=("$DEST/$s")
  done
  if [ "$COMMIT" = 1 ] && [ ${#copied[@]} -gt 0 ] && [ -n "$(git status --porcelain -- "${copied[@]}")" ]; then
    git add -- "${copied[@]}" &&
      git commit -q -m "$DEST: compact results of the runs complete so far" -- "${copied[@]}" ||
      echo "run_campaign: the commit of $DEST failed (tried again after the next copy)" >&2
  fi
  return 0
}

copy_while_running() {
  while kill -0 "$1" 2>/dev/null; do
    sleep "$COPY_EVERY_S"
    copy_all
  done
}

for stage in "${stages[@]}"; do
  case $stage in
    restore)
      for s in "${sweeps[@]}"; do
        s=$(sweep_name "$s")
        data/restore_campaign.sh "$DEST/$s" "$WORK/$s"
      done ;;
    sweeps)
      (for s in "${sweeps[@]}"; do
         "$IWB" sweep "$(sweep_file "$s")" --jobs "$JOBS" --np "$NP" -o "$WORK/$(sweep_name "$s")"
       done) &
      runner=$!
      copy_while_running "$runner" &
      wait "$runner" ;;
    copy)
      copy_all ;;
    *)
      echo "run_campaign: unknown stage '$stage'; stages: restore, sweeps, copy" >&2
      exit 2 ;;
  esac
done
