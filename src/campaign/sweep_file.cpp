#include "campaign/sweep_file.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <map>
#include <tuple>

#include "campaign/slurm.hpp"
#include "common/errors.hpp"
#include "common/input_file.hpp"
#include "dem/engines/engines.hpp"
#include "io/run_directory.hpp"
#include "io/toml_reader.hpp"
#include "models/registry.hpp"

namespace iwb::campaign {

namespace fs = std::filesystem;

std::string default_label(const std::string& key) {
  // The axes of issue 7. wall.height_d50 is R_n for the shipped sawtooth walls (pitch 2 d50: the
  // whole tooth fits a d50 gauge window); each manifest records the R_n actually computed.
  static const std::map<std::string, std::string> labels = {
      {"wall.height_d50", "rn"},
      {"particles.d50_mm", "d"},
      {"boundary.sigma_n_kPa", "sn"},
      {"boundary.type", ""},
      {"boundary.K_kPa_per_mm", "k"},
      {"specimen.consolidation_friction", "cf"},
      {"specimen.consolidation_rolling_friction", "crf"},
      {"seed", "s"},
      {"wall.profile", ""},
      {"particles.friction", "mu"},
      {"specimen.height_d50", "h"},
      {"boundary", ""}};
  if (auto it = labels.find(key); it != labels.end()) return it->second;
  return key.substr(key.rfind('.') + 1) + "-";  // pitch_d50-2: the dash keeps key and value apart
}

namespace {

// A table's entries in the order they were written: toml++ iterates keys sorted, but
// { type = "CNS", K_kPa_per_mm = 50 } should name its job cns-50, not 50-cns.
std::vector<std::pair<std::string, const toml::node*>> as_written(const toml::table& table) {
  std::vector<std::pair<std::string, const toml::node*>> entries;
  for (const auto& [k, node] : table) entries.emplace_back(std::string(k.str()), &node);
  std::stable_sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
    const auto &pa = a.second->source().begin, &pb = b.second->source().begin;
    return std::tie(pa.line, pa.column) < std::tie(pb.line, pb.column);
  });
  return entries;
}

// Leaves of a nested table as dotted keys: `[set] specimen.particles = 200` is TOML for the
// table set.specimen, so walking it gives back the key as written. `where` names the table.
void collect_settings(const toml::table& table, const std::string& prefix, const std::string& where,
                      std::vector<Setting>& out) {
  for (const auto& [k, node] : as_written(table)) {
    const std::string key = prefix.empty() ? k : prefix + "." + k;
    if (const auto* sub = node->as_table())
      collect_settings(*sub, key, where, out);
    else
      out.emplace_back(key, io::toml_value_of(*node, fmt::format("{} {}", where, key)));
  }
}

std::vector<std::string> read_engines(io::TableReader& top) {
  std::vector<std::string> engines;
  const toml::node* n = top.node("engines");
  if (n == nullptr) return {"liggghts"};
  const auto* list = n->as_array();
  if (list == nullptr || list->empty())
    throw InputError(fmt::format("{} = {}: a list of engine names, e.g. [\"liggghts\"]",
                                 top.where("engines"), io::describe(*n)));
  for (const auto& e : *list) {
    const auto name = e.value<std::string>();
    if (!name)
      throw InputError(
          fmt::format("{}: {} is not an engine name", top.where("engines"), io::describe(e)));
    dem::make_engine(*name,
                     top.where("engines"));  // unknown engines are refused with the known ones
    engines.push_back(*name);
  }
  return engines;
}

Axis read_axis(io::TableReader& t) {
  Axis a;
  a.key = t.text("key");
  a.label = t.optional_text("label").value_or(default_label(a.key));
  const toml::node* n = t.node("values");
  const auto* list = n ? n->as_array() : nullptr;
  if (list == nullptr || list->empty())
    throw InputError(fmt::format("{}: a non-empty list of values is needed", t.where("values")));
  for (const auto& v : *list) {
    AxisValue value;
    if (const auto* table = v.as_table())
      collect_settings(*table, a.key, t.where("values") + ":", value);
    else
      value.emplace_back(a.key, io::toml_value_of(v, t.where("values")));
    if (value.empty())
      throw InputError(fmt::format("{}: an empty table sets nothing", t.where("values")));
    a.values.push_back(std::move(value));
  }
  t.finish();
  return a;
}

// An unknown model is refused now, not after hours of DEM, naming the file and the key.
void require_known_model(const io::TableReader& t, const std::string& model) {
  std::string known;
  for (const auto& spec : models::model_registry()) {
    if (spec.name == model) return;
    known += (known.empty() ? "" : ", ") + spec.name;
  }
  throw InputError(
      fmt::format("{} = \"{}\": unknown model; known models: {}", t.where("model"), model, known));
}

std::optional<Comparison> read_comparison(io::TableReader& top, const fs::path& folder) {
  auto t = top.table("compare");
  if (!t) return std::nullopt;
  Comparison c{t->optional_text("model").value_or(models::kDefaultInterfaceModel),
               folder / t->text("params")};
  require_known_model(*t, c.model);
  if (const auto why = unreadable_input_file(c.params); !why.empty())
    throw InputError(fmt::format("{} = \"{}\": {} ({})", t->where("params"), t->text("params"), why,
                                 c.params.string()));
  t->finish();
  return c;
}

}  // namespace

SweepSpec parse_sweep(const std::string& text, const fs::path& file) {
  const auto root = io::parse_toml_text(text, file.string());
  io::TableReader top(root, file.string());
  SweepSpec s;
  s.file = file;
  s.text = text;
  s.description = top.optional_text("description").value_or("");
  const fs::path folder = file.parent_path();
  s.scene_file = folder / top.text("scene");
  // a named pipe would block the read for ever; a directory is not "no such file"
  if (const auto why = unreadable_input_file(s.scene_file); !why.empty())
    throw InputError(fmt::format("{} = \"{}\": {} ({})", top.where("scene"), top.text("scene"),
                                 why == "no such file" ? "no such scene file" : why,
                                 s.scene_file.string()));
  s.scene_text = io::read_file(s.scene_file);
  s.engines = read_engines(top);
  if (const toml::node* set = top.node("set")) {
    if (!set->is_table())
      throw InputError(fmt::format("{}: a table of scene keys is needed", top.where("set")));
    collect_settings(*set->as_table(), "", top.where("set") + ":", s.set);
  }
  for (auto& a : top.array_of_tables("axis")) s.axes.push_back(read_axis(a));
  s.compare = read_comparison(top, folder);
  if (auto slurm = top.table("slurm")) {
    s.slurm_time = slurm->optional_text("time").value_or(s.slurm_time);
    if (!is_slurm_time(s.slurm_time))
      throw InputError(
          fmt::format("{} = \"{}\" is not a Slurm time; allowed MM, MM:SS, HH:MM:SS, D-HH, D-HH:MM "
                      "or D-HH:MM:SS",
                      slurm->where("time"), s.slurm_time));
    slurm->finish();
  }
  top.finish();
  return s;
}

SweepSpec load_sweep(const fs::path& file) {
  if (!fs::exists(file)) throw InputError(fmt::format("{}: no such sweep file", file.string()));
  return parse_sweep(io::read_file(file), file);
}

}  // namespace iwb::campaign
