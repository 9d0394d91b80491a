#!/usr/bin/env bash
# Issue 56 item 3, the held-out cells the plan reports but does not decide by (README.md here,
# "What will count as success"): hvwe, ahe and both candidates, each with its fitted parameters from the
# deciding fits (hvwe_rd_held_walls/, hvwe_pg_held_walls/, soil held), predicted on
#   - the gradings of ../grains/ (C_u 2.2 and 3.2, R_n 0.25 and 0.5; cu2, cu3 and cu3_rn025), on the set scaled by their
#     dense packing (../params/grains_cu*_scaled.toml, as ../grains/ judged hvwe);
#   - the densities of ../grains/ (loose and medium-dense, 50 and 200 kPa, CNL and CNS), on the
#     soil tests' set (a hypoplastic set carries the density in e);
#   - the asymmetric wall both ways (asymmetric_wall/, once its runs are in);
#   - the six cyclic cells of ../cyclic/ at R_n 0.5 (A 0.25 and 1 mm; CNL, CNS, CV), with
#     ../cyclic/models_compare.sh and igs_table.py (the plain models: neither candidate has an
#     intergranular-strain variant), into more_verdicts_cyclic.md.
# `iwb compare --runs` into WORK/<set>/<model> (reproducible, not committed: 0.8 MB a run), then
# more_table.py writes more_verdicts.md and .json (committed). Usage, from the repository root:
#   data/models_beyond/judge_more.sh [SET...]   (default: cu2 cu3 density asymmetric)
set -euo pipefail
IWB=${IWB:-build/iwb}
HERE=data/models_beyond
WORK=${WORK:-runs/models_beyond_more}
sets=("$@")
[ ${#sets[@]} -eq 0 ] && sets=(cu2 cu3 cu3_rn025 density asymmetric cyclic)
mkdir -p "$WORK"

# a soil set with both candidates' fitted tables after it (each model reads its own tables)
params() {  # soil set file, output
  {
    echo "# Written by data/models_beyond/judge_more.sh: $1, then the candidates' fitted tables"
    echo "# (hvwe_rd_held_walls/, hvwe_pg_held_walls/ form_limit.toml). Not a calibration."
    grep -v '^#' "$1"
    echo
    sed -n '/^\[roughness_dilatancy\]/,/^chi/p' "$HERE/hvwe_rd_held_walls/form_limit.toml"
    echo
    sed -n '/^\[asperity_dilatancy\]/,/^lambda_w_d50/p' "$HERE/hvwe_pg_held_walls/form_limit.toml"
  } > "$2"
}

for s in "${sets[@]}"; do
  if [ "$s" = cyclic ]; then
    rm -rf "${WORK:?}/cyclic"
    params data/params/truth_grains_epsd2.toml "$WORK/cyclic.toml"
    PARAMS=$WORK/cyclic.toml IWB=$IWB data/cyclic/models_compare.sh hvwe,ahe,hvwe-rd,hvwe-pg "$WORK/cyclic"
    /usr/bin/python3 data/cyclic/igs_table.py --models hvwe,ahe,hvwe-rd,hvwe-pg "$WORK"/cyclic/*/ \
      > "$HERE/more_verdicts_cyclic.md"
    continue
  fi
  case $s in
    cu2) soil=data/params/grains_cu2_scaled.toml; runs=(data/grains/grains_cu2/runs/*) ;;
    cu3) soil=data/params/grains_cu3_scaled.toml; runs=(data/grains/grains_cu3/runs/*) ;;
    cu3_rn025) soil=data/params/grains_cu3_scaled.toml; runs=(data/grains/grains_cu3_rn025/runs/*) ;;
    density) soil=data/params/truth_grains_epsd2.toml
      runs=(data/grains/density/runs/* data/grains/density_settled/runs/*
        data/grains/density_stress/runs/* data/grains/density_rolling/runs/*) ;;
    asymmetric) soil=data/params/truth_grains_epsd2.toml; runs=($HERE/asymmetric_wall/runs/*) ;;
    *) echo "judge_more.sh: unknown set '$s' (cu2, cu3, cu3_rn025, density, asymmetric, cyclic)" >&2; exit 2 ;;
  esac
  complete=()
  for r in "${runs[@]}"; do [ -f "$r/summary.json" ] && complete+=("$r"); done
  [ ${#complete[@]} -eq 0 ] && { echo "judge_more.sh: $s: no complete run yet" >&2; continue; }
  rm -rf "${WORK:?}/$s"
  params "$soil" "$WORK/$s.toml"
  for m in hvwe ahe hvwe-rd hvwe-pg; do
    # a model that cannot start from the set's first states is refused for the set: its reason is
    # kept (WORK/<set>/<model>.refused) and the table says so
    rm -f "$WORK/$s/$m.refused"
    "$IWB" compare --runs "${complete[@]}" --model "$m" --params "$WORK/$s.toml" -o "$WORK/$s/$m" \
      --force > "$WORK/$s.$m.log" 2> "$WORK/$s.$m.err" || {
      [ $? -eq 2 ] || { cat "$WORK/$s.$m.err" >&2; exit 1; }
      mkdir -p "$WORK/$s" && cp "$WORK/$s.$m.err" "$WORK/$s/$m.refused"
    }
  done
done
# the table holds every set judged so far (this call's and earlier calls' in WORK), in one order
tables=()
for s in cu2 cu3 cu3_rn025 density asymmetric; do
  [ -d "$WORK/$s/hvwe" ] && tables+=("$s=$WORK/$s")
done
/usr/bin/python3 "$HERE/more_table.py" "${tables[@]}" --md "$HERE/more_verdicts.md" \
  --json "$HERE/more_verdicts.json"
