#!/bin/sh
# Rewrites the gold files src/models/<folder>/gold/<model>/<path>.csv that no longer pass, from the
# current build, for when a change of a model's response is intended; a file that passes is left
# as it is (its differences are within the tolerances: last digits, cost counters). The runs are
# the gold tests' own (tests/gold/), so what is written is exactly what they compare. The files are
# the list of cases: a new case is an empty <path>.csv put where it belongs (README.md), which this
# fills. Review `git diff --stat src/models` and say in the commit which models moved and why.
#   data/gold/regenerate.sh [BUILD_DIR]    (default: build)
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-build}
cd "$root"
cmake --build "$build" --target iwb_tests
IWB_GOLD_REGENERATE=1 "$build/tests/iwb_tests" "[gold-files]"
git status --short -- 'src/models/*/gold/'
