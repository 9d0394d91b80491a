// hcc: Masin's (2012) hypoplastic Cam clay (seed 6.2.2), on the reduced interface vectors
// [sigma_n, sigma_p, tau_x, tau_y] with independent in-plane stress (as hvwe), and hcc3d on full
// 3x3 tensors in simple shear (as vw3d), the reference the interface form is checked against.
// Rough walls: Arnold & Herle's scheme for clay, M from phi_c kappa_r (eq. 6.22).
#include "models/clay/declaration.hpp"
#include "models/clay/hypoplastic_cam_clay.hpp"
#include "models/hypoplastic/family.hpp"

namespace iwb::models {

namespace {

// Listed after the sand models (vw3d ... hp1d are 0-5).
constexpr int kListingOrder = 10;

template <class Kinematics>
std::unique_ptr<Model> build(const std::string& name, const Kinematics& kin, const ModelInputs& in,
                             WithIntergranularStrain igs) {
  const auto p = ClayParameters::from(require_table(in, "hypoplastic_clay"),
                                      in.source + " [hypoplastic_clay]");
  return make_member<HypoplasticCamClayLaw>(
      name, kin, make_hypoplastic_cam_clay_constants(p, in.roughness), in, igs);
}

std::unique_ptr<Model> build_interface(const ModelInputs& in, WithIntergranularStrain igs) {
  return build("hcc", ReducedInterfaceKinematics<algebra::ReducedOps>{}, in, igs);
}

std::unique_ptr<Model> build_3d(const ModelInputs& in, WithIntergranularStrain igs) {
  return build("hcc3d", SimpleShearKinematics{}, in, igs);
}

ModelDeclaration hcc_declaration(const std::vector<std::string>& stress_components,
                                 bool interface_model, int listing_order) {
  return clay_declaration(
      stress_components, interface_model, listing_order, RoughnessScheme::kArnoldHerle,
      {{"OCR", "-", "p_e* over the ASBS pressure p (M^2 + eta^2)/M^2: 1 on the ASBS",
        DiagnosticRole::kOverconsolidation}});
}

}  // namespace

ModelSpec hcc_spec() {
  return {"hcc",
          "Masin (2012) hypoplastic Cam clay interface model on [sigma_n, sigma_p, tau_x, tau_y]",
          "seed 6.2.2 (6.5-6.10, ERRATA 13), roughness 6.22",
          true,
          {&ClayParameters::table()},
          [](const ModelInputs& in) { return build_interface(in, WithIntergranularStrain::kNo); },
          hcc_declaration(ReducedInterfaceKinematics<algebra::ReducedOps>::component_names(), true,
                          kListingOrder)};
}

ModelSpec hcc3d_spec() {
  return {"hcc3d",
          "Masin (2012) hypoplastic Cam clay, full 3x3 tensors in simple shear",
          "seed 6.2.2 (6.5-6.10, ERRATA 13)",
          false,
          {&ClayParameters::table()},
          [](const ModelInputs& in) { return build_3d(in, WithIntergranularStrain::kNo); },
          hcc_declaration(SimpleShearKinematics::component_names(), false, kListingOrder + 1)};
}

// Table 6.4 is the seed's clay set with intergranular strain; e0 1.45 is OCR 1.2 at 100 kPa.
const std::map<std::string, double> kTable64Start{{"sigma_n_kPa", 100.0}, {"e0", 1.45}};
ModelSpec hcc_igs_spec() {
  return with_intergranular_strain(hcc_spec(), build_interface, "table_6_4_cyclic.toml",
                                   kTable64Start);
}
ModelSpec hcc3d_igs_spec() {
  return with_intergranular_strain(hcc3d_spec(), build_3d, "table_6_4_cyclic.toml", kTable64Start);
}

}  // namespace iwb::models
