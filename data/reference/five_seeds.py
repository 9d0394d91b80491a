"""Issue 36: the headline cells (R_n 0.5, CNL 50 kPa and CNS K = 50 kPa/mm) with seeds 4 and 5
(truth2_seeds45/) beside seeds 1-3: per quantity the mean and its 95 % Student-t half-width from
seeds 1-3 and from all five, where each seed's value lies, and where each run sheared. Run from
the repository root:  /usr/bin/python3 data/reference/five_seeds.py"""
import re
import sys

sys.path.insert(0, "data/reference")
sys.path.insert(0, "data")
from seed_stats import mean_half as interval  # noqa: E402
from campaign_runs import campaign_runs  # noqa: E402

CELLS = [("R_n 0.5", "CNL 50 kPa"), ("R_n 0.5", "CNS 50 kPa, K 50 kPa/mm")]
QUANTITIES = [("peak_friction", "peak friction", "{:.3f}"), ("residual_friction", "residual friction", "{:.3f}"),
              ("dilation_mm", "total dilation (mm)", "{:.2f}")]


def seed_of(run_dir):
    return int(re.search(r"_?s(\d)(_|$)", run_dir.rsplit("/", 1)[-1]).group(1))


def main():
    runs = campaign_runs()
    print("| cell | quantity | seeds 1-3: mean +- t half-width | seeds 1-5 | seed 4, seed 5 | half-width ratio 5/3 |")
    print("|---|---|---|---|---|---|")
    modes = []
    for cell in CELLS:
        members = sorted((seed_of(d), s) for g, d, s in runs if g == cell)
        modes.append((cell, [(k, s.get("shear_mode", "?")) for k, s in members]))
        for key, name, fmt in QUANTITIES:
            three = [s[key] for k, s in members if k <= 3]
            five = [s[key] for k, s in members]
            m3, h3 = interval(three)
            m5, h5 = interval(five)
            new = ", ".join(fmt.format(s[key]) for k, s in members if k > 3)
            print(f"| {cell[0]}, {cell[1]} | {name} | {fmt.format(m3)} +- {fmt.format(h3)} | "
                  f"{fmt.format(m5)} +- {fmt.format(h5)} (n = {len(five)}) | {new} | {h5 / h3:.2f} |")
    print()
    for cell, m in modes:
        print(f"- {cell[0]}, {cell[1]}: " + "; ".join(f"seed {k} {mode}" for k, mode in m))


main()
