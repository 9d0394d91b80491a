#!/usr/bin/env bash
# validate_anywhere.sh BUILD_DIR PREFIX: `iwb validate` as a user meets it outside the repository
# (issue 15, finding 9). Installs the build into PREFIX, then in a scratch directory under /tmp:
#   1. a bad --params-dir is refused with exit 2 before anything runs or is written;
#   2. `validate --scene smoke` runs the engine and writes the report, the parameter set built in;
#   3. the same command again reuses the complete DEM run: the engine is not started (its run
#      manifest is untouched) and compare.json, with every verdict, is byte-identical;
#   4. with --params-dir (the installed share/iwb/params) it reuses the run too, same verdicts;
#   5. the installed iwb links no VTK library (start-up, issue 37) and loads the VTK module from the
#      install, not from the build tree, when the run writes its VTK files.
set -u
build=$1; prefix=$2
fail() { echo "validate_anywhere.sh: $*"; exit 1; }
rm -rf "$prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null || fail "cmake --install failed"
iwb=$prefix/bin/iwb
[ -x "$iwb" ] && [ -f "$prefix/share/iwb/params/dem_default_grains.toml" ] || fail "install is incomplete"
scratch=$(mktemp -d /tmp/iwb-anywhere.XXXXXX)
trap 'rm -rf "$scratch"' EXIT
cd "$scratch" || fail "no scratch directory"

out=$("$iwb" validate --scene smoke --params-dir no_such_dir 2>&1); code=$?
echo "$out"
[ "$code" -eq 2 ] || fail "bad --params-dir: exit $code, expected 2"
grep -q -- "--params-dir: no_such_dir: no such directory" <<<"$out" || fail "bad --params-dir not named"
[ -z "$(ls -A)" ] || fail "bad --params-dir left files behind: $(ls -A)"

LD_TRACE_LOADED_OBJECTS=1 "$iwb" | grep -q vtk && fail "the installed iwb links VTK: $(LD_TRACE_LOADED_OBJECTS=1 "$iwb" | grep vtk)"
LD_DEBUG=files LD_DEBUG_OUTPUT=$scratch/loader "$iwb" validate --scene smoke --np 1 >first.log 2>&1 ||
  { cat first.log; fail "first validate failed"; }
cat first.log
grep -h "file=.*libiwb_vtk_plugin" "$scratch"/loader.* | head -1
grep -q "file=$prefix/.*/iwb/libiwb_vtk_plugin.so" "$scratch"/loader.* || fail "the VTK module was not loaded from $prefix"
rm -f "$scratch"/loader.*
run=runs/validate/dem-liggghts/manifest.json
grep -q '"status": "complete"' "$run" || fail "the DEM run is not complete"
grep -q "runs/validate/parameters/dem_default_grains.toml" runs/validate/compare-hvwe/manifest.json ||
  fail "the replay did not use the built-in calibrated set"
cp "$run" manifest.first; cp runs/validate/compare-hvwe/compare.json compare.first

for extra in "" "--params-dir $prefix/share/iwb/params"; do
  # shellcheck disable=SC2086
  "$iwb" validate --scene smoke --np 1 $extra >again.log 2>&1 || { cat again.log; fail "validate $extra failed"; }
  cat again.log
  grep -q "reused the complete run in runs/validate/dem-liggghts" again.log || fail "validate $extra did not reuse the run"
  grep -q "consolidating\|shearing" again.log && fail "validate $extra started the engine"
  cmp -s "$run" manifest.first || fail "validate $extra changed the DEM run's manifest"
  cmp -s runs/validate/compare-hvwe/compare.json compare.first || fail "validate $extra gave other verdicts"
  [ -f runs/validate/report.html ] || fail "no report"
done
echo "validate_anywhere.sh: ok"
