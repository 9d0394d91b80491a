#include "models/registry.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/errors.hpp"

namespace iwb::models {

namespace {

std::string layout_problem(const StateLayout& l) {
  if (l.size() > kMaxStateSize)
    return fmt::format("{} state components, more than kMaxStateSize = {}", l.size(),
                       kMaxStateSize);
  if (l.size() == 0 || l.components[0].kind != ComponentKind::kStress)
    return "state component 0 must be the normal stress (the driver reads sigma_n there)";
  const auto names = l.names();
  for (std::size_t i = 0; i < names.size(); ++i)
    for (std::size_t j = i + 1; j < names.size(); ++j)
      if (names[i] == names[j]) return fmt::format("state component '{}' declared twice", names[i]);
  if (l.void_ratio >= l.size() ||
      (l.void_ratio >= 0 &&
       l.components[std::size_t(l.void_ratio)].kind != ComponentKind::kVoidRatio))
    return fmt::format("void_ratio index {} is not a void-ratio component", l.void_ratio);
  for (int slot = 0; slot < kExternalSlots; ++slot) {
    const int i = l.external[std::size_t(slot)];
    if (i >= l.size() || (i >= 0 && l.components[std::size_t(i)].kind != ComponentKind::kExternal))
      return fmt::format("external variable slot {} points at {}, not an external component", slot,
                         i);
  }
  return {};
}

template <class Named>
std::string duplicate_name(const std::vector<Named>& items, const char* what) {
  for (std::size_t i = 0; i < items.size(); ++i)
    for (std::size_t j = i + 1; j < items.size(); ++j)
      if (items[i].name == items[j].name)
        return fmt::format("{} '{}' declared twice", what, items[i].name);
  return {};
}

std::vector<ModelSpec> checked_and_ordered(std::vector<ModelSpec> specs) {
  for (const auto& s : specs)
    if (const auto why = declaration_problem(s); !why.empty())
      throw std::logic_error(fmt::format("model '{}' is declared inconsistently: {}", s.name, why));
  std::stable_sort(specs.begin(), specs.end(), [](const ModelSpec& a, const ModelSpec& b) {
    return a.declaration.listing_order < b.declaration.listing_order;
  });
  return specs;
}

// "[hypoplastic], [intergranular_strain]": the tables a parameter file gave, for a message.
std::string tables_given(const ModelInputs& inputs) {
  if (inputs.tables.empty()) return "no table";
  std::string names;
  for (const auto& [name, values] : inputs.tables)
    names += fmt::format("{}[{}]", names.empty() ? "" : ", ", name);
  return names;
}

// The table `name` that `model` reads; InputError naming the model and what the file has.
const ParameterValues& table_for(const std::string& model, const ModelInputs& in,
                                 const std::string& name) {
  const auto it = in.tables.find(name);
  if (it == in.tables.end())
    throw InputError(fmt::format("{}: no table [{}] (the model {} reads it; the file has {})",
                                 in.source, name, model, tables_given(in)));
  return it->second;
}

// `spec` whose make first finds every table the model declares, naming the model in the message:
// a factory's own read (require_table) does not know which model it builds, and a table missing
// for mc once surfaced as "map::at" (issue 60).
ModelSpec with_checked_tables(ModelSpec spec) {
  spec.make = [make = std::move(spec.make), name = spec.name,
               tables = spec.tables](const ModelInputs& in) {
    for (const auto* t : tables) table_for(name, in, t->name);
    return make(in);
  };
  return spec;
}

}  // namespace

std::string declaration_problem(const ModelSpec& spec) {
  const auto& d = spec.declaration;
  if (auto why = layout_problem(d.layout); !why.empty()) return why;
  if (auto why = duplicate_name(d.diagnostics, "diagnostic"); !why.empty()) return why;
  if (auto why = duplicate_name(d.fit, "fit parameter"); !why.empty()) return why;
  if (spec.uses_roughness == d.roughness.schemes.empty())
    return "uses_roughness disagrees with the declared roughness schemes";
  if (!spec.uses_roughness && !d.fit.empty())
    return "fit parameters declared for a model without roughness";
  for (std::size_t i = 0; i < spec.tables.size(); ++i)
    for (std::size_t j = i + 1; j < spec.tables.size(); ++j)
      if (spec.tables[i]->name == spec.tables[j]->name)
        return fmt::format("parameter table [{}] listed twice", spec.tables[i]->name);
  return {};
}

namespace {

// Room for the models added at run time (a user's library): find_model's references must stay
// valid, so the vector never reallocates after it is built.
constexpr std::size_t kRuntimeModels = 16;

std::vector<ModelSpec>& registry_storage() {
  static std::vector<ModelSpec> specs = [] {
    ModelRegistry registry;
    register_all_models(registry);
    auto ordered = checked_and_ordered(registry.take());
    for (auto& spec : ordered) spec = with_checked_tables(std::move(spec));
    ordered.reserve(ordered.size() + kRuntimeModels);
    return ordered;
  }();
  return specs;
}

}  // namespace

const std::vector<ModelSpec>& model_registry() {
  return registry_storage();
}

void add_runtime_model(ModelSpec spec) {
  auto& specs = registry_storage();
  if (const auto why = declaration_problem(spec); !why.empty())
    throw InputError(fmt::format("model '{}' is declared inconsistently: {}", spec.name, why));
  for (const auto& s : specs)
    if (s.name == spec.name)
      throw InputError(fmt::format("model '{}' exists already: choose another name", spec.name));
  if (specs.size() == specs.capacity())
    throw InputError(fmt::format("at most {} models may be added at run time", kRuntimeModels));
  specs.push_back(with_checked_tables(std::move(spec)));
}

std::vector<std::string> ranked_interface_models(bool with_intergranular_strain) {
  std::vector<std::pair<int, std::string>> ranked;
  for (const auto& spec : model_registry()) {
    const auto& c = spec.declaration.layout.components;
    const bool intergranular = std::any_of(c.begin(), c.end(), [](const StateComponent& x) {
      return x.kind == ComponentKind::kIntergranularStrain;
    });
    if (spec.declaration.plan_rank > 0 && (with_intergranular_strain || !intergranular))
      ranked.emplace_back(spec.declaration.plan_rank, spec.name);
  }
  std::sort(ranked.begin(), ranked.end());
  std::vector<std::string> out;
  for (const auto& r : ranked) out.push_back(r.second);
  return out;
}

std::string ranked_interface_models_text() {
  const auto all = ranked_interface_models(true), plain = ranked_interface_models(false);
  std::string reversing;
  for (const auto& m : all)
    if (std::find(plain.begin(), plain.end(), m) == plain.end())
      reversing += (reversing.empty() ? "" : " and ") + m;
  return fmt::format("{}; {} for reversing paths", fmt::join(plain, ", "), reversing);
}

const ModelSpec& find_model(const std::string& name) {
  std::string known;
  for (const auto& s : model_registry()) {
    if (s.name == name) return s;
    known += (known.empty() ? "" : ", ") + s.name;
  }
  throw InputError(fmt::format("unknown model '{}'; known models: {}", name, known));
}

double critical_friction_angle(const ModelSpec& spec, const ModelInputs& inputs) {
  for (const auto* table : spec.tables)
    for (const auto& p : table->entries)
      if (p.role == ParameterRole::kCriticalFrictionAngle) {
        // read before the model is made (a wall's delta_deg): its checks have not run yet
        const auto& values = table_for(spec.name, inputs, table->name);
        require_keys(*table, values, fmt::format("{} [{}]", inputs.source, table->name));
        return values.at(p.key) * M_PI / 180.0;
      }
  return NAN;
}

void set_initial_input(InitialState& s, const std::string& key, double value) {
  if (key == "sigma_n_kPa")
    s.sigma_n = value;
  else if (key == "K0")
    s.K0 = value;
  else if (key == "e0")
    s.e0 = value;
  else
    s.named[key] = value;
}

void set_initial_vector(InitialState& s, const std::string& key, const std::array<double, 3>& v) {
  if (key != "delta")
    throw std::logic_error("a model declares the vector input '" + key +
                           "' that an InitialState cannot hold");
  s.delta = v;
}

InitialState offer(const ModelSpec& spec, const ModelInputs& inputs,
                   std::initializer_list<std::pair<std::string, double>> values) {
  InitialState s;
  for (const auto& input : spec.declaration.initial) {
    if (input.kind != InitialInputSpec::Kind::kNumber) continue;
    std::optional<double> v;
    for (const auto& [key, value] : values)
      if (key == input.key) v = value;
    if (input.need == InitialInputSpec::Need::kFixed || (!v && input.default_value))
      v = input.default_value(inputs);
    if (v) set_initial_input(s, input.key, *v);
  }
  return s;
}

const ParameterValues& require_table(const ModelInputs& inputs, const std::string& name) {
  const auto it = inputs.tables.find(name);
  if (it == inputs.tables.end())
    throw InputError(fmt::format("{}: no table [{}] (the file has {})", inputs.source, name,
                                 tables_given(inputs)));
  return it->second;
}

}  // namespace iwb::models
