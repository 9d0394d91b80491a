#include "driver/mixed_control.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "common/errors.hpp"

namespace iwb::driver {

using models::StateVector;
using models::StateVectorT;

namespace {

// Relative residual a root of the closed form may leave in the true rate: round-off of the four
// rate evaluations it is assembled from.
constexpr double kClosedFormRootTolerance = 1e-8;
// Newton iterates whose replayed plan left the domain and were re-planned, per increment.
constexpr int kMaxReplans = 2;

// The normal strains seen so far on either side of the root: x with a positive residual and x
// with a negative one. Once both exist the root lies between them (the row's residual is
// continuous in x), and a Newton step that leaves that interval is replaced by its midpoint
// (Numerical Recipes' rtsafe). Plain Newton cycles on a residual that is steepest near its root:
// at a strain reversal with intergranular strain the normal stiffness changes from m_R L at the
// reversal to the loading stiffness within one increment, and the residual is S-shaped (seen:
// slope -2.9e5 kPa near the root and -3e4 kPa 2e-4 away, hvwe-igs with Table 5.3 gravel;
// Newton alternated between x = -2.5e-4 and 1.4e-4 for 30 iterations around a root at -6.5e-5).
class Bracket {
 public:
  void add(double x, double r) {
    if (r > 0.0) positive_ = x, has_positive_ = true;
    if (r < 0.0) negative_ = x, has_negative_ = true;
  }
  bool closed() const { return has_positive_ && has_negative_; }
  bool contains(double x) const {
    return std::min(positive_, negative_) < x && x < std::max(positive_, negative_);
  }
  double midpoint() const { return 0.5 * (positive_ + negative_); }

 private:
  double positive_ = 0.0, negative_ = 0.0;
  bool has_positive_ = false, has_negative_ = false;
};

double residual_scale(const NormalControlRow& row, const StateVector& s, double shear) {
  constexpr double kStressFloor_kPa = 1.0;  // keeps the relative residual meaningful near 0 kPa
  return std::abs(row.a) * std::max(std::abs(models::normal_stress(s)), kStressFloor_kPa) +
         std::abs(row.b) * std::max(shear, 1e-14) + std::abs(row.c);
}

IncrementSolution newton(const models::Model& m, const StateVector& committed,
                         const IncrementRequest& rq, const integration::IntegratorSettings& is,
                         const MixedControlSettings& ms, double& first_step) {
  IncrementSolution out;
  const double shear = std::hypot(rq.gamma_x, rq.gamma_y);
  const double scale = residual_scale(rq.row, committed, shear);
  const StateVectorT<Dual> start = committed.cast<Dual>();
  const Dual sigma0 = models::normal_stress(start);
  double x = rq.eps_n_guess;
  integration::StepPlan plan;  // first iteration chooses the substeps, later ones replay them
  int replans = 0;
  std::string last_domain_error;  // why the last re-planned iterate left the domain
  Bracket bracket;
  for (out.iterations = 0; out.iterations < ms.max_iterations; ++out.iterations) {
    const Dual X = make_variable(x);
    const models::InterfaceStrainT<Dual> d = rq.strain(X);
    StateVectorT<Dual> trial;
    // A new step sequence makes the residual a slightly different function of x.
    const bool new_plan = !plan.replay;
    try {
      trial =
          integration::integrate_increment<Dual>(m, start, d, is, out.counters, first_step, &plan);
    } catch (const DomainError& e) {
      last_domain_error = e.what();
      // A replayed plan cannot cut back: let the adaptive scheme choose new substeps at this x.
      // If the adaptive scheme itself failed, or replays keep failing, the increment runs into
      // the domain's edge (e.g. e at e_d), and that domain error is the answer.
      if (!plan.replay || ++replans > kMaxReplans) throw;
      plan.replay = false;
      continue;
    }
    const bool plan_valid = !plan.needs_refresh;
    plan.replay = plan_valid;
    const Dual r = rq.row.a * (models::normal_stress(trial) - sigma0) + rq.row.b * X - rq.row.c;
    out.residuals.push_back(std::abs(r.value()) / scale);
    if (out.residuals.back() <= ms.tolerance && plan_valid) {
      out.state = integration::values_of<Dual>(trial);
      out.eps_n = x;
      return out;
    }
    if (new_plan) bracket = Bracket{};
    bracket.add(x, r.value());
    const double slope = derivative_of(r);
    const double newton_step = x - r.value() / slope;
    if (bracket.closed()) {
      x = bracket.contains(newton_step) ? newton_step : bracket.midpoint();
      continue;
    }
    if (!std::isfinite(slope))
      throw ConvergenceError(
          fmt::format("mixed control: the normal row's derivative is not finite "
                      "at eps_n = {:g} (the model's rate is not differentiable "
                      "at this state, e.g. e at e_d)",
                      x));
    if (!(std::abs(slope) > 0.0))
      throw ConvergenceError(
          fmt::format("mixed control: normal row has slope 0 at eps_n = {:g}", x));
    x = newton_step;
  }
  const std::string msg = fmt::format(
      "mixed control: Newton did not reach {:g} in {} iterations "
      "(last residual {:.3g})",
      ms.tolerance, ms.max_iterations, out.residuals.empty() ? INFINITY : out.residuals.back());
  // Iterates that left the domain mean the root lies at its edge: that is the cause to report.
  if (!last_domain_error.empty())
    throw DomainError(fmt::format("{}; iterates left the domain: {}", msg, last_domain_error));
  throw ConvergenceError(msg);
}

// The closed form reads L and N off the rate assuming T_rate = L:D + N||D||. A rate that is not of
// that form (intergranular strain switches its stiffness with the direction of D) gives a root
// that misses the row: substitute it into the true rate and refuse rather than drift silently.
void check_closed_form_root(const NormalControlRow& row, double x, const StateVector& rate) {
  const double d_sigma = models::normal_stress(rate);
  const double residual = row.a * d_sigma + row.b * x - row.c;
  // Measured against the whole stress rate: under CNL the normal row's own terms are all ~0.
  const double scale =
      std::abs(row.a) * rate.cwiseAbs().maxCoeff() + std::abs(row.b * x) + std::abs(row.c);
  if (!(std::abs(residual) <= kClosedFormRootTolerance * std::max(scale, 1e-300)))
    throw ConvergenceError(fmt::format(
        "mixed control: the closed form (appendix C) root misses the normal row by {:.3g} "
        "relative; "
        "the model's rate is not of the form L:D + N||D|| (e.g. intergranular strain): use "
        "mixed_control = \"newton\"",
        std::abs(residual) / std::max(scale, 1e-300)));
}

// Row of appendix C: per explicit Euler substep, the closed form gives x.
IncrementSolution closed_form(const models::Model& m, const StateVector& committed,
                              const IncrementRequest& rq, int substeps) {
  IncrementSolution out;
  const double n = substeps;
  const NormalControlRow sub{rq.row.a, rq.row.b, rq.row.c / n};
  StateVector y = committed;
  for (int k = 0; k < substeps; ++k) {
    const double x =
        closed_form_normal_strain(m, y, rq.gamma_x / n, rq.gamma_y / n, sub, out.counters);
    StateVector r;
    m.rate(y, {x, rq.gamma_x / n, rq.gamma_y / n}, r);
    ++out.counters.rate_evaluations;
    check_closed_form_root(sub, x, r);
    y += r;
    ++out.counters.accepted_substeps;
    if (const auto why = m.domain_violation(y); !why.empty())
      throw DomainError(fmt::format("explicit Euler substep {}/{}: {}", k + 1, substeps, why));
    out.eps_n += x;
  }
  out.state = y;
  out.iterations = 0;
  return out;
}

}  // namespace

double closed_form_normal_strain(const models::Model& m, const StateVector& y, double gx, double gy,
                                 const NormalControlRow& row,
                                 integration::IntegrationCounters& counters) {
  if (row.a == 0.0) return row.c / row.b;
  auto sigma_rate = [&](double en, double sx, double sy) {
    StateVector r;
    m.rate(y, {en, sx, sy}, r);
    ++counters.rate_evaluations;
    return models::normal_stress(r);
  };
  // sigma_n rate = x l_e + l_s + sgn(N) sqrt(x^2 nu_e^2 + nu_s^2): split into L and N parts by
  // evaluating at +-D (the L part is odd in D, the N part even).
  const double re_p = sigma_rate(1.0, 0.0, 0.0), re_m = sigma_rate(-1.0, 0.0, 0.0);
  const double l_e = 0.5 * (re_p - re_m), nu_e = 0.5 * (re_p + re_m);
  double l_s = 0.0, nu_s = 0.0;
  if (gx != 0.0 || gy != 0.0) {
    const double rs_p = sigma_rate(0.0, gx, gy), rs_m = sigma_rate(0.0, -gx, -gy);
    l_s = 0.5 * (rs_p - rs_m);
    nu_s = 0.5 * (rs_p + rs_m);
  }
  const double sgn = (nu_e + nu_s) < 0.0 ? -1.0 : 1.0;
  const double A = row.a * l_e + row.b, B = row.a * l_s - row.c, Q = row.a * sgn;
  auto unsquared = [&](double x) {
    return A * x + B + Q * std::sqrt(x * x * nu_e * nu_e + nu_s * nu_s);
  };
  // (A x + B)^2 = Q^2 (nu_e^2 x^2 + nu_s^2): ERRATA item 18's coefficients, derived.
  const double qa = A * A - Q * Q * nu_e * nu_e, qb = 2.0 * A * B, qc = B * B - Q * Q * nu_s * nu_s;
  std::vector<double> roots;
  if (std::abs(qa) <= 1e-14 * (A * A + Q * Q * nu_e * nu_e)) {
    if (qb != 0.0) roots.push_back(-qc / qb);
  } else {
    const double disc = qb * qb - 4.0 * qa * qc;
    if (disc >= 0.0) {
      const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));  // stable roots
      if (q != 0.0) roots.push_back(qc / q);
      roots.push_back(q / qa);
    }
  }
  double best = 0.0, best_res = INFINITY;
  for (double x : roots)
    if (std::abs(unsquared(x)) < best_res) best = x, best_res = std::abs(unsquared(x));
  const double scale =
      std::abs(A * best) + std::abs(B) + std::abs(Q) * std::hypot(best * nu_e, nu_s);
  if (!(best_res <= 1e-8 * std::max(scale, 1e-300)))
    throw ConvergenceError(
        "mixed control: no root of the closed form (appendix C) satisfies the "
        "unsquared normal row");
  return best;
}

IncrementSolution solve_increment(const models::Model& m, const StateVector& committed,
                                  const IncrementRequest& rq,
                                  const integration::IntegratorSettings& is,
                                  const MixedControlSettings& ms, double& first_step) {
  if (ms.method == MixedControlMethod::kClosedForm) {
    if (is.scheme != integration::Scheme::kExplicitEuler)
      throw InputError("mixed_control = \"closed-form\" (appendix C) needs scheme = \"euler\"");
    // appendix C reads L and N off rate evaluations in D alone: a temperature or suction rate
    // adds terms it does not know
    if (rq.has_external())
      throw InputError(
          "mixed_control = \"closed-form\" (appendix C) covers strain paths only; this path "
          "changes "
          "temperature or suction: use mixed_control = \"newton\"");
    return closed_form(m, committed, rq, is.substeps);
  }
  if (rq.row.a == 0.0) {  // normal strain prescribed: no unknown, plain integration
    IncrementSolution out;
    out.eps_n = rq.row.c / rq.row.b;
    out.state = integration::integrate_increment<double>(m, committed, rq.strain(out.eps_n), is,
                                                         out.counters, first_step);
    return out;
  }
  return newton(m, committed, rq, is, ms, first_step);
}

}  // namespace iwb::driver
