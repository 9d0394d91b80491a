#include "column/polar_law.hpp"

#include <cmath>

#include "algebra/ops.hpp"

namespace iwb::column {

PolarConstants make_polar_constants(const models::HypoplasticParameters& p, double d50_mm,
                                    bool polar) {
  // the soil's own set: a wall's roughness enters the column through its boundary conditions
  // (column.hpp), not through kappa_r in the rate
  const auto vw = models::make_constants(p, models::HypoplasticVariant{}, models::Roughness{}, 3.0);
  return {vw, d50_mm, polar};
}

PolarState polar_rate(const PolarState& s, const PolarRate& rate, const PolarConstants& c) {
  using Ops = algebra::Tensor3Ops;
  const auto h = models::von_wolffersdorff_tangent<Ops, double>(s.T, s.e, c.vw);
  const double tr = s.T.trace();
  const auto lim = models::limiting_void_ratios(-tr, c.vw.p);
  const double f_d = std::pow((s.e - lim.e_d) / (lim.e_c - lim.e_d), c.vw.alpha);
  const double aF = std::sqrt(h.a2 * h.F2);

  const double kd = c.polar ? rate.k * c.d50_mm : 0.0;
  const double m_hat = c.polar ? s.m / (c.d50_mm * tr) : 0.0;
  const double norm = std::sqrt(Ops::contract(rate.Dc, rate.Dc) + kd * kd);
  const double inner = Ops::contract(h.t_hat, rate.Dc) + m_hat * kd;

  Eigen::Matrix3d Wc = Eigen::Matrix3d::Zero();  // the grains' spin, W^c_ij = -e_ijk w_k
  Wc(0, 1) = -rate.w;
  Wc(1, 0) = rate.w;
  const Eigen::Matrix3d T_objective =
      h.scale * (h.F2 * rate.Dc + (h.a2 * inner) * h.t_hat) + norm * h.N;
  PolarState d;
  d.T = T_objective + Wc * s.T - s.T * Wc;
  // The couple stress vector turns with the grains too (its m_1 part, k_1 = 0 here, is not
  // carried: in a column it would only rotate back into m_2 at second order).
  d.m =
      c.polar ? h.scale * c.d50_mm * (h.F2 * (kd + m_hat * inner) + f_d * aF * m_hat * norm) : 0.0;
  d.e = (1.0 + s.e) * rate.Dc.trace();
  return d;
}

namespace {
PolarState advanced(const PolarState& s, const PolarState& d, double dt) {
  return {s.T + dt * d.T, s.m + dt * d.m, s.e + dt * d.e};
}
}  // namespace

PolarState integrate(const PolarState& s, const PolarRate& rate, const PolarConstants& c,
                     int substeps) {
  const double dt = 1.0 / substeps;
  PolarState x = s;
  for (int i = 0; i < substeps; ++i) {
    const PolarState mid = advanced(x, polar_rate(x, rate, c), 0.5 * dt);
    x = advanced(x, polar_rate(mid, rate, c), dt);
  }
  return x;
}

}  // namespace iwb::column
