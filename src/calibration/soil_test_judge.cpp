#include "calibration/soil_test_judge.hpp"

#include <fmt/core.h>

#include <memory>

#include "calibration/calibrate.hpp"
#include "calibration/seed_scatter.hpp"

namespace iwb::calibration {

comparison::FormLimitOptions::SoilTests soil_test_judge(const std::vector<std::string>& dirs) {
  if (dirs.empty()) return {};
  auto tests = std::make_shared<std::vector<soil_test::SoilTest>>();
  for (const auto& d : dirs) tests->push_back(soil_test::read_soil_test(d));
  measure_seed_scatter(*tests);
  return [tests](const comparison::FormLimitOptions::Tables& tables) {
    models::ModelInputs in;
    in.tables["hypoplastic"] = tables.at("hypoplastic");
    in.source = "form limit";
    const auto residuals = group_residuals(*tests, "vw3d", in);
    std::vector<comparison::FormLimitOptions::SoilGroup> out;
    for (const auto g : kObjectiveGroups) {
      const auto& r = residuals[std::size_t(g)];
      if (r.empty()) continue;  // no test of this group
      const GroupFit fit = group_fit(g, r);
      out.push_back({to_string(g), r, fit.rms, fit.unreached});
    }
    return out;
  };
}

}  // namespace iwb::calibration
