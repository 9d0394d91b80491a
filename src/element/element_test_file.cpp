#include "element/element_test_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "common/errors.hpp"
#include "common/physical_limits.hpp"
#include "element/element_test_keys.hpp"
#include "element/element_test_limits.hpp"
#include "io/parameter_file.hpp"
#include "io/toml_reader.hpp"
#include "models/registry.hpp"

namespace iwb::element {

namespace {

using io::describe;
using io::TableReader;

using nlohmann::json;

constexpr double kDegree = M_PI / 180.0;

// A table of the file read against its declared rows (element_test_keys.cpp).
io::DeclaredTable declared(TableReader t, const std::string& table) {
  return {std::move(t), element_test_keys(), table};
}

// The declared range of table.key, for values read from an inline table under it.
const Range& declared_range(const std::string& table, const std::string& key) {
  return io::declared(element_test_keys(), table, key).range;
}

std::optional<io::DeclaredTable> optional_table(TableReader& file, const std::string& table) {
  if (auto t = file.table(table)) return declared(std::move(*t), table);
  return std::nullopt;
}

void read_model(io::DeclaredTable model, ElementTestSpec& spec, const std::filesystem::path& base) {
  spec.model = model.text("name");
  try {
    models::find_model(spec.model);  // unknown names fail here, with the list of known ones
  } catch (const InputError& e) {
    throw InputError(model.where("name") + ": " + e.what());  // the file and the key (issue 37)
  }
  const toml::node* params = model.reader().node("parameters");  // a path or inline tables
  if (params == nullptr)
    throw InputError(model.where("parameters") +
                     " is missing (a parameter file path or inline tables)");
  if (const auto file = params->value<std::string>()) {
    const auto path = (base / *file).lexically_normal().string();
    spec.inputs.tables = io::load_parameter_file(path);
    spec.inputs.source = path;
    spec.parameter_source = path;
  } else if (const auto* inline_tables = params->as_table()) {
    spec.inputs.tables = io::read_parameter_tables(*inline_tables, model.where("parameters"));
    spec.inputs.source = model.where("parameters");
    spec.parameter_source = "inline";
  } else {
    throw InputError(fmt::format("{} = {} should be a file path or a table",
                                 model.where("parameters"), describe(*params)));
  }
  model.finish();
}

void read_roughness(std::optional<io::DeclaredTable> r, ElementTestSpec& spec) {
  const auto& model = models::find_model(spec.model);
  const auto& support = model.declaration.roughness;
  json out = {{"scheme", models::to_string(support.default_scheme)},
              {"kappa_r", 1.0},
              {"origin", "default (fully rough)"}};
  spec.inputs.roughness.scheme = support.default_scheme;
  if (!r && (support.reads_normalized_roughness || support.reads_mean_slope))
    throw InputError(fmt::format("model '{}' reads the wall: give a [roughness] table with {}",
                                 spec.model, support.reads_mean_slope ? "mean_abs_slope" : "R_n"));
  if (!r) {
    spec.resolved["roughness"] = model.uses_roughness ? out : json(nullptr);
    return;
  }
  if (!model.uses_roughness)
    throw InputError(
        fmt::format("{}: model '{}' is a continuum model and takes no wall roughness; "
                    "remove the table",
                    r->where(), spec.model));
  const std::string scheme =
      r->optional_text("scheme").value_or(models::to_string(support.default_scheme));
  const auto named = support.scheme_named(scheme);
  if (!named)
    throw InputError(fmt::format("{} = \"{}\"; allowed {}", r->where("scheme"), scheme,
                                 support.scheme_names(" or ")));
  spec.inputs.roughness.scheme = *named;
  // ERRATA 9: the reading of Arnold & Herle's f_c (eq. 5.40), for their sand scheme only
  const auto f_c = r->optional_text("f_c");
  if (f_c && !support.reads_arnold_herle_factor(*named))
    throw InputError(
        fmt::format("{}: f_c is the rate factor of Arnold & Herle's sand scheme (eq. 5.40); "
                    "give scheme = \"arnold-herle\" with a sand model, or drop it",
                    r->where("f_c")));
  if (f_c) spec.inputs.roughness.f_c = models::parse_arnold_herle_factor(*f_c, r->where("f_c"));
  const auto slope = r->optional_number("mean_abs_slope");
  if (slope && !support.reads_mean_slope)
    throw InputError(fmt::format("{}: model '{}' reads no wall slope; drop it",
                                 r->where("mean_abs_slope"), spec.model));
  if (support.reads_mean_slope && !slope)
    throw InputError(
        fmt::format("{}: model '{}' reads the wall's mean |slope| (its asperities' ride): give "
                    "mean_abs_slope (iwb dem roughness reports it)",
                    r->where(), spec.model));
  spec.inputs.roughness.mean_abs_slope = slope;
  const std::string source = r->one_of({"kappa_r", "R_n", "delta_deg"});
  if (source == "R_n" && !support.from_normalized_roughness)
    throw InputError(
        fmt::format("{}: model '{}' takes no R_n (eq. 5.35 is Gutjahr's for sand); give kappa_r or "
                    "delta_deg",
                    r->where("R_n"), spec.model));
  if (support.reads_normalized_roughness && source != "R_n")
    throw InputError(fmt::format(
        "{}: model '{}' reads the wall's R_n beside kappa_r (its roughness dilatancy); give R_n "
        "(kappa_r then follows from eq. 5.35)",
        r->where(source), spec.model));
  models::KappaR k{1.0, {}};
  std::string origin;
  if (source == "kappa_r") {
    k.value = r->number("kappa_r");
    origin = "given";
  } else if (source == "R_n") {
    const double base = r->number("log_base");
    const double rn = r->number("R_n");
    k = models::kappa_r_from_normalized_roughness(rn, base);
    spec.inputs.roughness.R_n = rn;
    origin = fmt::format("R_n = {:g}, eq. 5.35 with log base {:g}", rn, base);
  } else {
    const double delta = r->number("delta_deg");
    const double phi_c = models::critical_friction_angle(model, spec.inputs);
    const bool angles = support.from_angle == models::KappaFromAngle::kAngleRatio;
    k = angles ? models::kappa_r_from_angle_ratio(delta * kDegree, phi_c)
               : models::kappa_r_from_friction_angles(delta * kDegree, phi_c);
    origin = fmt::format("delta = {:g} deg, eq. {}", delta, angles ? "6.21" : "5.36");
  }
  r->finish();
  spec.inputs.roughness.kappa_r = k.value;
  for (auto& w : k.warnings) spec.warnings.push_back(r->where() + ": " + w);
  spec.resolved["roughness"] = {{"scheme", scheme}, {"kappa_r", k.value}, {"origin", origin}};
  if (f_c) spec.resolved["roughness"]["f_c"] = models::to_string(spec.inputs.roughness.f_c);
}

// The value as written, arrays included (describe() names only the type of an array).
std::string written(const toml::node& node) {
  if (const auto* arr = node.as_array()) {
    std::string s;
    for (const auto& v : *arr) s += (s.empty() ? "" : ", ") + written(v);
    return "[" + s + "]";
  }
  return describe(node);
}

bool all_numbers(const toml::array& a) {
  for (const auto& v : a)
    if (!v.is_integer() && !v.is_floating_point()) return false;
  return true;
}

// A declared vector of [initial] (the intergranular strain's delta): three numbers, or the keyword
// that names the model's default, which also applies when the key is absent; its size within the
// declared range in units of the declared scale (R).
void read_initial_vector(TableReader& t, const models::InitialInputSpec& in,
                         ElementTestSpec& spec) {
  const toml::node* node = t.node(in.key);
  const std::string keyword = in.choices.front();
  std::string origin = "given";
  std::array<double, 3> v{};
  if (node == nullptr || node->value<std::string>() == std::optional<std::string>(keyword)) {
    v = in.default_vector(spec.inputs);
    origin = in.default_origin;
  } else {
    const auto* arr = node->as_array();
    if (arr == nullptr || arr->size() != 3 || !all_numbers(*arr))
      throw InputError(fmt::format("{} = {} should be \"{}\" or three numbers {}", t.where(in.key),
                                   written(*node), keyword,
                                   fmt::format("[{0}_n, {0}_x, {0}_y]", in.key)));
    for (int i = 0; i < 3; ++i) v[i] = arr->get(i)->value<double>().value();
    const double scale = in.scale(spec.inputs);
    const double size = in.norm(v) / scale;
    if (!in.range.admits(size))
      throw InputError(
          fmt::format("{} = {}: ||{}|| = {:g} {} is out of range; allowed {} {} ({} = {:g})",
                      t.where(in.key), written(*node), in.key, size, in.scale_name, in.range.text(),
                      in.scale_name, in.scale_name, scale));
  }
  models::set_initial_vector(spec.initial, in.key, v);
  spec.resolved["initial"][in.key] = {
      {in.key + "_n", v[0]}, {in.key + "_x", v[1]}, {in.key + "_y", v[2]}, {"origin", origin}};
}

// A key of [initial] that this model does not declare but others do (the -igs variants' delta):
// say which take it, rather than the reader's bare "unknown key". A key already read (hp1d's K0,
// ignored with a warning) is not refused.
void refuse_inputs_of_other_models(TableReader& t, const ElementTestSpec& spec) {
  const auto& declared = models::find_model(spec.model).declaration.initial;
  for (const auto& other : models::model_registry())
    for (const auto& in : other.declaration.initial) {
      if (!t.has(in.key) || t.was_read(in.key) || models::find_initial_input(declared, in.key))
        continue;
      std::vector<std::string> variants;  // of this model, by name: hvwe-igs (not -exact-igs)
      for (const auto& m : models::model_registry())
        if (m.name.rfind(spec.model + "-", 0) == 0 &&
            m.name.find('-', spec.model.size() + 1) == std::string::npos &&
            models::find_initial_input(m.declaration.initial, in.key) != nullptr)
          variants.push_back(m.name);
      throw InputError(fmt::format("{} = {}: model '{}' takes no {} ({}; or remove the key)",
                                   t.where(in.key), written(*t.node(in.key)), spec.model, in.doc,
                                   variants.empty()
                                       ? "`iwb models` says which do"
                                       : fmt::format("{} {}", fmt::join(variants, ", "),
                                                     variants.size() == 1 ? "does" : "do")));
    }
}

// One declared number of [initial]: its range, its default when absent (K0 = 1 - sin phi_c, the
// oedometric start of CONVENTIONS.md), a fixed value kept with a warning when a file gives another.
void read_initial_number(TableReader& t, const models::InitialInputSpec& in,
                         ElementTestSpec& spec) {
  using Need = models::InitialInputSpec::Need;
  std::optional<double> v = in.need == Need::kRequired ? t.number_in(in.key, in.range)
                                                       : t.optional_number_in(in.key, in.range);
  if (in.need == Need::kOneOf && !v) return;  // the group's check says whether one was given
  if (in.need == Need::kFixed && v && *v != in.default_value(spec.inputs))
    spec.warnings.push_back(
        fmt::format("{} = {:g} is ignored: {} ({})", t.where(in.key), *v, in.doc, spec.model));
  if (in.need == Need::kFixed || (!v && in.default_value)) v = in.default_value(spec.inputs);
  if (!v) return;  // optional without a default: not given
  models::set_initial_input(spec.initial, in.key, *v);
  spec.resolved["initial"][in.key] = *v;
}

// Of each group of alternative inputs (a clay's e0 | OCR) exactly one is given.
void require_one_of_each_group(const TableReader& t,
                               const std::vector<models::InitialInputSpec>& declared) {
  std::map<std::string, std::vector<std::string>> groups;
  for (const auto& in : declared)
    if (in.need == models::InitialInputSpec::Need::kOneOf) groups[in.group].push_back(in.key);
  for (const auto& [group, keys] : groups) {
    std::string names, given;
    for (const auto& k : keys) {
      names += (names.empty() ? "" : " or ") + k;
      if (t.has(k)) given += (given.empty() ? "" : " and ") + k;
    }
    if (given.empty())
      throw InputError(fmt::format("{}: give the {} as {}", t.where(), group, names));
    if (given.find(" and ") != std::string::npos)
      throw InputError(fmt::format("{}: {} both set the {}; give one", t.where(), given, group));
  }
}

// [initial] as the model declares it. A K0 for a model without an in-plane stress (hp1d) is
// ignored with a warning: test files written for several models give one.
void read_initial(TableReader t, ElementTestSpec& spec) {
  const auto& declared = models::find_model(spec.model).declaration.initial;
  spec.resolved["initial"] = json::object();
  for (const auto& in : declared)
    if (in.kind == models::InitialInputSpec::Kind::kNumber) read_initial_number(t, in, spec);
  require_one_of_each_group(t, declared);
  if (models::find_initial_input(declared, "K0") != nullptr)
    spec.resolved["initial"]["sigma_p_kPa"] = spec.initial.K0 * spec.initial.sigma_n;
  else if (t.has("K0"))
    spec.warnings.push_back(fmt::format("{} = {:g} is ignored: {} has no in-plane stress",
                                        t.where("K0"), t.number_in("K0", positive(kMaxK0)),
                                        spec.model));
  for (const auto& in : declared)
    if (in.kind == models::InitialInputSpec::Kind::kKeywordOrVector3)
      read_initial_vector(t, in, spec);
  refuse_inputs_of_other_models(t, spec);
  t.finish();
}

void read_zone(std::optional<io::DeclaredTable> t, ElementTestSpec& spec) {
  if (t) {
    // d_s_mm (its default when the table gives neither form), or d50_mm times d_s_over_d50
    const bool grain_form = !t->has("d_s_mm") && (t->has("d50_mm") || t->has("d_s_over_d50"));
    spec.zone.d_s_mm =
        !grain_form ? t->number("d_s_mm") : t->number("d50_mm") * t->number("d_s_over_d50");
    if (grain_form) spec.inputs.d50_mm = t->number("d50_mm");  // a length in grains reads it
    spec.zone.measure = t->text("strain_measure") == "tangent"
                            ? driver::ShearStrainMeasure::kTangent
                            : driver::ShearStrainMeasure::kLinear;
    t->finish();
  }
  spec.resolved["shear_zone"] = {{"d_s_mm", spec.zone.d_s_mm},
                                 {"strain_measure", spec.zone.describe()}};
}

void read_boundary(io::DeclaredTable t, ElementTestSpec& spec) {
  // any case: "cnl" is CNL (driver::parse_boundary_kind)
  spec.boundary.kind = driver::parse_boundary_kind(t.reader().text("type"), t.where("type"));
  if (spec.boundary.kind == driver::BoundaryKind::kCNS) {
    const std::string key = t.one_of({"K_kPa_per_mm", "K_kPa"});
    const double k = t.number(key);
    spec.boundary = key == "K_kPa"
                        ? driver::BoundaryCondition{spec.boundary.kind, k}
                        : driver::with_stiffness_per_mm(spec.boundary.kind, k, spec.zone.d_s_mm);
  }
  t.finish();
  spec.resolved["boundary"] = {{"type", driver::to_string(spec.boundary.kind)},
                               {"K_kPa_per_unit_strain", spec.boundary.K_kPa},
                               {"K_kPa_per_mm", spec.boundary.K_kPa / spec.zone.d_s_mm}};
}

// A shear strain given as gamma or as a displacement u (mm) through d_s.
double strain(io::DeclaredTable& t, const std::string& gamma_key, const std::string& u_key,
              const driver::ShearZone& zone) {
  if (t.one_of({gamma_key, u_key}) == gamma_key) return t.number(gamma_key);
  const double u = t.number(u_key);
  const double gamma = zone.gamma_of(u);
  if (!(gamma <= kMaxShearStrain))
    throw InputError(
        fmt::format("{} = {:g} is a shear strain of {:g} over d_s = {:g} mm; allowed up to {:g}",
                    t.where(u_key), u, gamma, zone.d_s_mm, kMaxShearStrain));
  return gamma;
}

void check_length(const io::DeclaredTable& t, double increments) {
  if (increments > kMaxIncrements)
    throw InputError(
        fmt::format("{}: the path has {:g} increments; allowed up to {:g} (fewer cycles or "
                    "increments)",
                    t.where(), increments, kMaxIncrements));
}

// The key an external variable's path is given by and its unit's offset from the state's unit:
// T_K or T_C (deg C, stated in the key), s_kPa, t_s. Their ranges are the declared rows'.
struct ExternalKey {
  models::External slot;
  const char* key;
  double offset;
};
const ExternalKey kExternalKeys[] = {{models::External::kTemperature, "T_K", 0.0},
                                     {models::External::kTemperature, "T_C", kKelvinOffset},
                                     {models::External::kSuction, "s_kPa", 0.0},
                                     {models::External::kTime, "t_s", 0.0}};

// `{ to = V }` (ramp to a value), `{ by = dV }` (ramp by a change) or `{ amplitude = A, cycles = n
// }` (cycle about the value at the stage's start); `current` (state units) follows the path.
driver::ExternalPath read_external_path(TableReader t, const ExternalKey& k, double& current,
                                        json& out) {
  driver::ExternalPath x;
  // the range in the key's own unit (deg C for T_C), for the values and the messages alike, and in
  // the state's (K)
  const Range& in_unit = declared_range("path.stage", k.key);
  const Range range{in_unit.lower + k.offset, in_unit.upper + k.offset, false, false};
  const std::string how = t.one_of({"to", "by", "amplitude"});
  if (how == "to") {
    const double to = t.number_in("to", in_unit) + k.offset;
    x = {driver::ExternalPath::Kind::kRamp, to - current};
    current = to;
    out[k.key] = {{"to", to - k.offset}};
  } else if (how == "by") {
    const double by = t.number_in("by", closed(-range.upper, range.upper));
    if (!range.admits(current + by))
      throw InputError(fmt::format("{} = {:g} takes {} to {:g}, outside {}", t.where("by"), by,
                                   k.key, current + by - k.offset, in_unit.text()));
    x = {driver::ExternalPath::Kind::kRamp, by};
    current += by;
    out[k.key] = {{"by", by}};
  } else {
    const double a = t.positive("amplitude", range.upper);
    const int cycles = t.count("cycles");
    if (cycles > kMaxStageCycles || !range.admits(current + a) || !range.admits(current - a))
      throw InputError(
          fmt::format("{}: {} cycles of +-{:g} about {:g}; allowed up to {} cycles within {}",
                      t.where(), cycles, a, current - k.offset, kMaxStageCycles, in_unit.text()));
    x = {driver::ExternalPath::Kind::kCycle, 0.0, a, cycles};
    out[k.key] = {{"amplitude", a}, {"cycles", cycles}};
  }
  t.finish();
  return x;
}

// A stage that cycles a variable is walked a quarter cycle at a time (driver::stage_path): its
// increments must split into the quarters, checked here where the file and the key are known.
void check_quarters(const io::DeclaredTable& t, const driver::Stage& st, const char* key,
                    const driver::ExternalPath& x) {
  if (x.kind != driver::ExternalPath::Kind::kCycle || st.increments % (4 * x.cycles) == 0) return;
  throw InputError(fmt::format(
      "{} = {} does not split into the {} quarters of the {} cycles of {}; give a multiple of {}",
      t.where("increments"), st.increments, 4 * x.cycles, x.cycles, key, 4 * x.cycles));
}

// One [[path.stage]]: label, increments, an optional shear (gamma or u_mm, either sign), the
// normal control ([boundary] unless `normal` names another; CNL may ramp sigma_n_kPa = { to }),
// the paths of the external variables the model declares.
driver::Stage read_stage(io::DeclaredTable t, int index, ElementTestSpec& spec, double& sigma_n,
                         std::array<double, models::kExternalSlots>& current, json& out) {
  driver::Stage st;
  st.label = t.optional_text("label").value_or(fmt::format("stage {}", index + 1));
  st.increments = t.whole_number("increments");
  out = {{"label", st.label}, {"increments", st.increments}};
  st.gamma =
      t.has("u_mm") && !t.has("gamma") ? spec.zone.gamma_of(t.number("u_mm")) : t.number("gamma");
  out["gamma"] = st.gamma;
  st.bc = spec.boundary;
  if (const auto normal = t.reader().optional_text("normal")) {  // any case, as [boundary] type
    st.bc.kind = driver::parse_boundary_kind(*normal, t.where("normal"));
    if (st.bc.kind == driver::BoundaryKind::kCNS &&
        spec.boundary.kind != driver::BoundaryKind::kCNS)
      throw InputError(fmt::format("{} = \"CNS\" needs the stiffness of a [boundary] of type CNS",
                                   t.where("normal")));
  }
  out["normal"] = driver::to_string(st.bc.kind);
  if (auto ramp = t.table("sigma_n_kPa")) {
    if (st.bc.kind != driver::BoundaryKind::kCNL)
      throw InputError(
          fmt::format("{}: a ramp of sigma_n needs normal = \"CNL\"", t.where("sigma_n_kPa")));
    const double to = ramp->number_in("to", declared_range("path.stage", "sigma_n_kPa"));
    ramp->finish();
    st.d_sigma_n = to - sigma_n;
    sigma_n = to;
    out["sigma_n_kPa"] = {{"to", to}};
  }
  const auto& declared = models::find_model(spec.model).declaration.externals;
  for (const auto& k : kExternalKeys) {
    auto path = t.table(k.key);
    if (!path) continue;
    const bool read = std::any_of(declared.begin(), declared.end(),
                                  [&](const auto& x) { return x.which == k.slot; });
    if (!read)
      throw InputError(
          fmt::format("{}: model {} does not read {} (`iwb models` lists what each model reads)",
                      t.where(k.key), spec.model, k.key));
    const auto slot = std::size_t(k.slot);
    if (st.external[slot].kind != driver::ExternalPath::Kind::kHold)
      throw InputError(fmt::format("{}: the stage gives this variable twice", t.where(k.key)));
    st.external[slot] = read_external_path(*path, k, current[slot], out);
    check_quarters(t, st, k.key, st.external[slot]);
  }
  t.finish();
  return st;
}

// kind = "stages": the path as a list of [[path.stage]] tables (README.md of data/tests).
void read_stages(io::DeclaredTable& t, driver::ShearDirection dir, ElementTestSpec& spec,
                 json& out) {
  double sigma_n = spec.initial.sigma_n;
  std::array<double, models::kExternalSlots> current{};
  for (const auto& k : kExternalKeys)
    if (const auto v = spec.initial.named.find(models::external_key(k.slot));
        v != spec.initial.named.end())
      current[std::size_t(k.slot)] = v->second;
  std::vector<driver::Stage> stages;
  auto tables = t.tables("stage");
  if (tables.empty())
    throw InputError(
        fmt::format("{}: kind = \"stages\" needs at least one [[path.stage]]", t.where()));
  out["stages"] = json::array();
  for (std::size_t i = 0; i < tables.size(); ++i) {
    json o;
    stages.push_back(read_stage(declared(std::move(tables[i]), "path.stage"), int(i), spec, sigma_n,
                                current, o));
    out["stages"].push_back(o);
  }
  spec.path = driver::stage_path(stages, dir);
}

// A model that builds only its monotonic part (`iwb models`: monotonic only) has no law where a
// cyclic path reverses: its cycles would show a law never meant for them (compare and pile
// refuse it alike).
void require_reversible(const io::DeclaredTable& t, const std::string& model) {
  if (!models::find_model(model).declaration.monotonic_only) return;
  throw InputError(fmt::format(
      "{} = \"cyclic\": model '{}' is monotonic only (iwb models): it builds no law for where "
      "the path reverses; give a monotonic, staged or oedometric path, or a model that unloads",
      t.where("kind"), model));
}

void read_path(io::DeclaredTable t, ElementTestSpec& spec) {
  const std::string kind = t.text("kind");
  const std::string dir = t.text("direction");
  spec.direction = dir == "y" ? driver::ShearDirection::kY : driver::ShearDirection::kX;
  const auto d = spec.direction;
  json out = {{"kind", kind}, {"direction", dir}};
  if (kind == "monotonic") {
    const double g = strain(t, "gamma", "u_mm", spec.zone);
    spec.path = driver::monotonic_path(spec.boundary, g, d, t.whole_number("increments"));
    out["gamma"] = g;
  } else if (kind == "cyclic") {
    require_reversible(t, spec.model);
    const double a = strain(t, "amplitude_gamma", "amplitude_u_mm", spec.zone);
    const int cycles = t.whole_number("cycles");
    const int per_quarter = t.whole_number("increments_per_quarter");
    check_length(t, 4.0 * cycles * per_quarter);  // before a path of 4 stages per cycle is built
    if (t.has("steps")) {
      if (spec.boundary.kind != driver::BoundaryKind::kCNL)
        throw InputError(fmt::format("{}: staged cycles step sigma_n and need boundary type CNL",
                                     t.where("steps")));
      std::vector<driver::CyclicStage> stages;
      for (auto& table : t.tables("steps")) {
        auto s = declared(std::move(table), "path.steps");
        stages.push_back({s.whole_number("from_cycle"), s.number("sigma_n_kPa")});
        s.finish();
        out["steps"].push_back(
            {{"from_cycle", stages.back().from_cycle}, {"sigma_n_kPa", stages.back().sigma_n_kPa}});
      }
      spec.path = driver::staged_cyclic_path(spec.initial.sigma_n, a, cycles, stages, d,
                                             per_quarter, t.whole_number("step_increments"));
    } else {
      spec.path = driver::cyclic_path(spec.boundary, a, cycles, d, per_quarter);
    }
    out["amplitude_gamma"] = a;
    out["cycles"] = cycles;
  } else if (kind == "staged") {
    if (spec.boundary.kind != driver::BoundaryKind::kCNL)
      throw InputError(fmt::format("{}: a staged path steps sigma_n and needs boundary type CNL",
                                   t.where("kind")));
    const double g = strain(t, "gamma", "u_mm", spec.zone);
    std::vector<driver::StagedStep> steps;
    for (auto& table : t.tables("steps")) {
      auto s = declared(std::move(table), "path.steps");
      const double at = strain(s, "at_gamma", "at_u_mm", spec.zone);
      steps.push_back({at, s.number("sigma_n_kPa")});
      s.finish();
      out["steps"].push_back({{"at_gamma", at}, {"sigma_n_kPa", steps.back().sigma_n_kPa}});
    }
    spec.path = driver::staged_path(spec.initial.sigma_n, g, steps, d, t.whole_number("increments"),
                                    t.whole_number("step_increments"));
    out["gamma"] = g;
  } else if (kind == "stages") {
    read_stages(t, d, spec, out);
  } else if (kind == "oedometric") {
    const double to = t.number("sigma_n_end_kPa");
    spec.path = driver::oedometric_path(spec.initial.sigma_n, to, t.whole_number("increments"));
    out["sigma_n_end_kPa"] = to;
  }
  t.finish();
  long n = 0;
  for (const auto& s : spec.path) n += s.increments;
  check_length(t, double(n));
  out["increments_total"] = n;
  spec.resolved["path"] = out;
}

void read_integration(std::optional<io::DeclaredTable> t, ElementTestSpec& spec) {
  auto& is = spec.settings.integrator;
  auto& mc = spec.settings.mixed;
  if (t) {
    if (t->text("scheme") == "euler") {
      is.scheme = integration::Scheme::kExplicitEuler;
      is.substeps = t->whole_number("substeps");
    } else {
      is.scheme = integration::Scheme::kAdaptive;
      is.pair = t->text("pair");
      is.rtol = t->number("rtol");
    }
    if (t->text("mixed_control") == "closed-form")
      mc.method = driver::MixedControlMethod::kClosedForm;
    mc.tolerance = t->number("tolerance");
    t->finish();
  }
  if (mc.method == driver::MixedControlMethod::kClosedForm &&
      is.scheme != integration::Scheme::kExplicitEuler)
    throw InputError(fmt::format(
        "{}: mixed_control = \"closed-form\" (appendix C) needs scheme = \"euler\"", spec.source));
  spec.resolved["integration"] = {
      {"scheme", is.describe()},
      {"mixed_control",
       mc.method == driver::MixedControlMethod::kNewton ? "newton" : "closed-form"},
      {"tolerance", mc.tolerance}};
}

}  // namespace

ElementTestSpec parse_element_test(const toml::table& root, const std::string& source,
                                   const std::filesystem::path& base_dir) {
  ElementTestSpec spec;
  spec.source = source;
  io::DeclaredTable top = declared(TableReader(root, source), "");
  auto& file = top.reader();
  read_model(declared(file.required_table("model"), "model"), spec, base_dir);
  read_roughness(optional_table(file, "roughness"), spec);
  // the zone before the model is built: a model with a length in grains reads its d50
  read_zone(optional_table(file, "shear_zone"), spec);
  spec.inputs.shear_zone_mm = spec.zone.d_s_mm;
  models::find_model(spec.model).make(spec.inputs);  // parameters validated before anything runs
  for (const auto* table : models::find_model(spec.model).tables)
    if (const auto it = spec.inputs.tables.find(table->name); it != spec.inputs.tables.end())
      for (auto& w : models::implausible_values(*table, it->second,
                                                spec.parameter_source + " [" + table->name + "]"))
        spec.warnings.push_back(std::move(w));
  read_initial(file.required_table("initial"), spec);
  read_boundary(declared(file.required_table("boundary"), "boundary"), spec);
  read_path(declared(file.required_table("path"), "path"), spec);
  read_integration(optional_table(file, "integration"), spec);
  if (auto out = optional_table(file, "output")) {
    spec.settings.output_every = out->whole_number("every");
    out->finish();
  }
  const std::string description = top.text("description");
  top.finish();
  spec.resolved["description"] = description;
  spec.resolved["model"] = {
      {"name", spec.model}, {"parameters", spec.parameter_source}, {"values", spec.inputs.tables}};
  spec.resolved["output_every"] = spec.settings.output_every;
  return spec;
}

integration::IntegratorSettings parse_integrator_settings(const toml::table& integration,
                                                          const std::string& source) {
  ElementTestSpec spec;
  spec.source = source;
  read_integration(declared(TableReader(integration, source), "integration"), spec);
  return spec.settings.integrator;
}

models::InitialState parse_initial_state(const toml::table& initial, const std::string& model,
                                         const models::ModelInputs& inputs,
                                         const std::string& source) {
  ElementTestSpec spec;
  spec.model = model;
  spec.inputs = inputs;
  read_initial(TableReader(initial, source), spec);
  return spec.initial;
}

ElementTestSpec load_element_test(const std::string& path) {
  return parse_element_test(io::parse_toml_file(path), path,
                            std::filesystem::path(path).parent_path());
}

}  // namespace iwb::element
