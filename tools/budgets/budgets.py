#!/usr/bin/python3
"""The newcomer's budgets (issue 60), measured, never copied by hand.

    tools/budgets/budgets.py [--build DIR] [--check] [--json FILE]
    tools/budgets/budgets.py --measure-tests [--build DIR]     # runs the README's test command
    tools/budgets/budgets.py --measure-validate [--build DIR]  # runs `iwb validate` on the default scene
    tools/budgets/budgets.py --json data/budgets/latest.json    # record the figures (commit it)
    tools/budgets/budgets.py --from data/budgets/latest.json --write-readme README.md
    tools/budgets/budgets.py --from data/budgets/latest.json --check-readme README.md

Figures and where they come from:
- compiler time per unit and in all: the build log ninja keeps (BUILD/.ninja_log), the latest entry
  of every object and precompiled header; on 2 cores with ninja's -j2 each job has a core, so the sum is
  the compiler time of a fresh build;
- setup and build wall time: BUILD/budgets/setup.json, written by ./setup.sh as it runs;
- tests: BUILD/budgets/tests.json (--measure-tests), else the sum of the last ctest run's test times
  (Testing/Temporary/LastTest.log) halved for the two slots;
- validate: BUILD/budgets/validate.json (--measure-validate).

--check exits 1 when the compiler time or a unit exceeds its budget by more than the tolerance
(25 %): the test `budgets: compiler time ...` runs it on every CI build. The README's budget table
(between its "BEGIN budgets" and "END budgets" lines) is rendered from the committed record
data/budgets/latest.json, and --check-readme (a test) fails when it quotes other figures.
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


def readme_test_command(root):
    """The README's test command (its one line that starts `ctest --test-dir build`), as words:
    the figure is of the command a user runs, read where it is written, not copied here."""
    with open(os.path.join(root, "README.md"), encoding="utf-8") as f:
        for line in f:
            if line.startswith("ctest --test-dir build "):
                return line.split()
    raise SystemExit("README.md: no line starting 'ctest --test-dir build '")


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
    setup = read_json(os.path.join(build, "budgets", "setup.json"))
    f = {
        "when": time.strftime("%Y-%m-%d", time.gmtime()),
        "machine": f"{os.cpu_count()} cores, {os.uname().machine}",
        "compiler_s": round(sum(units.values()), 1),
        "units": len(units),
        "slowest_units": [{"unit": unit_name(u), "s": round(s, 1)} for u, s in slowest],
        "setup": setup,
        # this machine's own fresh build, kept apart from a fresh machine's setup (--setup-from)
        "build_wall_s": setup.get("build_s") if setup and setup.get("fresh_build") else None,
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


def unit_name(output):
    """build/src/CMakeFiles/iwb_dem.dir/Unity/unity_0_cxx.cxx.o -> iwb_dem batch 0; a model's file
    -> its source path; the tests' folder batches -> tests/<folder>."""
    m = re.search(r"CMakeFiles/([^/]+)\.dir/(.*)$", output)
    if not m:
        return output
    target, rest = m.groups()
    rest = re.sub(r"\.(o|gch|pch)$", "", rest)
    if "Unity/unity_" in rest:
        batch = rest.split("Unity/unity_", 1)[1]
        folder = re.search(r"(tests/.*)_cxx\.cxx$", batch)
        return folder.group(1) if folder else f"{target} batch {batch.replace('_cxx.cxx', '')}"
    return f"{target} {rest}"


def rows_of(f):
    setup = f.get("setup") or {}
    tests = f.get("tests") or {}
    validate = f.get("validate") or {}
    top = f["slowest_units"][0] if f["slowest_units"] else {"s": None, "unit": "-"}
    return [
        ("`./setup.sh` on a fresh machine", setup.get("total_s") if setup.get("packages_installed") else None, BUDGETS["setup_s"]),
        ("the build, wall (fresh build directory)",
         f.get("build_wall_s", setup.get("build_s") if setup.get("fresh_build") else None), BUDGETS["build_wall_s"]),
        ("the build, compiler time of all units", f["compiler_s"], BUDGETS["compiler_s"]),
        (f"the slowest unit (`{top['unit']}`)", top["s"], BUDGETS["unit_s"]),
        ("the README's tests, wall", tests.get("wall_s", tests.get("wall_estimate_s")), BUDGETS["tests_s"]),
        ("`iwb validate`, wall", validate.get("wall_s"), BUDGETS["validate_s"]),
    ]


def render(f):
    lines = ["| budget | measured | budget | verdict |", "|---|---|---|---|"]
    for name, value, budget in rows_of(f):
        shown = "not measured" if value is None else f"{value:.0f} s"
        lines.append(f"| {name} | {shown} | {budget:.0f} s | {verdict(value, budget)} |")
    lines.append("")
    lines.append(f"Measured {f.get('when', '?')} on {f.get('machine', '?')}; slowest units: "
                 + ", ".join(f"`{u['unit']}` {u['s']:.1f} s" for u in f["slowest_units"][:5]) + ".")
    tests = f.get("tests") or {}
    if tests:
        lines.append("The tests' run: " + ", ".join(f"{k} {tests[k]}" for k in ("wall_s", "when", "tests", "sum_s") if k in tests)
                     + " (the record's `tests` holds its exit code and the load it started at).")
    setup = f.get("setup") or {}
    if setup:
        lines.append("Setup phases: " + ", ".join(f"{k[:-2]} {v:.0f} s" for k, v in setup.items() if k.endswith("_s"))
                     + (f" (from `{setup['record']}`)" if "record" in setup else "") + ".")
    return "\n".join(lines) + "\n"


BEGIN, END = "<!-- BEGIN budgets: tools/budgets/budgets.py --write-readme -->", "<!-- END budgets -->"


def readme_block(path):
    text = open(path).read()
    if BEGIN not in text or END not in text:
        raise SystemExit(f"{path}: no budget block ({BEGIN} ... {END})")
    head, rest = text.split(BEGIN, 1)
    block, tail = rest.split(END, 1)
    return head, block, tail


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
    p.add_argument("--from", dest="from_json", help="read the figures from this record instead of the build")
    p.add_argument("--setup-from", help="take the setup's phases from this record: a fresh machine's "
                   "(setup.sh in a debootstrap'd Debian chroot, data/budgets/fresh_machine.json)")
    p.add_argument("--write-readme", help="rewrite this README's budget block from the figures")
    p.add_argument("--check-readme", help="exit 1 unless this README's budget block shows the figures")
    a = p.parse_args()
    build = os.path.abspath(a.build)
    root = os.path.dirname(build)
    if a.measure_tests:
        words = readme_test_command(os.path.dirname(os.path.abspath(__file__)) + "/../..")
        command = words[:2] + [build] + words[3:]
        timed(command, build, "tests.json", root)
    if a.measure_validate:
        out = os.path.join(build, "budgets", "validate-run")
        timed([os.path.join(build, "iwb"), "validate", "--out", out, "--force"], build, "validate.json", root)
    if a.from_json:
        f = read_json(a.from_json)
        if f is None:
            raise SystemExit(f"{a.from_json}: not a budget record")
    else:
        f = figures(build)
    if a.setup_from:
        fresh = read_json(a.setup_from)
        if fresh is None or not (fresh.get("setup") or {}).get("packages_installed"):
            raise SystemExit(f"{a.setup_from}: not a budget record of a setup that installed its packages")
        f["setup"] = dict(fresh["setup"], record=a.setup_from)
    table = render(f)
    print(table)
    if a.json:
        with open(a.json, "w") as out:
            json.dump(f, out, indent=1)
            out.write("\n")
    if a.write_readme:
        head, _, tail = readme_block(a.write_readme)
        with open(a.write_readme, "w") as out:
            out.write(head + BEGIN + "\n" + table + END + tail)
    if a.check_readme:
        _, block, _ = readme_block(a.check_readme)
        if block.strip() != table.strip():
            print(f"{a.check_readme}: the budget table is not the record's; run --write-readme", file=sys.stderr)
            return 1
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
