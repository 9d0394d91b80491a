// Pile load transfer (src/pile): facts derived by hand, not from the code. A linear t-z pile (an
// elastic Mohr-Coulomb interface that never yields) against the closed-form head stiffness of a
// compressible pile on uniform springs with a base spring, with second-order mesh convergence; a
// rigid-plastic shaft (psi = 0, no cohesion, no base) whose capacity is pi D tan(phi) K0 gamma' L^2
// / 2, and the same shaft cycled in settlement; the head load equal to shaft plus base at every
// step.
#include <fmt/core.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "io/csv_table.hpp"
#include "io/json_file.hpp"
#include "io/run_directory.hpp"
#include "pile/pile_run.hpp"
#include "pile/pile_spec.hpp"

using namespace iwb;
namespace fs = std::filesystem;

namespace {

constexpr double kL = 10.0, kD = 0.5, kEA = 4.0e6, kGamma = 10.0, kK0 = 0.5;

// A pile file for mc with the given Mohr-Coulomb set, written into `dir`.
fs::path write_case(const fs::path& dir, const std::string& mc_table, double base_kN_per_mm,
                    int elements, const std::string& loading) {
  fs::create_directories(dir);
  std::ofstream(dir / "mc.toml") << "[mohr_coulomb]\n" << mc_table;
  std::ofstream(dir / "pile.toml")
      << "[pile]\nlength_m = " << kL << "\ndiameter_m = " << kD << "\nEA_kN = " << kEA
      << "\nelements = " << elements << "\n[soil]\nunit_weight_kN_m3 = " << kGamma
      << "\nK0 = " << kK0
      << "\nshear_modulus_kPa = 20000\n[base]\nstiffness_kN_per_mm = " << base_kN_per_mm
      << "\n[interface]\nmodel = \"mc\"\nparameters = \"mc.toml\"\nd_s_mm = 5\n"
      << "[loading]\n"
      << loading;
  return dir / "pile.toml";
}

fs::path run(const fs::path& file, const fs::path& out) {
  const auto spec = pile::load_pile_spec(file);
  REQUIRE(pile::run_pile(spec, {out, true, "test", io::read_file(file), nullptr, {}}) == 0);
  return out;
}

}  // namespace

TEST_CASE("pile: a linear t-z pile has the closed-form head stiffness, converging at second order",
          "[pile]") {
  // shaft spring per unit area G/d_s (mc's elastic shear), never yielding (cohesion 1e9 kPa)
  const double E = 3000.0, nu = 0.25, G = E / (2 * (1 + nu)), d_s = 0.005,
               kb = 50.0;  // kb in kN/mm
  const auto dir = fs::path(IWB_TEST_RUNS_DIR) / "pile" / "linear";
  const auto file = write_case(
      dir,
      fmt::format(
          "E_kPa = {}\nnu = {}\nphi_i_deg = 30\npsi_deg = 0\nc_kPa = 1e9\ntension_cutoff_kPa = 0\n",
          E, nu),
      kb, 20, "kind = \"settlement\"\nsettlement_mm = 10\nincrements = 2\n");
  const auto out = run(file, dir / "run");
  // d2w/dz2 = mu^2 w, mu^2 = pi D (G/d_s) / EA; P/w_h = EA mu (Omega + tanh mu L)/(1 + Omega tanh
  // mu L), Omega = k_b/(EA mu)
  const double mu = std::sqrt(M_PI * kD * G / d_s / kEA), omega = kb * 1000.0 / (kEA * mu);
  const double stiffness = kEA * mu * (omega + std::tanh(mu * kL)) /
                           (1.0 + omega * std::tanh(mu * kL)) / 1000.0;  // kN/mm
  const auto summary = io::read_json_file(out / "summary.json");
  const double P = summary["end"]["head_load_kN"].get<double>();
  CHECK(P / 10.0 == Approx(stiffness).epsilon(2e-3));
  // halving h divides the error by 4: the observed order of the three meshes (10, 20, 40 elements)
  CHECK(summary["mesh_convergence"]["observed_order"].get<double>() == Approx(2.0).epsilon(0.05));
  CHECK(summary["mesh_convergence"]["extrapolated"].get<double>() / 10.0 ==
        Approx(stiffness).epsilon(1e-5));
}

TEST_CASE(
    "pile: a rigid-plastic shaft carries pi D tan(phi) K0 gamma' L^2 / 2, head = shaft + base at "
    "every step",
    "[pile]") {
  const auto dir = fs::path(IWB_TEST_RUNS_DIR) / "pile" / "plastic";
  const auto file = write_case(
      dir,
      "E_kPa = 3e6\nnu = 0.25\nphi_i_deg = 30\npsi_deg = 0\nc_kPa = 0\ntension_cutoff_kPa = 0\n",
      0.0, 10, "kind = \"settlement\"\nsettlement_mm = 50\nincrements = 10\n");
  const auto out = run(file, dir / "run");
  const double capacity = M_PI * kD * std::tan(M_PI / 6) * kK0 * kGamma * kL * kL /
                          2.0;  // the midpoint rule is exact on z
  const auto summary = io::read_json_file(out / "summary.json");
  CHECK(summary["end"]["head_load_kN"].get<double>() == Approx(capacity).epsilon(1e-9));
  const auto curve = io::read_csv_table(out / "load_settlement.csv");
  const auto head = curve.values("head_load_kN"), shaft = curve.values("shaft_load_kN"),
             base = curve.values("base_load_kN");
  for (std::size_t r = 0; r < head.size(); ++r)
    CHECK(head[r] == Approx(shaft[r] + base[r]).margin(1e-9 * capacity));
}

TEST_CASE(
    "pile: a rigid-plastic shaft cycled in settlement slips at tan(phi) both ways, carries +- pi D "
    "tan(phi) K0 gamma' L^2 / 2 at +-A and keeps its normal stress (psi = 0)",
    "[pile][cyclic]") {
  // A = 5 mm, far beyond the slip's elastic part and the pile's shortening under its capacity
  // (P L / 2 EA = 0.28 mm): at +-A every stress point slips, at tau = +-tan(phi) sigma_n0(z)
  constexpr double kAmplitude = 5.0;
  const auto dir = fs::path(IWB_TEST_RUNS_DIR) / "pile" / "plastic_cycles";
  const auto file = write_case(
      dir,
      "E_kPa = 3e6\nnu = 0.25\nphi_i_deg = 30\npsi_deg = 0\nc_kPa = 0\ntension_cutoff_kPa = 0\n",
      0.0, 10,
      fmt::format("kind = \"cyclic_settlement\"\namplitude_mm = {}\ncycles = 3\n"
                  "increments_per_quarter = 4\n",
                  kAmplitude));
  const auto out = run(file, dir / "run");
  const double capacity = M_PI * kD * std::tan(M_PI / 6) * kK0 * kGamma * kL * kL / 2.0;
  const auto curve = io::read_csv_table(out / "load_settlement.csv");
  const auto w = curve.values("head_settlement_mm"), shaft = curve.values("shaft_load_kN");
  int at_plus = 0, at_minus = 0;
  for (std::size_t r = 0; r < w.size(); ++r) {
    if (w[r] == Approx(kAmplitude).epsilon(1e-12)) {
      ++at_plus;
      CHECK(shaft[r] == Approx(capacity));
    }
    if (w[r] == Approx(-kAmplitude).epsilon(1e-12)) {
      ++at_minus;
      CHECK(shaft[r] == Approx(-capacity));
    }
  }
  CHECK(at_plus == 3);
  CHECK(at_minus == 3);
  // the shaft as one interface: its mean tau over its mean sigma_n is tan(phi) at every depth's
  // slip, so its peak friction each way is tan(phi); no dilatancy, so sigma_n stays sigma_n0
  const auto cycles = io::read_json_file(out / "summary.json")["cycles"]["cycles"];
  REQUIRE(cycles.size() == 3);
  for (const auto& c : cycles) {
    CHECK(c["peak_friction_positive"].get<double>() == Approx(std::tan(M_PI / 6)).epsilon(1e-9));
    CHECK(c["peak_friction_negative"].get<double>() == Approx(std::tan(M_PI / 6)).epsilon(1e-9));
    CHECK(c["sigma_n_ratio"].get<double>() == Approx(1.0).epsilon(1e-12));
  }
}

TEST_CASE(
    "pile: a load beyond the capacity fails the run, which says so and keeps what it reached "
    "(the profiles at the last state, the summary)",
    "[pile]") {
  // the rigid-plastic shaft carries pi D tan(phi) K0 gamma' L^2 / 2 = 227 kN, no base: 300 kN
  // cannot be carried, the head's Newton fails at the ramp's last step (and its subdivisions)
  const auto dir = fs::path(IWB_TEST_RUNS_DIR) / "pile" / "beyond_capacity";
  const auto file = write_case(
      dir,
      "E_kPa = 3e6\nnu = 0.25\nphi_i_deg = 30\npsi_deg = 0\nc_kPa = 0\ntension_cutoff_kPa = 0\n",
      0.0, 10,
      "kind = \"cyclic_load\"\nmean_kN = 300\namplitude_kN = 10\ncycles = 1\n"
      "increments_per_quarter = 4\n");
  const auto spec = pile::load_pile_spec(file);
  const fs::path out = dir / "run";
  CHECK(pile::run_pile(spec, {out, true, "test", io::read_file(file), nullptr, {}}) == 1);
  const auto manifest = io::read_json_file(out / "manifest.json");
  CHECK_THAT(manifest["status"].get<std::string>(), Catch::StartsWith("failed: "));
  CHECK(io::read_json_file(out / "summary.json")["status"] == manifest["status"]);
  CHECK_FALSE(io::read_csv_table(out / "profiles.csv").rows.empty());
}
