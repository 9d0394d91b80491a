// hcthm3d: hcthm (hcthm.cpp) on full 3x3 tensors in simple shear, apart so that each file
// instantiates the law for one kinematics (hcthm_build.hpp).
#include "models/thermo_hydro/hcthm_build.hpp"

namespace iwb::models {

ModelSpec hcthm3d_spec() {
  return {"hcthm3d",
          "Masin & Khalili (2012) thermo-hydro-mechanical clay hypoplasticity, full 3x3 tensors in "
          "simple shear",
          "seed 6.3 (6.29-6.52; issue 19 closing note)",
          false,
          {&MasinClayParameters::table(), &ThermoHydroParameters::table()},
          [](const ModelInputs& in) {
            return build_thermo_hydro("hcthm3d", SimpleShearKinematics{}, in);
          },
          thermo_hydro_declaration(SimpleShearKinematics::component_names(), false,
                                   kThermoHydroListingOrder + 1)};
}

}  // namespace iwb::models
