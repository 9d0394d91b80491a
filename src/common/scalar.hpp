#pragma once
// Scalars the constitutive code runs on: double, and a forward-mode dual number carrying one
// derivative (d/d of the normal strain increment) so the mixed-control Newton solve gets the
// consistent derivative of the integrated increment rather than a finite-difference guess.
#include <Eigen/Core>
#include <cmath>
#include <unsupported/Eigen/AutoDiff>

namespace iwb {

using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<double, 1, 1>>;

inline double value_of(double x) {
  return x;
}
inline double value_of(const Dual& x) {
  return x.value();
}

inline Dual make_variable(double value) {
  return Dual(value, Eigen::Matrix<double, 1, 1>(1.0));
}
inline double derivative_of(const Dual& x) {
  return x.derivatives()(0);
}

// sqrt with a finite derivative at zero: the norm of a zero stretching contributes nothing.
template <class S>
S safe_sqrt(const S& x) {
  using std::sqrt;
  if (value_of(x) <= 0.0) return S(0.0);
  return sqrt(x);
}

}  // namespace iwb
