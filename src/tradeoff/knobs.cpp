#include "tradeoff/knobs.hpp"

#include <fmt/core.h>

#include <cmath>

#include "common/errors.hpp"
#include "dem/scene/numerics.hpp"
#include "io/toml_override.hpp"
#include "io/toml_reader.hpp"

namespace iwb::tradeoff {

const std::vector<Knob>& all_knobs() {
  static const std::vector<Knob> k = {
      {"box", "box length and height in d50 (particle count with the volume)", 2.0},
      {"kappa", "stiffness level kappa = (E/((1-nu^2) sigma_n))^(2/3), through Young's modulus",
       2.0},
      {"dt", "timestep as a fraction of the smallest grain's Rayleigh time (numerics.dt_fraction)",
       0.5},
      {"I", "inertial number of the shear (shear speed)", 0.5},
  };
  return k;
}

const Knob& find_knob(const std::string& name) {
  std::string names;
  for (const auto& k : all_knobs()) {
    if (k.name == name) return k;
    names += (names.empty() ? "" : ", ") + k.name;
  }
  throw InputError(fmt::format("--knobs: unknown knob '{}'; the knobs are {}", name, names));
}

std::vector<std::string> parse_knob_list(const std::string& list) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t end = std::min(list.find(',', start), list.size());
    const std::string name = list.substr(start, end - start);
    if (!name.empty()) out.push_back(find_knob(name).name);
    start = end + 1;
  }
  if (out.empty()) throw InputError(fmt::format("--knobs '{}': name at least one knob", list));
  return out;
}

std::string derived_scene(const std::string& base_text, const std::string& base_name,
                          const std::vector<campaign::Setting>& settings,
                          const std::string& variant) {
  auto root = io::parse_toml_text(base_text, base_name);
  root.erase("requirements");  // what the results must meet does not change the run: keep reuse
  for (const auto& [key, value] : settings)
    io::set_dotted(root, key, value, base_name + ": " + variant);
  // The header names file and settings only: the text's sha256 decides reuse of a complete run.
  const std::string text = fmt::format("# {} with {} (iwb tradeoff, {})\n", base_name,
                                       campaign::describe(settings), variant) +
                           io::serialise(root);
  try {
    dem::parse_scene(text, variant + ".toml");
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: variant {} ({}) is not a valid scene; nothing was run: {}",
                                 base_name, variant, campaign::describe(settings), e.what()));
  }
  return text;
}

namespace {

constexpr double kMm = 1e-3;

// Decimal values that read well in scene files and job names (2.83e8, not 282842712.47).
double rounded(double v, int digits = 4) {
  if (v == 0.0) return v;
  const double scale = std::pow(10.0, digits - 1 - int(std::floor(std::log10(std::abs(v)))));
  return std::round(v * scale) / scale;
}

bool valid_scene(const std::string& text) {
  try {
    dem::parse_scene(text, "candidate.toml");
    return true;
  } catch (const InputError&) {
    return false;
  }
}

std::vector<campaign::Setting> box_settings(const dem::Scene& s, const std::string& base_text,
                                            double f) {
  const double d50 = s.particles.d50_m;
  const double length = s.length_m / d50, height = s.height_m / d50;
  // the plate's clamp is part of the height: it scales with it, keeping the free share
  std::vector<campaign::Setting> clamp;
  if (s.plate_clamp_m > 0.0)
    clamp.push_back({"plate.clamp_d50", rounded(s.plate_clamp_m / d50 * f)});
  std::vector<campaign::Setting> out = {
      {"specimen.length_d50", rounded(length * f)},
      {"specimen.height_d50", rounded(height * f)},
      {"specimen.particles", std::int64_t(std::lround(s.particle_count * f * f))}};
  out.insert(out.end(), clamp.begin(), clamp.end());
  auto root = io::parse_toml_text(base_text, "base");
  for (const auto& [key, value] : out) io::set_dotted(root, key, value, "base");
  if (valid_scene(io::serialise(root))) return out;
  // The length is at a limit of the scene rules: scale the height alone.
  std::vector<campaign::Setting> taller = {
      {"specimen.height_d50", rounded(height * f)},
      {"specimen.particles", std::int64_t(std::lround(s.particle_count * f))}};
  taller.insert(taller.end(), clamp.begin(), clamp.end());
  return taller;
}

std::vector<campaign::Setting> one_knob(const dem::Scene& s, const std::string& base_text,
                                        const std::string& knob, double f) {
  if (knob == "box") return box_settings(s, base_text, f);
  if (knob == "kappa")
    return {
        {"particles.youngs_modulus_Pa", rounded(s.particles.youngs_modulus_Pa * std::pow(f, 1.5))}};
  if (knob == "dt") return {{"numerics.dt_fraction", rounded(s.dt_fraction * f)}};
  // I: keep the way the scene states its speed
  const auto root = io::parse_toml_text(base_text, "base");
  if (root["shear"]["inertial_number"])
    return {{"shear.inertial_number", rounded(s.shear.inertial_number * f)}};
  return {{"shear.velocity_mm_s", rounded(s.shear.velocity_m_s / kMm * f)}};
}

}  // namespace

namespace {

// The consolidation in the same physical time as the base's: windows of the same duration (the
// servo's acceptance compares the plate's travel and the kinetic energy per window), and, in a
// taller box, proportionally more of them before the servo is declared stuck.
std::vector<campaign::Setting> consolidation_settings(
    const dem::Scene& base, const std::string& base_text,
    const std::vector<campaign::Setting>& settings) {
  auto root = io::parse_toml_text(base_text, "base");
  for (const auto& [key, value] : settings) io::set_dotted(root, key, value, "base");
  const auto variant = dem::parse_scene(io::serialise(root), "variant.toml");
  std::vector<campaign::Setting> out;
  const double dt_ratio = dem::derive(base).dt / dem::derive(variant).dt;
  if (std::abs(dt_ratio - 1.0) > 1e-9)
    out.push_back({"consolidation.window_steps",
                   std::int64_t(std::lround(base.consolidation.window_steps * dt_ratio))});
  const double taller = variant.height_m / base.height_m;
  if (taller > 1.0 + 1e-9)
    out.push_back({"consolidation.max_windows",
                   std::int64_t(std::ceil(base.consolidation.max_windows * taller))});
  return out;
}

}  // namespace

std::vector<campaign::Setting> knob_settings(
    const dem::Scene& base, const std::string& base_text,
    const std::vector<std::pair<std::string, double>>& knob_factors) {
  std::vector<campaign::Setting> out;
  for (const auto& [knob, f] : knob_factors) {
    const auto s = one_knob(base, base_text, find_knob(knob).name, f);
    out.insert(out.end(), s.begin(), s.end());
  }
  const auto c = consolidation_settings(base, base_text, out);
  out.insert(out.end(), c.begin(), c.end());
  return out;
}

}  // namespace iwb::tradeoff
