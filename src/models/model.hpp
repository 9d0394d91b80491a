#pragma once
// What the driver and the integrator know of a constitutive model: a flat state vector, its rate
// for a given interface stretching, the stresses it stands for, and its domain. Nothing else.
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/scalar.hpp"

namespace iwb::models {

inline constexpr int kMaxStateSize = 16;

template <class S>
using StateVectorT = Eigen::Matrix<S, Eigen::Dynamic, 1, 0, kMaxStateSize, 1>;
using StateVector = StateVectorT<double>;

// A component of a stress or strain-like tensor below this fraction of the tensor's largest
// component is zero for every purpose (round-off of that tensor's arithmetic is 1e-16 of it):
// flush_negligible_components sets it to exactly 0, 14 decades below round-off and far above
// the subnormal range (2.2e-308) for any stress or intergranular strain the models admit.
inline constexpr double kNegligibleComponent = 1e-30;

// Zeroes the entries of `v` below kNegligibleComponent times its largest entry.
template <class V>
void flush_negligible(V&& v) {
  const double largest = v.cwiseAbs().maxCoeff();
  for (int i = 0; i < v.size(); ++i)
    if (std::abs(v(i)) <= kNegligibleComponent * largest) v(i) = 0.0;
}

// The values of a state on dual numbers (the state itself on doubles).
template <class S>
StateVector values_of(const StateVectorT<S>& s) {
  StateVector v(s.size());
  for (int i = 0; i < s.size(); ++i) v(i) = value_of(s(i));
  return v;
}

// Every model stores the normal stress (tension positive) as state component 0, so the driver can
// read sigma_n, and its derivative, from any state or rate without knowing the model.
template <class S>
S normal_stress(const StateVectorT<S>& s) {
  return -s(0);
}

// External variables a model may read (issue 19): their current values are state components of
// the model (declaration.hpp, StateLayout::external), their increments travel with the stretching.
inline constexpr int kExternalSlots = 3;
enum class External : int { kTemperature = 0, kSuction = 1, kTime = 2 };

// The state component holding an external variable's value, as a test file's [initial] names it.
inline const char* external_key(External slot) {
  static const char* const keys[kExternalSlots] = {"T_K", "s_kPa", "t_s"};
  return keys[int(slot)];
}

// Stretching (or its increment) of an interface element, internal sign convention: eps_n > 0 is
// opening (dilation), engineering shear strains gamma_x, gamma_y (CONVENTIONS.md), and the
// increments of the external variables over the same pseudo-time: dT (K), ds (kPa), dt (s). Every
// rate is homogeneous of degree one in the whole of it (Masin & Khalili's H_T and H_s are of
// degree one in dT and ds), so the integrators need not know which part is which.
template <class S>
struct InterfaceStrainT {
  S eps_n{0.0};
  S gamma_x{0.0};
  S gamma_y{0.0};
  // Initialised explicitly: Eigen's AutoDiffScalar default constructor leaves its value
  // uninitialised, so `external{}` would be garbage for Dual.
  std::array<S, kExternalSlots> external{S(0.0), S(0.0), S(0.0)};

  S external_of(External slot) const { return external[std::size_t(slot)]; }
};
using InterfaceStrain = InterfaceStrainT<double>;

// Stresses an element stands for, geotechnical sign (compression positive), kPa. sigma_p is empty
// for models without an in-plane stress (hp1d).
struct InterfaceStress {
  double sigma_n = 0.0;
  std::optional<double> sigma_p;
  double tau_x = 0.0;
  double tau_y = 0.0;
};

// What a model does with a start outside its state boundary surface (a clay looser than any
// loading could have made it at that stress): refuse it (InputError, the default), or take it and
// say so in Model::initial_warnings, for a caller that must reproduce a published start lying
// outside (seed Table 6.5's CNL column).
enum class OutsideBoundary { kRefuse, kWarn };

// Initial state of an element test (CONVENTIONS.md): geotechnical sign, kPa.
struct InitialState {
  double sigma_n = 0.0;
  double K0 = 1.0;  // sigma_p0 = K0 sigma_n0
  double e0 = 0.0;
  // Models with intergranular strain: [delta_n, delta_x, delta_y] as tensor components (opening
  // positive like eps_n, delta_x = delta_12); empty = the model's default (seed 5.6).
  std::optional<std::array<double, 3>> delta = std::nullopt;
  // Every other input a model declares (src/models/declaration.hpp): "OCR", "T_K", "s_kPa", ...
  std::map<std::string, double, std::less<>> named = {};
  // Without `delta` (last, so that positional initialisers stay valid): true starts it fully
  // mobilised along the vertical compression that prepared the specimen, [-R, 0, 0] (rho = 1), as a
  // soil test's cell was consolidated; false takes the seed's default (5.6).
  bool delta_along_compression = false;
  OutsideBoundary outside_boundary = OutsideBoundary::kRefuse;
};

struct NamedValue {
  std::string name;
  double value;
};

class Model {
 public:
  virtual ~Model() = default;
  virtual std::string_view name() const = 0;
  virtual int state_size() const = 0;
  virtual std::vector<std::string> state_names() const = 0;
  // Throws InputError if the initial state is not admissible (tension, e outside [e_d, e_i]).
  virtual StateVector initial_state(const InitialState& initial) const = 0;
  // What initial_state accepts but doubts, one sentence each: a start outside the state boundary
  // surface taken with OutsideBoundary::kWarn. Empty for most models.
  virtual std::vector<std::string> initial_warnings(const InitialState&) const { return {}; }

  // Rate of the state for the stretching d. Hypoplastic rates are homogeneous of degree one in d
  // (rate independence), so integrating over unit pseudo-time with d = the strain increment
  // gives the increment's response. Throws DomainError where the rate is undefined.
  virtual void rate(const StateVector& s, const InterfaceStrain& d, StateVector& ds) const = 0;
  virtual void rate(const StateVectorT<Dual>& s, const InterfaceStrainT<Dual>& d,
                    StateVectorT<Dual>& ds) const = 0;

  // Models that declare StressPointUpdate::kIncrement (declaration.hpp; an elasto-plastic return)
  // give the state after a whole increment d in closed form; the integrator calls update instead
  // of integrating rate. On Dual numbers it carries the increment's consistent derivative.
  virtual bool updates_by_increment() const { return false; }
  virtual void update(const StateVector& s, const InterfaceStrain& d, StateVector& out) const;
  virtual void update(const StateVectorT<Dual>& s, const InterfaceStrainT<Dual>& d,
                      StateVectorT<Dual>& out) const;

  virtual InterfaceStress stress(const StateVector& s) const = 0;
  virtual double void_ratio(const StateVector& s) const = 0;
  // Why s is outside the model's domain; empty when it is inside.
  virtual std::string domain_violation(const StateVector& s) const = 0;
  // Per-component magnitude against which integration errors are measured (relative tolerance).
  virtual StateVector error_scale(const StateVector& s) const = 0;
  // Model-specific quantities worth recording (limiting void ratios, mean stress, ...).
  virtual std::vector<NamedValue> diagnostics(const StateVector& s) const = 0;
  // Whether the model reads this external variable: the driver refuses a path that changes one it
  // does not (a heated Mohr-Coulomb element would silently ignore the heat).
  virtual bool reads_external(External) const { return false; }
  // False for models with a single shear component (hp1d): the driver refuses y shear for them.
  virtual bool has_second_shear_direction() const = 0;
  // Called by the driver on each committed state: sets to exactly zero the components that are
  // negligible against the rest of their tensor (kNegligibleComponent). A component that decays
  // geometrically (tau_y and delta_y after the seed's initial delta, README of
  // src/models/hypoplastic) otherwise ends in the subnormal range, where it sticks a few units
  // above zero and makes every rate evaluation 2-3 times slower.
  virtual void flush_negligible_components(StateVector& /*committed*/) const {}
};

}  // namespace iwb::models
