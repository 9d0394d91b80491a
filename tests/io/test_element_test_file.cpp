// Element-test files: bad input gives one clear message naming file, key, value and range.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "common/errors.hpp"
#include "io/element_test_file.hpp"
#include "io/toml_reader.hpp"

using namespace iwb;

namespace {

const std::string kGood = R"(
[model]
name = "hvwe"
[model.parameters.hypoplastic]
phi_c_deg = 28
hs_kPa = 2.0e6
n = 0.29
ed0 = 0.61
ec0 = 0.96
ei0 = 1.09
alpha = 0.13
beta = 2
[initial]
sigma_n_kPa = 100
e0 = 0.8
[boundary]
type = "CNL"
[path]
kind = "monotonic"
gamma = 0.1
increments = 100
)";

io::ElementTestSpec parse(const std::string& text) {
  return io::parse_element_test(io::parse_toml_text(text, "t.toml"), "t.toml", ".");
}

std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto p = text.find(from);
  REQUIRE(p != std::string::npos);
  return text.replace(p, from.size(), to);
}

}  // namespace

TEST_CASE("a good file resolves defaults and conversions", "[io]") {
  const auto spec = parse(kGood);
  CHECK(spec.model == "hvwe");
  CHECK(spec.initial.K0 == Approx(1.0 - std::sin(28.0 * M_PI / 180.0)));
  CHECK(spec.path.size() == 1);
  CHECK(spec.resolved["roughness"]["kappa_r"] == 1.0);
}

TEST_CASE("CNS stiffness per mm converts through d_s", "[io]") {
  auto text = replaced(kGood, "type = \"CNL\"", "type = \"CNS\"\nK_kPa_per_mm = 500");
  text += "[shear_zone]\nd50_mm = 0.5\nd_s_over_d50 = 4\n";
  CHECK(parse(text).boundary.K_kPa == Approx(1000.0));
}

TEST_CASE("roughness from R_n records its origin", "[io]") {
  const auto spec = parse(kGood + "[roughness]\nR_n = 0.1\n");
  CHECK(spec.inputs.roughness.kappa_r == Approx(0.8));
  CHECK(spec.resolved["roughness"]["origin"].get<std::string>().find("eq. 5.35") != std::string::npos);
}

TEST_CASE("bad input names file, key, value and allowed range", "[io]") {
  CHECK_THAT(error_of(replaced(kGood, "name = \"hvwe\"", "name = \"hvwx\"")),
             Catch::Contains("unknown model 'hvwx'") && Catch::Contains("hvwe"));
  CHECK_THAT(error_of(replaced(kGood, "n = 0.29\n", "")),
             Catch::Contains("t.toml: key 'model.parameters'") && Catch::Contains("missing key 'n'"));
  CHECK_THAT(error_of(replaced(kGood, "phi_c_deg = 28", "phi_c_deg = 91")),
             Catch::Contains("'phi_c_deg' = 91 is out of range; allowed (0, 90) deg"));
  CHECK_THAT(error_of(replaced(kGood, "increments = 100", "incremnts = 100")),
             Catch::Contains("t.toml: key 'path.increments' is missing (a whole number >= 1); did you "
                             "mean 'incremnts' (value 100)?"));
  CHECK_THAT(error_of(kGood + "[output]\nevry = 3\n"),
             Catch::Contains("t.toml: key 'output.evry' is not a known key (value 3)"));
  CHECK_THAT(error_of(replaced(kGood, "sigma_n_kPa = 100", "sigma_n_kPa = -50")),
             Catch::Contains("t.toml: key 'initial.sigma_n_kPa' = -50 is out of range; allowed (0, inf)"));
  CHECK_THAT(error_of(replaced(kGood, "type = \"CNL\"", "type = \"CNX\"")),
             Catch::Contains("key 'boundary.type'") && Catch::Contains("CNL, CNS or CV"));
  CHECK_THAT(error_of(replaced(kGood, "gamma = 0.1", "gamma = \"big\"")),
             Catch::Contains("key 'path.gamma' = \"big\" is not a number"));
  CHECK_THAT(error_of(replaced(kGood, "name = \"hvwe\"", "name = \"vw3d\"") + "[roughness]\nkappa_r = 0.5\n"),
             Catch::Contains("takes no wall roughness"));
  CHECK_THAT(error_of(kGood + "[roughness]\nkappa_r = 0.5\nR_n = 0.1\n"),
             Catch::Contains("give only one of kappa_r, R_n, delta_deg"));
  CHECK_THAT(error_of(replaced(kGood, "[boundary]", "[integration]\nscheme = \"adaptive\"\nmixed_control = \"closed-form\"\n[boundary]")),
             Catch::Contains("closed-form") && Catch::Contains("euler"));
  CHECK_THAT(error_of("[model\n"), Catch::Contains("t.toml:1:") && Catch::Contains("TOML syntax error"));
}

TEST_CASE("parameter files: a relative path resolves against the test file", "[io]") {
  const auto dir = std::filesystem::temp_directory_path() / "iwb-io-test";
  std::filesystem::create_directories(dir / "p");
  std::ofstream(dir / "p" / "sand.toml") << "[hypoplastic]\nphi_c_deg = 28\nhs_kPa = 2e6\nn = 0.29\n"
                                             "ed0 = 0.61\nec0 = 0.96\nei0 = 1.09\nalpha = 0.13\nbeta = \"two\"\n";
  std::string text = kGood;
  const auto a = text.find("[model.parameters.hypoplastic]"), b = text.find("[initial]");
  text.replace(a, b - a, "parameters = \"p/sand.toml\"\n");
  std::ofstream(dir / "test.toml") << text;
  try {
    io::load_element_test((dir / "test.toml").string());
    FAIL("expected an error");
  } catch (const InputError& e) {
    CHECK_THAT(std::string(e.what()), Catch::Contains("p/sand.toml: key 'hypoplastic.beta' = \"two\" is not a number"));
  }
}
