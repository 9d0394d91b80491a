#pragma once
// Algebra policies: the same constitutive formula (src/models/hypoplastic) is written once over
// an `Ops` type that says what a stress-like tensor is and how its invariants are computed.
//
//   ReducedOps          4-vectors with the reduced operators of seed 5.4 (HvWE, AH, AHE)
//   EmbeddedReducedOps  4-vectors whose invariants are evaluated on the embedded 3x3 tensor
//                       (hvwe-exact, ERRATA item 2)
//   Tensor3Ops          full symmetric 3x3 tensors (vw3d)
//   ShearPlaneOps       Herle & Nuebel / Gutjahr 2-vectors [normal, shear] (hp1d, seed 3.3.4)
//
// Each policy also packs its tensor into a flat state vector, so models keep named state over a
// flat array (STYLE.md, Marmot).
#include <Eigen/Core>

#include "algebra/reduced.hpp"
#include "algebra/tensor3.hpp"

namespace iwb::algebra {

struct ReducedOps {
  template <class S>
  using Tensor = reduced::Vec4<S>;
  static constexpr int kPackedSize = 4;
  static constexpr bool kHasLodeAngle = true;

  template <class S>
  static S trace(const Tensor<S>& x) {
    return reduced::trace(x);
  }
  template <class S>
  static S contract(const Tensor<S>& x, const Tensor<S>& y) {
    return reduced::double_contraction(x, y);
  }
  template <class S>
  static S trace_of_cube(const Tensor<S>& x) {
    return reduced::trace_of_cube(x);
  }
  template <class S>
  static Tensor<S> unit() {
    return reduced::unit<S>();
  }
  // X . Y, eq. 5.31 (ERRATA 2: the embedding is not closed under it)
  template <class S>
  static Tensor<S> product(const Tensor<S>& x, const Tensor<S>& y) {
    return reduced::inner_product(x, y);
  }

  template <class S, class V>
  static Tensor<S> unpack(const V& v, int offset) {
    return v.template segment<4>(offset);
  }
  template <class S, class V>
  static void pack(const Tensor<S>& x, V& v, int offset) {
    v.template segment<4>(offset) = x;
  }
};

// Same storage as ReducedOps; trace, ':' and tr(X^3) are taken on embed(X). Differs from
// ReducedOps only in tr(X^3) of non-deviatoric arguments, which the model never forms.
struct EmbeddedReducedOps : ReducedOps {
  template <class S>
  static S trace(const Tensor<S>& x) {
    return reduced::embed(x).trace();
  }
  template <class S>
  static S contract(const Tensor<S>& x, const Tensor<S>& y) {
    return tensor3::double_contraction(reduced::embed(x), reduced::embed(y));
  }
  template <class S>
  static S trace_of_cube(const Tensor<S>& x) {
    return tensor3::trace_of_cube(reduced::embed(x));
  }
};

struct Tensor3Ops {
  template <class S>
  using Tensor = tensor3::Mat3<S>;
  static constexpr int kPackedSize = 6;  // 11, 22, 33, 12, 13, 23
  static constexpr bool kHasLodeAngle = true;

  template <class S>
  static S trace(const Tensor<S>& x) {
    return x.trace();
  }
  template <class S>
  static S contract(const Tensor<S>& x, const Tensor<S>& y) {
    return tensor3::double_contraction(x, y);
  }
  template <class S>
  static S trace_of_cube(const Tensor<S>& x) {
    return tensor3::trace_of_cube(x);
  }
  template <class S>
  static Tensor<S> unit() {
    return Tensor<S>::Identity();
  }
  template <class S>
  static Tensor<S> product(const Tensor<S>& x, const Tensor<S>& y) {
    return x * y;
  }

  template <class S, class V>
  static Tensor<S> unpack(const V& v, int o) {
    Tensor<S> x;
    x << v(o), v(o + 3), v(o + 4), v(o + 3), v(o + 1), v(o + 5), v(o + 4), v(o + 5), v(o + 2);
    return x;
  }
  template <class S, class V>
  static void pack(const Tensor<S>& x, V& v, int o) {
    v(o) = x(0, 0);
    v(o + 1) = x(1, 1);
    v(o + 2) = x(2, 2);
    v(o + 3) = x(0, 1);
    v(o + 4) = x(0, 2);
    v(o + 5) = x(1, 2);
  }
};

// Herle & Nuebel (1999) / Gutjahr (2003): stress [sigma_11, sigma_12], stretching
// [D_11, gamma] with the engineering shear strain and plain Euclidean products (eq. 3.73-3.75).
// The "trace" is the normal component, so T^ = T / sigma_11 and T^* = [0, sigma_12/sigma_11].
struct ShearPlaneOps {
  template <class S>
  using Tensor = Eigen::Matrix<S, 2, 1>;
  static constexpr int kPackedSize = 2;
  static constexpr bool kHasLodeAngle = false;  // F = 1 in the 1D model (seed 3.3.4)

  template <class S>
  static S trace(const Tensor<S>& x) {
    return x(0);
  }
  template <class S>
  static S contract(const Tensor<S>& x, const Tensor<S>& y) {
    return x.dot(y);
  }
  template <class S>
  static Tensor<S> unit() {
    return Tensor<S>(S(1.0), S(0.0));
  }

  template <class S, class V>
  static Tensor<S> unpack(const V& v, int offset) {
    return v.template segment<2>(offset);
  }
  template <class S, class V>
  static void pack(const Tensor<S>& x, V& v, int offset) {
    v.template segment<2>(offset) = x;
  }
};

}  // namespace iwb::algebra
