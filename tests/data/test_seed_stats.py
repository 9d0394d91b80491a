#!/usr/bin/python3
"""data/seed_stats.py, the campaigns' seed statistics, against Student's t where it has a closed
form (so the expected values owe nothing to scipy, which the module uses):
  nu = 1: quantile tan(pi (p - 1/2));
  nu = 2: quantile (2p - 1) / sqrt(2 p (1 - p)), CDF 1/2 + t / (2 sqrt(2 + t^2));
  nu = 4: CDF 1/2 + sin(theta) (1 + cos(theta)^2 / 2) / 2 with tan(theta) = t / 2
          (Abramowitz & Stegun 26.7.3 for even nu).
Welch-Satterthwaite's degrees of freedom are 2 (n - 1) for two equal variances of n each, and
n - 1 of the scattered side when the other has none. Usage: test_seed_stats.py REPO_ROOT"""
import math
import sys
import warnings
from pathlib import Path

sys.path.insert(0, str(Path(sys.argv[1]) / "data"))
import seed_stats  # noqa: E402

P = 0.975
failures = []


def close(what, got, want, tol=1e-9):
    if not math.isclose(got, want, rel_tol=tol, abs_tol=tol):
        failures.append(f"{what}: {got!r}, expected {want!r}")


def t_cdf_nu2(t):
    return 0.5 + t / (2 * math.sqrt(2 + t * t))


def t_cdf_nu4(t):
    # A&S 26.7.3 for even nu = 4: 1/2 + 1/2 sin(theta) (1 + cos^2(theta) / 2), tan(theta) = t / 2
    theta = math.atan(t / 2)
    return 0.5 + 0.5 * math.sin(theta) * (1 + math.cos(theta) ** 2 / 2)


t1 = math.tan(math.pi * (P - 0.5))
t2 = (2 * P - 1) / math.sqrt(2 * P * (1 - P))

# one degree of freedom: [0, 2] has SD sqrt(2), so the half-width is t1 itself
close("t_half([0, 2])", seed_stats.t_half([0.0, 2.0]), t1)
# two: [1, 2, 3] has mean 2, SD 1
mean, half = seed_stats.mean_half([1.0, 2.0, 3.0])
close("mean of [1, 2, 3]", mean, 2.0)
close("t_half([1, 2, 3])", half, t2 / math.sqrt(3))
if not math.isnan(seed_stats.t_half([1.0])):
    failures.append("t_half of one value is not NaN: one run has no scatter")

# Welch, equal variances and sizes: nu = 4; t = 3 / sqrt(2/3)
diff, half, p = seed_stats.welch([1.0, 2.0, 3.0], [4.0, 5.0, 6.0])
close("welch difference", diff, 3.0)
t = 3.0 / math.sqrt(2.0 / 3.0)
close("welch p (nu 4)", p, 2 * (1 - t_cdf_nu4(t)), 1e-7)
# the half-width at nu = 4 is the t for which the closed-form CDF is 0.975
close("welch half-width (nu 4)", t_cdf_nu4(half / math.sqrt(2.0 / 3.0)), P, 1e-9)
# Welch, one side of four without scatter: nu = 2 of the other (three); t = -3 / sqrt(1/3). The
# sides' sizes differ, so a swap of len(a) and len(b) shows
with warnings.catch_warnings():  # scipy warns of a side without scatter, which is the point
    warnings.simplefilter("ignore")
    diff, half, p = seed_stats.welch([5.0, 5.0, 5.0, 5.0], [1.0, 2.0, 3.0])
close("welch difference, one side fixed", diff, -3.0)
close("welch half-width (nu 2)", half, t2 * math.sqrt(1.0 / 3.0))
close("welch p (nu 2)", p, 2 * (1 - t_cdf_nu2(3.0 / math.sqrt(1.0 / 3.0))), 1e-7)
diff, half, p = seed_stats.welch([2.0, 2.0], [3.0, 3.0])
if not (diff == 1.0 and math.isnan(half) and math.isnan(p)):
    failures.append(f"welch without any scatter: {diff}, {half}, {p}; expected 1, nan, nan")

# seeds needed: at SD 1, t1 / sqrt(2) is resolved by 2 seeds, t2 / sqrt(3) first by 3 (a margin
# of 1e-9: scipy's quantile at nu = 1 lies 2e-11 (relative) above tan(0.475 pi)); just below
# t2 / sqrt(3) it takes 4, which n degrees of freedom instead of n - 1 would not
if seed_stats.seeds_needed(1.0, t1 / math.sqrt(2) * (1 + 1e-9)) != 2:
    failures.append("seeds_needed for a half-width of t1 / sqrt(2) is not 2")
if seed_stats.seeds_needed(1.0, t2 / math.sqrt(3) * (1 + 1e-9)) != 3:
    failures.append("seeds_needed for a half-width of t2 / sqrt(3) is not 3")
if seed_stats.seeds_needed(1.0, t2 / math.sqrt(3) * (1 - 1e-9)) != 4:
    failures.append("seeds_needed just below t2 / sqrt(3) is not 4")
if seed_stats.seeds_needed(0.0, 1.0) is not None:
    failures.append("seeds_needed with no scatter is not None")

# the text the README tables show
cases = [(seed_stats.interval([1.0, None, 3.0], ".2f"), f"2.00 +- {t1 * math.sqrt(2) / math.sqrt(2):.2f}"),
         (seed_stats.interval([0.5], ".3f"), "0.500 (1 run)"),
         (seed_stats.interval([None]), "-"),
         (seed_stats.interval([-1.0, -3.0], "+.1f"), f"-2.0 +- {t1:.1f}")]
for got, want in cases:
    if got != want:
        failures.append(f"interval: {got!r}, expected {want!r}")

for f in failures:
    print("FAIL", f)
print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
