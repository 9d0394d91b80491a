// Coarse-graining (src/coarse_graining): facts that hold whatever the code, from the definitions
// (Weinhart et al. 2012) and from configurations whose continuum fields are known by hand.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "coarse_graining/fields.hpp"

using namespace iwb::coarse_graining;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSpacing = 1e-3;  // lattice spacing, m
constexpr int kN = 6;              // lattice points along x and y; 2 kN along z

// A simple cubic lattice filling [0, kN a) x [0, kN a) x [0, 2 kN a), grains of radius 0.4 a, with
// velocity v(r) and spin omega(r).
template <class Velocity, class Spin>
Snapshot lattice(Velocity velocity, Spin spin) {
  Snapshot s;
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j)
      for (int k = 0; k < 2 * kN; ++k) {
        const Eigen::Vector3d r((i + 0.5) * kSpacing, (j + 0.5) * kSpacing, (k + 0.5) * kSpacing);
        s.grains.push_back({r, velocity(r), spin(r), 0.4 * kSpacing, 2.0e-6});
      }
  return s;
}

const PeriodicCell kCell{kN * kSpacing, kN* kSpacing};
// A Gaussian as wide as the lattice's spacing averages it out: the sampling error of a lattice sum
// is ~ 2 exp(-2 pi^2 w^2 / a^2) = 5e-9 relative (Poisson summation).
const GaussianKernel kKernel(kSpacing);
const double kMiddle = kN * kSpacing;  // half the lattice's height: 6 widths from either face

Eigen::Vector3d zero(const Eigen::Vector3d&) {
  return Eigen::Vector3d::Zero();
}

double at_height(const FieldSet& f, const HeightProfile& p, const std::string& name, double z) {
  return f[name][std::size_t(std::lround((z - p.z(0)) / p.spacing()))];
}

}  // namespace

TEST_CASE("a lattice's coarse-grained solid fraction is its grains' volume per cell",
          "[coarse_graining]") {
  const auto s = lattice(zero, zero);
  const double expected = 4.0 / 3.0 * kPi * std::pow(0.4, 3);  // (4/3) pi r^3 / a^3
  const HeightProfile profile(kKernel, kCell, 0.25 * kSpacing, 0.0, 2 * kN * kSpacing);
  const auto f = coarse_grain(s, profile);
  CHECK(at_height(f, profile, "solid_fraction", kMiddle) == Approx(expected).epsilon(1e-7));
  const PlaneGrid plane(kKernel, kCell, 0.25 * kSpacing, 0.0, 2 * kN * kSpacing);
  const auto g = coarse_grain(s, plane);
  const std::size_t j = std::size_t(std::lround(kMiddle / plane.hz()));
  for (int k = 0; k < plane.nx(); k += 3)
    CHECK(g["solid_fraction"][j * plane.nx() + k] == Approx(expected).epsilon(1e-7));
}

TEST_CASE("the solid fraction integrates to the grains' volume (mass balance)",
          "[coarse_graining]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Snapshot s;
  double volume = 0.0;
  for (int i = 0; i < 300; ++i) {
    const double r = (0.3 + 0.2 * u(rng)) * kSpacing;
    s.grains.push_back(
        {{u(rng) * kCell.length_x, u(rng) * kCell.length_y, (2 + 8 * u(rng)) * kSpacing},
         Eigen::Vector3d::Zero(),
         Eigen::Vector3d::Zero(),
         r,
         1e-6});
    volume += 4.0 / 3.0 * kPi * r * r * r;
  }
  const GaussianKernel kernel(0.5 * kSpacing);
  const HeightProfile profile(kernel, kCell, 0.1 * kSpacing, -1 * kSpacing,
                              13 * kSpacing);  // covers 5 widths beyond the grains
  const auto nu = coarse_grain(s, profile)["solid_fraction"];
  double integral = 0.0;  // trapezoidal: the kernel is smooth on the spacing, the ends are zero
  for (double v : nu) integral += v * profile.spacing();
  CHECK(integral * kCell.length_x * kCell.length_y == Approx(volume).epsilon(1e-6));
}

TEST_CASE("a rigid translation has no strain rate, no vorticity and the grains' velocity",
          "[coarse_graining]") {
  const Eigen::Vector3d v(0.3, -0.1, 0.05);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Snapshot s;  // random positions and masses: the translation's fields do not depend on them
  for (int i = 0; i < 400; ++i)
    s.grains.push_back({{u(rng) * kCell.length_x, u(rng) * kCell.length_y, 12 * kSpacing * u(rng)},
                        v,
                        Eigen::Vector3d::Zero(),
                        0.4 * kSpacing,
                        (1 + u(rng)) * 1e-6});
  const GaussianKernel kernel(0.5 * kSpacing);
  const PlaneGrid plane(kernel, kCell, 0.25 * kSpacing, 2 * kSpacing, 10 * kSpacing);
  const auto f = coarse_grain(s, plane);
  const double scale = v.norm() / kernel.width();  // a strain rate's natural size here
  for (std::size_t i = 0; i < plane.size(); i += 7) {
    CHECK(std::abs(f["strain_rate_xz_1_s"][i]) < 1e-12 * scale);
    CHECK(std::abs(f["strain_rate_xx_1_s"][i]) < 1e-12 * scale);
    CHECK(std::abs(f["vorticity_y_1_s"][i]) < 1e-12 * scale);
    CHECK(f["velocity_x_m_s"][i] == Approx(v.x()).epsilon(1e-12));
    CHECK(f["velocity_z_m_s"][i] == Approx(v.z()).epsilon(1e-12));
    CHECK(std::abs(f["kinetic_pressure_Pa"][i]) < 1e-12 * f["density_kg_m3"][i] * v.squaredNorm());
  }
}

TEST_CASE("simple shear on a lattice gives its gradient, its vorticity and no Cosserat rotation",
          "[coarse_graining]") {
  const double rate = 2.5;  // 1/s
  // v_x = rate z; grains rolling with the continuum spin at half the vorticity, omega_y = rate / 2
  const auto s =
      lattice([&](const Eigen::Vector3d& r) { return Eigen::Vector3d(rate * r.z(), 0, 0); },
              [&](const Eigen::Vector3d&) { return Eigen::Vector3d(0, 0.5 * rate, 0); });
  const HeightProfile profile(kKernel, kCell, 0.25 * kSpacing, 0.0, 2 * kN * kSpacing);
  const auto f = coarse_grain(s, profile);
  CHECK(at_height(f, profile, "shear_rate_dvx_dz_1_s", kMiddle) == Approx(rate).epsilon(1e-6));
  CHECK(at_height(f, profile, "velocity_x_m_s", kMiddle) == Approx(rate * kMiddle).epsilon(1e-6));
  const PlaneGrid plane(kKernel, kCell, 0.5 * kSpacing, 0.0, 2 * kN * kSpacing);
  const auto g = coarse_grain(s, plane);
  const std::size_t i = std::size_t(std::lround(kMiddle / plane.hz())) * plane.nx() + 2;
  CHECK(g["strain_rate_xz_1_s"][i] == Approx(0.5 * rate).epsilon(1e-6));
  CHECK(g["vorticity_y_1_s"][i] == Approx(rate).epsilon(1e-6));
  CHECK(std::abs(g["cosserat_rotation_y_rad_s"][i]) < 1e-6 * rate);
}

TEST_CASE("contact forces on a lattice give the stress a free-body cut gives",
          "[coarse_graining]") {
  // Every grain pushes on the one above with a normal force N and drags it along +x with T: a
  // horizontal cut of area a^2 carries N and T per column, so sigma_zz = N / a^2 and the material
  // below drags the material above with tau = sigma_xz = T / a^2 (compression positive, the wall's
  // sign: CONVENTIONS.md); sigma_xx = 0.
  const double N = 2.0, T = 0.7;  // newtons
  auto s = lattice(zero, zero);
  for (const Grain& lower : s.grains) {
    const Eigen::Vector3d upper = lower.position + Eigen::Vector3d(0, 0, kSpacing);
    if (upper.z() > 2 * kN * kSpacing) continue;
    s.contacts.push_back(
        {upper, lower.position, Eigen::Vector3d(T, 0, N)});  // force on the upper grain
  }
  const HeightProfile profile(kKernel, kCell, 0.25 * kSpacing, 0.0, 2 * kN * kSpacing);
  const auto f = coarse_grain(s, profile);
  CHECK(at_height(f, profile, "stress_zz_Pa", kMiddle) ==
        Approx(N / (kSpacing * kSpacing)).epsilon(1e-7));
  CHECK(at_height(f, profile, "stress_xz_Pa", kMiddle) ==
        Approx(T / (kSpacing * kSpacing)).epsilon(1e-7));
  CHECK(std::abs(at_height(f, profile, "stress_xx_Pa", kMiddle)) <
        1e-9 * N / (kSpacing * kSpacing));
}

TEST_CASE("the kernel's closed-form branch integrals equal quadrature", "[coarse_graining]") {
  const GaussianKernel k(0.7);
  const auto simpson = [](auto f) {
    const int n = 4000;
    double sum = f(0.0) + f(1.0);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(double(i) / n);
    return sum / (3.0 * n);
  };
  for (const auto& [a, b] :
       std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>{{{-0.3, 0.2}, {0.9, -0.4}},
                                                                {{1.5, 1.0}, {2.5, 1.1}},
                                                                {{0.1, -2.0}, {0.1, 2.0}},
                                                                {{0.2, 0.3}, {0.2, 0.3}}}) {
    const double q = simpson([&, &a = a, &b = b](double s) {
      const Eigen::Vector2d r = a + s * (b - a);
      return k.planar(-r.x(), -r.y()).phi;
    });
    CHECK(k.planar_along(a, b) == Approx(q).epsilon(1e-10));
    const double qz = simpson(
        [&, &a = a, &b = b](double s) { return k.vertical(-(a.y() + s * (b.y() - a.y()))).phi; });
    CHECK(k.vertical_along(a.y(), b.y()) == Approx(qz).epsilon(1e-10));
  }
}
