#!/usr/bin/env bash
# Copies the committed part of a campaign (an `iwb sweep` directory) into the repository: sweep.json,
# the job scenes, and per complete run the contract files without VTK and without the engine's
# directory (inputs, logs, restart files): manifest.json, summary.json, timeseries.csv,
# profiles.csv and fields/band.csv, fields/band_profile.csv. A run is copied once it is complete
# and again when its manifest changed; runs not complete are left out and named. The reverse is
# data/restore_campaign.sh.
# Usage: data/copy_campaign.sh SWEEP_DIR COMMITTED_DIR   (prints how many runs it copied)
set -euo pipefail
from=$1 to=$2
[ -f "$from/sweep.json" ] || { echo "copy_campaign: $from holds no sweep.json" >&2; exit 2; }
mkdir -p "$to/scenes" "$to/runs"
cp "$from/sweep.json" "$to/"
cp "$from"/scenes/*.toml "$to/scenes/"
copied=0 waiting=()
for run in "$from"/runs/*/; do
  name=$(basename "$run")
  if ! grep -q '"status": "complete"' "$run/manifest.json" 2>/dev/null; then
    waiting+=("$name")
    continue
  fi
  cmp -s "$run/manifest.json" "$to/runs/$name/manifest.json" && continue
  rm -rf "$to/runs/$name.tmp" && mkdir -p "$to/runs/$name.tmp"
  cp "$run"/{manifest.json,summary.json,timeseries.csv,profiles.csv} "$to/runs/$name.tmp/"
  if [ -f "$run/fields/band.csv" ]; then
    mkdir -p "$to/runs/$name.tmp/fields"
    cp "$run"/fields/{band.csv,band_profile.csv} "$to/runs/$name.tmp/fields/"
  fi
  rm -rf "$to/runs/$name" && mv "$to/runs/$name.tmp" "$to/runs/$name"  # never half a run
  copied=$((copied + 1))
done
echo "copy_campaign: $copied runs of $from copied to $to${waiting:+; not complete yet: ${waiting[*]}}"
