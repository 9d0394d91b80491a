// hce: Masin's (2013) clay hypoplasticity with explicit asymptotic states (seed 6.2.3, HCE), on the
// reduced interface vectors [sigma_n, sigma_p, tau_x, tau_y] with independent in-plane stress (as
// hvwe), and hce3d on full 3x3 tensors in simple shear (as vw3d), the reference the interface form
// is checked against. Rough walls: Stutz & Masin's scheme (eqs. 6.23-6.28).
#include "models/clay/declaration.hpp"
#include "models/clay/explicit_asymptotic_clay.hpp"
#include "models/hypoplastic/family.hpp"

namespace iwb::models {

namespace {

// Listed after the sand models (vw3d ... hp1d are 0-5).
constexpr int kListingOrder = 12;  // after hcc, hcc3d

template <class Kinematics>
std::unique_ptr<Model> build(const std::string& name, const Kinematics& kin, const ModelInputs& in,
                             WithIntergranularStrain igs) {
  const auto p = ClayParameters::from(require_table(in, "hypoplastic_clay"),
                                      in.source + " [hypoplastic_clay]");
  return make_member<ExplicitAsymptoticClayLaw>(
      name, kin, make_explicit_asymptotic_clay_constants(p, in.roughness), in, igs);
}

std::unique_ptr<Model> build_interface(const ModelInputs& in, WithIntergranularStrain igs) {
  return build("hce", ReducedInterfaceKinematics<algebra::ReducedOps>{}, in, igs);
}

std::unique_ptr<Model> build_3d(const ModelInputs& in, WithIntergranularStrain igs) {
  return build("hce3d", SimpleShearKinematics{}, in, igs);
}

ModelDeclaration hce_declaration(const std::vector<std::string>& stress_components,
                                 bool interface_model, int listing_order) {
  return clay_declaration(
      stress_components, interface_model, listing_order, RoughnessScheme::kStutzMasin,
      {{"F_m", "-", "Matsuoka-Nakai's F_m (eq. 6.16): sin^2 phi_c at the critical state"},
       {"f_d_over_f_dA", "-", "f_d / f_d^A (eqs. 6.11, 6.14): 1 on the ASBS, below inside it",
        DiagnosticRole::kOverconsolidation}});
}

}  // namespace

ModelSpec hce_spec() {
  return {"hce",
          "Masin (2013) clay hypoplasticity (explicit asymptotic states), interface model on "
          "[sigma_n, sigma_p, tau_x, tau_y]",
          "seed 6.2.3 (6.11-6.20, ERRATA 11-14), roughness 6.23-6.28",
          true,
          {&ClayParameters::table()},
          [](const ModelInputs& in) { return build_interface(in, WithIntergranularStrain::kNo); },
          hce_declaration(ReducedInterfaceKinematics<algebra::ReducedOps>::component_names(), true,
                          kListingOrder)};
}

ModelSpec hce3d_spec() {
  return {"hce3d",
          "Masin (2013) clay hypoplasticity (explicit asymptotic states), full 3x3 tensors in "
          "simple shear",
          "seed 6.2.3 (6.11-6.20, ERRATA 11-14)",
          false,
          {&ClayParameters::table()},
          [](const ModelInputs& in) { return build_3d(in, WithIntergranularStrain::kNo); },
          hce_declaration(SimpleShearKinematics::component_names(), false, kListingOrder + 1)};
}

// Table 6.4 is the seed's clay set with intergranular strain; e0 1.45 is OCR 1.2 at 100 kPa.
const std::map<std::string, double> kTable64Start{{"sigma_n_kPa", 100.0}, {"e0", 1.45}};
ModelSpec hce_igs_spec() {
  return with_intergranular_strain(hce_spec(), build_interface, "table_6_4_cyclic.toml",
                                   kTable64Start);
}
ModelSpec hce3d_igs_spec() {
  return with_intergranular_strain(hce3d_spec(), build_3d, "table_6_4_cyclic.toml", kTable64Start);
}

}  // namespace iwb::models
