#include "models/hypoplastic/family.hpp"

#include <fmt/core.h>

#include <cmath>

#include "common/physical_limits.hpp"

namespace iwb::models {

namespace {

// R of the parameters' intergranular strain table: the scale of an initial intergranular strain.
double intergranular_strain_R(const ModelInputs& in) {
  return require_table(in, IntergranularStrainParameters::table().name).at("R");
}

// In the order a test file's [initial] is read (the first bad value is the one reported). The
// default K0 is the oedometric 1 - sin phi_c of the phi_c_deg in `friction_table`.
std::vector<InitialInputSpec> rate_form_initial_inputs(InPlaneStart start,
                                                       const std::string& friction_table) {
  InitialInputSpec sigma_n{"sigma_n_kPa", "kPa",
                           "initial normal stress sigma_n0, compression positive"};
  sigma_n.range = positive(kMaxStressKPa);
  InitialInputSpec e0{"e0", "-",
                      "initial void ratio, inside (e_d, e_i) at the initial mean stress"};
  e0.range = positive(kMaxVoidRatio);
  std::vector<InitialInputSpec> in{sigma_n, e0};
  if (start == InPlaneStart::kNone) return in;
  InitialInputSpec k0{"K0", "-", "sigma_p0 = K0 sigma_n0 (default: 1 - sin phi_c)"};
  k0.range = positive(kMaxK0);
  k0.need = InitialInputSpec::Need::kOptional;
  k0.default_value = [friction_table](const ModelInputs& inputs) {
    return 1.0 - std::sin(require_table(inputs, friction_table).at("phi_c_deg") * M_PI / 180.0);
  };
  if (start == InPlaneStart::kIsotropic) {
    k0.doc = "fixed at 1: the kinematics start from sigma_p = sigma_n (eq. 5.16)";
    k0.need = InitialInputSpec::Need::kFixed;
    k0.default_value = [](const ModelInputs&) { return 1.0; };
  }
  in.push_back(k0);
  return in;
}

}  // namespace

std::vector<FitParameter> interface_fit_parameters() {
  FitParameter kappa{"kappa_r", FitParameter::Target::kRoughness};
  kappa.lower = kKappaRFloor, kappa.upper = 1.0;
  FitParameter d_s{"d_s_mm", FitParameter::Target::kShearZone};
  d_s.lower = 1.0, d_s.upper = 40.0, d_s.per_d50 = true, d_s.logarithmic = true;
  return {kappa, d_s};
}

std::vector<FitParameter> interface_fit_parameters_from_normalized_roughness() {
  auto fit = interface_fit_parameters();
  fit.front().predict = [](const WallDescription& wall) -> std::pair<double, std::string> {
    if (!(wall.R_n > 0.0))
      return {kKappaRFloor,
              fmt::format("kappa_r = {} (flat wall: eq. 5.35's floor)", kKappaRFloor)};
    const double k = kappa_r_from_normalized_roughness(wall.R_n).value;
    return {k, fmt::format("kappa_r = {:.3f} (eq. 5.35, R_n = {:.3g})", k, wall.R_n)};
  };
  return fit;
}

ModelDeclaration rate_form_declaration(const std::vector<std::string>& stress_components,
                                       InPlaneStart start, int listing_order,
                                       const std::string& friction_table) {
  ModelDeclaration d;
  d.listing_order = listing_order;
  for (const auto& c : stress_components)
    d.layout.components.push_back({c, "kPa", ComponentKind::kStress});
  d.layout.void_ratio = d.layout.size();
  d.layout.components.push_back({"e", "-", ComponentKind::kVoidRatio});
  d.initial = rate_form_initial_inputs(start, friction_table);
  d.second_shear_direction = start != InPlaneStart::kNone;
  return d;
}

ModelDeclaration hypoplastic_declaration(const std::vector<std::string>& stress_components,
                                         bool interface_model, InPlaneStart start,
                                         int listing_order) {
  ModelDeclaration d =
      rate_form_declaration(stress_components, start, listing_order, "hypoplastic");
  d.diagnostics = {
      {"mean_stress_kPa", "kPa", "mean stress -tr T / tr 1", DiagnosticRole::kMeanStress},
      {"e_i", "-", "maximum void ratio at the mean stress (eq. 5.13)",
       DiagnosticRole::kMaxVoidRatio},
      {"e_c", "-", "critical void ratio at the mean stress (eq. 5.13)",
       DiagnosticRole::kCriticalVoidRatio},
      {"e_d", "-", "minimum void ratio at the mean stress (eq. 5.13)",
       DiagnosticRole::kMinVoidRatio}};
  if (interface_model) {
    d.roughness = {{RoughnessScheme::kGutjahr, RoughnessScheme::kArnoldHerle},
                   RoughnessScheme::kGutjahr,
                   true,
                   KappaFromAngle::kTangentRatio};
    d.fit = interface_fit_parameters_from_normalized_roughness();
  }
  d.calibration_recipe = "herle-gudehus";
  d.example_parameters = "table_5_1_evaluation.toml";
  d.example_start = {{"sigma_n_kPa", 100.0}, {"e0", 0.8}};
  return d;
}

IntergranularStrainParameters intergranular_strain_parameters(const ModelInputs& in) {
  return IntergranularStrainParameters::from(require_table(in, "intergranular_strain"),
                                             in.source + " [intergranular_strain]");
}

// -igs models list after every base model, in their bases' order.
constexpr int kIntergranularListingOffset = 100;

ModelSpec with_intergranular_strain(ModelSpec base, HypoplasticBuilder build,
                                    const std::string& example_parameters,
                                    std::map<std::string, double> example_start) {
  base.name += "-igs";
  base.summary += ", with Niemunis & Herle's intergranular strain";
  base.equations += "; intergranular strain 5.42-5.48 (ERRATA 10)";
  base.tables.push_back(&IntergranularStrainParameters::table());
  base.make = [build](const ModelInputs& in) { return build(in, WithIntergranularStrain::kYes); };
  auto& d = base.declaration;
  d.listing_order += kIntergranularListingOffset;
  d.plan_rank = 0;  // a candidate of `iwb plan` only where its folder says so
  const int stress_size = d.layout.void_ratio;  // the packed stress precedes e
  for (int i = 0; i < stress_size; ++i)
    d.layout.components.push_back({"delta" + d.layout.components[i].name.substr(1), "-",
                                   ComponentKind::kIntergranularStrain});
  InitialInputSpec delta{"delta", "-", "initial intergranular strain [delta_n, delta_x, delta_y]"};
  delta.kind = InitialInputSpec::Kind::kKeywordOrVector3;
  delta.need = InitialInputSpec::Need::kOptional;
  delta.choices = {"seed"};
  delta.default_vector = [](const ModelInputs& in) {
    return seed_initial_intergranular_strain(intergranular_strain_R(in));
  };
  delta.default_origin = "seed 5.6 after oedometric loading: [0, R/sqrt(3), R/sqrt(3)]";
  // Beyond 2 R an initial intergranular strain is taken as a units mistake (e.g. a percentage):
  // the seed's own default has ||delta|| = 2R/sqrt(3) = 1.155 R (README).
  delta.range = closed(0.0, 2.0);
  delta.scale_name = "R";
  delta.scale = intergranular_strain_R;
  delta.norm = [](const std::array<double, 3>& d) {  // of the tensor: delta_x = delta_12 = delta_21
    return std::sqrt(d[0] * d[0] + 2.0 * (d[1] * d[1] + d[2] * d[2]));
  };
  d.initial.push_back(delta);
  d.diagnostics.push_back(
      {"rho", "-", "||delta|| / R (eq. 5.45)", DiagnosticRole::kIntergranularRho});
  d.example_parameters = example_parameters;
  if (!example_start.empty()) d.example_start = std::move(example_start);
  return base;
}

}  // namespace iwb::models
