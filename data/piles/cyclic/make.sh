#!/usr/bin/env bash
# The shaft's friction fatigue under displacement cycles against the DEM's cyclic CNS cells (issue
# 34 item 6; README.md here): every file of this folder through `iwb pile` into runs/<name>/
# (committed whole, ~0.5 MB each; 1-2 minutes a file alone), then the per-cycle table beside the
# DEM's. Run from the repository root after building:
#   data/piles/cyclic/make.sh
set -euo pipefail
IWB=${IWB:-build/iwb}
here=data/piles/cyclic
for f in "$here"/*.toml; do
  name=$(basename "$f" .toml)
  "$IWB" pile "$f" -o "$here/runs/$name" --force
done
table() { /usr/bin/python3 data/cyclic/cycle_table.py "$@"; }
{
  echo "## A = 0.25 mm, 20 cycles"
  table data/cyclic/cyclic_small/runs/cns-200_s*
  for m in hvwe hvwe-igs; do table "$here/runs/${m}_a0.25"; done
  echo "## A = 1 mm, 10 cycles"
  table --cycles 1,2,5,10 data/cyclic/cyclic_headline/runs/cns-200_s* data/cyclic/cyclic_inertial/runs/i0.0003
  for name in hvwe_a1 hvwe-igs_a1 hvwe-igs_a1_compressible; do
    table --cycles 1,2,5,10 "$here/runs/$name"
  done
} > "$here/tables.md"
echo "make.sh: runs in $here/runs, tables in $here/tables.md"
