#!/usr/bin/env bash
# recompute_twice.sh IWB RUN SCRATCH (issue 37, item 4): `iwb dem fields --force` and `iwb dem
# summary` on a copy of the complete run RUN, twice: the coarse-grained fields and summary.json
# are the same bytes each time, and the same as the run wrote when it completed.
set -euo pipefail
iwb=$1 run=$2 scratch=$3
rm -rf "$scratch"
mkdir -p "$scratch/0"
cp -r "$run" "$scratch/run"
cp -r "$run/fields" "$run/summary.json" "$scratch/0/"
for i in 1 2; do
  "$iwb" dem fields "$scratch/run" --force >/dev/null
  "$iwb" dem summary "$scratch/run" >/dev/null
  mkdir "$scratch/$i"
  cp -r "$scratch/run/fields" "$scratch/run/summary.json" "$scratch/$i/"
done
diff -r "$scratch/1" "$scratch/2"
diff -r "$scratch/0" "$scratch/1"
echo "fields and summary: the same bytes on every recomputation"
