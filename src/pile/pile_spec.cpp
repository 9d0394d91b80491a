#include "pile/pile_spec.hpp"

#include <fmt/core.h>

#include <cmath>

#include "common/errors.hpp"
#include "io/toml_reader.hpp"

namespace iwb::pile {

namespace {

// Far beyond any pile: only a units mistake is refused.
constexpr double kMaxLength_m = 500.0, kMaxDiameter_m = 20.0, kMaxElements = 10000;

PileGeometry read_pile(io::TableReader t) {
  PileGeometry p{t.positive("length_m", kMaxLength_m), t.positive("diameter_m", kMaxDiameter_m),
                 t.positive("EA_kN"), t.count("elements")};
  if (p.elements > kMaxElements)
    throw InputError(
        fmt::format("{} = {}; at most {}", t.where("elements"), p.elements, kMaxElements));
  t.finish();
  return p;
}

SoilProfile read_soil(io::TableReader t) {
  SoilProfile s{t.positive("unit_weight_kN_m3", 100.0), t.positive("K0", 10.0),
                t.positive("shear_modulus_kPa")};
  t.finish();
  return s;
}

InterfaceSpec read_interface(io::TableReader t, const std::filesystem::path& base_dir) {
  InterfaceSpec s;
  s.model = t.text("model");
  s.parameters = base_dir / t.text("parameters");
  s.kappa_r = t.optional_number_in("kappa_r", Range{0.0, 1.0, true, false}).value_or(s.kappa_r);
  s.d_s_mm = t.positive("d_s_mm", 1e4);
  // the model's own [initial] inputs besides sigma_n_kPa and K0, which the depth sets; checked
  // by the model when the shaft's stress points are made (the C interface names a bad key)
  if (const auto* initial = t.node("initial")) {
    if (!initial->is_table())
      throw InputError(
          fmt::format("{}: a table of the model's initial inputs", t.where("initial")));
    for (const auto& [key, node] : *initial->as_table()) {
      const auto v = node.value<double>();
      const std::string k(key.str());
      if (!v || !std::isfinite(*v))
        throw InputError(fmt::format("{}: a finite number", t.where("initial." + k)));
      if (k == "sigma_n_kPa" || k == "K0")
        throw InputError(fmt::format(
            "{}: set by the depth and [soil] K0 (sigma_n = K0 gamma' z, the in-plane stress "
            "the vertical one); leave it out",
            t.where("initial." + k)));
      s.initial[k] = *v;
    }
  }
  t.finish();
  return s;
}

Loading read_loading(io::TableReader t) {
  Loading l;
  const std::string kind = t.text("kind");
  if (kind == "settlement") {
    l.settlement_mm = t.positive("settlement_mm", 1e4);
    l.increments = t.count("increments");
  } else if (kind == "cyclic_load") {
    l.kind = LoadingKind::kCyclicLoad;
    l.mean_kN = t.number_in("mean_kN", Range{0.0, kInf, false, false});
    l.amplitude_kN = t.positive("amplitude_kN");
    l.cycles = t.count("cycles");
    l.increments_per_quarter = t.count("increments_per_quarter");
  } else if (kind == "cyclic_settlement") {
    l.kind = LoadingKind::kCyclicSettlement;
    l.amplitude_mm = t.positive("amplitude_mm", 1e4);
    l.cycles = t.count("cycles");
    l.increments_per_quarter = t.count("increments_per_quarter");
  } else {
    throw InputError(
        fmt::format("{} = \"{}\"; allowed \"settlement\", \"cyclic_load\" or \"cyclic_settlement\"",
                    t.where("kind"), kind));
  }
  if (const auto* loads = t.node("profile_loads_kN")) {
    const auto* array = loads->as_array();
    if (array == nullptr)
      throw InputError(fmt::format("{}: an array of loads in kN", t.where("profile_loads_kN")));
    for (const auto& v : *array) {
      const auto x = v.value<double>();
      if (!x || !(*x > 0.0))
        throw InputError(
            fmt::format("{}: every load must be a number > 0", t.where("profile_loads_kN")));
      l.profile_loads_kN.push_back(*x);
    }
  }
  t.finish();
  return l;
}

}  // namespace

PileSpec parse_pile_spec(const toml::table& root, const std::string& source,
                         const std::filesystem::path& base_dir) {
  io::TableReader top(root, source);
  PileSpec s;
  s.source = source;
  s.description = top.optional_text("description").value_or("");
  s.pile = read_pile(top.required_table("pile"));
  s.soil = read_soil(top.required_table("soil"));
  auto base = top.required_table("base");
  s.base_stiffness_kN_per_mm =
      base.number_in("stiffness_kN_per_mm", Range{0.0, kInf, false, false});
  base.finish();
  s.interface = read_interface(top.required_table("interface"), base_dir);
  s.loading = read_loading(top.required_table("loading"));
  top.finish();
  return s;
}

PileSpec load_pile_spec(const std::filesystem::path& file) {
  return parse_pile_spec(io::parse_toml_file(file.string()), file.string(), file.parent_path());
}

}  // namespace iwb::pile
