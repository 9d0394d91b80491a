#include "validation/parameter_choice.hpp"

#include <fmt/core.h>

#include <cmath>

#include "common/errors.hpp"

namespace iwb::validation {

namespace {

// Parameter sets calibrated on soil tests of one scene's grains (`iwb dem soiltest` + `iwb
// calibrate`, data/calibration/<name>/README.md): the set for a scene whose [particles] are those
// grains, and never a stand-in for other grains in the phi_c match.
struct CalibratedGrains {
  const char* scene;  // embedded scene whose particles were calibrated
  const char* file;   // parameter set name
  // the rolling resistance the grains had when calibrated, where the scene has since changed it
  // (truth.toml: cdt until the convergence study chose epsd2); empty: the scene's own
  const char* rolling_model = "";
};
constexpr CalibratedGrains kCalibratedGrains[] = {{"default", "dem_default_grains.toml"},
                                                  {"truth", "truth_grains.toml", "cdt"},
                                                  {"truth", "truth_grains_epsd2.toml"}};

bool calibrated_set(const io::ParameterSet& set) {
  for (const auto& c : kCalibratedGrains)
    if (set.name == c.file) return true;
  return false;
}

bool same_grains(const dem::Particles& a, const dem::Particles& b) {
  const auto key = [](const dem::Particles& p) {
    std::vector<double> k{p.d50_m,    p.density_kg_m3,    p.youngs_modulus_Pa, p.poisson,
                          p.friction, p.rolling_friction, p.restitution};
    for (const auto& c : p.sizes) k.insert(k.end(), {c.diameter_m, c.mass_fraction});
    return k;
  };
  // the rolling model changes the grains' strength (epsd2: +19 % peak friction at the rough wall)
  return key(a) == key(b) && a.rolling_model == b.rolling_model;
}

const double* phi_c_of(const io::ParameterSet& set) {
  const auto it = set.tables.find("hypoplastic");
  if (it == set.tables.end()) return nullptr;
  const auto phi = it->second.find("phi_c_deg");
  return phi == it->second.end() ? nullptr : &phi->second;
}

}  // namespace

const io::ParameterSet* calibrated_parameters(const std::vector<io::ParameterSet>& sets,
                                              const dem::Scene& scene, std::string& why) {
  for (const auto& c : kCalibratedGrains) {
    auto base =
        dem::parse_scene(dem::embedded_scenes().at(std::string(c.scene) + ".toml"), c.scene);
    if (*c.rolling_model != '\0') base.particles.rolling_model = c.rolling_model;
    if (!same_grains(base.particles, scene.particles)) continue;
    for (const auto& set : sets)
      if (set.name == c.file) {
        why = fmt::format(
            "calibrated on DEM soil tests of the {} scene's grains (data/calibration/)", c.scene);
        return &set;
      }
  }
  return nullptr;
}

void require_matchable(const std::vector<io::ParameterSet>& sets, const std::string& where) {
  for (const auto& set : sets)
    if (!calibrated_set(set) && phi_c_of(set) != nullptr) return;
  throw InputError(
      fmt::format("{}: no parameter set with [hypoplastic] phi_c_deg to match the DEM's residual "
                  "friction angle",
                  where));
}

// The only property of the grains a DEM run tells without calibration is its residual interface
// friction angle atan(tau/sigma_n); the closest phi_c is the best guess (issue 7 calibrates
// properly).
const io::ParameterSet& matching_parameters(const std::vector<io::ParameterSet>& sets,
                                            double residual_friction, std::string& why) {
  const double phi_dem = std::atan(residual_friction) * 180.0 / M_PI;
  const io::ParameterSet* best = nullptr;
  double best_gap = INFINITY;
  for (const auto& set : sets) {
    const double* phi = phi_c_of(set);
    if (calibrated_set(set) || phi == nullptr) continue;
    if (const double gap = std::abs(*phi - phi_dem); gap < best_gap) best_gap = gap, best = &set;
  }
  if (best == nullptr)
    require_matchable(sets, "the parameter sets");  // throws: none can be matched
  why = fmt::format("phi_c closest to the DEM's residual friction angle atan({:.3f}) = {:.1f} deg",
                    residual_friction, phi_dem);
  return *best;
}

const io::ParameterSet& parameters_for(const std::vector<io::ParameterSet>& sets,
                                       const dem::Scene& scene, double residual_friction,
                                       std::string& why) {
  const auto* calibrated = calibrated_parameters(sets, scene, why);
  return calibrated != nullptr ? *calibrated : matching_parameters(sets, residual_friction, why);
}

}  // namespace iwb::validation
