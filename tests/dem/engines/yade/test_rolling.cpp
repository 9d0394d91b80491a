// YADE stands in for LIGGGHTS's rolling models with one elastic-plastic moment (yade_engine.cpp).
// The expected values come from YADE itself: two d50 grains of the scene's material pressed
// together by sigma_n0 d50^2, and the stiffnesses YADE's Mindlin law gives that contact.
#include <fmt/format.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "common/subprocess.hpp"
#include "dem/engines/yade/yade_engine.hpp"
#include "dem/scene/scene.hpp"

namespace fs = std::filesystem;
using namespace iwb;
using namespace iwb::dem;

namespace {

// Finds by bisection the overlap at which YADE's Hertz force is F0, then prints the contact's
// normal and tangential stiffnesses and its bending-moment cap per unit force, eta R_mean, at
// eta = kProbeEta.
constexpr double kProbeEta = 0.05;
constexpr const char* kProbe = R"(
import sys
E, nu, d, F0, eta = [float(x) for x in sys.argv[1:6]]
m = O.materials.append(FrictMat(young=E, poisson=nu, frictionAngle=0.5, density=2650))
O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
             InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_MindlinPhys(krot=1.0, eta=eta)],
                             [Law2_ScGeom_MindlinPhys_Mindlin(includeMoment=True)]),
             NewtonIntegrator(gravity=(0, 0, 0))]
O.dt = 1e-12
def contact(overlap):
    O.interactions.clear(); O.bodies.clear()
    O.bodies.append(utils.sphere((0, 0, 0), d / 2, material=m, fixed=True))
    O.bodies.append(utils.sphere((0, 0, d - overlap), d / 2, material=m, fixed=True))
    O.run(1, True)
    return O.interactions[0, 1].phys
lo, hi = 0.0, 1e-2 * d
for _ in range(200):
    mid = 0.5 * (lo + hi)
    if contact(mid).normalForce.norm() < F0: lo = mid
    else: hi = mid
p = contact(0.5 * (lo + hi))
print("probe", p.normalForce.norm(), p.kn, p.ks, p.maxBendPl)
)";

std::map<std::string, double> yade_contact(const Scene& s) {
  const fs::path dir =
      fs::temp_directory_path() / ("iwb_yade_rolling_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "probe.py") << kProbe;
  const double f0 = s.boundary.sigma_n_Pa * s.particles.d50_m * s.particles.d50_m;
  std::map<std::string, double> out;
  const auto arg = [](double v) {
    return fmt::format("{:.17g}", v);
  };  // every digit: to_string keeps 6 decimals
  run_process({"yade", "-n", "-x", "probe.py", arg(s.particles.youngs_modulus_Pa),
               arg(s.particles.poisson), arg(s.particles.d50_m), arg(f0), arg(kProbeEta)},
              dir, [&out](const std::string& line) {
                std::istringstream in(line);
                std::string tag;
                if (in >> tag && tag == "probe")
                  in >> out["force"] >> out["kn"] >> out["ks"] >> out["cap_per_force"];
                return true;
              });
  fs::remove_all(dir);
  return out;
}

}  // namespace

TEST_CASE(
    "YADE's rolling spring for an epsd2 scene is LIGGGHTS's k_t R*^2 of a d50 contact at sigma_n0, "
    "its cap mu_r R* F_n",
    "[dem][yade][heavy]") {
  const Scene truth = load_scene("data/scenes/truth.toml");
  REQUIRE(truth.particles.rolling_model == "epsd2");
  const auto contact = yade_contact(truth);
  REQUIRE(contact.count("ks") == 1);
  const double f0 = truth.boundary.sigma_n_Pa * truth.particles.d50_m * truth.particles.d50_m;
  CHECK(contact.at("force") == Approx(f0).epsilon(1e-6));
  const double r_star = truth.particles.d50_m / 4.0;
  const auto rolling = YadeEngine().numerics(truth)["rolling"];
  // rolling_model_epsd2.h: kr = kt reff^2, kt being the same Mindlin stiffness as YADE's ks
  CHECK(rolling["krot"].get<double>() == Approx(contact.at("ks") * r_star * r_star).epsilon(1e-4));
  // YADE's cap per unit force is eta R_mean: equal to LIGGGHTS's mu_r R* for two d50 grains
  const double eta = rolling["eta"].get<double>();
  CHECK(eta * contact.at("cap_per_force") / kProbeEta ==
        Approx(truth.particles.rolling_friction * r_star).epsilon(1e-9));
}

TEST_CASE("YADE's rolling spring for a cdt scene stays Ai et al.'s 2.25 k_n mu_r^2 R*^2",
          "[dem][yade][heavy]") {
  Scene cdt = load_scene("data/scenes/truth.toml");
  cdt.particles.rolling_model = "cdt";
  const auto contact = yade_contact(cdt);
  REQUIRE(contact.count("kn") == 1);
  const double r_star = cdt.particles.d50_m / 4.0, mu_r = cdt.particles.rolling_friction;
  CHECK(YadeEngine().numerics(cdt)["rolling"]["krot"].get<double>() ==
        Approx(2.25 * contact.at("kn") * mu_r * mu_r * r_star * r_star).epsilon(1e-4));
}
