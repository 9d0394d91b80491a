// hvwe-rd: hvwe whose interface is looser-limited on a rough wall (issue 56, candidate A of
// data/models_beyond/README.md): the limit void ratios e_d0, e_c0, e_i0 of the soil, held as the
// soil tests give them, are raised by the factor 1 + chi R_n at a wall of normalized roughness
// R_n. At the wall's void ratio the interface is then denser relative to its limits: f_d falls
// (stiffer, more dilative), and the critical state lies at a looser e (more total dilation). On a
// flat wall (R_n = 0) or with chi = 0 it is hvwe.
#include <fmt/core.h>

#include "models/hypoplastic/family.hpp"

namespace iwb::models {

namespace {

// chi's box: 0 is hvwe; 0.3 per unit R_n raises the limits by 30 % on the roughest wall judged
// (R_n 1), which is past any start of the truth grains (e0 0.63-0.65 against e_d 0.57 at 50 kPa:
// e_d stays below e0 only while chi R_n < 0.11).
constexpr double kChiUpper = 0.3;

// Listed after the seed's interface models (iwb models).
constexpr int kListingOrder = 40;

const ParameterTable& roughness_dilatancy_table() {
  static const ParameterTable t{
      "roughness_dilatancy",
      {{"chi",
        "-",
        {0.0, false},
        {1.0, false},
        "rise of the interface's limit void ratios per unit R_n: e_x* = e_x (1 + chi R_n), "
        "x = d, c, i (0: hvwe)",
        "issue 56, data/models_beyond/README.md (candidate A)",
        ParameterRole::kMaterial,
        CalibrationBox{0.0, kChiUpper, false}}}};
  return t;
}

// The soil's limits raised by the wall: the ratios among them, and so the barotropy factor's
// (e_i0/e_c0)^beta and ((e_i0-e_d0)/(e_c0-e_d0))^alpha, stay the soil's.
HypoplasticParameters at_the_wall(HypoplasticParameters p, double chi, double R_n) {
  const double factor = 1.0 + chi * R_n;
  p.ed0 *= factor, p.ec0 *= factor, p.ei0 *= factor;
  return p;
}

std::unique_ptr<Model> build(const ModelInputs& in, WithIntergranularStrain igs) {
  const auto& table = require_table(in, "roughness_dilatancy");
  validate(roughness_dilatancy_table(), table, in.source + " [roughness_dilatancy]");
  // where no wall is described (the stability map, a pile) the wall is taken as smooth: hvwe
  const double R_n = in.roughness.R_n.value_or(0.0);
  const auto p = at_the_wall(hypoplastic_parameters(in), table.at("chi"), R_n);
  return make_hypoplastic("hvwe-rd", ReducedInterfaceKinematics<algebra::ReducedOps>{},
                          HypoplasticVariant{}, p, in, igs);
}

}  // namespace

ModelSpec hvwe_rd_spec() {
  ModelSpec spec{
      "hvwe-rd",
      "hvwe with the limit void ratios raised by the wall's roughness (1 + chi R_n)",
      "seed 5.2, 5.4, 5.5 as hvwe; e_x (1 + chi R_n) (issue 56, candidate A)",
      true,
      {&HypoplasticParameters::table(), &roughness_dilatancy_table()},
      [](const ModelInputs& in) { return build(in, WithIntergranularStrain::kNo); },
      hypoplastic_declaration(ReducedInterfaceKinematics<algebra::ReducedOps>::component_names(),
                              true, InPlaneStart::kFreeK0, kListingOrder)};
  spec.declaration.roughness.reads_normalized_roughness = true;
  spec.declaration.example_parameters = "hvwe_rd_example.toml";
  // tried by `iwb plan` and the league after hvwe, whose form it extends by one parameter (its
  // chi from a set fitted to DEM walls: --params-for hvwe-rd=FILE)
  spec.declaration.plan_rank = 9;
  return spec;
}

}  // namespace iwb::models
