#pragma once
// Micro-polar hypoplasticity at a point: von Wolffersdorff's (1996) rate with the polar terms of
// Tejchman's form (Tejchman & Gudehus 2001; Tejchman 2008, ch. 4), written over the workbench's
// von Wolffersdorff tangent (models/hypoplastic/von_wolffersdorff.hpp), tension positive. The form
// and where each term comes from: src/column/README.md, "The law".
//
//   T° = s [F^2 D^c + a^2 T^ (T^:D^c + m^ k d50)] + s f_d a F (T^ + T^*) ||D^c||
//   m° = s d50 [F^2 (k d50 + m^ (T^:D^c + m^ k d50)) + f_d a F m^ ||D^c||]
//
// s = f_b f_e / (T^:T^), m^ = m / (d50 tr T), ||D^c|| = sqrt(D^c:D^c + (k d50)^2), the Jaumann
// rates taken with the grains' spin W^c. It is Tejchman's a_1 form multiplied through by a^2, with
// a_1 = F/a and the micro-polar constant a_c = 1/a_1. Without rotations (D^c = D, k = 0, m = 0) it
// is the plain model term for term.
#include <Eigen/Core>

#include "models/hypoplastic/von_wolffersdorff.hpp"

namespace iwb::column {

// What a point of the column carries: the non-symmetric force stress (kPa; T(0,1) = T_12, the
// shear stress on horizontal planes, first index the force's direction), the couple stress m_2
// (kPa mm, conjugate to the curvature dw/dy) and the void ratio.
struct PolarState {
  Eigen::Matrix3d T = Eigen::Matrix3d::Zero();
  double m = 0.0;
  double e = 0.0;
};

// The kinematics at a point over one increment: the polar deformation D^c = grad v + e.w (non-
// symmetric), the grains' spin w (rad per unit of the increment's time) and the curvature k = dw/dy
// (rad/mm). The column's components: D^c_12 = du1/dy + w, D^c_21 = -w, D^c_22 = du2/dy.
struct PolarRate {
  Eigen::Matrix3d Dc = Eigen::Matrix3d::Zero();
  double w = 0.0;
  double k = 0.0;
};

struct PolarConstants {
  models::VonWolffersdorffConstants vw;
  double d50_mm;
  // false: the plain model (the couple stress stays zero, the curvature is not read)
  bool polar = true;
};

PolarConstants make_polar_constants(const models::HypoplasticParameters& p, double d50_mm,
                                    bool polar);

// The state's rate (dT/dt, dm/dt, de/dt) under `rate`; DomainError where the law has no rate
// (contact lost, e at or below e_d).
PolarState polar_rate(const PolarState& s, const PolarRate& rate, const PolarConstants& c);

// `s` carried through `rate` applied for unit time in `substeps` explicit midpoint (RK2) steps.
PolarState integrate(const PolarState& s, const PolarRate& rate, const PolarConstants& c,
                     int substeps);

}  // namespace iwb::column
