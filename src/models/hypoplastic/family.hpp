#pragma once
// Building a member of the hypoplastic family from its inputs: shared by the model folders so each
// of them states only what makes it different (kinematics and variant data).
#include <memory>

#include "models/hypoplastic/hypoplastic_model.hpp"
#include "models/registry.hpp"

namespace iwb::models {

enum class WithIntergranularStrain : bool { kNo = false, kYes = true };

// The [intergranular_strain] table of `in`, checked; shared by every hypoplastic law.
IntergranularStrainParameters intergranular_strain_parameters(const ModelInputs& in);

// A member of the family over the rate law `Law`, with or without the intergranular strain.
template <class Law, class Kinematics>
std::unique_ptr<Model> make_member(const std::string& name, const Kinematics& kin,
                                   const typename Law::Constants& c, const ModelInputs& in,
                                   WithIntergranularStrain igs) {
  using Member = HypoplasticModel<Kinematics, Law>;
  if (igs == WithIntergranularStrain::kNo) return std::make_unique<Member>(name, kin, c);
  return std::make_unique<Member>(name + "-igs", kin, c, intergranular_strain_parameters(in));
}

// The [hypoplastic] table of `in`, checked.
inline HypoplasticParameters hypoplastic_parameters(const ModelInputs& in) {
  return HypoplasticParameters::from(require_table(in, "hypoplastic"),
                                     in.source + " [hypoplastic]");
}

// A member over the given parameters: a form that changes the soil's constants by what else it
// reads (the wall's roughness dilatancy, models/hvwe_rd) passes them changed.
template <class Kinematics>
std::unique_ptr<Model> make_hypoplastic(const std::string& name, const Kinematics& kin,
                                        const HypoplasticVariant& variant,
                                        const HypoplasticParameters& p, const ModelInputs& in,
                                        WithIntergranularStrain igs) {
  const auto c =
      make_constants(p, variant, in.roughness, HypoplasticModel<Kinematics>::trace_of_unit());
  return make_member<VonWolffersdorffLaw>(name, kin, c, in, igs);
}

template <class Kinematics>
std::unique_ptr<Model> make_hypoplastic(
    const std::string& name, const Kinematics& kin, const HypoplasticVariant& variant,
    const ModelInputs& in, WithIntergranularStrain igs = WithIntergranularStrain::kNo) {
  return make_hypoplastic(name, kin, variant, hypoplastic_parameters(in), in, igs);
}

// How a member of the family starts: K0 free with the oedometric default (hvwe, vw3d), fixed at
// 1 by the kinematics (AH, AHE: eq. 5.16), or absent (hp1d has no in-plane stress).
enum class InPlaneStart { kFreeK0, kIsotropic, kNone };

// What every rate-form model with a packed stress and a void ratio declares alike: the layout
// (the kinematics' stress components, then e), sigma_n_kPa, e0 and, with an in-plane stress, K0
// (default 1 - sin phi_c of `friction_table`'s phi_c_deg), the shear directions.
ModelDeclaration rate_form_declaration(const std::vector<std::string>& stress_components,
                                       InPlaneStart start, int listing_order,
                                       const std::string& friction_table);

// kappa_r in [0.05, 1] and d_s in [1, 40] d50 (log): what `iwb compare` fits of an interface model.
std::vector<FitParameter> interface_fit_parameters();
// The same with kappa_r predicted from the wall's normalized roughness by Gutjahr's eq. 5.35
// (sand): what `iwb compare` replays without a fit.
std::vector<FitParameter> interface_fit_parameters_from_normalized_roughness();

// The declaration the sand family shares (src/models/README.md 8.1): the kinematics' stress
// components and e, sigma_n_kPa, K0 and e0 at the start, mean stress and Bauer's limiting void
// ratios as diagnostics, and for interface models Gutjahr's and Arnold & Herle's roughness with
// kappa_r and d_s for `iwb compare` to fit.
ModelDeclaration hypoplastic_declaration(const std::vector<std::string>& stress_components,
                                         bool interface_model, InPlaneStart start,
                                         int listing_order);

// `d` as a candidate of `iwb plan` at `rank` (simplest first).
inline ModelDeclaration with_plan_rank(ModelDeclaration d, int rank) {
  d.plan_rank = rank;
  return d;
}

// Builds one member of the family, with or without the intergranular strain.
using HypoplasticBuilder = std::unique_ptr<Model> (*)(const ModelInputs&, WithIntergranularStrain);

// The spec of `base` extended by the intergranular strain (seed 5.6): name `<base>-igs`, one more
// parameter table, the delta components, the initial delta, rho, and `make` = `build` with the
// extension; its example set is `example_parameters` (a file of data/params/ with both tables).
ModelSpec with_intergranular_strain(
    ModelSpec base, HypoplasticBuilder build,
    const std::string& example_parameters = "table_5_3_toyoura.toml",
    std::map<std::string, double> example_start = {});

}  // namespace iwb::models
