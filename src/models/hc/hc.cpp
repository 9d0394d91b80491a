// hc: Masin's (2005) clay hypoplasticity (seed 6.3 at T = T0, s = 0), on the reduced interface
// vectors [sigma_n, sigma_p, tau_x, tau_y] as hce, and hc3d on full 3x3 tensors in simple shear,
// the reference the interface form is checked against; the base model of the thermo-hydro
// model hcthm. Rough walls: both clay schemes of 6.2.4 (clay/masin_clay.hpp).
#include "models/clay/declaration.hpp"
#include "models/clay/masin_clay.hpp"
#include "models/hypoplastic/family.hpp"

namespace iwb::models {

namespace {

constexpr int kListingOrder = 14;  // after hce, hce3d

template <class Kinematics>
std::unique_ptr<Model> build(const std::string& name, const Kinematics& kin, const ModelInputs& in,
                             WithIntergranularStrain igs) {
  const auto p = MasinClayParameters::from(require_table(in, "clay_hypoplasticity"),
                                           in.source + " [clay_hypoplasticity]");
  return make_member<MasinClayLaw>(name, kin, make_masin_clay_constants(p, in.roughness), in, igs);
}

}  // namespace

// What hc and hcthm declare alike: the clay declaration over [clay_hypoplasticity], Stutz &
// Masin's roughness by default, F_m among the diagnostics, Table 6.5's Soil 1 as the example.
ModelDeclaration masin_clay_declaration(const std::vector<std::string>& stress_components,
                                        bool interface_model, int listing_order) {
  auto d = clay_declaration(
      stress_components, interface_model, listing_order, RoughnessScheme::kStutzMasin,
      {{"F_m", "-", "Matsuoka-Nakai's F_m: sin^2 phi_c at the critical state"}},
      "clay_hypoplasticity");
  d.initial[2].doc =
      "overconsolidation ratio at the start: p_e over its value on the state boundary surface "
      "at the initial stress (6.49; 1: normally consolidated), which sets e0";
  d.example_parameters = "table_6_5_soil_1.toml";
  // Table 6.5, Soil 1, at a start inside its state boundary surface (the table's e0 0.5 at 300 kPa
  // lies outside: src/models/thermo_hydro/README.md)
  d.example_start = {{"sigma_n_kPa", 300.0}, {"e0", 0.44}};
  return d;
}

ModelSpec hc_spec() {
  return {"hc",
          "Masin (2005) clay hypoplasticity, interface model on [sigma_n, sigma_p, tau_x, tau_y]",
          "seed 6.3 at T = T0, s = 0 (6.33-6.43, ERRATA 14), roughness 6.2.4",
          true,
          {&MasinClayParameters::table()},
          [](const ModelInputs& in) {
            return build("hc", ReducedInterfaceKinematics<algebra::ReducedOps>{}, in,
                         WithIntergranularStrain::kNo);
          },
          masin_clay_declaration(ReducedInterfaceKinematics<algebra::ReducedOps>::component_names(),
                                 true, kListingOrder)};
}

ModelSpec hc3d_spec() {
  return {
      "hc3d",
      "Masin (2005) clay hypoplasticity, full 3x3 tensors in simple shear",
      "seed 6.3 at T = T0, s = 0 (6.33-6.43, ERRATA 14)",
      false,
      {&MasinClayParameters::table()},
      [](const ModelInputs& in) {
        return build("hc3d", SimpleShearKinematics{}, in, WithIntergranularStrain::kNo);
      },
      masin_clay_declaration(SimpleShearKinematics::component_names(), false, kListingOrder + 1)};
}

}  // namespace iwb::models
