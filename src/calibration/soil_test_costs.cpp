#include "calibration/soil_test_costs.hpp"

#include <fmt/core.h>

#include <memory>

#include "calibration/calibrate.hpp"
#include "calibration/seed_scatter.hpp"

namespace iwb::calibration {

comparison::FormLimitOptions::Elsewhere soil_test_costs(const std::vector<std::string>& dirs) {
  if (dirs.empty()) return {};
  auto tests = std::make_shared<std::vector<SoilTest>>();
  for (const auto& d : dirs) tests->push_back(read_soil_test(d));
  measure_seed_scatter(*tests);
  return [tests](const auto& form, const auto& soil) {
    const auto costs = [&](const auto& tables) {
      models::ModelInputs in;
      in.tables["hypoplastic"] = tables.at("hypoplastic");
      in.source = "form limit";
      return group_fits(*tests, "vw3d", in, {});
    };
    const auto at_form = costs(form), at_soil = costs(soil);
    const auto not_reached = [](const GroupFit& g) {
      return g.unreached
                 ? fmt::format(" ({} of {} residuals not reached)", g.unreached, g.residuals)
                 : std::string();
    };
    nlohmann::json rows = nlohmann::json::array();
    for (std::size_t g = 0; g < at_form.size(); ++g)
      if (at_form[g].residuals > 0)
        rows.push_back({{"what", fmt::format("soil tests ({}), RMS in scatter units: {}",
                                             tests->size(), to_string(at_form[g].group))},
                        {"soil_test", at_soil[g].rms},
                        {"form_limit", at_form[g].rms},
                        {"soil_test_note", not_reached(at_soil[g])},
                        {"form_limit_note", not_reached(at_form[g])}});
    return rows;
  };
}

}  // namespace iwb::calibration
