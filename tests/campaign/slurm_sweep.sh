#!/usr/bin/env bash
# slurm_sweep.sh CASE IWB REPO CLUSTER SCRATCH: `iwb sweep --executor slurm` on the one-node Slurm
# that slurm_cluster.sh started in CLUSTER (issue 35). The cases:
#   same       data/sweeps/tiny.toml run locally and on Slurm, one rank each: every number of every
#              job's summary.json is the same. On Slurm the longest job's task is cancelled with
#              scancel once its consolidation has finished: the executor resubmits it, the task
#              resumes from the run directory (consolidation not run again) and ends complete.
#              The three jobs share one consolidation across tasks: one consolidates, the two others
#              (one waiting on its lock) start from its specimen.
#   failing    a sweep on 2 ranks per task (mpirun inside the Slurm task) whose second job the
#              engine rejects (consolidation allowed one window: the servo cannot converge): that job
#              is resubmitted once, then reported failed with its task's log; the other job
#              completes on 2 ranks; the sweep exits 1.
#   adopt      the watcher stopped with Ctrl-C once the tasks are queued leaves them to Slurm (sweep
#              "interrupted", the tasks still listed by squeue); the same command again adopts them
#              (no second submission) and ends complete.
#   refused    bad input exits 2 naming it, nothing submitted: a partition the cluster does not
#              have (sbatch --test-only's own words), a time Slurm would not take, no sbatch on PATH.
set -uo pipefail
case=$1 iwb=$2 repo=$3 cluster=$4 scratch=$5
fail() { echo "slurm_sweep.sh $case: $*"; exit 1; }
# shellcheck disable=SC1091  # written by slurm_cluster.sh start
source "$cluster/env" || fail "no cluster in $cluster (slurm_cluster.sh start did not run)"
rm -rf "$scratch" && mkdir -p "$scratch"
cd "$repo" || fail "no repository at $repo"

jobs_submitted() { squeue --noheader --me --array --format=%i | wc -l; }

# The numbers of two summary.json files, key by key (exact: same binary, same rank count).
same_summaries() {
  /usr/bin/python3 - "$1" "$2" <<'EOF'
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
def numbers(x, path=""):
    if isinstance(x, dict):
        for k, v in x.items(): yield from numbers(v, f"{path}.{k}")
    elif isinstance(x, list):
        for i, v in enumerate(x): yield from numbers(v, f"{path}[{i}]")
    elif isinstance(x, (int, float)) and not isinstance(x, bool):
        yield path, x
na, nb = dict(numbers(a)), dict(numbers(b))
bad = [f"{k}: {na.get(k)} against {nb.get(k)}" for k in sorted(set(na) | set(nb)) if na.get(k) != nb.get(k)]
print("\n".join(bad))
sys.exit(1 if bad or not na else 0)
EOF
}

# Cancels the task of job NAME once its run has finished consolidating (prints the task's ID).
cancel_after_consolidation() {
  local out=$1 name=$2 task
  for _ in $(seq 1 600); do
    if grep -q '"consolidate"' "$out/runs/$name/manifest.json" 2>/dev/null &&
      grep -q '"status": "running' "$out/runs/$name/manifest.json"; then
      task=$(/usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); j=[j for j in d['jobs'] if j['name']==sys.argv[2]][0]; print(f\"{j['slurm_job']}_{d['jobs'].index(j)}\")" "$out/sweep.json" "$name")
      scancel "$task" && echo "$task"
      return 0
    fi
    sleep 0.2
  done
  return 1
}

case $case in
same)
  "$iwb" sweep data/sweeps/tiny.toml -o "$scratch/local" --jobs 2 >"$scratch/local.log" 2>&1 ||
    { cat "$scratch/local.log"; fail "the local sweep failed"; }
  "$iwb" sweep data/sweeps/tiny.toml -o "$scratch/slurm" --executor slurm --poll 1 >"$scratch/slurm.log" 2>&1 &
  watcher=$!
  cancelled=$(cancel_after_consolidation "$scratch/slurm" u10) || { kill $watcher; fail "u10 never finished consolidating"; }
  wait $watcher; code=$?
  cat "$scratch/slurm.log"
  [ "$code" -eq 0 ] || fail "the Slurm sweep exits $code"
  echo "cancelled task $cancelled after its consolidation"
  grep -q "u10: its task ended with the run 'interrupted\|u10: its task ended with the run 'running" "$scratch/slurm.log" ||
    fail "the cancelled u10 was not seen ending without a complete run"
  grep -q '"status": "complete"' "$scratch/slurm/sweep.json" || fail "sweep.json is not complete"
  /usr/bin/python3 - "$scratch/slurm" <<'EOF' || fail "the resubmitted u10 did not resume"
import json, sys
d = json.load(open(sys.argv[1] + "/sweep.json"))
assert len(d["slurm"]["submissions"]) == 2, d["slurm"]["submissions"]
u10 = [j for j in d["jobs"] if j["name"] == "u10"][0]
assert u10["start"] == "resumed" and u10["status"] == "complete", u10
m = json.load(open(sys.argv[1] + "/runs/u10/manifest.json"))
assert len(m["resumed"]) == 1, m.get("resumed")
print("u10 resumed at", m["resumed"][0])
EOF
  /usr/bin/python3 - "$scratch/slurm" <<'EOF' || fail "the tasks did not share one consolidation"
import json, sys
stages = [json.load(open(f"{sys.argv[1]}/runs/{j}/manifest.json"))["stages"]["consolidate"]["consolidation"]
          for j in ("u0.05", "u10", "u0.1")]
assert len({s["key"] for s in stages}) == 1, stages
assert sum(1 for s in stages if "consolidated_in" in s) == 2, stages
print("one consolidation for the three tasks, in", [s for s in stages if "consolidated_in" in s][0]["consolidated_in"])
EOF
  for job in u0.05 u10 u0.1; do
    same_summaries "$scratch/local/runs/$job/summary.json" "$scratch/slurm/runs/$job/summary.json" ||
      fail "$job: the Slurm run's summary differs from the local one"
    echo "ok: $job: summary.json the same locally and on Slurm"
  done
  ;;
failing)
  cat >"$scratch/failing.toml" <<EOF
description = "one job the engine rejects: the servo gets a single window"
scene = "$repo/data/scenes/smoke.toml"
[set]
specimen.height_d50 = 4
specimen.particles = 180
shear.inertial_number = 1e-2
shear.displacement_mm = 0.1
consolidation.window_steps = 500
consolidation.windows_required = 2
[[axis]]
key = "consolidation.max_windows"
label = "w"
values = [60, 1]
EOF
  "$iwb" sweep "$scratch/failing.toml" -o "$scratch/out" --executor slurm --np 2 --poll 1 >"$scratch/out.log" 2>&1; code=$?
  cat "$scratch/out.log"
  [ "$code" -eq 1 ] || fail "a sweep with a failed job exits $code, expected 1"
  grep -q "w1: its task ended with the run 'failed: servo did not converge" "$scratch/out.log" ||
    fail "the rejected job was not resubmitted once"
  grep -q "^w1: failed: servo did not converge" "$scratch/out.log" || fail "the rejected job is not reported failed"
  grep -q "log $scratch/out/logs/1-" "$scratch/out.log" || fail "the failed task's log is not named"
  grep -q "servo did not converge" "$scratch/out/logs/"1-*.out || fail "the task's log does not say why"
  grep -q '"status": "finished: 1 of 2 failed"' "$scratch/out/sweep.json" || fail "sweep.json's status"
  grep -q '"status": "complete"' "$scratch/out/runs/w60/manifest.json" || fail "the other job did not complete"
  grep -q '"processes": 2' "$scratch/out/runs/w60/manifest.json" || fail "the other job did not run on 2 ranks"
  grep -q "Loop time of .* on 2 procs" "$scratch/out/runs/w60/liggghts/shear.out" || fail "LIGGGHTS did not run on 2 MPI ranks"
  ;;
adopt)
  # one job of tiny.toml (the longest, 10 mm): still running when the watch is stopped
  sed -e 's|^scene = "../scenes/smoke.toml"|scene = "'"$repo"'/data/scenes/smoke.toml"|' \
    -e 's|^values = \[0.05, 10.0, 0.1\]|values = [10.0]|' data/sweeps/tiny.toml >"$scratch/one.toml"
  grep -q '^values = \[10.0\]' "$scratch/one.toml" || fail "tiny.toml changed: the one-job sweep was not made"
  "$iwb" sweep "$scratch/one.toml" -o "$scratch/out" --executor slurm --poll 1 >"$scratch/first.log" 2>&1 &
  watcher=$!
  for _ in $(seq 1 100); do grep -q "submitted Slurm job" "$scratch/first.log" && break; sleep 0.1; done
  kill -INT $watcher; wait $watcher; code=$?
  cat "$scratch/first.log"
  [ "$code" -eq 1 ] || fail "the stopped watch exits $code, expected 1"
  grep -q '"status": "interrupted"' "$scratch/out/sweep.json" || fail "the stopped watch's sweep.json is not interrupted"
  [ "$(jobs_submitted)" -ge 1 ] || fail "stopping the watch took the tasks out of Slurm"
  "$iwb" sweep "$scratch/one.toml" -o "$scratch/out" --executor slurm --poll 1 >"$scratch/second.log" 2>&1 ||
    { cat "$scratch/second.log"; fail "the second watch failed"; }
  cat "$scratch/second.log"
  grep -q "submitted Slurm job" "$scratch/second.log" && fail "the second watch submitted again"
  /usr/bin/python3 - "$scratch/out/sweep.json" <<'EOF' || fail "the second watch did not adopt the tasks"
import json, sys
d = json.load(open(sys.argv[1]))
assert d["status"] == "complete" and len(d["slurm"]["submissions"]) == 1, d["slurm"]
starts = [j["start"] for j in d["jobs"]]
assert set(starts) <= {"adopted", "reused"} and "adopted" in starts, starts
EOF
  ;;
refused)
  before=$(jobs_submitted)
  expect_refused() {  # REGEX ARGS...: exit 2, the message, nothing written, nothing queued
    local regex=$1 out=$scratch/refused-$RANDOM
    shift
    msg=$(env "${client_path:-PATH=$PATH}" "$iwb" sweep data/sweeps/tiny.toml -o "$out" --executor slurm "$@" 2>&1); code=$?
    echo "$msg"
    [ "$code" -eq 2 ] || fail "$*: exit $code, expected 2"
    grep -Eq -- "$regex" <<<"$msg" || fail "$*: the message does not match '$regex'"
    [ ! -e "$out" ] || fail "$*: $out was written"
    [ "$(jobs_submitted)" -eq "$before" ] || fail "$*: something was queued"
  }
  expect_refused "sbatch --test-only refuses the campaign's script: .*[Pp]artition" --partition no_such_partition
  expect_refused "--time '2-25': not one of Slurm's --time formats" --time 2-25
  expect_refused "--mem '4 GB': not a Slurm memory size" --mem "4 GB"
  client_path=PATH=/nonexistent expect_refused "--executor slurm: no sbatch on this machine's PATH"
  expect_refused "--stop-after is for a local run" --stop-after 1
  msg=$("$iwb" sweep data/sweeps/tiny.toml -o "$scratch/local-partition" --partition x 2>&1); code=$?
  [ "$code" -eq 2 ] && grep -q -- "--partition is a Slurm option: it needs --executor slurm" <<<"$msg" ||
    fail "--partition without Slurm: exit $code: $msg"
  ;;
*) fail "unknown case" ;;
esac
echo "slurm_sweep.sh $case: ok"
