#!/usr/bin/env bash
# Bit-identity of two builds of iwb (src/models/README.md, section 9): the migration to the model
# contract must not move a single output byte. Not a ctest: it needs a second binary, the one
# built from the commit before the change.
#   tests/identity/run.sh BASE_IWB NEW_IWB [WORK_DIR]
# Compares, per binary: every gold case (src/models/<folder>/gold/<model>/<path>.csv, as
# tests/gold/test_gold_files.cpp finds them) through `iwb element` (history.csv, cycles.csv;
# manifest.json without clocks and command line), every data/tests/*.toml,
# `iwb run` (histories and summary), and `--help` of every command. Prints each difference; exit 1
# if there is any.
set -euo pipefail
base=$(realpath "$1") new=$(realpath "$2")
work=${3:-$(mktemp -d /tmp/identity.XXXX)}
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
mkdir -p "$work"
differences=0

# The gold template for one model: [model] name set, its parameter file's path made absolute (the
# case is written elsewhere), [roughness] dropped where the model takes none.
gold_case() {  # model template out.toml rough(yes|no)
  /usr/bin/python3 - "$@" <<'PY'
import os, re, sys
model, src, out, rough = sys.argv[1:]
text = open(src).read()
text = re.sub(r'(?m)^name = ".*"$', f'name = "{model}"', text, count=1)
here = os.path.dirname(os.path.abspath(src))
text = re.sub(r'(?m)^parameters = "(.*)"$',
              lambda m: 'parameters = "' + os.path.normpath(os.path.join(here, m.group(1))) + '"', text, count=1)
if rough == "no":  # the table's lines up to the next table (a DOTALL pattern once ate the rest)
    text = re.sub(r'(?m)^\[roughness\]\n(?:(?!\[).*\n)*', '', text)
open(out, "w").write(text)
PY
}

# manifest.json without what differs between two runs of the same inputs
stable_manifest() { /usr/bin/python3 -c '
import json, sys
m = json.load(open(sys.argv[1]))
def strip(x):
    if isinstance(x, dict):
        return {k: strip(v) for k, v in x.items() if k not in ("started", "finished", "wall_seconds", "command_line", "seconds", "binary", "executable")}
    if isinstance(x, list): return [strip(v) for v in x]
    return x
print(json.dumps(strip(m), indent=1, sort_keys=True))' "$1"; }

compare_dirs() {  # label dirA dirB
  for f in history.csv cycles.csv summary.json; do
    [ -f "$2/$f" ] || [ -f "$3/$f" ] || continue
    cmp -s "$2/$f" "$3/$f" || { echo "DIFF $1: $f"; differences=$((differences + 1)); }
  done
  if [ -f "$2/manifest.json" ]; then
    diff -q <(stable_manifest "$2/manifest.json") <(stable_manifest "$3/manifest.json") >/dev/null ||
      { echo "DIFF $1: manifest.json"; differences=$((differences + 1)); }
  fi
}

run_both() {  # label args...
  local label=$1; shift
  for side in base new; do
    local bin=$base; [ $side = new ] && bin=$new
    "$bin" "$@" --out "$work/$side/$label" --force >"$work/$side/$label.out" 2>&1 || true
  done
  compare_dirs "$label" "$work/base/$label" "$work/new/$label"
}

mkdir -p "$work/base" "$work/new" "$work/cases"
# model:template:path of every gold file; the template is the folder's own, else the shared one
# (data/gold/README.md: exactly one exists, the gold test checks it).
cases=$(/usr/bin/python3 -c '
import glob, os
for f in sorted(glob.glob("src/models/*/gold/*/*.csv")):
    gold, model = os.path.split(os.path.dirname(f))
    path = os.path.basename(f)[:-len(".csv")]
    template = os.path.join(gold, path + ".toml")
    if not os.path.exists(template): template = os.path.join("data/gold/tests", path + ".toml")
    print(f"{model}:{template}:{path}")')
# the models that take no [roughness], as the new binary declares them
continuum=$("$new" models --json | /usr/bin/python3 -c '
import json, sys
print(" ".join(m["name"] for m in json.load(sys.stdin) if not m["roughness"]))')
for case in $cases; do
  IFS=: read -r model template path <<<"$case"
  rough=yes; [[ " $continuum " == *" $model "* ]] && rough=no
  gold_case "$model" "$template" "$work/cases/$model-$path.toml" "$rough"
  run_both "gold-$model-$path" element "$work/cases/$model-$path.toml"
  # a case both binaries refuse would compare equal: every gold case has a history to compare
  [ -f "$work/new/gold-$model-$path/history.csv" ] ||
    { echo "NO RUN gold-$model-$path: $(head -c 300 "$work/new/gold-$model-$path.out")"; differences=$((differences + 1)); }
done
for t in data/tests/*.toml; do run_both "test-$(basename "$t" .toml)" element "$t"; done
# both into one directory, then moved: `iwb run` writes its parameter set there and its manifests
# name (and hash) that path
for side in base new; do
  bin=$base; [ $side = new ] && bin=$new
  rm -rf "$work/run"
  "$bin" run --out "$work/run" --force >/dev/null 2>&1 || true
  rm -rf "$work/$side/run" && mv "$work/run" "$work/$side/run"
done
compare_dirs run "$work/base/run" "$work/new/run"
for d in "$work"/base/run/*/; do compare_dirs "run-$(basename "$d")" "$d" "$work/new/run/$(basename "$d")"; done

# help texts of every command (the split of main.cpp must not move them)
for cmd in "" element models run dem "dem run" "dem soiltest" "dem crosscheck" "dem summary" compare sweep \
           report validate stability bench "bench element" "bench integrators" "bench dem" soiltest \
           "soiltest synthetic" calibrate tradeoff plan; do
  # shellcheck disable=SC2086
  # (the usage line names the binary as invoked)
  diff -q <("$base" $cmd --help 2>&1 | sed "s|$base|iwb|g") <("$new" $cmd --help 2>&1 | sed "s|$new|iwb|g") >/dev/null ||
    { echo "DIFF help: iwb $cmd --help"; differences=$((differences + 1)); }
done
echo "identity: $differences difference(s); outputs in $work"
[ "$differences" -eq 0 ]
