#pragma once
// Scalars the constitutive code runs on: double, and a forward-mode dual number carrying one
// derivative (d/d of the normal strain increment) so the mixed-control Newton solve gets the
// consistent derivative of the integrated increment rather than a finite-difference guess.
//
// Dual was Eigen's AutoDiffScalar<Matrix<double, 1, 1>>. Its expression templates for a derivative
// vector of one entry were half of the compiler's time in a model's file (hcthm.cpp 37 s -> 18 s
// without them; issue 60, the build's budget): this is the same number written out, each rule the
// one of Eigen's AutoDiffScalar.h, term for term and in the same order, so that values and
// derivatives are the same bits as before (tests/common/test_scalar.cpp holds both against each
// other and against finite differences).
#include <Eigen/Core>
#include <cmath>

namespace iwb {

class Dual {
 public:
  Dual() = default;
  Dual(double value) : v_(value) {}  // NOLINT(google-explicit-constructor): a constant
  Dual(double value, double derivative) : v_(value), d_(derivative) {}

  double value() const { return v_; }
  double derivative() const { return d_; }

  Dual& operator+=(const Dual& o) { return *this = *this + o; }
  Dual& operator-=(const Dual& o) { return *this = *this - o; }
  Dual& operator*=(const Dual& o) { return *this = *this * o; }
  Dual& operator/=(const Dual& o) { return *this = *this / o; }

  friend Dual operator-(const Dual& a) { return {-a.v_, -a.d_}; }
  friend Dual operator+(const Dual& a, const Dual& b) { return {a.v_ + b.v_, a.d_ + b.d_}; }
  friend Dual operator-(const Dual& a, const Dual& b) { return {a.v_ - b.v_, a.d_ - b.d_}; }
  friend Dual operator*(const Dual& a, const Dual& b) {
    return {a.v_ * b.v_, (a.d_ * b.v_) + (b.d_ * a.v_)};
  }
  friend Dual operator/(const Dual& a, const Dual& b) {
    return {a.v_ / b.v_, ((a.d_ * b.v_) - (b.d_ * a.v_)) * (1.0 / (b.v_ * b.v_))};
  }
  friend Dual operator+(const Dual& a, double b) { return {a.v_ + b, a.d_}; }
  friend Dual operator+(double a, const Dual& b) { return {a + b.v_, b.d_}; }
  friend Dual operator-(const Dual& a, double b) { return {a.v_ - b, a.d_}; }
  friend Dual operator-(double a, const Dual& b) { return {a - b.v_, -b.d_}; }
  friend Dual operator*(const Dual& a, double b) { return {a.v_ * b, a.d_ * b}; }
  friend Dual operator*(double a, const Dual& b) { return {b.v_ * a, b.d_ * a}; }
  friend Dual operator/(const Dual& a, double b) { return {a.v_ / b, a.d_ * (1.0 / b)}; }
  friend Dual operator/(double a, const Dual& b) { return {a / b.v_, b.d_ * (-a / (b.v_ * b.v_))}; }

  // Compared by value, as Eigen's AutoDiffScalar is.
  friend bool operator<(const Dual& a, const Dual& b) { return a.v_ < b.v_; }
  friend bool operator<=(const Dual& a, const Dual& b) { return a.v_ <= b.v_; }
  friend bool operator>(const Dual& a, const Dual& b) { return a.v_ > b.v_; }
  friend bool operator>=(const Dual& a, const Dual& b) { return a.v_ >= b.v_; }
  friend bool operator==(const Dual& a, const Dual& b) { return a.v_ == b.v_; }
  friend bool operator!=(const Dual& a, const Dual& b) { return a.v_ != b.v_; }

 private:
  double v_ = 0.0, d_ = 0.0;
};

// The functions the models call, found by argument-dependent lookup beside std's (`using std::sqrt;
// sqrt(x)`), each with the derivative rule of Eigen's AutoDiffScalar.h.
inline Dual abs(const Dual& x) {
  return {std::abs(x.value()), x.derivative() * (x.value() < 0 ? -1 : 1)};
}
inline Dual sqrt(const Dual& x) {
  const double s = std::sqrt(x.value());
  return {s, x.derivative() * (0.5 / s)};
}
inline Dual exp(const Dual& x) {
  const double e = std::exp(x.value());
  return {e, x.derivative() * e};
}
inline Dual log(const Dual& x) {
  return {std::log(x.value()), x.derivative() * (1.0 / x.value())};
}
inline Dual pow(const Dual& x, double y) {
  return {std::pow(x.value(), y), x.derivative() * (y * std::pow(x.value(), y - 1))};
}
inline Dual sin(const Dual& x) {
  return {std::sin(x.value()), x.derivative() * std::cos(x.value())};
}
inline Dual cos(const Dual& x) {
  return {std::cos(x.value()), x.derivative() * (-std::sin(x.value()))};
}
inline Dual tan(const Dual& x) {
  const double c = std::cos(x.value());
  return {std::tan(x.value()), x.derivative() * (1.0 / (c * c))};
}
inline Dual asin(const Dual& x) {
  return {std::asin(x.value()), x.derivative() * (1.0 / std::sqrt(1 - x.value() * x.value()))};
}
inline Dual acos(const Dual& x) {
  return {std::acos(x.value()), x.derivative() * (-1.0 / std::sqrt(1 - x.value() * x.value()))};
}
inline Dual tanh(const Dual& x) {
  const double c = std::cosh(x.value());
  return {std::tanh(x.value()), x.derivative() * (1.0 / (c * c))};
}
inline Dual atan2(const Dual& a, const Dual& b) {
  const double squared_hypot = a.value() * a.value() + b.value() * b.value();
  return {std::atan2(a.value(), b.value()),
          (a.derivative() * b.value() - a.value() * b.derivative()) / squared_hypot};
}
inline Dual(min)(const Dual& x, const Dual& y) {
  return x.value() < y.value() ? x : y;
}
inline Dual(max)(const Dual& x, const Dual& y) {
  return x.value() >= y.value() ? x : y;
}
inline bool isfinite(const Dual& x) {
  return std::isfinite(x.value());
}

inline double value_of(double x) {
  return x;
}
inline double value_of(const Dual& x) {
  return x.value();
}

inline Dual make_variable(double value) {
  return Dual(value, 1.0);
}
inline double derivative_of(const Dual& x) {
  return x.derivative();
}

// sqrt with a finite derivative at zero: the norm of a zero stretching contributes nothing.
template <class S>
S safe_sqrt(const S& x) {
  using std::sqrt;
  if (value_of(x) <= 0.0) return S(0.0);
  return sqrt(x);
}

}  // namespace iwb

// Eigen's matrices of Dual (the models' tensors) need its traits: those of double, the type's own
// name for the real and non-integer type.
namespace Eigen {
template <>
struct NumTraits<iwb::Dual> : NumTraits<double> {
  using Real = iwb::Dual;
  using NonInteger = iwb::Dual;
  using Nested = iwb::Dual;
  using Literal = iwb::Dual;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 1,
    AddCost = 2,
    MulCost = 3
  };
};
}  // namespace Eigen
