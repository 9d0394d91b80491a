"""Seed statistics for the campaigns' table scripts (data/*/*.py), in one place so that every
README table states its intervals the same way (issue 36 item 4): a DEM quantity is a mean over
seeds with a 95 % interval from Student's t with n - 1 degrees of freedom, and two cells are told
apart by Welch's test (unequal variances; the cells' seeds are independent specimens). A script
beside this file's folder imports it after

    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # data/seed_stats.py
"""
import math
import statistics as st

from scipy import stats

LEVEL = 0.95


def t_half(values):
    """The 95 % t half-width of the mean of values; NaN for fewer than two (no scatter known)."""
    n = len(values)
    if n < 2:
        return float("nan")
    return stats.t.ppf(0.5 + LEVEL / 2, n - 1) * st.stdev(values) / math.sqrt(n)


def mean_half(values):
    """(mean, 95 % t half-width) of values."""
    return st.mean(values), t_half(values)


def interval(values, fmt=".3f", half_fmt=None, single="{:s} (1 run)"):
    """'mean +- half' as text, None values left out; one value is shown as `single` says, none as '-'."""
    v = [x for x in values if x is not None]
    if not v:
        return "-"
    if len(v) == 1:
        return single.format(format(v[0], fmt))
    mean, half = mean_half(v)
    return f"{format(mean, fmt)} +- {format(half, half_fmt or fmt.lstrip('+'))}"


def welch(a, b):
    """b - a: the difference of the means, its 95 % half-width on Welch-Satterthwaite's degrees of
    freedom, and Welch's two-sided p; half-width and p NaN when neither side scatters (equal seeds,
    e.g. a band thickness read in whole bins, leave nothing to test against)."""
    va, vb = st.variance(a) / len(a), st.variance(b) / len(b)
    if va + vb == 0:
        return st.mean(b) - st.mean(a), float("nan"), float("nan")
    dof = (va + vb) ** 2 / (va ** 2 / (len(a) - 1) + vb ** 2 / (len(b) - 1))
    half = stats.t.ppf(0.5 + LEVEL / 2, dof) * math.sqrt(va + vb)
    return st.mean(b) - st.mean(a), half, stats.ttest_ind(b, a, equal_var=False).pvalue


def seeds_needed(sd, half_width, at_most=1000):
    """The fewest seeds (>= 2) whose 95 % t half-width, at the SD measured, is at most half_width
    (as the comparison's src/statistics values_needed); None when sd is 0 (nothing to resolve) or
    more than at_most would be needed."""
    if not sd > 0:
        return None
    for n in range(2, at_most + 1):
        if stats.t.ppf(0.5 + LEVEL / 2, n - 1) * sd / math.sqrt(n) <= half_width:
            return n
    return None
