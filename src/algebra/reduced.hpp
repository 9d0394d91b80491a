#pragma once
// Reduced interface vectors and their operators (seed section 5.4, eqs. 5.22-5.34, with
// ../shared/spec/ERRATA.md items 1-3).
//
// A reduced vector X = [X1, X2, X3, X4] stands for the symmetric tensor
//   [[X1, X3, X4],
//    [X3, X2, 0 ],
//    [X4, 0,  X2]]
// (axis 1 normal to the wall, 2 = shear direction x, 3 = y). Every operator below is the 3x3
// operation on that embedding written in components; tests/algebra checks each against embed().
// Templated on the scalar so the same code runs on doubles and on dual numbers (consistent
// derivatives for the mixed-control Newton solve).
#include <Eigen/Core>
#include <cmath>

namespace iwb::algebra::reduced {

template <class S>
using Vec4 = Eigen::Matrix<S, 4, 1>;
template <class S>
using Mat4 = Eigen::Matrix<S, 4, 4>;
template <class S>
using Mat3 = Eigen::Matrix<S, 3, 3>;

// Weight of component i in ':' and the norm: the off-diagonal shear entries and the doubled
// in-plane diagonal each appear twice in the 3x3 double contraction (eq. 5.25, 5.32).
inline constexpr double kWeight[4] = {1.0, 2.0, 2.0, 2.0};

template <class S>
S trace(const Vec4<S>& x) {  // eq. 5.23
  return x(0) + 2.0 * x(1);
}

template <class S>
S determinant(const Vec4<S>& x) {  // eq. 5.24
  return x(0) * x(1) * x(1) - x(3) * x(3) * x(1) - x(2) * x(2) * x(1);
}

template <class S>
S double_contraction(const Vec4<S>& x, const Vec4<S>& y) {  // eq. 5.32, X : Y
  return x(0) * y(0) + 2.0 * (x(1) * y(1) + x(2) * y(2) + x(3) * y(3));
}

template <class S>
S norm(const Vec4<S>& x) {  // eq. 5.25
  using std::sqrt;
  return sqrt(double_contraction(x, x));
}

template <class S = double>
Vec4<S> unit() {  // eq. 5.26, second-order unit tensor 1
  return Vec4<S>(S(1.0), S(1.0), S(0.0), S(0.0));
}

template <class S = double>
Mat4<S> unit4() {  // eq. 5.27, fourth-order unit tensor I (I : X = X under eq. 5.33)
  Mat4<S> m = Mat4<S>::Zero();
  m(0, 0) = S(1.0);
  m(1, 1) = m(2, 2) = m(3, 3) = S(0.5);
  return m;
}

template <class S>
Vec4<S> deviator(const Vec4<S>& x) {  // eq. 5.28, X* = X - tr(X)/3 1
  Vec4<S> d = x;
  const S third = trace(x) / 3.0;
  d(0) -= third;
  d(1) -= third;
  return d;
}

template <class S>
Vec4<S> normalized(const Vec4<S>& x) {  // eq. 5.30, X^ = X / tr X
  return x / trace(x);
}

template <class S>
Vec4<S> normalized_deviator(const Vec4<S>& x) {  // eq. 5.29 with ERRATA item 1 (4th component)
  Vec4<S> d = normalized(x);
  d(0) -= 1.0 / 3.0;
  d(1) -= 1.0 / 3.0;
  return d;
}

// Eq. 5.31: the (1,1), (2,2), (1,2) and (3,1) entries of the 3x3 product of the embeddings. The
// embedding is not closed under this product (ERRATA item 2): the (3,3) entry of the true product
// is X4 Y4 + X2 Y2, and a (2,3) entry X3 Y4 appears, neither of which survives here.
template <class S>
Vec4<S> inner_product(const Vec4<S>& x, const Vec4<S>& y) {
  return Vec4<S>(x(0) * y(0) + x(2) * y(2) + x(3) * y(3), x(1) * y(1) + x(2) * y(2),
                 x(0) * y(2) + x(2) * y(1), x(3) * y(0) + x(1) * y(3));
}

// tr(X . X . X) with the reduced operators. It equals tr of the cube of embed(X) minus
// tr(X) (X3^2 - X4^2) (ERRATA item 2, derived in src/algebra/README.md); zero for deviators.
template <class S>
S trace_of_cube(const Vec4<S>& x) {
  return trace(inner_product(inner_product(x, x), x));
}

template <class S>
Mat4<S> outer_product(const Vec4<S>& x, const Vec4<S>& y) {  // eq. 5.34
  return x * y.transpose();
}

template <class S>
Vec4<S> double_contraction(const Mat4<S>& s, const Vec4<S>& x) {  // eq. 5.33, S : X
  Vec4<S> weighted = x;
  for (int i = 1; i < 4; ++i) weighted(i) *= kWeight[i];
  return s * weighted;
}

// The symmetric 3x3 tensor a reduced vector stands for (CONVENTIONS.md).
template <class S>
Mat3<S> embed(const Vec4<S>& x) {
  Mat3<S> m;
  m << x(0), x(2), x(3), x(2), x(1), S(0.0), x(3), S(0.0), x(1);
  return m;
}

}  // namespace iwb::algebra::reduced
