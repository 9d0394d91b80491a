#include "dem/scene/requirements.hpp"

#include <fmt/core.h>

#include "common/errors.hpp"

namespace iwb::dem {

const std::vector<Qoi>& quantities_of_interest() {
  static const std::vector<Qoi> q = {
      {"peak_friction", "peak tau/sigma_n"},
      {"residual_friction", "residual tau/sigma_n (last fifth)"},
      {"dilation_rate", "dilation rate du_n/du_x (last fifth)"},
      // the verdicts' dilation: near the critical state the rate at the end is ~0 and its
      // relative error says nothing (data/tradeoff/truth/README.md)
      {"total_dilation", "total dilation u_n at the end"},
      {"band_thickness", "wall band thickness / d50"},
  };
  return q;
}

const std::vector<Qoi>& compared_only_quantities() {
  static const std::vector<Qoi> q = {
      {"u_x_at_peak", "displacement to the peak"},
      {"sigma_n_change", "normal stress change at the end (CNS, CV)"},
      {"sigma_n_lowest", "lowest normal stress on the way less the first (CNS, CV)"},
      {"wall_zone_dilation", "dilation of the wall zone, from its void ratio (CNL, CNS)"},
  };
  return q;
}

const std::vector<Qoi>& cyclic_quantities() {
  static const std::vector<Qoi> q = {
      {"cycle_peak_friction", "peak tau/sigma_n of each cycle, towards +A and -A"},
      {"cycle_sigma_n_ratio", "sigma_n at each cycle's end over sigma_n0 (cyclic CNS, CV)"},
      {"cycle_u_n", "accumulated u_n at each cycle's end (cyclic CNL, CNS)"},
      {"reversal_secant", "secant stiffness over half the amplitude after each reversal"},
      {"post_cyclic_peak_friction", "peak tau/sigma_n of the shear after the cycles"},
      {"post_cyclic_u_n_change", "u_n change over the shear after the cycles (CNL, CNS)"},
  };
  return q;
}

const std::vector<const std::vector<Qoi>*>& requirement_lists() {
  static const std::vector<const std::vector<Qoi>*> lists = {
      &quantities_of_interest(), &compared_only_quantities(), &cyclic_quantities()};
  return lists;
}

namespace {

std::string known_keys() {
  std::string s;
  for (const auto* list : requirement_lists())
    for (const auto& q : *list) s += (s.empty() ? "" : ", ") + std::string(q.key);
  return s;
}

}  // namespace

Requirements read_requirements(io::TableReader t) {
  Requirements r;
  for (const auto* list : requirement_lists())
    for (const auto& q : *list)
      if (const auto tolerance = io::read_tolerance(t, q.key)) r[q.key] = *tolerance;
  try {
    t.finish();
  } catch (const InputError& e) {
    throw InputError(fmt::format("{} (the quantities of interest are {})", e.what(), known_keys()));
  }
  return r;
}

}  // namespace iwb::dem
