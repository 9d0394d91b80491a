"""Is the cyclic response converged in the inertial number? (README.md here, "Is the cyclic
response converged"): one cell and seed sheared at several inertial numbers from one consolidated
specimen, side by side per cycle ("a / b / c" in the order of the runs given), then the reversal
secants as mean +- SD over the reversals of each run, and the post-cyclic quantities. Run from the
repository root:
  /usr/bin/python3 data/cyclic/inertial_table.py data/cyclic/cyclic_inertial/runs/i0.001 \
      data/cyclic/cyclic_inertial/runs/i0.0003 data/cyclic/cyclic_inertial_fine/runs/cns-200_i0.0001"""
import json
import statistics as st
import sys
from pathlib import Path

ROWS = [("peak +tau/sigma_n", lambda c: c["peak_friction_positive"], ".3f"),
        ("peak -tau/sigma_n", lambda c: c["peak_friction_negative"], ".3f"),
        ("sigma_n / sigma_n0", lambda c: c["sigma_n_ratio"], ".3f"),
        ("u_n end (mm)", lambda c: c["u_n_end_mm"], ".3f"),
        ("loop energy (J/m^2)", lambda c: c["dissipated_energy_J_m2"], ".1f"),
        ("secant 10 % of A at +A (kPa/mm)", lambda c: c["reversal_at_plus"]["secant_10_kPa_per_mm"], ".0f"),
        ("secant 50 % of A at +A (kPa/mm)", lambda c: c["reversal_at_plus"]["secant_50_kPa_per_mm"], ".0f")]


def summary(run):
    return json.loads((Path(run) / "summary.json").read_text())


def main(runs):
    if len(runs) < 2:
        sys.exit(__doc__)
    sums = [summary(r) for r in runs]
    labels = [Path(r).name for r in runs]
    cycles = [s["cyclic"]["cycles"] for s in sums]
    n = min(len(c) for c in cycles)
    print("| cycle | " + " | ".join(name for name, _, _ in ROWS) + " |")
    print("|---" * (len(ROWS) + 1) + "|")
    for i in range(n):
        cells = [" / ".join(format(get(c[i]), fmt) for c in cycles) for _, get, fmt in ROWS]
        print(f"| {i + 1} | " + " | ".join(cells) + " |")
    print(f"\nruns: {' / '.join(labels)}")
    for key in ("secant_10_kPa_per_mm", "secant_50_kPa_per_mm"):
        for side in ("reversal_at_plus", "reversal_at_minus"):
            parts = []
            for label, c in zip(labels, cycles):
                v = [x[side][key] for x in c]
                parts.append(f"{label} {st.mean(v):.0f} +- {st.stdev(v):.0f}")
            print(f"{key} {side} (mean +- SD over {n} reversals): " + ", ".join(parts))
    for key in ("peak_friction", "final_friction", "u_n_change_mm"):
        vals = [s["cyclic"].get("post_cyclic", {}).get(key) for s in sums]
        print(f"post-cyclic {key}: " + " / ".join("-" if v is None else f"{v:.3f}" for v in vals))


if __name__ == "__main__":
    main(sys.argv[1:])
