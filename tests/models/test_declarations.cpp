// The model contract's declarations (src/models/README.md, sections 2.2-2.7) against what each
// model does: a declaration the workbench reads instead of the model must say what the model is.
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>

#include "io/parameter_file.hpp"
#include "models/registry.hpp"

namespace iwb {

namespace {

models::ModelInputs example_inputs(const models::ModelSpec& spec) {
  const auto file = "data/params/" + spec.declaration.example_parameters;
  return {io::load_parameter_file(file), file, {}};
}

models::InitialState example_start(const models::ModelSpec& spec, const models::ModelInputs& in) {
  models::InitialState s;
  s.sigma_n = spec.declaration.example_start.at("sigma_n_kPa");
  if (spec.declaration.example_start.count("e0")) s.e0 = spec.declaration.example_start.at("e0");
  for (const auto& input : spec.declaration.initial)
    if (input.key == "K0") s.K0 = input.default_value(in);
  return s;
}

std::vector<std::string> diagnostic_names(const std::vector<models::NamedValue>& values) {
  std::vector<std::string> out;
  for (const auto& v : values) out.push_back(v.name);
  return out;
}

}  // namespace

TEST_CASE(
    "every model's declaration says what the model does: state, diagnostics, shear directions") {
  for (const auto& spec : models::model_registry()) {
    INFO(spec.name);
    const auto& d = spec.declaration;
    REQUIRE(std::filesystem::exists("data/params/" + d.example_parameters));
    const auto in = example_inputs(spec);
    const auto model = spec.make(in);
    CHECK(d.layout.names() == model->state_names());
    CHECK(d.layout.size() == model->state_size());
    CHECK(d.layout.size() <= models::kMaxStateSize);
    CHECK(d.second_shear_direction == model->has_second_shear_direction());
    // a closed-form return the model forgets to expose (a private update_of without the friend)
    // would be integrated through the rate instead: the declaration says which it is
    CHECK((d.update == models::StressPointUpdate::kIncrement) == model->updates_by_increment());
    const auto s = model->initial_state(example_start(spec, in));
    CHECK(s(0) == Approx(-d.example_start.at("sigma_n_kPa")));  // component 0: the normal stress
    if (d.layout.void_ratio >= 0)
      CHECK(s(d.layout.void_ratio) == d.example_start.at("e0"));
    else  // no void ratio declared (mc): none reported, and history.csv's e stays empty
      CHECK(std::isnan(model->void_ratio(s)));
    std::vector<std::string> declared;
    for (const auto& diag : d.diagnostics) declared.push_back(diag.name);
    CHECK(declared == diagnostic_names(model->diagnostics(s)));
  }
}

TEST_CASE(
    "the registry lists models in their declared order, each at its own place, the -igs variants "
    "after every model without intergranular strain") {
  // read from the declarations, not listed here: a new model touches its own folder only (issue 33)
  const auto& registry = models::model_registry();
  REQUIRE_FALSE(registry.empty());
  CHECK(registry.front().name == "vw3d");  // the soil model the interface models derive from
  bool igs_seen = false;
  for (std::size_t i = 0; i < registry.size(); ++i) {
    INFO(registry[i].name);
    if (i > 0)
      CHECK(registry[i - 1].declaration.listing_order < registry[i].declaration.listing_order);
    const bool igs = registry[i].name.size() > 4 &&
                     registry[i].name.compare(registry[i].name.size() - 4, 4, "-igs") == 0;
    CHECK((igs || !igs_seen));  // no plain model after the first -igs one
    igs_seen = igs_seen || igs;
  }
}

// Not a list of names: a model that joins the plan declares its rank in its own folder. What holds
// whatever joins: the ranked models are exactly those declaring a rank, in its order, each rank
// once; and the simplest of today's stay in the order chapter 4 ranks them (closed form, then
// non-linear elastic, then hypoplastic, intergranular strain last).
TEST_CASE("the interface models of the plan and the league are declared, simplest first") {
  const auto ranked = models::ranked_interface_models(true);
  std::vector<int> ranks;
  for (const auto& spec : models::model_registry())
    if (spec.declaration.plan_rank > 0) ranks.push_back(spec.declaration.plan_rank);
  REQUIRE(ranked.size() == ranks.size());
  std::sort(ranks.begin(), ranks.end());
  CHECK(std::adjacent_find(ranks.begin(), ranks.end()) == ranks.end());  // each rank once
  for (std::size_t i = 0; i < ranked.size(); ++i)
    CHECK(models::find_model(ranked[i]).declaration.plan_rank == ranks[i]);
  const auto at = [&](const std::string& name) {
    return std::find(ranked.begin(), ranked.end(), name) - ranked.begin();
  };
  CHECK(ranked.front() == "mc");
  CHECK(at("mc") < at("hyperbolic"));
  CHECK(at("hyperbolic") < at("hp1d"));
  CHECK(at("hp1d") < at("ah"));
  CHECK(at("ah") < at("hvwe"));
  CHECK(at("hvwe") < at("hvwe-rd"));  // issue 56's candidates: hvwe and one parameter, then two
  CHECK(at("hvwe-rd") < at("hvwe-pg"));
  CHECK(at("hvwe-pg") < at("hvwe-igs"));
  CHECK(at("hvwe-igs") < std::ptrdiff_t(ranked.size()));
  const auto plain = models::ranked_interface_models(false);
  CHECK(std::find(plain.begin(), plain.end(), "hvwe-igs") == plain.end());
  CHECK(plain.size() + 2 == ranked.size());  // ahe-igs and hvwe-igs join for reversing paths
}

TEST_CASE("the default K0 declared by the sand family is 1 - sin phi_c of the file's table") {
  const auto& spec = models::find_model("hvwe");
  const auto in = example_inputs(spec);
  const double phi_c = in.tables.at("hypoplastic").at("phi_c_deg") * M_PI / 180.0;
  for (const auto& input : spec.declaration.initial)
    if (input.key == "K0")
      CHECK(input.default_value(in) == Approx(1.0 - std::sin(phi_c)).epsilon(1e-15));
  const auto* ah_K0 =
      models::find_initial_input(models::find_model("ah").declaration.initial, "K0");
  REQUIRE(ah_K0 != nullptr);
  CHECK(ah_K0->need == models::InitialInputSpec::Need::kFixed);
  CHECK(ah_K0->default_value(in) == 1.0);
  CHECK(models::find_initial_input(models::find_model("hp1d").declaration.initial, "K0") ==
        nullptr);
}

TEST_CASE("an inconsistent declaration is refused, with the reason") {
  auto spec = models::find_model("hvwe-igs");
  CHECK(models::declaration_problem(spec).empty());

  auto too_big = spec;
  while (too_big.declaration.layout.size() <= models::kMaxStateSize)
    too_big.declaration.layout.components.push_back(
        {"x" + std::to_string(too_big.declaration.layout.size()), "-",
         models::ComponentKind::kHardening});
  CHECK_THAT(models::declaration_problem(too_big), Catch::Contains("more than kMaxStateSize"));

  auto e_first = spec;
  std::swap(e_first.declaration.layout.components[0], e_first.declaration.layout.components[4]);
  CHECK_THAT(models::declaration_problem(e_first),
             Catch::Contains("component 0 must be the normal stress"));

  auto twice = spec;
  twice.declaration.layout.components[1].name = "T_n";
  CHECK_THAT(models::declaration_problem(twice), Catch::Contains("'T_n' declared twice"));

  auto wrong_e = spec;
  wrong_e.declaration.layout.void_ratio = 5;
  CHECK_THAT(models::declaration_problem(wrong_e), Catch::Contains("not a void-ratio component"));

  auto wrong_external = spec;
  wrong_external.declaration.layout.external[0] = 4;
  CHECK_THAT(models::declaration_problem(wrong_external),
             Catch::Contains("not an external component"));

  auto no_schemes = spec;
  no_schemes.declaration.roughness.schemes.clear();
  CHECK_THAT(models::declaration_problem(no_schemes), Catch::Contains("uses_roughness disagrees"));

  auto table_twice = spec;
  table_twice.tables.push_back(table_twice.tables.front());
  CHECK_THAT(models::declaration_problem(table_twice), Catch::Contains("listed twice"));
}

}  // namespace iwb

namespace iwb {

// src/models/README.md section 11, item 5: phi_c was taken from the alphabetically first table
// holding a phi_c_deg key, whichever model it belonged to.
TEST_CASE("the critical friction angle is read by role, from the model's own table") {
  const auto& spec = models::find_model("hvwe");
  models::ModelInputs in = example_inputs(spec);
  in.tables["a_clay_table"] = {{"phi_c_deg", 10.0}};  // sorts before [hypoplastic]
  CHECK(models::critical_friction_angle(spec, in) == Approx(28.0 * M_PI / 180.0));
}

TEST_CASE(
    "offer: a caller that does not know the model gives what the model declares, defaults the "
    "rest") {
  const auto& hvwe = models::find_model("hvwe");
  const auto in = example_inputs(hvwe);
  const auto s = models::offer(hvwe, in, {{"sigma_n_kPa", 50.0}, {"e0", 0.7}, {"OCR", 2.0}});
  CHECK(s.sigma_n == 50.0);
  CHECK(s.e0 == 0.7);
  CHECK(s.K0 == Approx(1.0 - std::sin(28.0 * M_PI / 180.0)));
  CHECK(s.named.empty());  // hvwe declares no OCR: dropped
  CHECK(models::offer(models::find_model("ahe"), in, {{"K0", 0.4}}).K0 ==
        1.0);  // fixed by eq. 5.16
}

}  // namespace iwb
