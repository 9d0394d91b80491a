#include "integration/butcher_tableau.hpp"

#include <fmt/core.h>

#include "common/errors.hpp"

namespace iwb::integration {

const ButcherTableau& explicit_euler() {
  static const ButcherTableau t{"euler", {{}}, {1.0}, {}, 0, false};
  return t;
}

const ButcherTableau& bogacki_shampine_32() {
  static const ButcherTableau t{"rk32",
                                {{}, {1.0 / 2}, {0.0, 3.0 / 4}, {2.0 / 9, 1.0 / 3, 4.0 / 9}},
                                {2.0 / 9, 1.0 / 3, 4.0 / 9, 0.0},
                                {7.0 / 24, 1.0 / 4, 1.0 / 3, 1.0 / 8},
                                2,
                                true};
  return t;
}

const ButcherTableau& dormand_prince_54() {
  static const ButcherTableau t{
      "rk54",
      {{},
       {1.0 / 5},
       {3.0 / 40, 9.0 / 40},
       {44.0 / 45, -56.0 / 15, 32.0 / 9},
       {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
       {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
       {35.0 / 384, 0.0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84}},
      {35.0 / 384, 0.0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0.0},
      {5179.0 / 57600, 0.0, 7571.0 / 16695, 393.0 / 640, -92097.0 / 339200, 187.0 / 2100, 1.0 / 40},
      4,
      true};
  return t;
}

const std::vector<std::string>& embedded_pair_names() {
  static const std::vector<std::string> names{"rk32", "rk54"};
  return names;
}

const ButcherTableau& embedded_pair(const std::string& name) {
  if (name == "rk32") return bogacki_shampine_32();
  if (name == "rk54") return dormand_prince_54();
  throw InputError(fmt::format("unknown adaptive scheme '{}'; use rk32 or rk54", name));
}

}  // namespace iwb::integration
