#!/usr/bin/python3
"""The newcomer's budgets (issue 60), measured, never copied by hand.

    tools/budgets/budgets.py [--build DIR] [--check] [--json FILE]
    tools/budgets/budgets.py --measure-tests [--build DIR]     # runs the README's test command
    tools/budgets/budgets.py --measure-validate [--build DIR]  # runs `iwb validate` on the default scene

Figures and where they come from:
- compiler time per unit and in all: the build log ninja keeps (BUILD/.ninja_log), the latest entry
  of every object and precompiled header; on 2 cores with -j2 each job has a core, so the sum is
  the compiler time of a fresh build;
- setup and build wall time: BUILD/budgets/setup.json, written by ./setup.sh as it runs;
- tests: BUILD/budgets/tests.json (--measure-tests), else the sum of the last ctest run's test times
  (Testing/Temporary/LastTest.log) halved for the two slots;
- validate: BUILD/budgets/validate.json (--measure-validate).

--check exits 1 when the compiler time or a unit exceeds its budget by more than the tolerance
(25 %): the test `budgets: compiler time ...` runs it on every CI build.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import time

BUDGETS = {  # seconds, issue 60
    "setup_s": 600.0,
    "build_wall_s": 300.0,
    "compiler_s": 600.0,
    "unit_s": 30.0,
    "tests_s": 360.0,
    "validate_s": 45.0,
}
TOLERANCE = 0.25  # --check fails beyond budget * (1 + TOLERANCE)
README_TEST_COMMAND = ["ctest", "--test-dir", "build", "-LE", "heavy", "-j2", "--output-on-failure"]


def ninja_units(build):
    """{output: seconds} of the latest build of each compiled unit in BUILD/.ninja_log."""
    path = os.path.join(build, ".ninja_log")
    latest = {}
    with open(path) as f:
        header = f.readline()
        if not header.startswith("# ninja log v"):
            raise SystemExit(f"{path}: not a ninja log ({header.strip()!r})")
        for line in f:
            fields = line.rstrip("\n").split("\t")
            if len(fields) < 5:
                continue
            start, end, output = int(fields[0]), int(fields[1]), fields[3]
            latest[output] = (end - start) / 1000.0
    compiled = re.compile(r"\.(o|gch|pch)$")
    return {o: s for o, s in latest.items() if compiled.search(o)}


def read_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def last_ctest_sum(build):
    path = os.path.join(build, "Testing", "Temporary", "LastTest.log")
    try:
        text = open(path, errors="replace").read()
    except OSError:
        return None
    times = [float(t) for t in re.findall(r'Test time =\s*([0-9.]+) sec', text)]
    return {"tests": len(times), "sum_s": sum(times), "wall_estimate_s": sum(times) / 2} if times else None


def figures(build):
    units = ninja_units(build)
    slowest = sorted(units.items(), key=lambda kv: -kv[1])[:10]
    f = {
        "compiler_s": round(sum(units.values()), 1),
        "units": len(units),
        "slowest_units": [{"unit": u, "s": round(s, 1)} for u, s in slowest],
        "setup": read_json(os.path.join(build, "budgets", "setup.json")),
        "tests": read_json(os.path.join(build, "budgets", "tests.json")) or last_ctest_sum(build),
        "validate": read_json(os.path.join(build, "budgets", "validate.json")),
    }
    return f


def verdict(value, budget):
    if value is None:
        return "not measured"
    if value <= budget:
        return "within"
    return "over" if value <= budget * (1 + TOLERANCE) else f"over by more than {TOLERANCE:.0%}"


def print_figures(f):
    rows = []
    setup = f["setup"] or {}
    rows.append(("setup (fresh machine)", setup.get("total_s") if setup.get("packages_installed") else None, BUDGETS["setup_s"]))
    rows.append(("build, wall (fresh build dir)", setup.get("build_s") if setup.get("fresh_build") else None, BUDGETS["build_wall_s"]))
    rows.append(("compiler time, all units", f["compiler_s"], BUDGETS["compiler_s"]))
    top = f["slowest_units"][0] if f["slowest_units"] else {"s": None, "unit": "-"}
    rows.append((f"slowest unit ({top['unit']})", top["s"], BUDGETS["unit_s"]))
    tests = f["tests"] or {}
    rows.append(("default tests, wall", tests.get("wall_s", tests.get("wall_estimate_s")), BUDGETS["tests_s"]))
    validate = f["validate"] or {}
    rows.append(("iwb validate, wall", validate.get("wall_s"), BUDGETS["validate_s"]))
    print("| budget | measured s | budget s | verdict |\n|---|---|---|---|")
    for name, value, budget in rows:
        shown = "-" if value is None else f"{value:.0f}"
        print(f"| {name} | {shown} | {budget:.0f} | {verdict(value, budget)} |")
    print("\nslowest units (s): " + ", ".join(f"{u['unit'].split('/')[-1]} {u['s']:.1f}" for u in f["slowest_units"]))
    if setup:
        print("setup phases (s): " + ", ".join(f"{k} {v:.0f}" for k, v in setup.items() if k.endswith("_s")))
    if tests:
        print("tests: " + ", ".join(f"{k} {v}" for k, v in tests.items()))


def timed(command, build, name, cwd):
    t0 = time.monotonic()
    code = subprocess.call(command, cwd=cwd)
    wall = time.monotonic() - t0
    os.makedirs(os.path.join(build, "budgets"), exist_ok=True)
    record = {"wall_s": round(wall, 1), "exit_code": code, "command": " ".join(command),
              "when": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()), "load_before": os.getloadavg()[0]}
    with open(os.path.join(build, "budgets", name), "w") as out:
        json.dump(record, out, indent=1)
    return code


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--build", default=os.path.join(os.path.dirname(__file__), "..", "..", "build"))
    p.add_argument("--check", action="store_true", help="exit 1 when compiler time or a unit is over budget by more than 25 %%")
    p.add_argument("--json", help="also write the figures to this file")
    p.add_argument("--measure-tests", action="store_true", help="run the README's test command, timed")
    p.add_argument("--measure-validate", action="store_true", help="run `iwb validate` (default scene), timed")
    a = p.parse_args()
    build = os.path.abspath(a.build)
    root = os.path.dirname(build)
    if a.measure_tests:
        command = README_TEST_COMMAND[:2] + [build] + README_TEST_COMMAND[3:]
        timed(command, build, "tests.json", root)
    if a.measure_validate:
        out = os.path.join(build, "budgets", "validate-run")
        timed([os.path.join(build, "iwb"), "validate", "--out", out, "--force"], build, "validate.json", root)
    f = figures(build)
    print_figures(f)
    if a.json:
        with open(a.json, "w") as out:
            json.dump(f, out, indent=1)
    if a.check:
        over = []
        limit = 1 + TOLERANCE
        if f["compiler_s"] > BUDGETS["compiler_s"] * limit:
            over.append(f"compiler time {f['compiler_s']:.0f} s > {BUDGETS['compiler_s'] * limit:.0f} s")
        over += [f"{u['unit']} {u['s']:.1f} s > {BUDGETS['unit_s'] * limit:.1f} s"
                 for u in f["slowest_units"] if u["s"] > BUDGETS["unit_s"] * limit]
        if over:
            print("budgets: over by more than 25 %: " + "; ".join(over), file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
