#!/usr/bin/python3
"""The house's floors (issue 58), checked from the includes: within src/dem and src/comparison no
unit (a .hpp with its .cpp) includes one that includes it back, and each folder's sublayers read
only those below them: src/dem scene < engines, analysis < run < soil_cells (engines and analysis
apart); src/comparison replay < verdicts < compare, presentation < causes (compare and
presentation apart).
Prints each violation; exit 1 if any.
    tools/house/layers.py [SRC]"""
import collections
import os
import re
import sys

LAYERS = {
    "dem": {"scene": 0, "engines": 1, "analysis": 1, "run": 2, "soil_cells": 3},
    "comparison": {"replay": 0, "verdicts": 1, "compare": 2, "presentation": 2, "causes": 3},
}
INCLUDE = re.compile(r'#include "([^"]+)"')


def units(src):
    """{unit: set of units it includes}, a unit being a path under src without its extension."""
    out = collections.defaultdict(set)
    for d, _, files in os.walk(src):
        for f in files:
            if f.endswith((".cpp", ".hpp")):
                path = os.path.join(d, f)
                me = os.path.splitext(os.path.relpath(path, src))[0]
                for m in INCLUDE.finditer(open(path, encoding="utf-8").read()):
                    out[me].add(os.path.splitext(m.group(1))[0])
    return out


def violations(src):
    graph = units(src)
    found = []
    for a in sorted(graph):
        if not a.startswith(("dem/", "comparison/")):
            continue
        for b in sorted(graph[a]):
            if b != a and a < b and a in graph.get(b, ()):
                found.append(f"{a} and {b} include each other")
        top = a.split("/")[0]
        layers = LAYERS[top]
        mine = a.split("/")[1]
        for b in graph[a]:
            if not b.startswith(top + "/"):
                continue
            theirs = b.split("/")[1]
            if theirs not in layers or mine not in layers:
                found.append(f"{a} -> {b}: outside src/{top}'s sublayers {sorted(layers)}")
            elif theirs != mine and layers[theirs] >= layers[mine]:
                found.append(f"{a} -> {b}: {mine} may not read {theirs}")
    return found


def main():
    src = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..", "src")
    found = violations(src)
    for v in found:
        print(v)
    print(f"layers: {len(found)} violation(s)")
    return 1 if found else 0


if __name__ == "__main__":
    raise SystemExit(main())
