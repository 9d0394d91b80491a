#!/usr/bin/python3
"""Holds a caller of the C interface against `iwb element` (tests/c_api): runs the element test
TOML into a temporary directory, runs the caller, and compares its lines "gamma,sigma_n,tau" with
history.csv's rows, largest difference relative to the largest stress.
Usage: compare_with_element.py IWB TOML RTOL CALLER [ARGS...]"""
import csv, subprocess, sys, tempfile


def element_history(iwb, toml):
    with tempfile.TemporaryDirectory() as out:
        subprocess.run([iwb, "element", toml, "-o", out + "/run"], check=True, capture_output=True)
        with open(out + "/run/history.csv") as f:
            rows = list(csv.DictReader(f))
    return [(float(r["gamma_x"]), float(r["sigma_n_kPa"]), float(r["tau_x_kPa"])) for r in rows[1:]]


def main():
    iwb, toml, rtol, caller = sys.argv[1], sys.argv[2], float(sys.argv[3]), sys.argv[4:]
    expected = element_history(iwb, toml)
    run = subprocess.run(caller, check=True, capture_output=True, text=True)
    got = [tuple(float(x) for x in line.split(",")) for line in run.stdout.splitlines() if line.strip()]
    if len(got) != len(expected):
        sys.exit(f"{len(got)} increments from the caller, {len(expected)} from iwb element")
    scale = max(abs(v) for row in expected for v in row[1:])
    worst = max(abs(a - b) for g, e in zip(got, expected) for a, b in zip(g, e)) / scale
    print(f"{caller[0]}: {len(got)} increments, largest difference {worst:.2e} of {scale:.4g} kPa (allowed {rtol:g})")
    sys.exit(0 if worst <= rtol else 1)


main()
