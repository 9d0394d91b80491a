#include "calibration/seed_scatter.hpp"

#include <algorithm>
#include <cmath>

#include "calibration/calibrate.hpp"
#include "calibration/objectives.hpp"

namespace iwb::calibration {

namespace {

double largest_gamma(const soil_test::SoilTest& t) {
  double g = 0.0;
  for (const double x : t.control) g = std::max(g, std::abs(x));
  return g;
}

}  // namespace

bool same_design(const soil_test::SoilTest& a, const soil_test::SoilTest& b) {
  // sigma0 within 5 %: an oedometer records the stress its servo reached (10.19 and 10.05 kPa for
  // two seeds of a 10 kPa start); designs of a campaign differ by factors of 2 or more. The same
  // holds for the amplitude of cyclic tests.
  constexpr double kSame = 0.05;
  const auto close = [](double x, double y) { return std::abs(x - y) <= kSame * std::max(x, y); };
  return a.kind == b.kind && a.boundary == b.boundary && a.specimen == b.specimen &&
         a.source == b.source && close(a.sigma0_kPa, b.sigma0_kPa) &&
         (a.kind != soil_test::SoilTestKind::kCyclicShear ||
          close(largest_gamma(a), largest_gamma(b)));
}

namespace {

// RMS over rows 1..rows-1 of the sample SD across the members of one column.
double row_scatter(const std::vector<const soil_test::SoilTest*>& members,
                   std::vector<double> soil_test::SoilTest::*column) {
  std::size_t rows = members.front()->rows();
  for (const auto* m : members) rows = std::min(rows, m->rows());
  const double n = double(members.size());
  double sum_of_variances = 0.0;
  for (std::size_t i = 1; i < rows; ++i) {
    double mean = 0.0;
    for (const auto* m : members) mean += (m->*column)[i] / n;
    double squares = 0.0;
    for (const auto* m : members) squares += std::pow((m->*column)[i] - mean, 2);
    sum_of_variances += squares / (n - 1.0);
  }
  return rows > 1 ? std::sqrt(sum_of_variances / double(rows - 1)) : 0.0;
}

// Sample SD across the members of their peak dilatancy rates (CNL shear).
double rate_scatter(const std::vector<const soil_test::SoilTest*>& members) {
  std::vector<double> rates;
  for (const auto* m : members) rates.push_back(peak_dilatancy_rate(m->control, m->e, m->rows()));
  double mean = 0.0, squares = 0.0;
  for (const double r : rates) mean += r / double(rates.size());
  for (const double r : rates) squares += (r - mean) * (r - mean);
  return std::sqrt(squares / double(rates.size() - 1));
}

}  // namespace

void measure_seed_scatter(std::vector<soil_test::SoilTest>& tests) {
  std::vector<bool> done(tests.size(), false);
  for (std::size_t i = 0; i < tests.size(); ++i) {
    if (done[i]) continue;
    std::vector<std::size_t> group;
    for (std::size_t j = i; j < tests.size(); ++j)
      if (!done[j] && same_design(tests[i], tests[j])) group.push_back(j), done[j] = true;
    if (group.size() < 2) continue;
    std::vector<const soil_test::SoilTest*> members;
    for (const auto j : group) members.push_back(&tests[j]);
    const double stress_floor = kStressRatioScale * tests[i].sigma0_kPa;
    const bool shear = soil_test::is_shear(tests[i].kind);
    soil_test::ResidualScales s;
    s.replicates = int(group.size());
    s.e = std::max(kVoidRatioScale, row_scatter(members, &soil_test::SoilTest::e));
    s.tau_kPa = shear ? std::max(stress_floor, row_scatter(members, &soil_test::SoilTest::tau_kPa))
                      : stress_floor;
    s.sigma_n_kPa =
        shear ? std::max(stress_floor, row_scatter(members, &soil_test::SoilTest::sigma_n_kPa))
              : stress_floor;
    if (tests[i].kind == soil_test::SoilTestKind::kSimpleShear &&
        tests[i].boundary == driver::BoundaryKind::kCNL)
      s.dilatancy_rate = std::max(kDilatancyRateScale, rate_scatter(members));
    for (const auto j : group) tests[j].scales = s;
  }
}

}  // namespace iwb::calibration
