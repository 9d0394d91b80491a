#include "element/element_test_keys.hpp"

#include <fmt/format.h>

#include <map>
#include <set>

#include "common/physical_limits.hpp"
#include "driver/control.hpp"
#include "driver/element_test.hpp"
#include "driver/mixed_control.hpp"
#include "element/element_test_limits.hpp"
#include "integration/butcher_tableau.hpp"
#include "integration/stress_point_integrator.hpp"
#include "models/registry.hpp"
#include "models/roughness/roughness.hpp"

namespace iwb::element {

namespace {

using io::KeyDeclaration;
using io::KeyDeclarations;
using io::KeyKind;
using io::Need;

// The defaults of what an element test runs are those of the structs that carry them (the
// driver's, the integrator's), so that a caller without a file (the C interface, the replay) and a
// file without the key start alike.
const integration::IntegratorSettings kIntegrator{};
const driver::MixedControlSettings kMixed{};
const driver::RunSettings kRun{};
const driver::ShearZone kZone{};

const std::vector<std::string> kNormalControls = driver::boundary_kind_names();

KeyDeclarations model_and_roughness_keys() {
  return {
      {.key = "description",
       .kind = KeyKind::kText,
       .value = std::string(),
       .meaning = "free text, copied to the manifest"},
      {.table = "model",
       .key = "name",
       .kind = KeyKind::kText,
       .need = Need::kRequired,
       .meaning = "the model (`iwb models` lists them with their parameters)"},
      {.table = "model",
       .key = "parameters",
       .kind = KeyKind::kPath,
       .need = Need::kRequired,
       .limit = "or inline tables `[model.parameters.<table>]`",
       .meaning = "the parameter set"},
      {.table = "roughness",
       .key = "scheme",
       .kind = KeyKind::kText,
       .default_note = "the model's",
       .meaning = "sand: `\"gutjahr\"` (eqs. 5.37-5.39) or `\"arnold-herle\"` (5.37, 5.40, "
                  "5.41); clay (hcc, hce): `\"arnold-herle\"` (phi_c kappa_r in the critical "
                  "state, 6.22) or `\"stutz-masin\"` (also nu_r, 6.23-6.28); interface models "
                  "only, and without `[roughness]` kappa_r = 1 (fully rough)"},
      {.table = "roughness",
       .key = "kappa_r",
       .range = closed(models::kKappaRFloor, 1.0),
       .need = Need::kConditional,
       .when = "one of kappa_r, R_n, delta_deg",
       .meaning = "roughness coefficient, given directly ..."},
      {.table = "roughness",
       .key = "R_n",
       .range = positive(kMaxRoughness),
       .need = Need::kConditional,
       .when = "one of kappa_r, R_n, delta_deg",
       .meaning = "... or from normalized roughness, eq. 5.35 (values below 0.05 clamp with a "
                  "warning; sand models only) ..."},
      {.table = "roughness",
       .key = "mean_abs_slope",
       .range = closed(0.0, kMaxSlope),
       .need = Need::kConditional,
       .when = "a model that reads the wall's slope (hvwe-pg)",
       .meaning = "the wall's mean |dz/dx| along the shear direction (`iwb dem roughness`): the "
                  "asperities' ride, hvwe-pg only"},
      {.table = "roughness",
       .key = "log_base",
       .range = {1.0, 1e3, true, false},
       .value = 10.0,
       .meaning = "the logarithm's base in eq. 5.35"},
      {.table = "roughness",
       .key = "delta_deg",
       .unit = "deg",
       .range = {0.0, 90.0, true, true},
       .need = Need::kConditional,
       .when = "one of kappa_r, R_n, delta_deg",
       .meaning = "... or from the interface friction angle: eq. 5.36 (sand, tan delta / tan "
                  "phi_c), eq. 6.21 (clay, delta / phi_c)"},
      {.table = "roughness",
       .key = "f_c",
       .kind = KeyKind::kText,
       .choices = {"1/kappa_r", "kappa_r"},
       .need = Need::kConditional,
       .when = "scheme = \"arnold-herle\", sand",
       .limit = "eq. 5.40 as printed, or the reading of 5.7.3 (ERRATA 9)",
       .meaning = "Arnold & Herle's rate factor for sand (`\"1/kappa_r\"` when absent)"},
  };
}

KeyDeclarations zone_and_boundary_keys() {
  return {
      {.table = "shear_zone",
       .key = "d_s_mm",
       .unit = "mm",
       .range = positive(kMaxLengthMm),
       .value = kZone.d_s_mm,
       .limit = "or d50_mm and d_s_over_d50",
       .meaning = "shear-zone thickness"},
      {.table = "shear_zone",
       .key = "d50_mm",
       .unit = "mm",
       .range = positive(kMaxLengthMm),
       .need = Need::kConditional,
       .when = "instead of d_s_mm",
       .meaning = "mean grain size; d_s = d50_mm d_s_over_d50"},
      {.table = "shear_zone",
       .key = "d_s_over_d50",
       .range = positive(kMaxLengthMm),
       .need = Need::kConditional,
       .when = "instead of d_s_mm",
       .meaning = "shear-zone thickness in grain sizes"},
      {.table = "shear_zone",
       .key = "strain_measure",
       .kind = KeyKind::kText,
       .choices = {"linear", "tangent"},
       .value = std::string("linear"),
       .meaning = "gamma = u/d_s (linear) or tan gamma = u/d_s (tangent, eq. 5.5)"},
      {.table = "boundary",
       .key = "type",
       .kind = KeyKind::kText,
       .choices = kNormalControls,
       .need = Need::kRequired,
       .limit = "in any case",
       .meaning = "the normal control: constant normal load, stiffness or volume"},
      {.table = "boundary",
       .key = "K_kPa_per_mm",
       .unit = "kPa/mm",
       .range = positive(),
       .need = Need::kConditional,
       .when = "CNS: one of K_kPa_per_mm, K_kPa",
       .meaning = "stiffness per mm of normal displacement (converted with d_s)"},
      {.table = "boundary",
       .key = "K_kPa",
       .unit = "kPa",
       .range = positive(),
       .need = Need::kConditional,
       .when = "CNS: one of K_kPa_per_mm, K_kPa",
       .meaning = "stiffness per unit normal strain"},
  };
}

KeyDeclarations path_keys() {
  const std::string strain_or_u = "one of gamma, u_mm";
  return {
      {.table = "path",
       .key = "kind",
       .kind = KeyKind::kText,
       .choices = {"monotonic", "cyclic", "staged", "oedometric", "stages"},
       .need = Need::kRequired,
       .limit = fmt::format("at most {:g} increments in all", kMaxIncrements),
       .meaning = "the path: shear at the boundary's control; cycles 0 -> +A -> -A -> 0 "
                  "(`cycles.csv`); shear with sigma_n steps (CNL); normal loading without shear; "
                  "a list of stages"},
      {.table = "path",
       .key = "direction",
       .kind = KeyKind::kText,
       .choices = {"x", "y"},
       .value = std::string("x"),
       .meaning = "shear direction (hp1d: x only; `\"y\"` is refused before the run directory is "
                  "touched)"},
      {.table = "path",
       .key = "gamma",
       .range = positive(kMaxShearStrain),
       .need = Need::kConditional,
       .when = "monotonic, staged: " + strain_or_u,
       .meaning = "total shear strain"},
      {.table = "path",
       .key = "u_mm",
       .unit = "mm",
       .range = positive(kMaxLengthMm),
       .need = Need::kConditional,
       .when = "monotonic, staged: " + strain_or_u,
       .limit = fmt::format("u/d_s at most {:g}", kMaxShearStrain),
       .meaning = "total shear displacement"},
      {.table = "path",
       .key = "increments",
       .kind = KeyKind::kWholeNumber,
       .need = Need::kConditional,
       .when = "monotonic, staged, oedometric",
       .meaning = "equal increments over the path"},
      {.table = "path",
       .key = "amplitude_gamma",
       .range = positive(kMaxShearStrain),
       .need = Need::kConditional,
       .when = "cyclic: one of amplitude_gamma, amplitude_u_mm",
       .meaning = "the cycles' amplitude A as a shear strain"},
      {.table = "path",
       .key = "amplitude_u_mm",
       .unit = "mm",
       .range = positive(kMaxLengthMm),
       .need = Need::kConditional,
       .when = "cyclic: one of amplitude_gamma, amplitude_u_mm",
       .limit = fmt::format("u/d_s at most {:g}", kMaxShearStrain),
       .meaning = "the cycles' amplitude A as a displacement"},
      {.table = "path",
       .key = "cycles",
       .kind = KeyKind::kWholeNumber,
       .need = Need::kConditional,
       .when = "cyclic",
       .meaning = "number of cycles"},
      {.table = "path",
       .key = "increments_per_quarter",
       .kind = KeyKind::kWholeNumber,
       .need = Need::kConditional,
       .when = "cyclic",
       .meaning = "increments of each quarter cycle"},
      {.table = "path",
       .key = "steps",
       .kind = KeyKind::kTables,
       .need = Need::kConditional,
       .when = "staged (CNL); cyclic (CNL), optional",
       .meaning = "sigma_n changes: staged at `at_gamma` or `at_u_mm`; cyclic ramped at zero "
                  "shear before `from_cycle`"},
      {.table = "path",
       .key = "step_increments",
       .kind = KeyKind::kWholeNumber,
       .value = 50.0,
       .meaning = "increments of each sigma_n ramp (at fixed shear)"},
      {.table = "path",
       .key = "sigma_n_end_kPa",
       .unit = "kPa",
       .range = positive(kMaxStressKPa),
       .need = Need::kConditional,
       .when = "oedometric",
       .meaning = "normal loading without shear to this stress"},
      {.table = "path",
       .key = "stage",
       .kind = KeyKind::kTables,
       .need = Need::kConditional,
       .when = "stages",
       .meaning = "the path as a list of stages `[[path.stage]]`, run in order; each spreads what "
                  "it prescribes evenly over its increments"},
  };
}

KeyDeclarations step_keys() {
  return {
      {.table = "path.steps",
       .key = "at_gamma",
       .range = positive(kMaxShearStrain),
       .need = Need::kConditional,
       .when = "staged: one of at_gamma, at_u_mm",
       .meaning = "the shear strain of a sigma_n step"},
      {.table = "path.steps",
       .key = "at_u_mm",
       .unit = "mm",
       .range = positive(kMaxLengthMm),
       .need = Need::kConditional,
       .when = "staged: one of at_gamma, at_u_mm",
       .meaning = "the shear displacement of a sigma_n step"},
      {.table = "path.steps",
       .key = "from_cycle",
       .kind = KeyKind::kWholeNumber,
       .need = Need::kConditional,
       .when = "cyclic",
       .meaning = "the first cycle at the new sigma_n"},
      {.table = "path.steps",
       .key = "sigma_n_kPa",
       .unit = "kPa",
       .range = positive(kMaxStressKPa),
       .need = Need::kRequired,
       .meaning = "the new normal stress"},
  };
}

// An external variable's path over a stage: a ramp to a value, by a change, or cycles about the
// stage's start value. The row's range is the variable's, in the key's unit.
KeyDeclaration external_path(const std::string& key, const std::string& unit, Range range,
                             const std::string& what) {
  return {.table = "path.stage",
          .key = key,
          .kind = KeyKind::kTable,
          .unit = unit,
          .range = range,
          .default_note = "held",
          .limit = "`{ to = V }`, `{ by = dV }` or `{ amplitude = A, cycles = n }` (at most " +
                   fmt::format("{}", kMaxStageCycles) + " cycles)",
          .meaning = what +
                     " (only a model that reads it: `iwb models`); a cycle goes 0 -> +A "
                     "-> 0 -> -A -> 0 about the stage's start value (`increments` a "
                     "multiple of 4 n; the run gets `cycles.csv`)"};
}

KeyDeclarations stage_keys() {
  return {
      {.table = "path.stage",
       .key = "label",
       .kind = KeyKind::kText,
       .default_note = "\"stage k\"",
       .meaning = "name in messages and in history.csv's segment labels"},
      {.table = "path.stage",
       .key = "increments",
       .kind = KeyKind::kWholeNumber,
       .need = Need::kRequired,
       .meaning = "increments of the stage"},
      {.table = "path.stage",
       .key = "gamma",
       .range = closed(-kMaxShearStrain, kMaxShearStrain),
       .value = 0.0,
       .limit = "or u_mm",
       .meaning = "shear over the stage in the path's direction (either sign; 0: held)"},
      {.table = "path.stage",
       .key = "u_mm",
       .unit = "mm",
       .range = closed(-kMaxLengthMm, kMaxLengthMm),
       .need = Need::kConditional,
       .when = "instead of gamma",
       .meaning = "shear displacement over the stage"},
      {.table = "path.stage",
       .key = "normal",
       .kind = KeyKind::kText,
       .choices = kNormalControls,
       .default_note = "[boundary] type",
       .limit = "in any case; CNS needs a [boundary] of type CNS for its K",
       .meaning = "normal control of the stage"},
      {.table = "path.stage",
       .key = "sigma_n_kPa",
       .kind = KeyKind::kTable,
       .unit = "kPa",
       .range = positive(kMaxStressKPa),
       .default_note = "held",
       .limit = "`{ to = V }`, CNL only",
       .meaning = "ramp the normal stress to V"},
      external_path("T_K", "K", kTemperatureK, "temperature"),
      external_path("T_C", "deg C", kTemperatureC,
                    "temperature in deg C (history.csv records T_K)"),
      external_path("s_kPa", "kPa", kSuctionKPa, "matric suction"),
      external_path("t_s", "s", kTimeS, "time"),
  };
}

KeyDeclarations integration_and_output_keys() {
  return {
      {.table = "integration",
       .key = "scheme",
       .kind = KeyKind::kText,
       .choices = {"adaptive", "euler"},
       .value = std::string("adaptive"),
       .meaning = "embedded Runge-Kutta, or explicit Euler (the seed's scheme)"},
      {.table = "integration",
       .key = "pair",
       .kind = KeyKind::kText,
       .choices = integration::embedded_pair_names(),
       .value = kIntegrator.pair,
       .meaning = "adaptive: Bogacki-Shampine (rk32) or Dormand-Prince (rk54)"},
      {.table = "integration",
       .key = "rtol",
       .range = kRelativeTolerance,
       .value = kIntegrator.rtol,
       .meaning = "adaptive: relative error tolerance per substep"},
      {.table = "integration",
       .key = "substeps",
       .kind = KeyKind::kWholeNumber,
       .value = double(kIntegrator.substeps),
       .meaning = "euler: equal substeps per increment"},
      {.table = "integration",
       .key = "mixed_control",
       .kind = KeyKind::kText,
       .choices = {"newton", "closed-form"},
       .value = std::string("newton"),
       .limit = "closed-form with euler only",
       .meaning = "how the normal row is met: Newton, or appendix C's closed form"},
      {.table = "integration",
       .key = "tolerance",
       .range = kRelativeTolerance,
       .value = kMixed.tolerance,
       .meaning = "relative residual of the normal row per increment"},
      {.table = "output",
       .key = "every",
       .kind = KeyKind::kWholeNumber,
       .value = double(kRun.output_every),
       .meaning = "write every n-th increment (and the last)"},
  };
}

void append(KeyDeclarations& to, KeyDeclarations rows) {
  for (auto& r : rows) to.push_back(std::move(r));
}

// One model-declared input as a row: the first model's declaration.
KeyDeclaration initial_row(const models::InitialInputSpec& in,
                           const std::vector<models::ModelSpec>& registry) {
  using models::InitialInputSpec;
  KeyDeclaration r{.table = "initial", .key = in.key, .unit = in.unit == "-" ? "" : in.unit};
  if (in.kind == InitialInputSpec::Kind::kNumber) {
    r.range = in.range;
  } else {
    r.kind = KeyKind::kText;
    r.choices = in.choices;
    r.limit = fmt::format("or three numbers [{0}_n, {0}_x, {0}_y], ||{0}|| in {1} {2}", in.key,
                          in.range.text(), in.scale_name);
    r.default_note = fmt::format("\"{}\": {}", in.choices.front(), in.default_origin);
  }
  if (in.default_value)
    r.default_note = in.need == InitialInputSpec::Need::kFixed ? "fixed by some models"
                                                               : "the model's (see meaning)";
  r.need = in.need == InitialInputSpec::Need::kRequired ? Need::kRequired : Need::kOptional;
  // a key some model groups with others (a clay's e0 | OCR): say so, whoever declared it first
  std::set<std::string> group;
  for (const auto& m : registry)
    for (const auto& other : m.declaration.initial)
      if (other.need == InitialInputSpec::Need::kOneOf)
        for (const auto& o : m.declaration.initial)
          if (o.group == other.group && other.key == in.key) group.insert(o.key);
  if (!group.empty()) {
    r.need = Need::kConditional;
    r.when = fmt::format("{}where a model groups them, one of {}",
                         in.need == InitialInputSpec::Need::kRequired ? "required; " : "",
                         fmt::join(group, ", "));
  }
  r.meaning = in.doc + " (as the model declares it)";
  return r;
}

}  // namespace

const io::KeyDeclarations& element_test_keys() {
  static const KeyDeclarations rows = [] {
    KeyDeclarations r = model_and_roughness_keys();
    append(r, zone_and_boundary_keys());
    append(r, path_keys());
    append(r, step_keys());
    append(r, stage_keys());
    append(r, integration_and_output_keys());
    return r;
  }();
  return rows;
}

// The models that take a key are not listed: a model added would change the README of every
// element-test file. A model refuses a key it does not declare and names the models that take it.
io::KeyDeclarations initial_input_keys() {
  const auto& registry = models::model_registry();
  std::vector<std::string> order;
  std::map<std::string, const models::InitialInputSpec*> first;
  for (const auto& m : registry)
    for (const auto& in : m.declaration.initial)
      if (first.try_emplace(in.key, &in).second) order.push_back(in.key);
  KeyDeclarations rows;
  for (const auto& key : order) rows.push_back(initial_row(*first[key], registry));
  return rows;
}

std::string element_test_key_table() {
  KeyDeclarations rows;
  for (const auto& r : element_test_keys()) {
    if (&r == &io::declared(element_test_keys(), "shear_zone", "d_s_mm"))  // throws if renamed
      append(rows, initial_input_keys());
    rows.push_back(r);
  }
  return io::markdown_table(rows);
}

}  // namespace iwb::element
