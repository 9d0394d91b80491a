#pragma once
// What hcthm (hcthm.cpp) and hcthm3d (hcthm3d.cpp) share: the law built on a kinematics, and the
// declaration with temperature and suction. Two files, each instantiating the law for one
// kinematics: one file took 27-40 s of the compiler, over the 30 s a unit may take (issue 60).
#include <memory>
#include <string>
#include <vector>

#include "models/clay/masin_clay.hpp"
#include "models/hypoplastic/family.hpp"
#include "models/thermo_hydro/thermo_hydro_clay.hpp"

namespace iwb::models {

inline constexpr int kThermoHydroListingOrder = 16;  // after hc, hc3d

template <class Kinematics>
std::unique_ptr<Model> build_thermo_hydro(const std::string& name, const Kinematics& kin,
                                          const ModelInputs& in) {
  const auto p = MasinClayParameters::from(require_table(in, "clay_hypoplasticity"),
                                           in.source + " [clay_hypoplasticity]");
  const auto th =
      ThermoHydroParameters::from(require_table(in, "thermo_hydro"), in.source + " [thermo_hydro]");
  return make_member<ThermoHydroClayLaw>(
      name, kin, ThermoHydroClayConstants{make_masin_clay_constants(p, in.roughness), th}, in,
      WithIntergranularStrain::kNo);
}

// hc's declaration with T_K and s_kPa as external variables and initial inputs (hcthm.cpp).
ModelDeclaration thermo_hydro_declaration(const std::vector<std::string>& stress_components,
                                          bool interface_model, int listing_order);

}  // namespace iwb::models
