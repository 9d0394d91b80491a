#pragma once
// The pile as a 1D finite-element bar (axial stiffness EA, linear elements) on t-z springs that are
// interface stress points (after Randolph's RATZ): one ShaftPoint at each element's middle, its
// shaft force split to the element's two nodes, a linear base spring at the tip. Equilibrium by
// Newton with the stress points' condensed tangents, the head's settlement or load prescribed.
#include <Eigen/Core>
#include <vector>

#include "pile/pile_spec.hpp"
#include "pile/shaft_point.hpp"

namespace iwb::pile {

// A committed state of the pile, for the outputs.
struct PileSnapshot {
  double head_settlement_mm = 0.0, head_load_kN = 0.0, base_load_kN = 0.0, shaft_load_kN = 0.0;
  double tip_settlement_mm = 0.0;
  double shaft_sigma_n_mean_kPa = 0.0;  // over the shaft's stress points (equal areas)
  int newton_iterations = 0;
};

// Per element, at its middle: depth, settlement, axial force (compression positive), shaft
// friction and normal stress.
struct ProfileRow {
  double z_m, w_mm, axial_kN, tau_kPa, sigma_n_kPa;
};

class LoadTransfer {
 public:
  // `elements` overrides the file's (mesh convergence).
  LoadTransfer(const PileSpec& spec, const ShaftMaterial& material, int elements);

  // Equilibrium with the head at settlement w (mm), or under the head load P (kN); committed on
  // success. ConvergenceError when Newton fails (a load beyond the capacity, a stress point that
  // cannot follow), leaving the last committed state.
  PileSnapshot settle_to(double w_mm);
  PileSnapshot load_to(double P_kN);

  PileSnapshot snapshot() const;
  std::vector<ProfileRow> profile() const;
  int elements() const { return int(points_.size()); }

 private:
  struct Assembly {
    Eigen::VectorXd force;      // internal nodal forces, kN
    Eigen::MatrixXd stiffness;  // kN / mm
    std::vector<ShaftResponse> shaft;
  };
  Assembly assemble(const Eigen::VectorXd& w) const;
  PileSnapshot solve(bool head_load_given, double head_value);
  void commit(const Eigen::VectorXd& w, const Assembly& a);

  double h_m_, bar_kN_per_mm_, shaft_area_m2_, base_kN_per_mm_;
  std::vector<ShaftPoint> points_;
  Eigen::VectorXd w_;  // committed nodal settlements, mm (node 0 the head)
  int last_iterations_ = 0;
};

}  // namespace iwb::pile
