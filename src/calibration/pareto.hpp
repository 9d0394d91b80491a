#pragma once
// The Pareto front between two objective groups (issue 38): what one kind of evidence costs in the
// other when the calibration leans on it. Each point is a whole calibration (calibrate.hpp) at
// weights that give group a the share s of the pair's weight and group b the rest,
//   w_a = s T / N_a,  w_b = (1 - s) T / N_b,  T = w_a0 N_a + w_b0 N_b
// (N: the group's residual count; w_0: the weights given), so that at s = 1/2 the two groups' mean
// squares count alike whatever their sizes, and at s_0 = w_a0 N_a / T the point is the calibration
// at the given weights. Other groups keep their given weights. The given point is fitted first
// from the staged estimate; the others follow it outwards, each from its neighbour's estimate, so
// the front is one continuous path of optima.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "calibration/calibrate.hpp"

namespace iwb::calibration {

struct ParetoPoint {
  double share = 0.0;  // of the pair's weight on group a
  ObjectiveWeights weights;
  bool given = false;  // the point at the weights given
  CalibrationResult result;
  double rms_a = 0.0, rms_b = 0.0;  // the two groups' RMS (unweighted, scatter units)
};

struct ParetoFront {
  ObjectiveGroup a, b;
  std::vector<ParetoPoint> points;  // in order of share
  double seconds = 0.0;
  int evaluations = 0;
  // Where a point does worse in both groups than its neighbour (a local optimum the path fell
  // into); empty when the front is monotonic.
  std::vector<std::string> notes;
  const ParetoPoint& given() const;
};

inline constexpr int kMinParetoPoints = 3, kMaxParetoPoints = 25;
// The front's points span this many decades of the pair's weight ratio s / (1 - s), evenly in its
// logarithm and centred on the given weights' ratio: one group can be far more sensitive to the
// parameters than the other (a shear path's rows against a dozen peak rates), and a linear grid
// in s then leaves the whole trade in its last point. --weight moves the centre.
inline constexpr double kParetoRatioDecades = 6.0;

// The front of `points` shares s_k with s_k / (1 - s_k) = r_0 10^(-3 + 6 k / (points - 1)), k =
// 0..points-1 (r_0 the given weights' ratio, 1 if either is 0), and the given point.
// InputError for a equal to b, points outside [kMinParetoPoints, kMaxParetoPoints], and a group
// the tests give no residual to. `progress` receives a line per point fitted.
ParetoFront trace_front(const std::vector<soil_test::SoilTest>& tests,
                        const CalibrationOptions& options, ObjectiveGroup a, ObjectiveGroup b,
                        int points, const std::function<void(const std::string&)>& progress = {});

// Into `dir`: pareto.csv (a row per point: share, the pair's weights, every group's RMS, s^2,
// given, converged, the parameters), pareto.json (the same with sigmas, bounds reached and notes),
// the figure pareto.svg/.png/.gp (RMS of b against RMS of a) and pareto/point-K.toml.
void write_front_files(const ParetoFront& front, const std::filesystem::path& dir,
                       const std::vector<soil_test::SoilTest>& tests,
                       const std::string& command_line);

// The "A,B" of --pareto; InputError naming the option otherwise.
std::pair<ObjectiveGroup, ObjectiveGroup> parse_pareto_groups(const std::string& text);

}  // namespace iwb::calibration
