// hvwe-pg (src/models/hvwe_pg, issue 56 candidate B): the facts of its form, each derived from the
// form's statement (eps_n = eps_n,soil + beta_w m_w exp(-u_s/lambda_w) |gamma_rate|), not from the
// code.
#include <fmt/core.h>
#include <toml++/toml.h>

#include <catch2/catch.hpp>
#include <cmath>

#include "element/element_test_file.hpp"
#include "support/fixtures.hpp"

using namespace iwb;

namespace {

constexpr double kBeta = 0.5, kLambdaD50 = 5.0, kD50 = 0.2, kSlope = 0.4;

// The example set (Toyoura with beta, lambda_w) on a wall of mean |slope| `slope`, d_s 1 mm.
models::ModelInputs on_wall(double slope, double beta = kBeta) {
  auto in = test::shipped("hvwe_pg_example.toml");
  in.tables["asperity_dilatancy"]["beta_w"] = beta;
  in.tables["asperity_dilatancy"]["lambda_w_d50"] = kLambdaD50;
  in.roughness = {models::RoughnessScheme::kGutjahr, 0.9};
  in.roughness.mean_abs_slope = slope;
  in.d50_mm = kD50;
  return in;
}

test::Run sheared(const std::string& model, const models::ModelInputs& in,
                  driver::BoundaryKind kind) {
  test::ShearSpec s;
  s.model = model;
  s.inputs = in;
  s.bc = {kind, 0.0};
  s.e0 = 0.70;
  s.gamma = 2.0;  // u_x = 2 mm at d_s 1 mm: two lambda_w
  s.increments = 2000;
  s.output_every = 100;
  s.settings.integrator.rtol = 1e-10;
  auto r = test::shear(s);
  REQUIRE(r.result.complete());
  return r;
}

}  // namespace

TEST_CASE("hvwe-pg: on a flat wall, with beta_w = 0 or with no wall described the soil is hvwe's",
          "[models][hvwe-pg]") {
  const auto hvwe = sheared("hvwe", on_wall(kSlope), driver::BoundaryKind::kCV);
  auto undescribed = on_wall(kSlope);
  undescribed.roughness.mean_abs_slope.reset();
  for (const auto& in : {on_wall(0.0), on_wall(kSlope, 0.0), undescribed}) {
    const auto pg = sheared("hvwe-pg", in, driver::BoundaryKind::kCV);
    const auto& a = pg.result.rows.back().state;
    const auto& b = hvwe.result.rows.back().state;
    CHECK((a.head(b.size()) - b).norm() == 0.0);
  }
}

TEST_CASE(
    "hvwe-pg: under CNL the soil's path is hvwe's and u_n gains the ride's integral, beta_w m_w "
    "lambda_w (1 - exp(-u_x / lambda_w))",
    "[models][hvwe-pg]") {
  const auto hvwe = sheared("hvwe", on_wall(kSlope), driver::BoundaryKind::kCNL);
  const auto pg = sheared("hvwe-pg", on_wall(kSlope), driver::BoundaryKind::kCNL);
  REQUIRE(pg.result.rows.size() == hvwe.result.rows.size());
  const double lambda = kLambdaD50 * kD50;  // mm; d_s = 1 mm, so u_x = gamma_x in mm
  for (std::size_t i = 0; i < pg.result.rows.size(); ++i) {
    CHECK(pg.stress(i).tau_x == Approx(hvwe.stress(i).tau_x).epsilon(1e-6));  // CNL held to 1e-7
    const double u = pg.result.rows[i].gamma_x;
    const double ride = kBeta * kSlope * lambda * (1.0 - std::exp(-u / lambda));
    CHECK(pg.result.rows[i].eps_n - hvwe.result.rows[i].eps_n == Approx(ride).margin(1e-6));
  }
}

TEST_CASE("hvwe-pg: under constant volume the ride compresses the soil", "[models][hvwe-pg]") {
  const auto hvwe = sheared("hvwe", on_wall(kSlope), driver::BoundaryKind::kCV);
  const auto pg = sheared("hvwe-pg", on_wall(kSlope), driver::BoundaryKind::kCV);
  CHECK(pg.last().sigma_n > 1.05 * hvwe.last().sigma_n);
  CHECK(pg.last_e() < hvwe.last_e());  // the soil took the ride as compression
}

TEST_CASE("hvwe-pg: an element test must give the wall's slope and the grains' d50",
          "[models][hvwe-pg]") {
  const auto read = [](const std::string& tables) {
    const std::string text = fmt::format(
        "[model]\nname = \"hvwe-pg\"\nparameters = \"data/params/hvwe_pg_example.toml\"\n{}"
        "[initial]\nsigma_n_kPa = 100\ne0 = 0.7\n[boundary]\ntype = \"CNL\"\n[path]\nkind = "
        "\"monotonic\"\ngamma = 0.1\nincrements = 10\n",
        tables);
    return element::parse_element_test(toml::parse(text), "t.toml", ".");
  };
  CHECK_THROWS_WITH(read(""), Catch::Contains("give a [roughness] table with mean_abs_slope"));
  CHECK_THROWS_WITH(read("[roughness]\nkappa_r = 0.9\n"), Catch::Contains("give mean_abs_slope"));
  const auto ok = read(
      "[roughness]\nkappa_r = 0.9\nmean_abs_slope = 0.4\n[shear_zone]\nd50_mm = 0.2\n"
      "d_s_over_d50 = 5\n");
  CHECK(ok.inputs.roughness.mean_abs_slope == 0.4);
  CHECK(ok.inputs.d50_mm == 0.2);
  CHECK_THROWS_WITH(models::find_model("hvwe-pg").make(
                        read("[roughness]\nkappa_r = 0.9\nmean_abs_slope = 0.4\n").inputs),
                    Catch::Contains("no d50 is given"));
}
