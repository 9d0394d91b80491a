#pragma once
// Explicit Runge-Kutta schemes as data. Euler is the seed's scheme (5.7, appendix C); the
// embedded pairs give the error estimate for adaptive substepping.
#include <string>
#include <vector>

namespace iwb::integration {

struct ButcherTableau {
  std::string name;
  std::vector<std::vector<double>> a;  // stage coefficients, row i has i entries
  std::vector<double> b;               // weights of the propagated solution
  std::vector<double> b_embedded;      // weights of the embedded estimate; empty: none
  int embedded_order;                  // order of the embedded estimate (step-size exponent)
  bool first_same_as_last;             // last stage is f(y_new): reused as the next first stage
};

const ButcherTableau& explicit_euler();
const ButcherTableau& bogacki_shampine_32();  // 3rd order, embedded 2nd, FSAL
const ButcherTableau& dormand_prince_54();    // 5th order, embedded 4th, FSAL

// "rk32" or "rk54"; InputError otherwise.
const ButcherTableau& embedded_pair(const std::string& name);
// The names embedded_pair takes, for the readers' declared choices.
const std::vector<std::string>& embedded_pair_names();

}  // namespace iwb::integration
