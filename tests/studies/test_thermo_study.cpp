// iwb run --study thermo (src/studies/): every case runs, the page holds its figures, and the CV
// ends obey the critical state line of Masin's law at each temperature, derived from its equations.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fmt/core.h>
#include <sstream>

#include "io/json_file.hpp"
#include "io/run_directory.hpp"
#include "studies/thermo_study.hpp"

using namespace iwb;
namespace fs = std::filesystem;

namespace {

double last_value(const fs::path& run, const std::string& column) {
  std::istringstream in(io::read_file(run / "history.csv"));
  std::string header, line, last;
  std::getline(in, header);
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  std::istringstream h(header), l(last);
  std::string name, value;
  while (std::getline(h, name, ',') && std::getline(l, value, ','))
    if (name == column) return std::stod(value);
  return NAN;
}

}  // namespace

TEST_CASE("thermo study: every case completes, the page holds every figure, CV ends on the heated critical state line",
          "[studies]") {
  const auto dir = fs::path(IWB_TEST_RUNS_DIR) / "thermo-study";
  fs::remove_all(dir);
  const auto study = studies::thermo_study();
  REQUIRE(studies::run_study(study, {dir, false, "test", nullptr}) == 0);
  for (const auto& c : study.cases) {
    INFO(c.name);
    CHECK(io::read_json_file(dir / c.name / "manifest.json")["status"] == "complete");
  }
  const auto json = io::read_json_file(dir / "study.json");
  REQUIRE(json["claims"].size() == 8);
  CHECK(json["claims"][0]["holds"] == true);  // reduced = 3D
  const std::string html = io::read_file(dir / "thermo.html");
  std::size_t svgs = 0;
  for (auto p = html.find("<svg"); p != std::string::npos; p = html.find("<svg", p + 1)) ++svgs;
  CHECK(svgs == study.figures.size());
  // Under CV e stays 0.44; Masin's critical state is f_d = 1 on the Matsuoka-Nakai cone, i.e.
  // p = p_e / 2 with p_e = exp[(N(T) - ln(1+e)) / lambda*], N(T) = 0.88 - 0.01 ln(T / 298.15) (Soil 1)
  for (double T_C : {25.0, 40.0, 60.0}) {
    const double N = 0.88 - 0.01 * std::log((T_C + 273.15) / 298.15);
    const double p_cs = 0.5 * std::exp((N - std::log(1.44)) / 0.09);
    const auto run = dir / fmt::format("cv_T{:g}", T_C);
    INFO(T_C << " deg C: p at the end against p_e / 2 = " << p_cs);
    CHECK(last_value(run, "e") == Approx(0.44).epsilon(1e-12));
    CHECK(last_value(run, "mean_stress_kPa") == Approx(p_cs).epsilon(0.02));
  }
}
