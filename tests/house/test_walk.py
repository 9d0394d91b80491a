#!/usr/bin/python3
"""tools/house/walk/walk.py's measure on a walk worked out by hand (issue 58).

A house of three rooms, io (floor 1), comparison (reads io: floor 2) and app (reads comparison:
floor 3). The walk, cut off before its end (a run stopped): app/main.cpp calls
comparison/compare.cpp, which calls io/run_directory.cpp, returns from it and calls it again.
Moves (the innermost function's file after each event): app, comparison, io, comparison, io.
Stays: 5; climbs to a higher floor: io -> comparison = 1 (the three other moves go down);
io/run_directory.cpp entered twice."""
import json
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "house", "walk"))
import walk  # noqa: E402

with tempfile.TemporaryDirectory() as work:
    src = os.path.join(work, "src", "src")
    for room, reads in (("io", None), ("comparison", "io"), ("app", "comparison")):
        os.makedirs(os.path.join(src, room))
        with open(os.path.join(src, room, "x.cpp"), "w") as f:
            f.write(f'#include "{reads}/y.hpp"\n' if reads else "\n")
    files = ["app/main.cpp", "comparison/compare.cpp", "io/run_directory.cpp"]
    json.dump(files, open(os.path.join(work, "walk_files.json"), "w"))
    open(os.path.join(work, "walk.txt"), "w").write("E 0\nE 1\nE 2\nX 2\nE 2\n")
    r = walk.measure(work)
    expected = {"rooms": 3, "stays": 5, "climbs": 1, "entries of io/run_directory.cpp": 2, "moves": 5}
    got = {k: r[k] for k in expected}
    if got != expected:
        sys.exit(f"measured {got}, worked out by hand {expected}")
