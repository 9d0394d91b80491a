// Stress-point integration: explicit Euler converges to the adaptive reference at first order,
// the adaptive scheme meets its tolerance, rejected substeps never leak, and a state leaving the
// domain stops with a message that names it, never with NaN.
#include <catch2/catch.hpp>

#include "common/errors.hpp"
#include "integration/stress_point_integrator.hpp"
#include "support/fixtures.hpp"

using namespace iwb;
using integration::IntegrationCounters;
using integration::IntegratorSettings;
using integration::Scheme;

namespace {

// A strain-controlled simple-shear path (CV: eps_n = 0, no Newton) integrated increment by
// increment with the given settings; returns the final state.
models::StateVector integrate_path(const models::Model& m, const IntegratorSettings& set,
                                   IntegrationCounters& count, int increments = 20,
                                   double gamma = 0.05) {
  auto s = m.initial_state({100.0, test::kK0Oedometric51, 0.70});
  double first = 1.0;
  for (int i = 0; i < increments; ++i)
    s = integration::integrate_increment<double>(m, s, {0.0, gamma / increments, 0.0}, set, count,
                                                 first);
  return s;
}

double tau_error(const models::Model& m, const models::StateVector& a,
                 const models::StateVector& b) {
  return std::abs(m.stress(a).tau_x - m.stress(b).tau_x) / std::abs(m.stress(b).tau_x);
}

IntegratorSettings adaptive(double rtol, const std::string& pair = "rk54") {
  IntegratorSettings s;
  s.rtol = rtol;
  s.pair = pair;
  return s;
}

}  // namespace

TEST_CASE("explicit Euler converges to the adaptive reference at first order", "[integration]") {
  for (const std::string name : {"hvwe", "vw3d"}) {
    const auto m = test::make(name);
    IntegrationCounters c;
    const auto reference = integrate_path(*m, adaptive(1e-12), c);
    std::vector<double> errors;
    // 1-4 substeps are pre-asymptotic (observed 1.5, 1.16); the order is measured from 8 on.
    for (int n : {8, 16, 32, 64, 128}) {
      IntegratorSettings euler;
      euler.scheme = Scheme::kExplicitEuler;
      euler.substeps = n;
      errors.push_back(tau_error(*m, integrate_path(*m, euler, c), reference));
    }
    for (std::size_t i = 1; i < errors.size(); ++i) {
      const double order = std::log2(errors[i - 1] / errors[i]);
      INFO(name << ": error " << errors[i] << " at " << (8 << i) << " substeps, observed order "
                << order);
      CHECK(order == Approx(1.0).margin(0.1));
    }
  }
}

TEST_CASE("the adaptive scheme's error follows its tolerance", "[integration]") {
  const auto m = test::make("hvwe");
  IntegrationCounters c;
  const auto reference = integrate_path(*m, adaptive(1e-12), c);
  for (const std::string pair : {"rk32", "rk54"}) {
    long previous_evals = 0;
    for (double rtol : {1e-3, 1e-5, 1e-7}) {
      IntegrationCounters count;
      const double err = tau_error(*m, integrate_path(*m, adaptive(rtol, pair), count), reference);
      INFO(pair << " rtol " << rtol << ": error " << err << ", " << count.rate_evaluations
                << " evaluations");
      CHECK(err < 20 * rtol);  // global error over 20 increments, each within rtol locally
      CHECK(count.rate_evaluations > previous_evals);
      previous_evals = count.rate_evaluations;
    }
  }
}

TEST_CASE("rejected substeps do not leak into the committed state", "[integration]") {
  // One large increment started with a whole-increment first step: the controller must reject
  // and shrink; the answer must still match a run that never rejects.
  const auto m = test::make("hvwe");
  const auto s0 = m->initial_state({100.0, test::kK0Oedometric51, 0.70});
  const models::InterfaceStrain big{0.0, 0.05, 0.0};
  IntegrationCounters with_rejections, without;
  double first = 1.0;
  const auto a =
      integration::integrate_increment<double>(*m, s0, big, adaptive(1e-8), with_rejections, first);
  first = 1e-4;
  const auto b =
      integration::integrate_increment<double>(*m, s0, big, adaptive(1e-8), without, first);
  CHECK(with_rejections.rejected_substeps > 0);
  CHECK(tau_error(*m, a, b) < 1e-6);
}

TEST_CASE("leaving the domain: Euler names the substep and state, adaptive cuts back",
          "[integration]") {
  const auto m = test::make("hvwe");
  const auto s0 = m->initial_state({100.0, test::kK0Oedometric51, 0.70});
  const models::InterfaceStrain tear{0.3, 0.0, 0.0};  // 30 % opening in one increment: tension
  IntegratorSettings euler;
  euler.scheme = Scheme::kExplicitEuler;
  IntegrationCounters c;
  double first = 1.0;
  CHECK_THROWS_WITH(integration::integrate_increment<double>(*m, s0, tear, euler, c, first),
                    Catch::Contains("substep 1/1") && Catch::Contains("T_n="));
  IntegrationCounters ca;
  first = 1.0;
  try {
    const auto s =
        integration::integrate_increment<double>(*m, s0, tear, adaptive(1e-6), ca, first);
    CHECK(s.allFinite());
    CHECK(m->domain_violation(s).empty());
  } catch (const DomainError& e) {
    CHECK_THAT(std::string(e.what()), Catch::Contains("contact lost") || Catch::Contains("e ="));
  }
  CHECK(ca.domain_cutbacks > 0);
}
