#!/usr/bin/env bash
# models_compare.sh MODELS OUT: `iwb compare` of the six R_n 0.5 cyclic cells (A 0.25 and 1 mm;
# CNL 50 kPa, CNS 200 kPa/mm, CV) with the grains' hypoplastic set and intergranular strain
# (data/params/truth_grains_epsd2_igs.toml), each model of MODELS (comma-separated, e.g.
# "ahe-igs,ahe") replayed along each cell's first run and judged against all its seeds, into
# OUT/<cell>/<model>. Then: /usr/bin/python3 data/cyclic/igs_table.py --models ... OUT/*/
# Run from the repository root; IWB overrides build/iwb, PARAMS the parameter file (a set with
# further tables for models that read them: ../models_beyond/judge_more.sh). A cell whose
# comparison exists is compared again (seconds to a minute each).
set -euo pipefail
models=${1:?MODELS, e.g. ahe-igs,ahe} out=${2:?OUT directory}
iwb=${IWB:-build/iwb}
params=${PARAMS:-data/params/truth_grains_epsd2_igs.toml}
c=data/cyclic
cell() {  # name, the run compared, its other seeds
  local name=$1 run=$2
  shift 2
  echo "== $name: $models" >&2
  "$iwb" compare "$run" --seeds "$@" --params "$params" \
    --model "$models" -o "$out/$name" --force >"$out/$name.log"
}
mkdir -p "$out"
for bc in cnl cv; do
  cell "small_$bc" $c/cyclic_small/runs/${bc}_s1 $c/cyclic_small/runs/${bc}_s{2,3}
  cell "a1_$bc" $c/cyclic_rn05/runs/${bc}_s1 $c/cyclic_rn05/runs/${bc}_s{2,3}
done
cell small_cns $c/cyclic_small/runs/cns-200_s1 $c/cyclic_small/runs/cns-200_s{2,3}
cell a1_cns $c/cyclic_inertial/runs/i0.0003 $c/cyclic_headline/runs/cns-200_s{2,3,4,5}
