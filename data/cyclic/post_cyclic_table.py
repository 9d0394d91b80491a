#!/usr/bin/python3
"""Post-cyclic against virgin peak friction (README.md here, Mortara et al.'s post-cyclic half):
the peak tau/sigma_n of the monotonic shear after the cycles (summary.json: cyclic.post_cyclic)
against the peak of monotonic runs of the same scene and wall from a fresh specimen, each a mean
over its seeds with the 95 % Student-t half-width, their difference with Welch's t-test (the
specimens differ: the cyclic and monotonic runs were consolidated by different builds) and the
relative change with its 95 % interval (Welch's degrees of freedom). Run from the repository root:

    data/cyclic/post_cyclic_table.py --cyclic RUN... --monotonic RUN...
"""
import json
import statistics as st
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # data/seed_stats.py
from seed_stats import welch  # noqa: E402
from cycle_table import interval  # noqa: E402


def post_cyclic_peaks(runs):
    return [json.load(open(f"{d}/summary.json"))["cyclic"]["post_cyclic"]["peak_friction"] for d in runs]


def monotonic_peaks(runs):
    return [json.load(open(f"{d}/summary.json"))["peak_friction"] for d in runs]


def split(args):
    if "--cyclic" not in args or "--monotonic" not in args:
        sys.exit(__doc__)
    i, j = args.index("--cyclic"), args.index("--monotonic")
    if i < j:
        return args[i + 1:j], args[j + 1:]
    return args[i + 1:], args[j + 1:i]


def main(args):
    cyclic, monotonic = split(args)
    post, virgin = post_cyclic_peaks(cyclic), monotonic_peaks(monotonic)
    print(f"virgin peak ({len(virgin)} runs): {interval(virgin)}")
    print(f"post-cyclic peak ({len(post)} runs): {interval(post)}")
    if min(len(post), len(virgin)) < 2:
        print("change: needs two runs a side")
        return
    diff, half, p = welch(virgin, post)
    base = st.mean(virgin)
    print(f"change: {diff:+.3f} +- {half:.3f} ({100 * diff / base:+.1f} % +- {100 * half / base:.1f} %), "
          f"Welch p = {p:.2f}")


if __name__ == "__main__":
    main(sys.argv[1:])
