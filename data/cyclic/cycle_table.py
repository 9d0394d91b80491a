"""Per-cycle means over the seeds of a cyclic cell, with the 95 % Student-t half-width (README.md
here): peak tau/sigma_n towards +A and -A, sigma_n / sigma_n0 and u_n at the cycle's end, the loop's
dissipated energy and the reversal secants, at the cycles given, then the post-cyclic peak and u_n
change. The same for the shaft of a pile cycled in settlement (data/piles/cyclic/). Run from the
repository root:
  /usr/bin/python3 data/cyclic/cycle_table.py data/cyclic/cyclic_small/runs/cns-200_s* [--cycles 1,2,5,10,20]"""
import json
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # data/seed_stats.py
import seed_stats  # noqa: E402


def interval(values):
    return seed_stats.interval(values, ".3g", ".2g")


ROWS = [("peak +tau/sigma_n", lambda c: c["peak_friction_positive"]),
        ("peak -tau/sigma_n", lambda c: c["peak_friction_negative"]),
        ("sigma_n / sigma_n0 at the cycle's end", lambda c: c["sigma_n_ratio"]),
        ("u_n at the cycle's end (mm)", lambda c: c["u_n_end_mm"]),
        ("loop energy (J/m^2)", lambda c: c["dissipated_energy_J_m2"]),
        ("reversal secant over 50 % of A at +A (kPa/mm)", lambda c: c["reversal_at_plus"]["secant_50_kPa_per_mm"]),
        ("tau at +A (kPa; a pile's shaft friction)", lambda c: c["reversal_at_plus"]["tau_kPa"])]


def cycles_option(args, default=(1, 2, 5, 10, 20)):
    """The cycles of `--cycles 1,2,5` (else `default`), and the arguments without the option."""
    if "--cycles" not in args:
        return list(default), args
    i = args.index("--cycles")
    return [int(x) for x in args[i + 1].split(",")], args[:i] + args[i + 2:]


def main(args):
    cycles, args = cycles_option(args)
    # a DEM run's summary has them under "cyclic", a pile's (iwb pile, cyclic_settlement) "cycles"
    runs = [(lambda s: s.get("cyclic") or s["cycles"])(json.load(open(f"{d}/summary.json"))) for d in args]
    print(f"{len(runs)} runs: " + ", ".join(args) + "\n")
    print("| quantity | " + " | ".join(f"cycle {k}" for k in cycles) + " |")
    print("|---|" + "---|" * len(cycles))
    for name, get in ROWS:
        cells = []
        for k in cycles:
            vals = [get(r["cycles"][k - 1]) for r in runs if len(r["cycles"]) >= k]
            cells.append(interval(vals) if vals else "-")
        print(f"| {name} | " + " | ".join(cells) + " |")
    post = [r["post_cyclic"] for r in runs if r.get("post_cyclic")]
    if post:
        keys = [k for k in post[0] if isinstance(post[0][k], (int, float))]
        print("\nAfter the cycles: " + "; ".join(f"{k} {interval([p[k] for p in post])}" for k in keys))


if __name__ == "__main__":
    main(sys.argv[1:])
