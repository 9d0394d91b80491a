#!/usr/bin/python3
"""A run's walk through the house (issue 58): which rooms (src/ folders) the main thread passes
through while `iwb validate` runs, how long it stays in each and how often it climbs back up.

    tools/house/walk/walk.py REV WORK      # builds REV's iwb instrumented in WORK, runs, measures
    tools/house/walk/walk.py --measure WORK

How it is measured:
- REV is checked out in WORK/src (a git worktree) and its iwb built with clang,
  -finstrument-functions-after-inlining, frame pointers and line tables, linked with walk_hook.c,
  the orchestration at -O1 instead of -O0 (clang instruments after inlining only where its inliner
  runs), setup.sh's configuration otherwise (a few minutes on 2 cores). A function inlined into
  its caller is not a step of the walk.
- Every function of the executable whose first line lies under src/ is followed (nm, addr2line);
  library code is transparent. The hook writes the main thread's first-visit walk: a call is
  walked the first time its edge (caller, callee) is taken, so that a loop counts once and the
  walk is the code's shape, not the run's length (TBB's worker threads are not followed).
- The walk moves into the callee's room on a call and back into the caller's on a return. A stay
  is a maximal stretch in one room; a climb is a move to a room on a higher floor, a room's floor
  being 1 + the highest floor of the rooms it includes (read from REV's own includes). Rooms are
  src/'s top folders (src/dem/scene counts as dem), the same for any revision; entries of a file
  count the moves into it from another file.
Prints the figures and writes WORK/walk.json."""
import collections
import json
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
FLAGS = "-finstrument-functions-after-inlining -fno-omit-frame-pointer -g1"
INCLUDE = re.compile(r'#include "([^"/]+)/[^"]+"')
WATCHED_FILE = "io/run_directory.cpp"


def sh(cmd, **kw):
    print("+", " ".join(cmd), file=sys.stderr)
    subprocess.run(cmd, check=True, **kw)


def build(rev, work):
    src, bld = os.path.join(work, "src"), os.path.join(work, "build")
    if not os.path.isdir(src):
        sh(["git", "-C", REPO, "worktree", "add", "--detach", src, rev])
    hook = os.path.join(work, "walk_hook.o")
    sh(["clang", "-c", "-O2", "-fPIC", "-fno-omit-frame-pointer", "-Wno-frame-address",
        os.path.join(HERE, "walk_hook.c"), "-o", hook])
    sh(["cmake", "-S", src, "-B", bld, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
        "-DCMAKE_CXX_COMPILER=clang++", "-DCMAKE_C_COMPILER=clang", f"-DCMAKE_CXX_FLAGS={FLAGS}",
        # clang instruments after inlining only where its inliner runs: not at -O0
        "-DIWB_ORCHESTRATION_OPT=-O1",
        f"-DCMAKE_EXE_LINKER_FLAGS={hook} -ldl"], stdout=subprocess.DEVNULL)
    sh(["cmake", "--build", bld, "--target", "iwb", "-j2"], stdout=subprocess.DEVNULL)


def function_map(work):
    """{address: file under src/} for the executable's functions, and writes the hook's map."""
    exe = os.path.join(work, "build", "iwb")
    src = os.path.realpath(os.path.join(work, "src", "src")) + "/"
    nm = subprocess.run(["nm", "--defined-only", exe], check=True, capture_output=True, text=True).stdout
    addrs = sorted({int(a, 16) for a, kind, *_ in (l.split() for l in nm.splitlines() if len(l.split()) >= 3)
                    if kind in "tTwW"})
    lines = subprocess.run(["addr2line", "-e", exe], input="\n".join(f"{a:x}" for a in addrs),
                           check=True, capture_output=True, text=True).stdout.splitlines()
    files, out = [], []
    for a, where in zip(addrs, lines):
        path = os.path.realpath(where.rsplit(":", 1)[0]) if where.startswith("/") else ""
        if path.startswith(src):
            rel = path[len(src):]
            if rel not in files:
                files.append(rel)
            out.append(f"{a:x} {files.index(rel)}")
    with open(os.path.join(work, "walk_map.txt"), "w") as f:
        f.write("\n".join(out) + "\n")
    return files


def run(work):
    files = function_map(work)
    env = dict(os.environ, IWB_WALK_MAP=os.path.join(work, "walk_map.txt"),
               IWB_WALK_OUT=os.path.join(work, "walk.txt"))
    sh([os.path.join(work, "build", "iwb"), "validate", "--out", os.path.join(work, "validate-run"),
        "--force"], env=env, cwd=os.path.join(work, "src"), stdout=subprocess.DEVNULL)
    json.dump(files, open(os.path.join(work, "walk_files.json"), "w"))


def floors(src):
    """{room: floor} from the rooms' includes: 1 + the highest floor below it."""
    reads = collections.defaultdict(set)
    for d, _, names in os.walk(src):
        room = os.path.relpath(d, src).split(os.sep)[0]
        for n in names:
            if n.endswith((".cpp", ".hpp")):
                for m in INCLUDE.finditer(open(os.path.join(d, n), encoding="utf-8").read()):
                    if m.group(1) != room and os.path.isdir(os.path.join(src, m.group(1))):
                        reads[room].add(m.group(1))
    floor = {}

    def of(room, seen=()):
        if room not in floor:
            below = [of(r, seen + (room,)) for r in reads[room] if r not in seen]
            floor[room] = 1 + max(below, default=0)
        return floor[room]
    for r in list(reads):
        of(r)
    return floor


def measure(work):
    files = json.load(open(os.path.join(work, "walk_files.json")))
    floor = floors(os.path.join(work, "src", "src"))
    stack, path = [], []
    for line in open(os.path.join(work, "walk.txt")):
        kind, fid = line.split()
        if kind == "E":
            stack.append(int(fid))
        elif stack:
            stack.pop()
        if stack:
            path.append(files[stack[-1]])
    rooms = [p.split("/")[0] for p in path]
    stays = [r for k, r in enumerate(rooms) if k == 0 or r != rooms[k - 1]]
    climbs = sum(1 for a, b in zip(stays, stays[1:]) if floor.get(b, 0) > floor.get(a, 0))
    entries = sum(1 for k, p in enumerate(path) if p == WATCHED_FILE and (k == 0 or path[k - 1] != p))
    result = {"rooms": len(set(rooms)), "stays": len(stays), "climbs": climbs,
              f"entries of {WATCHED_FILE}": entries, "moves": len(path),
              "stays_per_room": collections.Counter(stays).most_common()}
    json.dump(result, open(os.path.join(work, "walk.json"), "w"), indent=1)
    print(f"{work}: {result['rooms']} rooms, {result['stays']} stays, {climbs} climbs back up, "
          f"{WATCHED_FILE} entered {entries} times ({len(path)} moves)")
    print("  stays per room: " + ", ".join(f"{r} {n}" for r, n in result["stays_per_room"]))
    return result


def main():
    if len(sys.argv) == 3 and sys.argv[1] == "--measure":
        measure(os.path.abspath(sys.argv[2]))
    elif len(sys.argv) == 3:
        work = os.path.abspath(sys.argv[2])
        os.makedirs(work, exist_ok=True)
        build(sys.argv[1], work)
        run(work)
        measure(work)
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
