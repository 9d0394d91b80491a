#!/usr/bin/python3
"""Each default of issue 58's list written once (item 3): a rule per default, the one file that
may write it, and a pattern that finds it written elsewhere in src/. Where a pattern cannot tell a
default from another number it is not checked here (say so in the rule). Prints each repetition;
exit 1 if any.
    tools/house/defaults.py [SRC]"""
import os
import re
import sys

RULES = [
    # (what, the one file, where else it must not be written (a path prefix of src/), the pattern)
    ("the default interface model", "models/registry.hpp", "",
     re.compile(r'(=\s*|default\w*\(\s*|value\(\s*)"hvwe"')),
    ("the particle cap 1e8", "dem/scene/scene_keys.hpp", "",
     re.compile(r"(?i)particle.*\b1e8\b|\b1e8\b.*particle")),
    ("the ramp's 4 transits", "dem/scene/shear_start.hpp", "",
     re.compile(r"(?i)(ramp\w*\s*=\s*4(\.0)?\b|\b4(\.0)? (round trips|transits))")),
    # other kappa_r = 1.0 are other defaults (a model's Roughness, a study's case): the pile's own
    ("the pile's kappa_r 1.0", "pile/pile_spec.hpp", "pile/", re.compile(r"kappa_r\s*=\s*1\.0\b")),
    ("the comparison's default tolerances", "comparison/replay/quantities.cpp", "",
     re.compile(r"10, 5, 30|else 10, |\b10 %, 5 %, 30 %")),
    ("the cyclic default tolerances", "comparison/verdicts/cyclic_verdicts.cpp", "",
     re.compile(r"10, 10, 20, 30|\"cycle_peak_friction\",\s*0\.")),
]


def main():
    src = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..", "src")
    found = []
    for d, _, files in os.walk(src):
        for f in files:
            if not f.endswith((".cpp", ".hpp")):
                continue
            path = os.path.join(d, f)
            rel = os.path.relpath(path, src)
            for n, line in enumerate(open(path, encoding="utf-8"), 1):
                if line.lstrip().startswith("//"):
                    continue
                for what, home, scope, pattern in RULES:
                    if rel != home and rel.startswith(scope) and pattern.search(line):
                        found.append(f"{rel}:{n}: {what} written again (its one place: {home}): {line.strip()}")
    for f in found:
        print(f)
    print(f"defaults: {len(found)} written twice")
    return 1 if found else 0


if __name__ == "__main__":
    raise SystemExit(main())
