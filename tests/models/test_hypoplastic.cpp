// The hypoplastic family: rate-level facts (rate independence, consistent derivatives, the
// equivalences ERRATA items 2 and 3 state, Gutjahr's eq. 3.75 re-derived) and the states the
// models must reach (critical state, compression lines).
#include <catch2/catch.hpp>
#include <random>

#include "algebra/ops.hpp"
#include "models/hypoplastic/von_wolffersdorff.hpp"
#include "support/fixtures.hpp"

using namespace iwb;
using iwb::test::make;

namespace {

// Random admissible reduced states [T_n, T_p, T_x, T_y, e] (tension positive) of Table 5.1 sand.
std::vector<models::StateVector> reduced_states(int n, bool with_tau_y = true) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto p =
      models::HypoplasticParameters::from(test::table_5_1().tables.at("hypoplastic"), "t");
  std::vector<models::StateVector> out;
  for (int i = 0; i < n; ++i) {
    const double sn = 10.0 + 990.0 * u(rng), sp = sn * (0.4 + 0.8 * u(rng));
    const double tx = (u(rng) - 0.5) * 0.6 * sn, ty = with_tau_y ? (u(rng) - 0.5) * 0.3 * sn : 0.0;
    const auto lim = models::limiting_void_ratios(sn + 2 * sp, p);
    models::StateVector s(5);
    s << -sn, -sp, tx, ty, lim.e_d + (0.05 + 0.9 * u(rng)) * (lim.e_i - lim.e_d);
    out.push_back(s);
  }
  return out;
}

models::InterfaceStrain random_strain(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return {1e-4 * u(rng), 1e-4 * u(rng), 0.5e-4 * u(rng)};
}

models::StateVector to_3d(const models::StateVector& r) {  // [11, 22, 33, 12, 13, 23, e]
  models::StateVector s(7);
  s << r(0), r(1), r(1), r(2), r(3), 0.0, r(4);
  return s;
}

// The model an -igs model extends.
std::string base_of(const std::string& name) {
  return test::has_intergranular_strain(name) ? name.substr(0, name.size() - 4) : name;
}

// `s` (a state of the base model) with an intergranular strain [delta_n, delta_x, delta_y]
// (tensor components) appended when `m` carries one, packed like its stress.
models::StateVector with_delta(const models::Model& m, const models::StateVector& s, double dn,
                               double dx, double dy) {
  if (m.state_size() == s.size()) return s;
  if (m.state_size() == s.size() + 1) {  // hvwe-pg: the travelled shear strain, some way along
    models::StateVector out(m.state_size());
    out << s, 0.2;
    return out;
  }
  models::StateVector out(m.state_size());
  out.head(s.size()) = s;
  if (m.state_size() - s.size() == 6)
    out.tail(6) << dn, 0.0, 0.0, dx, dy, 0.0;
  else
    out.tail(4) << dn, 0.0, dx, dy;
  return out;
}

}  // namespace

TEST_CASE("every model is rate independent: rate(s, l d) = l rate(s, d) for l > 0", "[models]") {
  std::mt19937 rng(1);
  for (const auto& spec : models::model_registry()) {
    if (!test::is_sand(spec)) continue;  // sand states; the clay models' own: tests/models/hcc
    const auto m = make(spec.name);
    const std::string base = base_of(spec.name);
    for (const auto& r : reduced_states(50, base != "hp1d")) {
      models::StateVector s = base == "vw3d" ? to_3d(r) : r;
      if (base == "hp1d") s = (models::StateVector(3) << r(0), r(2), r(4)).finished();
      if (base == "ah" || base == "ahe") s(1) = s(0);
      s = with_delta(*m, s, -0.3e-4, 0.5e-4, -0.2e-4);
      auto d = random_strain(rng);
      if (spec.name == "hp1d") d.gamma_y = 0.0;
      models::StateVector r1, r2;
      m->rate(s, d, r1);
      for (double l : {1e-3, 0.5, 7.0}) {
        m->rate(s, {l * d.eps_n, l * d.gamma_x, l * d.gamma_y}, r2);
        CHECK((r2 - l * r1).cwiseAbs().maxCoeff() <= 1e-12 * l * r1.cwiseAbs().maxCoeff());
      }
    }
  }
}

TEST_CASE("dual-number rates carry the finite-difference derivative in eps_n", "[models]") {
  std::mt19937 rng(2);
  for (const std::string name : {"hvwe", "vw3d", "ah", "hp1d", "hvwe-igs", "vw3d-igs", "ahe-igs"}) {
    const auto m = make(name);
    const std::string base = base_of(name);
    int k = 0;
    for (const auto& r : reduced_states(20, false)) {
      models::StateVector s = base == "vw3d" ? to_3d(r) : r;
      if (base == "hp1d") s = (models::StateVector(3) << r(0), r(2), r(4)).finished();
      if (base == "ah" || base == "ahe") s(1) = s(0);
      // intergranular strain inside, on and beyond ||delta|| = R (and zero), both branches
      const double rho[] = {0.0, 0.4, 1.0, 1.1547};
      const double sign = (k % 2 == 0) ? 1.0 : -1.0;
      s = with_delta(*m, s, 0.0, sign * rho[k % 4] * 1e-4 / std::sqrt(2.0), 0.0);
      ++k;
      auto d = random_strain(rng);
      d.gamma_y = 0.0;
      models::StateVectorT<Dual> rd;
      m->rate(s.cast<Dual>(), {make_variable(d.eps_n), Dual(d.gamma_x), Dual(0.0)}, rd);
      const double h = 1e-7 * std::abs(d.gamma_x);
      models::StateVector rp, rm, r0;
      m->rate(s, {d.eps_n + h, d.gamma_x, 0.0}, rp);
      m->rate(s, {d.eps_n - h, d.gamma_x, 0.0}, rm);
      m->rate(s, d, r0);
      for (int i = 0; i < s.size(); ++i) {
        CHECK(rd(i).value() == Approx(r0(i)).epsilon(1e-13).margin(1e-300));
        const double fd = (rp(i) - rm(i)) / (2 * h);
        CHECK(derivative_of(rd(i)) ==
              Approx(fd).epsilon(1e-5).margin(1e-6 * std::abs(r0(i)) / std::abs(d.gamma_x)));
      }
    }
  }
}

TEST_CASE("hvwe equals vw3d in simple shear, rate by rate (ERRATA 3)", "[models]") {
  std::mt19937 rng(3);
  const auto hvwe = make("hvwe"), vw3d = make("vw3d");
  for (const auto& r : reduced_states(200)) {
    const auto d = random_strain(rng);
    models::StateVector a, b;
    hvwe->rate(r, d, a);
    vw3d->rate(to_3d(r), d, b);
    const double s = b.cwiseAbs().maxCoeff();
    CHECK(std::abs(a(0) - b(0)) <= 1e-12 * s);   // sigma_n
    CHECK(std::abs(a(1) - b(1)) <= 1e-12 * s);   // sigma_p = sigma_22
    CHECK(std::abs(b(2) - b(1)) <= 1e-12 * s);   // sigma_33 stays equal to sigma_22
    CHECK(std::abs(a(2) - b(3)) <= 1e-12 * s);   // tau_x
    CHECK(std::abs(a(3) - b(4)) <= 1e-12 * s);   // tau_y
    CHECK(std::abs(b(5)) <= 1e-12 * s);          // sigma_23 stays zero
    CHECK(a(4) == Approx(b(6)).epsilon(1e-13));  // void ratio
  }
}

TEST_CASE("hvwe-exact equals hvwe to round-off (ERRATA 2)", "[models]") {
  std::mt19937 rng(4);
  const auto hvwe = make("hvwe"), exact = make("hvwe-exact");
  for (const auto& r : reduced_states(200)) {
    const auto d = random_strain(rng);
    models::StateVector a, b;
    hvwe->rate(r, d, a);
    exact->rate(r, d, b);
    CHECK((a - b).cwiseAbs().maxCoeff() <= 1e-12 * a.cwiseAbs().maxCoeff());
  }
}

TEST_CASE("hp1d is Gutjahr's eq. 3.75, re-derived (ERRATA 7)", "[models][hp1d]") {
  // Eq. 3.75 in the seed's own compression-positive form, written out independently of the shared
  // rate: [s_n, tau]' = f_b f_e / (1 + t^2) ([e_n, g] + a^2 [1, t](e_n + g t) - f_d a [1, 2t] |D|),
  // t = tau/sigma_n, a = 1/tan(phi_c) (eq. 3.76), f_b of eq. 3.77, Bauer's law in sigma_n.
  const auto in = test::table_5_2_hostun();
  const auto m = make("hp1d", in);
  const auto p = models::HypoplasticParameters::from(in.tables.at("hypoplastic"), "t");
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const double sn = 5.0 + 2000.0 * u(rng), tau = (u(rng) - 0.5) * sn, g = (u(rng) - 0.5) * 1e-3;
    const double en = (u(rng) - 0.5) * 1e-3;  // compression positive
    const double x = std::exp(-std::pow(sn / p.hs, p.n));
    const double ei = p.ei0 * x, ec = p.ec0 * x, ed = p.ed0 * x;
    const double e = ed + (0.05 + 0.9 * u(rng)) * (ei - ed);
    const double a = 1.0 / std::tan(p.phi_c), t = tau / sn;
    const double fb = p.hs / p.n * std::pow(p.ei0 / p.ec0, p.beta) * (1 + ei) / ei *
                      std::pow(sn / p.hs, 1 - p.n) /
                      (1 + a * a - a * std::pow((p.ei0 - p.ed0) / (p.ec0 - p.ed0), p.alpha));
    const double fe = std::pow(ec / e, p.beta), fd = std::pow((e - ed) / (ec - ed), p.alpha);
    const double k = fb * fe / (1 + t * t), nd = std::hypot(en, g);
    const double dsn = k * (en + a * a * (en + g * t) - fd * a * nd);
    const double dtau = k * (g + a * a * t * (en + g * t) - fd * a * 2 * t * nd);
    models::StateVector s(3), r;
    s << -sn, tau, e;
    m->rate(s, {-en, g, 0.0}, r);  // internal: tension positive, eps_n opening positive
    CHECK(-r(0) == Approx(dsn).epsilon(1e-12).margin(1e-12 * std::abs(k) * nd));
    CHECK(r(1) == Approx(dtau).epsilon(1e-12).margin(1e-12 * std::abs(k) * nd));
    CHECK(r(2) == Approx(-(1 + e) * en).epsilon(1e-14));
  }
}

TEST_CASE("hp1d at tau = 0 has the 3D model's isotropic stiffness on the compression line",
          "[models][hp1d]") {
  // On e = e_i, d(-tr T)/d(-tr D) of vw3d under isotropic compression equals d sigma_n/d eps_n of
  // hp1d when sigma_n = -tr T: both put the normal compression line on Bauer's e_i.
  const auto in = test::table_5_2_hostun();
  const auto p = models::HypoplasticParameters::from(in.tables.at("hypoplastic"), "t");
  const models::Roughness rough{};
  const auto c3 = models::make_constants(p, {}, rough, 3.0);
  const auto m1 = make("hp1d", in);
  for (double bauer : {10.0, 100.0, 1000.0, 10000.0}) {
    const double ei = models::limiting_void_ratios(bauer, p).e_i;
    const Eigen::Matrix3d T = -bauer / 3.0 * Eigen::Matrix3d::Identity();
    const Eigen::Matrix3d D = -1e-4 / 3.0 * Eigen::Matrix3d::Identity();
    const auto rate3 = models::von_wolffersdorff_rate<algebra::Tensor3Ops, double>(T, ei, D, c3);
    const double k3 = rate3.trace() / D.trace();
    models::StateVector s(3), r;
    s << -bauer, 0.0, ei;
    m1->rate(s, {-1e-4, 0.0, 0.0}, r);
    const double k1 = r(0) / -1e-4;
    CHECK(k1 == Approx(k3).epsilon(1e-12));
    // and both equal the stiffness Bauer's law implies: (1 + e_i) / (-d e_i / d p)
    const double dei = -ei * p.n / p.hs * std::pow(bauer / p.hs, p.n - 1);
    CHECK(k1 == Approx((1 + ei) / -dei).epsilon(1e-12));
  }
}

TEST_CASE("coefficients a of eqs. 5.15, 5.21 and 3.76", "[models]") {
  const double phi = 30.0 * M_PI / 180.0;
  CHECK(models::coefficient_a(models::CoefficientARule::kVonWolffersdorff, phi) ==
        Approx(std::sqrt(3.0) * 2.5 / (2 * std::sqrt(2.0) * 0.5)));
  CHECK(models::coefficient_a(models::CoefficientARule::kGutjahr1D, phi) == Approx(std::sqrt(3.0)));
  // Eq. 5.21 with tan psi = tan phi: a = 3 sqrt(3/2 - 1/8) - sqrt(3)/(2 sqrt 2) for phi = 30 deg
  CHECK(models::coefficient_a(models::CoefficientARule::kArnoldHerle, phi) ==
        Approx(3 * std::sqrt(1.5 - 0.125) - std::sqrt(3.0) / (2 * std::sqrt(2.0))));
}

TEST_CASE("initial states outside the domain are refused with the reason", "[models]") {
  const auto m = make("hvwe");
  CHECK_THROWS_WITH(m->initial_state({100.0, 0.5, 1.2}), Catch::Contains("outside (e_d, e_i)"));
  CHECK_THROWS_WITH(m->initial_state({100.0, 0.5, 0.55}), Catch::Contains("outside (e_d, e_i)"));
  CHECK_THROWS_WITH(m->initial_state({-10.0, 0.5, 0.8}), Catch::Contains("no compression"));
}
