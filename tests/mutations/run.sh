#!/usr/bin/env bash
# tests/mutations/run.sh [PATCH...]: break the code on purpose, one change at a time, and record
# which tests fail (tests/README.md, "Mutations").
#
# For each patch (all of tests/mutations/NN-*.patch, or the ones named): apply it, build, run the
# selected tests, record the names of the failing ones, revert (also on failure or interrupt).
# The selection is every unit test and CLI test that does not start a DEM engine: Catch tags
# [liggghts], [yade], [heavy] are left out, and so is [dem] except in the four files whose [dem]
# tests are pure functions (scene, wall geometry, summary, crosscheck's helpers).
# Writes tests/mutations/results.md: one row per patch (rows of patches not run this time are kept).
#
# Environment: BUILD_DIR (default build), JOBS (default 2), TEST_TIMEOUT per test in s (600).
set -uo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(git -C "$here" rev-parse --show-toplevel)
build=${BUILD_DIR:-$repo/build}
jobs=${JOBS:-2}
timeout=${TEST_TIMEOUT:-600}
results=$here/results.md
work=$build/mutations
# [dem] tests that start no engine, by file (Catch's -# adds the tag [#<file name>]).
pure_dem_files=(test_scene test_wall_geometry test_summary test_crosscheck)

cd "$repo" || exit 2
mkdir -p "$work"

patches=()
if [ $# -gt 0 ]; then
  for p in "$@"; do
    [ -f "$p" ] || p=$here/$(basename "$p")
    [ -f "$p" ] || { echo "run.sh: no patch '$p' (looked in $here)" >&2; exit 2; }
    patches+=("$(cd "$(dirname "$p")" && pwd)/$(basename "$p")")
  done
else
  patches=("$here"/[0-9][0-9]-*.patch)
fi

applied=""
revert() {
  if [ -n "$applied" ]; then
    git apply -R "$applied" && echo "reverted $(basename "$applied")"
    applied=""
  fi
}
trap 'revert' EXIT
trap 'revert; exit 130' INT TERM

build_all() { cmake --build "$build" -j"$jobs" >"$1" 2>&1; }

# The names of the tests left out, from Catch's own list, one a line.
engine_tests() {
  local spec="[liggghts],[yade],[heavy],[dem]" f
  for f in "${pure_dem_files[@]}"; do spec+="~[#$f]"; done
  "$build/tests/iwb_tests" -# --list-test-names-only "$spec" | grep -v '^$'
}

# The -E regex of ctest for those names (registered as "unit:NAME" or "heavy:NAME").
as_regex() { sed -E 's/[][\\^$.|?*+(){}]/\\&/g; s/^/^[a-z]+: ?/; s/$/$/' | paste -sd'|'; }

# The patch's "# breaks: ..." line, a "|" escaped for the table.
what_it_breaks() { sed -n 's/^# breaks: //p' "$1" | head -1 | sed 's/|/\\|/g'; }

# Sets ROW, "| `patch` | what | failed | ..." for one patch (no subshell: the traps must see
# `applied`); the test names are in $work/<patch>.failed, the logs beside them.
run_one() {
  local patch=$1 name what start end log failed rc
  name=$(basename "$patch")
  what=$(what_it_breaks "$patch")
  log=$work/${name%.patch}
  start=$(date +%s)
  if ! git apply --check "$patch" 2>"$log.apply"; then
    ROW="| \`$name\` | $what | does not apply: $(head -1 "$log.apply") | | | $stamp |"
    return
  fi
  git apply "$patch" && applied=$patch
  echo "== $name: $what" >&2
  if ! build_all "$log.build"; then
    revert
    ROW="| \`$name\` | $what | the build fails (see $log.build) | | $(($(date +%s) - start)) s | $stamp |"
    return
  fi
  rm -f "$build/Testing/Temporary/LastTestsFailed.log"
  ctest --test-dir "$build" -j"$jobs" --timeout "$timeout" -E "$exclude" >"$log.ctest" 2>&1
  rc=$?
  revert
  end=$(date +%s)
  failed=$(sed -E 's/^[0-9]+://' "$build/Testing/Temporary/LastTestsFailed.log" 2>/dev/null | sort)
  printf '%s\n' "$failed" >"$log.failed"
  local total count cell
  total=$(grep -oE 'tests passed, [0-9]+ tests failed out of [0-9]+' "$log.ctest" | grep -oE '[0-9]+$')
  if [ -z "$failed" ]; then
    [ "$rc" -eq 0 ] && cell="none: SURVIVED" || cell="ctest exited $rc without a failed test (see $log.ctest)"
    count=0
  else
    count=$(wc -l <<<"$failed")
    # names without their "unit: " prefix, a "|" inside one escaped for the table
    cell=$(sed -E 's/^unit: ?//; s/\|/\\|/g' <<<"$failed" | paste -sd';' | sed 's/;/; /g')
  fi
  echo "== $name: $count of ${total:-?} failed in $((end - start)) s" >&2
  ROW="| \`$name\` | $what | $cell | $count of ${total:-?} | $((end - start)) s | $stamp |"
}

echo "building the unmutated tree" >&2
build_all "$work/base.build" || { echo "run.sh: the unmutated tree does not build ($work/base.build)" >&2; exit 1; }
left_out=$(engine_tests | wc -l)
exclude=$(engine_tests | as_regex)
# ctest's regex allows 10 groups and compiles silently to nothing beyond: check the count.
all=$(ctest --test-dir "$build" -N | sed -n 's/^Total Tests: //p')
kept=$(ctest --test-dir "$build" -N -E "$exclude" | sed -n 's/^Total Tests: //p')
if [ -z "$exclude" ] || [ "$((all - kept))" -ne "$left_out" ]; then
  echo "run.sh: the engine tests were not left out ($all tests, $kept kept, $left_out to leave out)" >&2
  exit 1
fi
echo "selected $kept of $all tests (left out $left_out that start an engine or are heavy)" >&2
stamp="$(git rev-parse --short HEAD), $(date -u +%Y-%m-%d)"
# The unmutated tree must pass the selection, or a failure below would say nothing.
rm -f "$build/Testing/Temporary/LastTestsFailed.log"
if ! ctest --test-dir "$build" -j"$jobs" --timeout "$timeout" -E "$exclude" >"$work/base.ctest" 2>&1; then
  echo "run.sh: the unmutated tree fails these tests ($work/base.ctest):" >&2
  sed -E 's/^[0-9]+:/  /' "$build/Testing/Temporary/LastTestsFailed.log" >&2
  exit 1
fi

declare -A row
for p in "${patches[@]}"; do
  ROW=""
  run_one "$p"
  row[$(basename "$p")]=$ROW
done
build_all "$work/base.build"  # leave the build matching the sources

{
  echo "# Mutation results"
  echo
  echo "Written by \`tests/mutations/run.sh\` (tests/README.md, \"Mutations\"): each patch applied alone,"
  echo "the tree built, every unit and CLI test that starts no DEM engine run, the patch reverted."
  echo "\"run at\" is the commit the patch was applied to (2 cores, Release build; the time includes"
  echo "the build)."
  echo
  echo "| patch | what it breaks | tests that failed | failed | time | run at |"
  echo "|---|---|---|---|---|---|"
  for p in "$here"/[0-9][0-9]-*.patch; do
    n=$(basename "$p")
    if [ -n "${row[$n]:-}" ]; then
      echo "${row[$n]}"
    elif [ -f "$results" ] && grep -qF "| \`$n\` |" "$results"; then
      grep -F "| \`$n\` |" "$results" | head -1
    else
      echo "| \`$n\` | $(what_it_breaks "$p") | not run yet | | | |"
    fi
  done
} >"$results.new" && mv "$results.new" "$results"
echo "results: $results" >&2
