#!/usr/bin/python3
"""The head settlement at the mean load after each cycle of the cyclic runs (ratcheting):
cycle, hvwe, hvwe-igs (mm). Usage: ratcheting.py RUNS_DIR"""
import csv, sys, tomllib

runs = sys.argv[1]


def settlements(name):
    with open(f"{runs}/{name}/pile.toml", "rb") as f:
        q = tomllib.load(f)["loading"]["increments_per_quarter"]
    with open(f"{runs}/{name}/load_settlement.csv") as f:
        rows = list(csv.DictReader(f))
    # the ramp to the mean takes q steps, each cycle 4 q
    return [float(rows[q + 4 * q * c]["head_settlement_mm"]) for c in range((len(rows) - 1 - q) // (4 * q) + 1)]


a, b = settlements("hvwe_cyclic"), settlements("hvwe_igs_cyclic")
print("cycle,hvwe_mm,hvwe_igs_mm")
for c, (x, y) in enumerate(zip(a, b)):
    print(f"{c},{x},{y}")
