#include "pile/shaft_point.hpp"

#include <fmt/core.h>

#include <cmath>

#include "common/errors.hpp"

namespace iwb::pile {

namespace {

constexpr size_t kMessage = 1024;
constexpr int kNormalIterations = 30;
constexpr double kNormalTolerance = 1e-10;  // of the normal stress
constexpr double kSmallestFraction = 1e-4;  // of a Newton step, in the backtracking

[[noreturn]] void fail(const std::string& where, const char* message) {
  throw InputError(fmt::format("{}: {}", where, message));
}

}  // namespace

ShaftMaterial::ShaftMaterial(const InterfaceSpec& spec, const std::string& where)
    : thickness_mm_(spec.d_s_mm), initial_(spec.initial), where_(where) {
  char message[kMessage];
  iwb_material* m = nullptr;
  if (iwb_material_create(spec.model.c_str(), spec.parameters.string().c_str(), spec.kappa_r,
                          nullptr, &m, message, kMessage) != IWB_OK)
    fail(where, message);
  material_.reset(m);
}

std::vector<double> ShaftMaterial::initial_state(double sigma_n, double sigma_v) const {
  std::vector<std::string> keys{"sigma_n_kPa"};
  std::vector<double> values{sigma_n};
  for (int i = 0; i < iwb_initial_input_count(get()); ++i)
    if (std::string(iwb_initial_input_key(get(), i)) == "K0")
      keys.push_back("K0"), values.push_back(sigma_v / sigma_n);
  for (const auto& [k, v] : initial_) keys.push_back(k), values.push_back(v);
  std::vector<const char*> pointers;
  for (const auto& k : keys) pointers.push_back(k.c_str());
  std::vector<double> state(iwb_state_size(get()));
  char message[kMessage];
  if (iwb_initial_state(get(), pointers.data(), values.data(), int(keys.size()), state.data(),
                        message, kMessage) != IWB_OK)
    fail(where_ + fmt::format(" (initial state at sigma_n = {:.4g} kPa)", sigma_n), message);
  return state;
}

ShaftPoint::ShaftPoint(const ShaftMaterial& m, double sigma_n0, double sigma_v0,
                       double K_kPa_per_mm)
    : m_(&m), K_(K_kPa_per_mm) {
  committed_.state = m.initial_state(sigma_n0, sigma_v0);
  committed_.sigma_n_kPa = sigma_n0;
}

ShaftResponse ShaftPoint::trial(double dw_mm) const {
  ShaftResponse r{std::vector<double>(committed_.state.size())};
  double traction[3], tangent[9];
  // sigma_n(u_n) - (sigma_n,c + K u_n) at the normal displacement increment u_n: the cavity's
  // spring resists the interface's dilation. false where the model refuses the increment.
  const auto residual_at = [&](double u_n, double& residual) {
    double factor = 1.0;
    char message[kMessage];
    const double du[3] = {u_n, dw_mm, 0.0};
    if (iwb_update(m_->get(), committed_.state.data(), du, m_->thickness_mm(), 0.0, nullptr,
                   r.state.data(), traction, tangent, &factor, message, kMessage) != IWB_OK)
      return false;
    residual = traction[0] - (committed_.sigma_n_kPa + K_ * u_n);
    return true;
  };
  double u_n = 0.0, residual = 0.0;
  if (!residual_at(u_n, residual))
    throw ConvergenceError(fmt::format(
        "shaft stress point at sigma_n = {:.4g} kPa refuses the shear increment {:.3g} mm",
        committed_.sigma_n_kPa, dw_mm));
  for (int it = 0; it < kNormalIterations; ++it) {
    if (std::abs(residual) <= kNormalTolerance * std::max(1.0, std::abs(traction[0]))) {
      r.tau_kPa = traction[1], r.sigma_n_kPa = traction[0], r.u_n_mm = u_n;
      // d tau / d w with u_n following: T_ss - T_sn T_ns / (T_nn - K)
      r.stiffness = tangent[4] - tangent[3] * tangent[1] / (tangent[0] - K_);
      return r;
    }
    // Newton, its step halved until the residual falls (the hypoplastic ||D|| makes the first
    // steps from u_n = 0 overshoot)
    const double step = -residual / (tangent[0] - K_);
    double fraction = 1.0, trial = 0.0;
    while (fraction > kSmallestFraction &&
           !(residual_at(u_n + fraction * step, trial) && std::abs(trial) < std::abs(residual)))
      fraction *= 0.5;
    if (fraction <= kSmallestFraction) break;
    u_n += fraction * step;
    residual = trial;
  }
  throw ConvergenceError(fmt::format(
      "shaft stress point at sigma_n = {:.4g} kPa: the normal displacement did not converge "
      "in {} iterations",
      committed_.sigma_n_kPa, kNormalIterations));
}

void ShaftPoint::commit(const ShaftResponse& r) {
  committed_ = r;
}

}  // namespace iwb::pile
