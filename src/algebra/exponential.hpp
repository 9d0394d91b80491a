#pragma once
// exp(X) = sum_k X^k / k! over an algebra policy's product (ops.hpp), with the powers formed left
// to right, X^(k+1) = X^k . X: Barodesy's R = -exp(alpha D^0) (seed eq. 8.2) written once for the
// 3x3 tensors and the reduced vectors. For 3x3 tensors it is the matrix exponential to round-off.
// For reduced vectors with one shear component (X4 = 0) the reduced product is the 2x2 block
// product of the embedding, with X2 standing also for the (3,3) entry, so the series is exact
// there too: the (1,1), (1,2), (2,2) entries of the block's exponential, and (3,3) := (2,2) where
// the 3x3 exponential would have exp(X2-part) alone (src/algebra/README.md). No scaling and
// squaring: with two shear components the reduced product is not associative, and squaring would
// define another function. The isotropic part is taken out first, exp(X) = e^m exp(X - m 1) with
// m = tr X / 3 (1 is the unit of both products, so the series obeys the shift): an isotropic
// argument is then exact, and the series' round-off, eps e^||X - m 1|| from its largest terms,
// concerns the deviatoric part only.
#include <cmath>
#include <stdexcept>

#include "common/scalar.hpp"

namespace iwb::algebra {

// Terms are summed until one is below 1e-17 of the sum's size; arguments of the norm met in
// Barodesy (|alpha| < 40) need at most ~130 terms.
template <class Ops, class S>
typename Ops::template Tensor<S> exponential(const typename Ops::template Tensor<S>& x) {
  using Tensor = typename Ops::template Tensor<S>;
  constexpr int kMaxTerms = 400;
  using std::exp;
  const S m = Ops::trace(x) / 3.0;
  const Tensor dev = x - m * Ops::template unit<S>();
  Tensor sum = Ops::template unit<S>();
  Tensor term = Ops::template unit<S>();
  for (int k = 1; k < kMaxTerms; ++k) {
    term = Tensor(Ops::product(term, dev) / double(k));
    sum += term;
    const double t = value_of(Ops::contract(term, term)), s = value_of(Ops::contract(sum, sum));
    if (t <= 1e-34 * s && k > 2) return exp(m) * sum;
  }
  throw std::domain_error("exponential: the series did not converge (argument too large)");
}

}  // namespace iwb::algebra
