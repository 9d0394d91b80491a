// hvwe-rd (src/models/hvwe_rd, issue 56 candidate A): the facts of its form, each derived from the
// form's statement (e_x* = e_x (1 + chi R_n)), not from the code.
#include <fmt/core.h>
#include <toml++/toml.h>

#include <catch2/catch.hpp>

#include "element/element_test_file.hpp"
#include "support/fixtures.hpp"

using namespace iwb;

namespace {

constexpr double kChi = 0.1;

// The example set (Toyoura with chi) on a wall of normalized roughness `R_n`.
models::ModelInputs on_wall(double R_n, double chi = kChi) {
  auto in = test::shipped("hvwe_rd_example.toml");
  in.tables["roughness_dilatancy"]["chi"] = chi;
  in.roughness = {models::RoughnessScheme::kGutjahr, 0.9};
  in.roughness.R_n = R_n;
  return in;
}

test::Run cnl(const std::string& model, const models::ModelInputs& in, double gamma,
              int increments) {
  test::ShearSpec s;
  s.model = model;
  s.inputs = in;
  s.e0 = 0.70;
  s.gamma = gamma;
  s.increments = increments;
  s.settings.integrator.rtol = 1e-10;
  auto r = test::shear(s);
  REQUIRE(r.result.complete());
  return r;
}

}  // namespace

TEST_CASE("hvwe-rd: on a flat wall, with chi = 0 or with no wall described it is hvwe",
          "[models][hvwe-rd]") {
  const auto hvwe = cnl("hvwe", on_wall(0.5), 0.3, 600);
  for (const auto& in : {on_wall(0.0), on_wall(0.5, 0.0)}) {
    const auto rd = cnl("hvwe-rd", in, 0.3, 600);
    REQUIRE(rd.result.rows.size() == hvwe.result.rows.size());
    CHECK((rd.result.rows.back().state - hvwe.result.rows.back().state).norm() == 0.0);
  }
  auto undescribed = on_wall(0.5);
  undescribed.roughness.R_n.reset();
  const auto rd = cnl("hvwe-rd", undescribed, 0.3, 600);
  CHECK((rd.result.rows.back().state - hvwe.result.rows.back().state).norm() == 0.0);
}

TEST_CASE("hvwe-rd: it is hvwe over a soil whose three limit void ratios are scaled by 1 + chi R_n",
          "[models][hvwe-rd]") {
  const double R_n = 0.5, factor = 1.0 + kChi * R_n;
  auto scaled = on_wall(R_n);
  for (const char* key : {"ed0", "ec0", "ei0"}) scaled.tables["hypoplastic"][key] *= factor;
  const auto hvwe = cnl("hvwe", scaled, 0.3, 600);
  const auto rd = cnl("hvwe-rd", on_wall(R_n), 0.3, 600);
  CHECK((rd.result.rows.back().state - hvwe.result.rows.back().state).norm() <
        1e-9 * hvwe.result.rows.back().state.norm());
}

TEST_CASE(
    "hvwe-rd: sheared to its critical state under CNL, its void ratio is the soil's times 1 + chi "
    "R_n, and it dilates more on the way",
    "[models][hvwe-rd]") {
  // At the critical state f_d = 1 and the stationary stress ratio depends on a and F alone, so
  // both reach the same stress under the same sigma_n, where e_c* = (1 + chi R_n) e_c.
  const double R_n = 1.0, factor = 1.0 + kChi * R_n;
  const auto hvwe = cnl("hvwe", on_wall(R_n), 6.0, 6000);
  const auto rd = cnl("hvwe-rd", on_wall(R_n), 6.0, 6000);
  CHECK(*rd.last().sigma_p == Approx(*hvwe.last().sigma_p).epsilon(1e-3));
  CHECK(rd.last_e() / hvwe.last_e() == Approx(factor).epsilon(1e-3));
  CHECK(rd.last_e() - 0.70 > hvwe.last_e() - 0.70);
}

TEST_CASE("hvwe-rd: an element test must give the wall's R_n", "[models][hvwe-rd]") {
  const auto read = [](const std::string& roughness) {
    const std::string text = fmt::format(
        "[model]\nname = \"hvwe-rd\"\nparameters = \"data/params/hvwe_rd_example.toml\"\n{}"
        "[initial]\nsigma_n_kPa = 100\ne0 = 0.7\n[boundary]\ntype = \"CNL\"\n[path]\nkind = "
        "\"monotonic\"\ngamma = 0.1\nincrements = 10\n",
        roughness);
    return element::parse_element_test(toml::parse(text), "t.toml", ".");
  };
  CHECK_THROWS_WITH(read(""), Catch::Contains("give a [roughness] table with R_n"));
  CHECK_THROWS_WITH(read("[roughness]\nkappa_r = 0.9\n"),
                    Catch::Contains("reads the wall's R_n beside kappa_r"));
  CHECK(read("[roughness]\nR_n = 0.5\n").inputs.roughness.R_n == 0.5);
}
