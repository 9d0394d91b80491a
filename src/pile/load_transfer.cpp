#include "pile/load_transfer.hpp"

#include <fmt/core.h>

#include <Eigen/Dense>
#include <cmath>

#include "common/errors.hpp"

namespace iwb::pile {

namespace {

constexpr int kNewtonIterations = 40;
// Equilibrium: the residual below this fraction of the largest nodal force (and of 1e-6 kN).
constexpr double kTolerance = 1e-9;

}  // namespace

LoadTransfer::LoadTransfer(const PileSpec& spec, const ShaftMaterial& material, int elements)
    : h_m_(spec.pile.length_m / elements),
      bar_kN_per_mm_(spec.pile.EA_kN / (spec.pile.length_m / elements) / 1000.0),
      shaft_area_m2_(M_PI * spec.pile.diameter_m * spec.pile.length_m / elements),
      base_kN_per_mm_(spec.base_stiffness_kN_per_mm),
      w_(Eigen::VectorXd::Zero(elements + 1)) {
  // the cavity's spring 4G/D, kPa per mm of normal displacement
  const double K = 4.0 * spec.soil.shear_modulus_kPa / (spec.pile.diameter_m * 1000.0);
  for (int e = 0; e < elements; ++e) {
    const double z = (e + 0.5) * h_m_, sigma_v = spec.soil.unit_weight_kN_m3 * z;
    points_.emplace_back(material, spec.soil.K0 * sigma_v, sigma_v, K);
  }
}

LoadTransfer::Assembly LoadTransfer::assemble(const Eigen::VectorXd& w) const {
  const int n = int(points_.size());
  Assembly a{Eigen::VectorXd::Zero(n + 1), Eigen::MatrixXd::Zero(n + 1, n + 1), {}};
  for (int e = 0; e < n; ++e) {
    // the bar
    const double N = bar_kN_per_mm_ * (w(e) - w(e + 1));
    a.force(e) += N, a.force(e + 1) -= N;
    a.stiffness(e, e) += bar_kN_per_mm_, a.stiffness(e + 1, e + 1) += bar_kN_per_mm_;
    a.stiffness(e, e + 1) -= bar_kN_per_mm_, a.stiffness(e + 1, e) -= bar_kN_per_mm_;
    // the shaft at the element's middle: w_m = (w_e + w_e+1)/2, its force halved to the nodes
    const double dw = 0.5 * (w(e) + w(e + 1) - w_(e) - w_(e + 1));
    a.shaft.push_back(points_[e].trial(dw));
    const double F = a.shaft.back().tau_kPa * shaft_area_m2_,
                 k = a.shaft.back().stiffness * shaft_area_m2_ / 4.0;
    a.force(e) += 0.5 * F, a.force(e + 1) += 0.5 * F;
    a.stiffness.block(e, e, 2, 2).array() += k;
  }
  a.force(n) += base_kN_per_mm_ * w(n);
  a.stiffness(n, n) += base_kN_per_mm_;
  return a;
}

PileSnapshot LoadTransfer::solve(bool head_load_given, double head_value) {
  const int n = int(points_.size());
  Eigen::VectorXd w = w_;
  if (!head_load_given) w(0) = head_value;
  const int first = head_load_given ? 0 : 1;  // the unknowns: every node, or all but the head
  for (int it = 1; it <= kNewtonIterations; ++it) {
    const Assembly a = assemble(w);
    Eigen::VectorXd residual = a.force;
    if (head_load_given) residual(0) -= head_value;
    const Eigen::VectorXd r = residual.tail(n + 1 - first);
    const double scale = std::max({1e-6, std::abs(head_value), a.force.cwiseAbs().maxCoeff()});
    if (r.cwiseAbs().maxCoeff() <= kTolerance * scale) {
      last_iterations_ = it - 1;
      commit(w, a);
      return snapshot();
    }
    const Eigen::VectorXd dw =
        a.stiffness.bottomRightCorner(n + 1 - first, n + 1 - first).partialPivLu().solve(-r);
    if (!dw.allFinite()) break;
    w.tail(n + 1 - first) += dw;
  }
  throw ConvergenceError(fmt::format(
      "pile: no equilibrium in {} Newton iterations at head {} {:.6g} {} (beyond the capacity?)",
      kNewtonIterations, head_load_given ? "load" : "settlement", head_value,
      head_load_given ? "kN" : "mm"));
}

void LoadTransfer::commit(const Eigen::VectorXd& w, const Assembly& a) {
  w_ = w;
  for (std::size_t e = 0; e < points_.size(); ++e) points_[e].commit(a.shaft[e]);
}

PileSnapshot LoadTransfer::settle_to(double w_mm) {
  return solve(false, w_mm);
}
PileSnapshot LoadTransfer::load_to(double P_kN) {
  return solve(true, P_kN);
}

PileSnapshot LoadTransfer::snapshot() const {
  const int n = int(points_.size());
  PileSnapshot s;
  s.head_settlement_mm = w_(0), s.tip_settlement_mm = w_(n);
  s.base_load_kN = base_kN_per_mm_ * w_(n);
  for (const auto& p : points_) {
    s.shaft_load_kN += p.committed().tau_kPa * shaft_area_m2_;
    s.shaft_sigma_n_mean_kPa += p.committed().sigma_n_kPa / double(n);
  }
  s.head_load_kN =
      bar_kN_per_mm_ * (w_(0) - w_(1)) + 0.5 * points_[0].committed().tau_kPa * shaft_area_m2_;
  s.newton_iterations = last_iterations_;
  return s;
}

std::vector<ProfileRow> LoadTransfer::profile() const {
  std::vector<ProfileRow> rows;
  for (std::size_t e = 0; e < points_.size(); ++e) {
    const auto& c = points_[e].committed();
    rows.push_back({(double(e) + 0.5) * h_m_, 0.5 * (w_(e) + w_(e + 1)),
                    bar_kN_per_mm_ * (w_(e) - w_(e + 1)), c.tau_kPa, c.sigma_n_kPa});
  }
  return rows;
}

}  // namespace iwb::pile
