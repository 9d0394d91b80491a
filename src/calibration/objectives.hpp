#pragma once
// What a calibration minimises: groups of residuals, each a kind of evidence a modeller may weigh
// against the others (issue 38). A residual is (model - measured) / scale in units of the
// measurement's scatter (calibrate.hpp, seed_scatter.hpp); a group's weight w multiplies the
// squares of its residuals, so w = 1 counts each as one measurement and the default objective
// (every weight 1) is the least-squares fit to everything measured.
//   oedometer  the e-paths of the oedometer tests
//   shear      the simple-shear paths: tau and e (CNL) or tau and sigma_n (CV), row by row
//   dilatancy  per CNL simple-shear test, the peak dilatancy rate d eps_n / d gamma and the total
//              dilation (e at the end): the two numbers an interface's dilation is judged by,
//              which a whole-path fit can trade away for its many rows (data/dilatancy/).
//   cyclic     the cyclic simple-shear paths, row by row as `shear`: what the intergranular
//              strain's parameters are fitted to (issue 34), weighed apart from the monotonic
//              paths so that a front can trade one against the other.
#include <array>
#include <string>
#include <vector>

#include "calibration/simulate.hpp"
#include "soil_test/soil_test.hpp"

namespace iwb::calibration {

enum class ObjectiveGroup { kOedometer, kShear, kDilatancy, kCyclic };
inline constexpr std::array<ObjectiveGroup, 4> kObjectiveGroups{
    ObjectiveGroup::kOedometer, ObjectiveGroup::kShear, ObjectiveGroup::kDilatancy,
    ObjectiveGroup::kCyclic};

const char* to_string(ObjectiveGroup g);
// One line: what the group's residuals are (for --help and the outputs).
const char* describe(ObjectiveGroup g);
// The group of a name; InputError naming `where` (an option) and listing the names otherwise.
ObjectiveGroup objective_group(const std::string& name, const std::string& where);

struct ObjectiveWeights {
  std::array<double, kObjectiveGroups.size()> weight{1.0, 1.0, 1.0, 1.0};
  double& operator[](ObjectiveGroup g) { return weight[std::size_t(g)]; }
  double operator[](ObjectiveGroup g) const { return weight[std::size_t(g)]; }
};

// "group=weight" items (--weight); groups not named keep weight 1. InputError naming the item for
// an unknown group, a weight that is not a number, negative or not finite, a group named twice,
// and for weights that are all zero.
ObjectiveWeights parse_weights(const std::vector<std::string>& items);

// Scatter of a peak dilatancy rate where a test's seeds do not measure it: the DEM soil cells of
// data/dilatancy/ scatter by 0.011-0.015 across three seeds at each density.
inline constexpr double kDilatancyRateScale = 0.01;
// The rate is a least-squares slope of eps_n over gamma in a window of this width (at least three
// rows): 1 mm of travel on the 12 d50 calibration cell of d50 2 mm, as data/dilatancy/ measures it.
inline constexpr double kRateWindowGamma = 0.04;

// The largest least-squares slope d eps_n / d gamma, eps_n = (e - e0) / (1 + e0) (dilation
// positive), over windows of kRateWindowGamma centred on each of the first `rows` rows.
double peak_dilatancy_rate(const std::vector<double>& gamma, const std::vector<double>& e,
                           std::size_t rows);

// Appends the residuals of group `g` for test `t` simulated as `s` (nothing when the group does
// not apply to the test), in scatter units and unweighted; rows the model did not reach count
// kUnreachedResidual each.
void append_group_residuals(ObjectiveGroup g, const soil_test::SoilTest& t, const Simulated& s,
                            std::vector<double>& r);

}  // namespace iwb::calibration
