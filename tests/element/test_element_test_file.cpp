// Element-test files: bad input gives one clear message naming file, key, value and range.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/errors.hpp"
#include "element/element_run.hpp"
#include "element/element_test_file.hpp"
#include "io/toml_reader.hpp"
#include "support/replaced.hpp"

using namespace iwb;
using iwb::test::replaced;

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

element::ElementTestSpec parse(const std::string& text) {
  return element::parse_element_test(io::parse_toml_text(text, "t.toml"), "t.toml", ".");
}

std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
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
  CHECK(spec.resolved["roughness"]["origin"].get<std::string>().find("eq. 5.35") !=
        std::string::npos);
}

TEST_CASE("bad input names file, key, value and allowed range", "[io]") {
  CHECK_THAT(error_of(replaced(kGood, "name = \"hvwe\"", "name = \"hvwx\"")),
             Catch::Contains("unknown model 'hvwx'") && Catch::Contains("hvwe"));
  CHECK_THAT(
      error_of(replaced(kGood, "n = 0.29\n", "")),
      Catch::Contains("t.toml: key 'model.parameters'") && Catch::Contains("missing key 'n'"));
  CHECK_THAT(error_of(replaced(kGood, "phi_c_deg = 28", "phi_c_deg = 91")),
             Catch::Contains("'phi_c_deg' = 91 is out of range; allowed (0, 90) deg"));
  CHECK_THAT(
      error_of(replaced(kGood, "increments = 100", "incremnts = 100")),
      Catch::Contains("t.toml: key 'path.increments' is missing (a whole number >= 1); did you "
                      "mean 'incremnts' (value 100)?"));
  CHECK_THAT(error_of(kGood + "[output]\nevry = 3\n"),
             Catch::Contains("t.toml: key 'output.evry' is not a known key (value 3)"));
  CHECK_THAT(error_of(replaced(kGood, "sigma_n_kPa = 100", "sigma_n_kPa = -50")),
             Catch::Contains(
                 "t.toml: key 'initial.sigma_n_kPa' = -50 is out of range; allowed (0, 100000]"));
  CHECK_THAT(error_of(replaced(kGood, "type = \"CNL\"", "type = \"CNX\"")),
             Catch::Contains("key 'boundary.type'") && Catch::Contains("CNL, CNS or CV"));
  CHECK_THAT(error_of(replaced(kGood, "gamma = 0.1", "gamma = \"big\"")),
             Catch::Contains("key 'path.gamma' = \"big\" is not a number"));
  CHECK_THAT(error_of(replaced(kGood, "name = \"hvwe\"", "name = \"vw3d\"") +
                      "[roughness]\nkappa_r = 0.5\n"),
             Catch::Contains("takes no wall roughness"));
  CHECK_THAT(error_of(kGood + "[roughness]\nkappa_r = 0.5\nR_n = 0.1\n"),
             Catch::Contains("give only one of kappa_r, R_n, delta_deg"));
  CHECK_THAT(
      error_of(replaced(
          kGood, "[boundary]",
          "[integration]\nscheme = \"adaptive\"\nmixed_control = \"closed-form\"\n[boundary]")),
      Catch::Contains("closed-form") && Catch::Contains("euler"));
  CHECK_THAT(error_of("[model\n"),
             Catch::Contains("t.toml:1:") && Catch::Contains("TOML syntax error"));
}

TEST_CASE("parameter files: a relative path resolves against the test file", "[io]") {
  const auto dir = std::filesystem::temp_directory_path() / "iwb-io-test";
  std::filesystem::create_directories(dir / "p");
  std::ofstream(dir / "p" / "sand.toml")
      << "[hypoplastic]\nphi_c_deg = 28\nhs_kPa = 2e6\nn = 0.29\n"
         "ed0 = 0.61\nec0 = 0.96\nei0 = 1.09\nalpha = 0.13\nbeta = \"two\"\n";
  std::string text = kGood;
  const auto a = text.find("[model.parameters.hypoplastic]"), b = text.find("[initial]");
  text.replace(a, b - a, "parameters = \"p/sand.toml\"\n");
  std::ofstream(dir / "test.toml") << text;
  try {
    element::load_element_test((dir / "test.toml").string());
    FAIL("expected an error");
  } catch (const InputError& e) {
    CHECK_THAT(std::string(e.what()),
               Catch::Contains("p/sand.toml: key 'hypoplastic.beta' = \"two\" is not a number"));
  }
}

namespace {
// kGood with hvwe-igs and Table 5.3's intergranular-strain columns inline.
std::string igs_file(const std::string& initial_extra = "") {
  auto text = replaced(kGood, "name = \"hvwe\"", "name = \"hvwe-igs\"");
  text = replaced(text, "[initial]",
                  "[model.parameters.intergranular_strain]\nR = 1e-4\nm_R = 5\nm_T = 2\n"
                  "beta_r = 0.12\nchi = 1\n[initial]\n" +
                      initial_extra);
  return text;
}
}  // namespace

TEST_CASE("initial intergranular strain: the seed's default, given values, and bad ones",
          "[io][igs]") {
  const auto seed = parse(igs_file());
  REQUIRE(seed.initial.delta.has_value());
  CHECK((*seed.initial.delta)[0] == 0.0);
  CHECK((*seed.initial.delta)[1] == Approx(1e-4 / std::sqrt(3.0)));
  CHECK((*seed.initial.delta)[2] == Approx(1e-4 / std::sqrt(3.0)));
  CHECK(seed.resolved["initial"]["delta"]["origin"].get<std::string>().find("seed 5.6") !=
        std::string::npos);

  const auto given = parse(igs_file("delta = [-1e-4, 0, 0]\n"));
  CHECK((*given.initial.delta)[0] == -1e-4);

  CHECK_THAT(error_of(igs_file("delta = [1e-4, 0]\n")),
             Catch::Contains("t.toml: key 'initial.delta' = [0.0001, 0]") &&
                 Catch::Contains("three numbers"));
  CHECK_THAT(error_of(igs_file("delta = [0, 1e-3, 0]\n")),
             Catch::Contains("key 'initial.delta'") && Catch::Contains("allowed [0, 2] R"));
  CHECK_THAT(error_of(igs_file("delta = \"oedometric\"\n")),
             Catch::Contains("should be \"seed\" or three numbers"));
  CHECK_THAT(error_of(replaced(kGood, "e0 = 0.8", "e0 = 0.8\ndelta = [0, 0, 0]")),
             Catch::Contains("key 'initial.delta'") &&
                 Catch::Contains("model 'hvwe' takes no initial intergranular strain") &&
                 Catch::Contains("(hvwe-igs does; or remove the key)"));
  // an input another family declares (hcthm's temperature) is named, not merely unknown
  CHECK_THAT(
      error_of(replaced(kGood, "e0 = 0.8", "e0 = 0.8\nT_K = 300")),
      Catch::Contains("key 'initial.T_K' = 300: model 'hvwe' takes no initial temperature") &&
          Catch::Contains("`iwb models` says which do"));
  CHECK_THAT(error_of(replaced(igs_file(), "chi = 1", "chi = 0")),
             Catch::Contains("key 'chi' = 0 is out of range; allowed (0, 100]"));
}

TEST_CASE("cyclic paths with staged sigma_n are read, and the stages need CNL", "[io][cyclic]") {
  const std::string cyclic =
      "kind = \"cyclic\"\namplitude_gamma = 0.01\ncycles = 3\nincrements_per_quarter = 5\n"
      "steps = [ { from_cycle = 2, sigma_n_kPa = 200 } ]\n";
  auto text = replaced(kGood, "kind = \"monotonic\"\ngamma = 0.1\nincrements = 100\n", cyclic);
  const auto spec = parse(text);
  CHECK(spec.path.size() == 10);
  CHECK(spec.resolved["path"]["steps"][0]["from_cycle"] == 2);
  CHECK_THAT(error_of(replaced(text, "type = \"CNL\"", "type = \"CV\"")),
             Catch::Contains("key 'path.steps'") && Catch::Contains("need boundary type CNL"));
  CHECK_THAT(error_of(replaced(text, "from_cycle = 2", "from_cycle = 4")),
             Catch::Contains("stage 1 (from_cycle = 4) does not"));
}

TEST_CASE("a cyclic run directory holds cycles.csv, one row per cycle, listed in the manifest",
          "[io][cyclic]") {
  const std::string cyclic =
      "kind = \"cyclic\"\namplitude_u_mm = 0.002\ncycles = 3\nincrements_per_quarter = 5\n";
  const auto text =
      replaced(igs_file(), "kind = \"monotonic\"\ngamma = 0.1\nincrements = 100\n", cyclic) +
      "[shear_zone]\nd_s_mm = 2\n";
  const auto spec = parse(text);
  const auto dir = std::filesystem::temp_directory_path() / "iwb-io-cycles";
  element::ElementRunOptions opt;
  opt.out = dir;
  opt.force = true;
  opt.input_text = text;
  const auto outcome = element::run_element_to_directory(spec, opt);
  REQUIRE(outcome.result.complete());
  std::ifstream in(dir / "cycles.csv");
  std::string line;
  std::vector<std::string> lines;
  while (std::getline(in, line)) lines.push_back(line);
  REQUIRE(lines.size() == 4);
  CHECK(lines[0].rfind("cycle,tau_max_kPa,tau_min_kPa,sigma_n_at_plus_reversal_kPa", 0) == 0);
  CHECK(lines[3].rfind("3,", 0) == 0);
  CHECK(lines[3].substr(lines[3].size() - 2) == ",1");  // complete
  // u_n through d_s = 2 mm: u_n_end_mm (column 7) = 2 eps_n
  std::vector<std::string> fields;
  std::stringstream row(lines[3]);
  for (std::string f; std::getline(row, f, ',');) fields.push_back(f);
  REQUIRE(fields.size() == 10);
  CHECK(std::stod(fields[6]) == Approx(2.0 * outcome.result.cycles.back().eps_n_end));
  CHECK(outcome.manifest["files"].dump().find("cycles.csv") != std::string::npos);
}

TEST_CASE("element-test values are finite and within their physical range", "[io]") {
  CHECK_THAT(error_of(replaced(kGood, "sigma_n_kPa = 100", "sigma_n_kPa = inf")),
             Catch::Contains("t.toml: key 'initial.sigma_n_kPa' = inf is not a finite number"));
  CHECK_THAT(error_of(replaced(kGood, "e0 = 0.8", "e0 = nan")),
             Catch::Contains("t.toml: key 'initial.e0' = nan is not a finite number"));
  CHECK_THAT(error_of(replaced(kGood, "gamma = 0.1", "gamma = 1e6")),
             Catch::Contains("t.toml: key 'path.gamma' = 1e+06 is out of range; allowed (0, 10]"));
  CHECK_THAT(error_of(replaced(kGood, "gamma = 0.1", "u_mm = 500")),
             Catch::Contains("t.toml: key 'path.u_mm' = 500 is a shear strain of 500 over d_s = 1 "
                             "mm; allowed up to 10"));
  CHECK_THAT(
      error_of(kGood + "[integration]\nrtol = 2\n"),
      Catch::Contains("t.toml: key 'integration.rtol' = 2 is out of range; allowed (0, 0.1]"));
  CHECK_THAT(error_of(replaced(kGood, "hs_kPa = 2.0e6", "hs_kPa = inf")),
             Catch::Contains("key 'hypoplastic.hs_kPa' = inf is not a finite number"));
  CHECK_THAT(error_of(replaced(kGood, "hs_kPa = 2.0e6", "hs_kPa = 1e300")),
             Catch::Contains("key 'hs_kPa' = 1e+300 is out of range; allowed (0, 1e+09] kPa"));
}

// src/models/README.md section 11, item 2: AH and AHE start from sigma_p = sigma_n whatever K0
// (eq. 5.16), so their manifests say so; hp1d has no in-plane stress at all.
TEST_CASE(
    "[initial] is read as the model declares it: AH's fixed K0, hp1d's missing in-plane stress",
    "[io]") {
  const auto ah = parse(replaced(kGood, "name = \"hvwe\"", "name = \"ah\""));
  CHECK(ah.initial.K0 == 1.0);
  CHECK(ah.resolved["initial"]["K0"] == 1.0);
  CHECK(ah.resolved["initial"]["sigma_p_kPa"] == 100.0);
  CHECK(ah.warnings.empty());

  const auto given = parse(replaced(replaced(kGood, "name = \"hvwe\"", "name = \"ah\""), "e0 = 0.8",
                                    "e0 = 0.8\nK0 = 0.5"));
  CHECK(given.initial.K0 == 1.0);
  REQUIRE(given.warnings.size() == 1);
  CHECK_THAT(given.warnings[0],
             Catch::Contains("key 'initial.K0' = 0.5 is ignored") && Catch::Contains("eq. 5.16"));

  const auto hp1d = parse(replaced(replaced(kGood, "name = \"hvwe\"", "name = \"hp1d\""),
                                   "e0 = 0.8", "e0 = 0.8\nK0 = 0.5"));
  CHECK_FALSE(hp1d.resolved["initial"].contains("sigma_p_kPa"));
  CHECK_FALSE(hp1d.resolved["initial"].contains("K0"));
  REQUIRE(hp1d.warnings.size() == 1);
  CHECK_THAT(hp1d.warnings[0], Catch::Contains("hp1d has no in-plane stress"));

  const auto hvwe = parse(replaced(kGood, "e0 = 0.8", "e0 = 0.8\nK0 = 0.5"));
  CHECK(hvwe.initial.K0 == 0.5);
  CHECK(hvwe.resolved["initial"]["sigma_p_kPa"] == 50.0);
  CHECK(hvwe.warnings.empty());
}

// The wall roughness as the model declares it: hcc takes Arnold & Herle's scheme (its default),
// kappa_r from an angle ratio (eq. 6.21), and no R_n (eq. 5.35 is Gutjahr's, for sand).
TEST_CASE("[roughness] is read as the model declares it: clay's scheme, angle rule and no R_n",
          "[io]") {
  const std::string clay = R"(
[model]
name = "hcc"
parameters = "data/params/table_6_1_evaluation.toml"
[initial]
sigma_n_kPa = 100
e0 = 0.7
[boundary]
type = "CV"
[path]
kind = "monotonic"
gamma = 0.1
increments = 100
)";
  const auto with = [&](const std::string& roughness) {
    return clay + "[roughness]\n" + roughness;
  };
  const auto by_angle = parse(with("delta_deg = 20\n"));
  CHECK(by_angle.inputs.roughness.scheme == models::RoughnessScheme::kArnoldHerle);
  CHECK(by_angle.inputs.roughness.kappa_r == Approx(20.0 / 25.0));
  CHECK(by_angle.resolved["roughness"]["scheme"] == "arnold-herle");
  CHECK_THAT(error_of(with("R_n = 0.5\n")), Catch::Contains("model 'hcc' takes no R_n"));
  CHECK_THAT(error_of(with("scheme = \"gutjahr\"\nkappa_r = 0.8\n")),
             Catch::Contains("allowed \"arnold-herle\""));
  // sand keeps both schemes, Gutjahr's by default and eq. 5.36's tangent ratio
  const auto sand = parse(replaced(kGood, "[initial]", "[roughness]\ndelta_deg = 20\n[initial]"));
  CHECK(sand.inputs.roughness.scheme == models::RoughnessScheme::kGutjahr);
  CHECK(sand.inputs.roughness.kappa_r ==
        Approx(std::tan(20.0 * M_PI / 180.0) / std::tan(28.0 * M_PI / 180.0)));
}

TEST_CASE("a clay's density is e0 or OCR, exactly one", "[io]") {
  const std::string clay = R"(
[model]
name = "hcc"
parameters = "data/params/table_6_1_evaluation.toml"
[boundary]
type = "CV"
[path]
kind = "monotonic"
gamma = 0.1
increments = 100
[initial]
sigma_n_kPa = 100
)";
  const auto by_ocr = parse(clay + "OCR = 2\n");
  CHECK(by_ocr.initial.named.at("OCR") == 2.0);
  CHECK(by_ocr.resolved["initial"]["OCR"] == 2.0);
  CHECK_THAT(error_of(clay), Catch::Contains("give the density as e0 or OCR"));
  CHECK_THAT(error_of(clay + "OCR = 2\ne0 = 0.7\n"),
             Catch::Contains("e0 and OCR both set the density"));
  CHECK_THAT(error_of(clay + "OCR = 0.5\n"),
             Catch::Contains("key 'initial.OCR' = 0.5 is out of range"));
  CHECK_THAT(error_of(replaced(kGood, "e0 = 0.8", "e0 = 0.8\nOCR = 2")),
             Catch::Contains("OCR"));  // sand: no OCR
}
