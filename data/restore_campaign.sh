#!/usr/bin/env bash
# Puts the committed runs of a campaign back into its work directory so that `iwb sweep` reuses
# them (a complete run of the same scene is not run again) on a machine where the full campaign is
# gone: a session may start on a new machine, and only the compact results are committed.
# Usage: data/restore_campaign.sh COMMITTED_DIR WORK_DIR   (runs already in WORK_DIR are kept)
set -euo pipefail
from=$1 to=$2
[ -d "$from/runs" ] || exit 0  # nothing committed yet
mkdir -p "$to/runs"
restored=0
shopt -s nullglob  # a campaign whose first run is not complete has an empty runs/
for run in "$from"/runs/*/; do
  name=$(basename "$run")
  [ -e "$to/runs/$name" ] && continue
  cp -r "$run" "$to/runs/$name"
  restored=$((restored + 1))
done
echo "restore_campaign: $restored committed runs of $from put into $to"
