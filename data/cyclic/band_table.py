"""The band's void ratio over the cycles (issue 34, item 2; README.md here, "Does the band contract
and dilate with every reversal?"): from each run's coarse-grained snapshots (fields/band.csv,
e_band_cg: the void ratio averaged over the wall band, one snapshot a quarter cycle: at +A, 0, -A,
0), per cycle and seed the dilation towards each reversal (e at +A and at -A less e at the 0 before
it), and the cycle's end less the start (compaction when negative); means over the seeds +- the
95 % Student-t half-width. Run from the repository root:
  /usr/bin/python3 data/cyclic/band_table.py data/cyclic/cyclic_rn05/runs/cnl_s* [--cycles 1,2,5,10]"""
import csv
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))  # cycle_table.py beside this file
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # data/seed_stats.py
import seed_stats  # noqa: E402
from cycle_table import cycles_option  # noqa: E402


def interval(values):
    return seed_stats.interval(values, "+.4f")


def per_cycle(run, cycles):
    """(towards +A, towards -A, end less start) per cycle of one run's snapshots."""
    rows = list(csv.DictReader(open(f"{run}/fields/band.csv")))
    e = [float(r["e_band_cg"]) for r in rows]
    out = {}
    for c in cycles:
        k = 4 * (c - 1)  # the snapshot at the cycle's start (u_x = 0)
        if k + 4 < len(e):
            out[c] = (e[k + 1] - e[k], e[k + 3] - e[k + 2], e[k + 4] - e[0])
    return out


def main(args):
    cycles, args = cycles_option(args)
    runs = [per_cycle(r, cycles) for r in args]
    print(f"{len(runs)} runs: " + ", ".join(args) + "\n")
    print("| cycle | e at +A less e at 0 | e at -A less e at 0 | e at the cycle's end less e0 |")
    print("|---|---|---|---|")
    for c in cycles:
        got = [r[c] for r in runs if c in r]
        if got:
            print(f"| {c} | " + " | ".join(interval([g[i] for g in got]) for i in range(3)) + " |")


main(sys.argv[1:])
