#pragma once
// The tests a campaign's claims rest on (issue 59, "one statistics layer for every claim"): two
// groups of DEM seeds compared by Welch's t-test (unequal scatter: a rough and a flat wall do not
// scatter alike), a single run against a group by the group's prediction interval, and a family of
// such tests controlled for multiplicity by Benjamini & Hochberg (1995).
#include <optional>
#include <vector>

namespace iwb::statistics {

struct Sample {
  int n = 0;
  double mean = 0.0, sd = 0.0;  // sample SD (n - 1)
};
Sample describe(const std::vector<double>& values);

struct Difference {
  double effect = 0.0;               // mean of b - mean of a
  double half_width = 0.0;           // of its 95 % interval
  double degrees_of_freedom = 0.0;   // Welch-Satterthwaite (or n_a - 1 for one run)
  double standard_error = 0.0;       // of the effect (of a new run's deviation, for one run)
  double p_value = 1.0;              // two-sided
  bool prediction_interval = false;  // b is a single run, judged against a's interval
};

// b against a: Welch's t-test when both have at least two values; a single b against a's 95 %
// prediction interval, t = (b - mean_a) / (sd_a sqrt(1 + 1/n_a)) with n_a - 1 degrees of freedom;
// nullopt when neither applies (a group of fewer than two, or no scatter at all).
std::optional<Difference> compare_groups(const Sample& a, const Sample& b);

// "b equals a within +-margin", by two one-sided tests (Schuirmann 1987) at the difference's own
// degrees of freedom and standard error: the larger of the p-values of H0 effect <= -margin and of
// H0 effect >= margin. A small p shows the groups equal within the margin; a large one shows
// nothing (a difference not resolved is never equality: this is the test that can say "equal").
double equivalence_p_value(const Difference& d, double margin);

// Benjamini-Hochberg adjusted p-values, in the order given: p_(i) m / i made monotone from the
// largest down and capped at 1. A test is significant at false-discovery rate q where its adjusted
// p is at most q.
std::vector<double> benjamini_hochberg(const std::vector<double>& p_values);

// The fewest seeds per group (>= 2) at which the effect and scatter measured would give Welch's
// two-sided p at most `alpha`: a claim tested among m at false-discovery rate q survives
// Benjamini-Hochberg whatever the others give once its p is at most q / m, so a family passes
// alpha = q / m. (At the measured effect, not a power calculation: about even odds of resolving
// it with that many seeds.) nullopt beyond `at_most` or for no effect.
std::optional<int> seeds_to_resolve(const Sample& a, const Sample& b, double effect, double alpha,
                                    int at_most = 1000);
// The same for equality within +-margin (equivalence_p_value at most alpha); nullopt where the
// measured effect is not inside the margin (no count of seeds shows it equal) or beyond at_most.
std::optional<int> seeds_to_show_equal(const Sample& a, const Sample& b, double effect,
                                       double margin, double alpha, int at_most = 1000);

}  // namespace iwb::statistics
