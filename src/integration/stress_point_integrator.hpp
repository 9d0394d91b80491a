#pragma once
// Integrates a model's rate over one strain increment (unit pseudo-time, d = the increment).
//
//  - explicit Euler with n equal substeps (the seed's scheme), or
//  - an embedded Runge-Kutta pair with a relative error tolerance and step-size control.
//
// The committed state (`start`) is never written: substeps work on trial copies and a substep is
// committed only when accepted, so a rejected substep never leaks (STYLE.md, Kratos). A trial
// state outside the model's domain is a rejection for the adaptive scheme (the step is cut back)
// and a DomainError for fixed-step Euler. Runs on doubles and on dual numbers; step sizes and
// error control use the values only, so the derivative carried by a Dual is the exact derivative
// of the discrete scheme (the consistent derivative the Newton solve needs).
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "integration/butcher_tableau.hpp"
#include "models/model.hpp"

namespace iwb::integration {

enum class Scheme { kExplicitEuler, kAdaptive };

struct IntegratorSettings {
  Scheme scheme = Scheme::kAdaptive;
  int substeps = 1;           // explicit Euler: equal substeps per increment
  double rtol = 1e-6;         // adaptive: relative error tolerance per substep
  std::string pair = "rk32";  // adaptive: embedded pair (rk32, rk54)
  int max_substeps = 100000;  // adaptive: per increment
  double min_step = 1e-12;    // adaptive: smallest substep, fraction of the increment

  std::string describe() const;
};

struct IntegrationCounters {
  long rate_evaluations = 0;
  long accepted_substeps = 0;
  long rejected_substeps = 0;  // error too large or trial left the domain
  long domain_cutbacks = 0;    // of those, rejected because the trial left the domain

  IntegrationCounters& operator+=(const IntegrationCounters& o);
};

// The accepted substep sizes of an adaptive integration. Replaying a recorded plan makes the
// integrated increment a smooth function of the strain increment (the step sequence no longer
// jumps with it), which the mixed-control Newton solve needs to converge below the integration
// tolerance. A replay still measures the embedded error and asks for a new plan if it is exceeded.
struct StepPlan {
  std::vector<double> steps;
  bool replay = false;         // in: replay `steps` instead of choosing them
  bool needs_refresh = false;  // out: a replayed step exceeded the tolerance
};

using models::values_of;

namespace detail {

template <class S>
struct Stepper {
  const models::Model& model;
  const ButcherTableau& tab;
  const models::InterfaceStrainT<S>& d;
  IntegrationCounters& count;
  std::vector<models::StateVectorT<S>> k;

  models::StateVectorT<S> rate(const models::StateVectorT<S>& y) {
    models::StateVectorT<S> r;
    ++count.rate_evaluations;
    model.rate(y, d, r);
    return r;
  }

  // One trial step of size h from y; k[0] must hold f(y). Returns y_new; `err` gets the
  // embedded difference when the tableau has one.
  models::StateVectorT<S> step(const models::StateVectorT<S>& y, double h,
                               models::StateVector* err) {
    const std::size_t stages = tab.b.size();
    k.resize(stages);
    for (std::size_t i = 1; i < stages; ++i) {
      models::StateVectorT<S> yi = y;
      for (std::size_t j = 0; j < i; ++j)
        if (tab.a[i][j] != 0.0) yi += (h * tab.a[i][j]) * k[j];
      k[i] = rate(yi);
    }
    models::StateVectorT<S> y_new = y;
    for (std::size_t i = 0; i < stages; ++i)
      if (tab.b[i] != 0.0) y_new += (h * tab.b[i]) * k[i];
    if (err != nullptr) {
      *err = models::StateVector::Zero(y.size());
      for (std::size_t i = 0; i < stages; ++i)
        *err += (h * (tab.b[i] - tab.b_embedded[i])) * values_of<S>(k[i]);
    }
    return y_new;
  }
};

inline std::string describe_state(const models::Model& m, const models::StateVector& s) {
  const auto names = m.state_names();
  std::string out;
  for (int i = 0; i < s.size(); ++i)
    out += fmt::format("{}{}={:.6g}", i ? ", " : "", i < int(names.size()) ? names[i] : "?", s(i));
  return out;
}

}  // namespace detail

// Fixed-step explicit Euler.
template <class S>
models::StateVectorT<S> integrate_euler(const models::Model& m,
                                        const models::StateVectorT<S>& start,
                                        const models::InterfaceStrainT<S>& increment, int substeps,
                                        IntegrationCounters& count) {
  const double h = 1.0 / substeps;
  detail::Stepper<S> st{m, explicit_euler(), increment, count, {}};
  models::StateVectorT<S> y = start;
  for (int i = 0; i < substeps; ++i) {
    y += h * st.rate(y);
    ++count.accepted_substeps;
    if (const auto why = m.domain_violation(values_of<S>(y)); !why.empty())
      throw DomainError(fmt::format("explicit Euler substep {}/{}: {} [{}]", i + 1, substeps, why,
                                    detail::describe_state(m, values_of<S>(y))));
  }
  return y;
}

namespace detail {
inline double error_norm(const models::StateVector& err, const models::StateVector& scale,
                         double rtol) {
  double e = 0.0;
  for (int i = 0; i < err.size(); ++i)
    e = std::max(e, std::abs(err(i)) / (rtol * std::max(scale(i), 1e-300)));
  return e;
}

// A replayed step may exceed its error target by this factor before the plan is re-chosen: the
// plan was accepted (error <= 1, typically ~0.5 after the controller's safety factor) for a
// nearby increment, and re-planning on every small excess would make Newton chase the plan.
inline constexpr double kReplayErrorAllowance = 2.0;

// Replays plan.steps with the embedded pair. A replay cannot cut back, so a step leaving the
// domain throws; the caller (the driver's Newton) then lets the adaptive scheme re-plan.
template <class S>
models::StateVectorT<S> replay_plan(const models::Model& m, const models::StateVectorT<S>& start,
                                    const models::InterfaceStrainT<S>& increment,
                                    const IntegratorSettings& set, IntegrationCounters& count,
                                    StepPlan& plan) {
  const ButcherTableau& tab = embedded_pair(set.pair);
  Stepper<S> st{m, tab, increment, count, {}};
  models::StateVectorT<S> y = start;
  models::StateVectorT<S> k0 = st.rate(y);
  models::StateVector err;
  plan.needs_refresh = false;
  for (double h : plan.steps) {
    st.k.assign(1, k0);
    const auto scale = m.error_scale(values_of<S>(y));
    y = st.step(y, h, &err);
    ++count.accepted_substeps;
    if (error_norm(err, scale, set.rtol) > kReplayErrorAllowance) plan.needs_refresh = true;
    if (const auto why = m.domain_violation(values_of<S>(y)); !why.empty())
      throw DomainError(
          fmt::format("replayed substep: {} [{}]", why, describe_state(m, values_of<S>(y))));
    k0 = tab.first_same_as_last ? st.k.back() : st.rate(y);
  }
  return y;
}
}  // namespace detail

// Adaptive embedded Runge-Kutta. `first_step` is the suggested first substep (fraction of the
// increment); on return it holds the suggestion for the next increment. With a plan, either
// records the accepted steps into it or (plan->replay) replays them.
template <class S>
models::StateVectorT<S> integrate_adaptive(const models::Model& m,
                                           const models::StateVectorT<S>& start,
                                           const models::InterfaceStrainT<S>& increment,
                                           const IntegratorSettings& set,
                                           IntegrationCounters& count, double& first_step,
                                           StepPlan* plan = nullptr) {
  if (plan != nullptr && plan->replay)
    return detail::replay_plan<S>(m, start, increment, set, count, *plan);
  if (plan != nullptr) {
    plan->steps.clear();
    plan->needs_refresh = false;
  }
  const ButcherTableau& tab = embedded_pair(set.pair);
  const double exponent = 1.0 / (tab.embedded_order + 1.0);
  detail::Stepper<S> st{m, tab, increment, count, {}};
  models::StateVectorT<S> y = start;  // committed substep state
  double t = 0.0;
  double h = std::clamp(first_step, set.min_step, 1.0);
  double last_accepted = h;
  models::StateVectorT<S> k0 = st.rate(y);
  models::StateVector err;
  std::string last_rejection = "none";
  bool last_rejection_left_domain = false;
  for (int n = 0; t < 1.0; ++n) {
    if (n >= set.max_substeps) {
      const std::string msg = fmt::format(
          "adaptive integration needed more than {} substeps "
          "(last rejection: {})",
          set.max_substeps, last_rejection);
      // Creeping along the domain's edge (e towards e_d) is the domain's limit, not the error
      // controller's: classify it as the domain error it approaches.
      if (last_rejection_left_domain) throw DomainError(msg);
      throw ConvergenceError(msg);
    }
    h = std::min(h, 1.0 - t);
    st.k.assign(1, k0);
    double factor;
    models::StateVectorT<S> trial;
    std::string why;
    try {
      trial = st.step(y, h, &err);
      why = m.domain_violation(values_of<S>(trial));
    } catch (const DomainError& e) {
      why = e.what();
    }
    if (!why.empty()) {
      ++count.rejected_substeps;
      ++count.domain_cutbacks;
      last_rejection = why;
      last_rejection_left_domain = true;
      factor = 0.25;
    } else {
      const double e_norm = detail::error_norm(err, m.error_scale(values_of<S>(y)), set.rtol);
      if (e_norm <= 1.0) {
        y = trial;  // commit
        t += h;
        if (plan != nullptr) plan->steps.push_back(h);
        last_accepted = h;
        ++count.accepted_substeps;
        k0 = tab.first_same_as_last ? st.k.back() : st.rate(y);
        factor = std::clamp(0.9 * std::pow(std::max(e_norm, 1e-10), -exponent), 0.2, 5.0);
      } else {
        ++count.rejected_substeps;
        last_rejection = fmt::format("error {:.3g} x tolerance", e_norm);
        last_rejection_left_domain = false;
        factor = std::clamp(0.9 * std::pow(e_norm, -exponent), 0.1, 0.9);
      }
    }
    h *= factor;
    if (h < set.min_step && t < 1.0)
      throw DomainError(
          fmt::format("substep below {:g} of the increment at fraction {:.6g}: {} [{}]",
                      set.min_step, t, last_rejection, detail::describe_state(m, values_of<S>(y))));
  }
  first_step = std::max(last_accepted, h);
  return y;
}

template <class S>
models::StateVectorT<S> integrate_increment(const models::Model& m,
                                            const models::StateVectorT<S>& start,
                                            const models::InterfaceStrainT<S>& increment,
                                            const IntegratorSettings& set,
                                            IntegrationCounters& count, double& first_step,
                                            StepPlan* plan = nullptr) {
  if (m.updates_by_increment()) {  // a closed-form return: exact for the whole increment
    models::StateVectorT<S> out;
    m.update(start, increment, out);
    ++count.accepted_substeps;
    return out;
  }
  if (set.scheme == Scheme::kExplicitEuler)
    return integrate_euler<S>(m, start, increment, set.substeps, count);
  return integrate_adaptive<S>(m, start, increment, set, count, first_step, plan);
}

}  // namespace iwb::integration
