#!/usr/bin/env bash
# The campaigns still running (issues 34 and 36) as lanes: one resumable chain of sweeps each
# (data/run_campaign.sh), committing every completed run's compact files, so that a session on a
# fresh machine restarts all of them with one command after ./setup.sh. From the repository root:
#   data/lanes.sh start [LANE...]   copy build/iwb to runs/bin-iwb-<its sha256> (a rebuild must not
#                          change the binary under a running campaign) and start the lanes named
#                          (default: every lane) that are not running; each runs one DEM job at a
#                          time, or JOBS at once (JOBS=2 data/lanes.sh start cyclic: the last lane
#                          left takes both cores)
#   data/lanes.sh status   each lane's last progress line (its sweep, and each running job's
#                          stage, how far and ETA)
#   data/lanes.sh pause    stop the lanes' processes (SIGSTOP), e.g. to time the test suite idle
#   data/lanes.sh resume   continue them (SIGCONT)
#   data/lanes.sh stop [LANE...]    stop lanes cleanly: each sweep as by Ctrl-C (a LIGGGHTS shear
#                          stage keeps its last checkpoint, so `start` on this machine resumes it),
#                          then copy and commit what completed
# Each lane runs in its own process group (runs/lanes/<lane>.pgid), logs to runs/lanes/<lane>.log.
# The lanes, each in order of value (a sweep already complete is restored and costs nothing):
#   cyclic   nice 19  data/cyclic/make.sh: the virgin CNS peaks, the medium-dense cell, K 50, the
#                     flat small amplitude, the check at I 1e-4, flat CV (data/cyclic/README.md)
#   grains   nice 19  C_u 2.2 at R_n 0.5, the deeper clamp, twice the travel (data/grains/README.md)
#   grading  nice 5   C_u 3.2 at R_n 0.5 (the third grading; ~50 min a run: it gets a core of its
#                     own), the rest of the densities, then C_u 3.2 at R_n 0.25
set -euo pipefail
cd "$(dirname "$0")/.."
ALL_LANES=(cyclic grains grading)
DIR=runs/lanes
command=${1:-}
[ $# -gt 0 ] && shift
LANES=("$@")
[ ${#LANES[@]} -eq 0 ] && LANES=("${ALL_LANES[@]}")
for lane in "${LANES[@]}"; do
  case " ${ALL_LANES[*]} " in
    *" $lane "*) ;;
    *) echo "lanes: unknown lane '$lane'; lanes: ${ALL_LANES[*]}" >&2; exit 2 ;;
  esac
done

lane_command() {  # the environment and command of a lane
  case $1 in
    cyclic) echo "SWEEPS='cyclic_virgin cyclic_medium cyclic_k50 cyclic_flat_small cyclic_inertial_fine cyclic_flat_cv' data/cyclic/make.sh" ;;
    grains) echo "DEST=data/grains SWEEPS='grains_cu2 clamp_depth truth_travel20' data/run_campaign.sh" ;;
    grading) echo "DEST=data/grains SWEEPS='grains_cu3 density grains_cu3_rn025' data/run_campaign.sh" ;;
  esac
}

lane_nice() { [ "$1" = grading ] && echo 5 || echo 19; }

running() {  # the lane's process group still has a live process (not a zombie being reaped)
  local f=$DIR/$1.pgid
  [ -f "$f" ] && pgrep -g "$(cat "$f")" -r R,S,D,T >/dev/null 2>&1
}

start() {
  [ -x build/iwb ] || { echo "lanes: build/iwb missing: run ./setup.sh first" >&2; exit 2; }
  mkdir -p "$DIR"
  # named by its content: lanes started from one build share it, whatever was committed since
  local bin
  bin=$PWD/runs/bin-iwb-$(sha256sum build/iwb | cut -c1-12)
  [ -x "$bin" ] || cp build/iwb "$bin"
  for lane in "${LANES[@]}"; do
    if running "$lane"; then
      echo "lanes: $lane is running (process group $(cat "$DIR/$lane.pgid")): left alone"
      continue
    fi
    local cmd
    cmd="COMMIT=1 IWB=$bin JOBS=${JOBS:-1} NP=1 $(lane_command "$lane")"
    # setsid: the lane's own process group, so that stop reaches its sweeps and nothing else
    setsid nice -n "$(lane_nice "$lane")" bash -c "echo \$\$ > $DIR/$lane.pgid; exec env $cmd" \
      >> "$DIR/$lane.log" 2>&1 < /dev/null &
    sleep 1
    echo "lanes: $lane started (nice $(lane_nice "$lane"), process group $(cat "$DIR/$lane.pgid")): $cmd"
  done
}

status() {
  for lane in "${LANES[@]}"; do
    local state=stopped
    running "$lane" && state=running
    local last=""
    [ -f "$DIR/$lane.log" ] && last=$(grep -a "sweep:" "$DIR/$lane.log" | tail -n 1 || true)
    echo "$lane ($state): ${last:-no progress yet}"
  done
}

signal_all() {  # signal every process of every running lane
  for lane in "${LANES[@]}"; do
    running "$lane" && kill "-$1" -- "-$(cat "$DIR/$lane.pgid")"
  done
  return 0
}

stop() {
  for lane in "${LANES[@]}"; do
    running "$lane" || continue
    local group
    group=$(cat "$DIR/$lane.pgid")
    kill -CONT -- "-$group" 2>/dev/null || true  # a paused lane cannot stop
    # the chain's shells first, so that no next sweep starts; then each sweep as by Ctrl-C
    pkill -TERM -g "$group" -x bash || true
    pkill -INT -g "$group" -f " sweep " || true
    echo "lanes: $lane stopping (its sweeps write their state and stop their runs)"
    for _ in $(seq 120); do pgrep -g "$group" -f " sweep " >/dev/null || break; sleep 1; done
    pgrep -g "$group" -f " sweep " >/dev/null && echo "lanes: $lane's sweep still runs after 2 min" >&2
    kill -TERM -- "-$group" 2>/dev/null || true  # what is left: the copy loop's sleep
    for _ in $(seq 10); do running "$lane" || break; sleep 1; done
    # what completed since the lane's last copy (every 2 min) is committed now
    env COMMIT=1 bash -c "$(lane_command "$lane") copy" >> "$DIR/$lane.log" 2>&1 || true
  done
}

case $command in
  start) start ;;
  status) status ;;
  pause) signal_all STOP ;;
  resume) signal_all CONT ;;
  stop) stop ;;
  -h | --help) sed -n '2,/^[^#]/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//' ;;
  *) echo "lanes: unknown command '$command'; commands: start, status, pause, resume, stop (--help)" >&2; exit 2 ;;
esac
