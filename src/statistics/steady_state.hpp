#pragma once
// Where a DEM curve has settled (issue 59: "the residual is not residual"). After its peak the
// friction of a dense specimen falls towards the critical state, and its dilation rises towards
// its own; a run stopped at 10 mm is, in most cells, still on the way. The curve is fitted with
// an exponential decay towards a steady value,
//   y(s) = y_inf + A exp(-(s - s0) / lambda),   s >= s0,
// (the critical state approached at a rate proportional to the distance from it, the form of the
// soil models' own evolution of e towards e_c), lambda on a logarithmic grid with (y_inf, A) by
// linear least squares at each. From it:
//   - steady: what the decay still has to go at the centre of the judged window, |A| exp(-(s_w -
//     s0) / lambda), is at most kSteadyShare of the window's mean. kSteadyShare is half the 5 %
//     tolerance of the residual verdict: a window that lies further above its steady value can
//     turn a verdict by itself.
//     And the window itself must not drift: a line through block means of the window (blocks
//     given by the caller, long enough that the grains' stick-slip in one carries little into the
//     next; at least 3 blocks, else no such test) whose drift over the window is beyond
//     kSteadyShare of its mean and beyond its 95 % t-interval is a trend the decay does not
//     describe (a run rising again), not steady.
//   - extrapolated: y_inf, only where the fit resolves the decay, lambda at most the fitted span
//     over kResolvedDecayLengths (two decay lengths seen); a longer lambda is a straight drift
//     whose end the run does not show.
// The fit runs on every row: rows 0.02 mm apart scatter with the grains' stick-slip, which the
// least squares averages; the shape is fitted, no row picked.
#include <optional>
#include <vector>

namespace iwb::statistics {

inline constexpr double kSteadyShare = 0.025;
inline constexpr double kResolvedDecayLengths = 2.0;
// The residual is judged over the last fifth of the travel.
inline constexpr double kResidualWindowShare = 0.2;
// The block length of the steady-state test's window, in grains: block means of 1 mm on the truth
// runs (d50 2 mm) sheared 20 mm correlate at lag 1 by 0.29 on average over 10-20 mm (0.58 for
// 0.4 mm blocks, -0.2 for 2 mm; data/grains/truth_travel20): nearly independent, where a shorter
// block would make the drift's interval too narrow.
inline constexpr double kSteadyBlockD50 = 0.5;

struct DecayFit {
  double steady = 0.0;     // y_inf
  double amplitude = 0.0;  // A: y(s0) - y_inf
  double length = 0.0;     // lambda, in the units of s
  double span = 0.0;       // the fitted travel, s_end - s0
  bool resolved() const { return length * kResolvedDecayLengths <= span; }
  double remaining_at(double s, double s0) const;  // y(s) - y_inf
};

// The decay fitted to the rows with s >= s0 (s ascending); nullopt with fewer than 4 such rows.
std::optional<DecayFit> fit_decay(const std::vector<double>& s, const std::vector<double>& y,
                                  double s0);

struct SteadyState {
  bool steady = false;
  double window_mean = 0.0;
  double remaining = 0.0;              // the fit's y(window centre) - y_inf
  double window_drift = 0.0;           // the block means' line, over the window's length
  double window_drift_ci = 0.0;        // its 95 % t half-width
  std::optional<double> extrapolated;  // y_inf where the decay is resolved
};

// Whether y has settled over the window s >= window_from (the last fifth: judged there), from the
// decay fitted over s >= s0 and the window's block means of length `block`; nullopt when either
// has too few rows.
std::optional<SteadyState> steady_state(const std::vector<double>& s, const std::vector<double>& y,
                                        double s0, double window_from, double block);

// The residual rule every DEM run is held to, by the summary and the comparison alike: the decay
// fitted from the friction's peak (index `peak`), the window the last kResidualWindowShare of the
// travel s, blocks of kSteadyBlockD50 grains of d50_mm.
std::optional<SteadyState> residual_steady_state(const std::vector<double>& s,
                                                 const std::vector<double>& friction,
                                                 std::size_t peak, double d50_mm);

}  // namespace iwb::statistics
