#pragma once
// Symmetric 3x3 tensor operations: the reference the reduced algebra is tested against and the
// algebra of the full continuum model vw3d. Templated on the scalar like reduced.hpp.
#include <Eigen/Core>
#include <Eigen/LU>  // determinant
#include <cmath>

namespace iwb::algebra::tensor3 {

template <class S>
using Mat3 = Eigen::Matrix<S, 3, 3>;

template <class S>
S trace(const Mat3<S>& x) {
  return x.trace();
}

template <class S>
S double_contraction(const Mat3<S>& x, const Mat3<S>& y) {
  return x.cwiseProduct(y).sum();
}

template <class S>
S norm(const Mat3<S>& x) {
  using std::sqrt;
  return sqrt(double_contraction(x, x));
}

template <class S = double>
Mat3<S> unit() {
  return Mat3<S>::Identity();
}

template <class S>
Mat3<S> deviator(const Mat3<S>& x) {
  return x - Mat3<S>::Identity() * (x.trace() / 3.0);
}

template <class S>
S trace_of_cube(const Mat3<S>& x) {
  return (x * x * x).trace();
}

template <class S>
S determinant(const Mat3<S>& x) {
  return x.determinant();
}

}  // namespace iwb::algebra::tensor3
