#include "claims/seed_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include "common/errors.hpp"
#include "io/json_file.hpp"
#include "io/run_directory.hpp"

namespace iwb::claims {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

struct GroupRuns {
  const Group* group;
  std::vector<std::string> patterns;
};

std::string key_of(const std::vector<std::string>& patterns) {
  std::string k;
  for (const auto& p : patterns) k += p + "\n";
  return k;
}

// "cyclic_small/runs/cnl_s*" -> "cyclic_small-cnl": the pattern's directory and the name's stem.
std::string name_of(const std::string& pattern) {
  std::string stem = pattern.substr(0, pattern.find('*'));
  if (stem.size() >= 2 && stem.compare(stem.size() - 2, 2, "_s") == 0) stem.resize(stem.size() - 2);
  if (const auto at = stem.find("/runs/"); at != std::string::npos) stem.replace(at, 6, "-");
  std::string out;
  for (char c : stem) {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_')
      out += c;
    else if (!out.empty() && out.back() != '-')
      out += '-';
  }
  while (!out.empty() && (out.back() == '-' || out.back() == '_')) out.pop_back();
  while (!out.empty() && (out.front() == '-' || out.front() == '.')) out.erase(out.begin());
  return out.empty() ? "group" : out;
}

std::vector<std::string> all_runs(const Group& g) {
  std::vector<std::string> runs = g.runs;
  for (const auto& [run, why] : g.excluded) runs.push_back(run);
  return runs;
}

// The group's plan for `needed` usable runs; to_run 0 where it has them already, -1 where none of
// its runs was kept (more of the same scene would not be kept either).
GroupPlan group_plan(const Group& g, const std::vector<std::string>& patterns, int needed) {
  GroupPlan p;
  p.name = name_of(patterns.front());
  p.patterns = patterns;
  p.usable = int(g.runs.size());
  p.read = p.usable + int(g.excluded.size());
  p.needed = needed;
  if (p.usable == 0) {
    p.to_run = -1;
    return p;
  }
  const int extra = std::max(0, needed - p.usable);
  p.to_run = int(std::ceil(double(extra) * p.read / p.usable - 1e-9));
  double hours = 0.0;
  int priced = 0, top_seed = 0;
  bool unseeded = false;  // a run whose manifest gives no seed: new seeds could repeat it
  for (const auto& run : all_runs(g)) {
    const fs::path manifest = fs::path(run) / "manifest.json";
    if (fs::is_regular_file(manifest)) {
      const auto m = io::read_json_file(manifest);
      if (const auto h = engine_core_hours(m)) hours += *h, ++priced;
      if (m.contains("seed") && m["seed"].is_number_integer())
        top_seed = std::max(top_seed, m["seed"].get<int>());
      else
        unseeded = true;
      if (p.scene_text.empty() && m.contains("/scene/text"_json_pointer) &&
          std::find(g.runs.begin(), g.runs.end(), run) != g.runs.end()) {
        p.scene_text = m.at("/scene/text"_json_pointer).get<std::string>();
        p.engine = m.value("/engine/name"_json_pointer, std::string("liggghts"));
        p.soil_cells = m.value("kind", std::string()) == "soiltest";
        p.command_line = m.value("command_line", std::string());
      }
    }
  }
  if (unseeded || top_seed == 0) {
    p.to_run = -2;
    return p;
  }
  p.core_hours_per_run = priced > 0 ? hours / priced : 0.0;
  for (int k = 1; k <= p.to_run; ++k) p.seeds.push_back(top_seed + k);
  return p;
}

double cost(const GroupPlan& p) {
  return std::max(p.to_run, 0) * p.core_hours_per_run;
}

}  // namespace

SeedPlan plan_seeds(const ClaimsReport& report, double budget_core_hours) {
  SeedPlan plan;
  plan.budget_core_hours = budget_core_hours;
  struct Candidate {
    const ClaimResult* result;
    std::vector<GroupPlan> groups;
    double standalone = 0.0;
  };
  std::vector<Candidate> candidates;
  for (const auto& r : report.results) {
    if (r.status != "not resolved" && r.status != "not testable") continue;
    if (!r.seeds_needed) {
      plan.left_out.emplace_back(
          r.claim.id, r.status == "not testable"
                          ? "not testable: a group has fewer than two usable runs, so no scatter "
                            "to count seeds from"
                          : "no count of seeds resolves it (not within 1000 a group, or one run "
                            "against a group)");
      continue;
    }
    Candidate c{
        &r,
        {group_plan(r.a, r.claim.a, *r.seeds_needed), group_plan(r.b, r.claim.b, *r.seeds_needed)}};
    const int worst = std::min(c.groups[0].to_run, c.groups[1].to_run);
    if (worst == -1) {
      plan.left_out.emplace_back(r.claim.id,
                                 "every run of a group was left out (split, at the plate or not "
                                 "steady): its scene needs changing before seeds");
      continue;
    }
    if (worst == -2) {
      plan.left_out.emplace_back(r.claim.id,
                                 "a group's runs do not all record their seed (manifest.json "
                                 "\"seed\"): new seeds could repeat one");
      continue;
    }
    for (const auto& g : c.groups) c.standalone += cost(g);
    candidates.push_back(std::move(c));
  }
  std::stable_sort(
      candidates.begin(), candidates.end(),
      [](const Candidate& x, const Candidate& y) { return x.standalone < y.standalone; });
  std::map<std::string, GroupPlan> chosen;  // by the group's patterns
  for (const auto& c : candidates) {
    double more = 0.0;
    for (const auto& g : c.groups) {
      const auto it = chosen.find(key_of(g.patterns));
      more += it == chosen.end() ? cost(g) : std::max(0.0, cost(g) - cost(it->second));
    }
    if (plan.planned_core_hours + more > budget_core_hours + 1e-9) {
      plan.left_out.emplace_back(
          c.result->claim.id,
          fmt::format("beyond the budget: {:.1f} core-hours more ({:.1f} of {:.1f} planned)", more,
                      plan.planned_core_hours, budget_core_hours));
      continue;
    }
    plan.planned_core_hours += more;
    for (const auto& g : c.groups) {
      auto [it, fresh] = chosen.try_emplace(key_of(g.patterns), g);
      if (!fresh && g.to_run > it->second.to_run) {
        auto claims = it->second.claims;
        it->second = g;
        it->second.claims = claims;
      }
      it->second.claims.push_back(c.result->claim.id);
    }
  }
  for (auto& [key, g] : chosen)
    if (g.to_run > 0) plan.groups.push_back(g);
  // distinct file names where two groups' first patterns read alike
  std::map<std::string, int> seen;
  for (auto& g : plan.groups)
    if (const int n = seen[g.name]++; n > 0) g.name += fmt::format("-{}", n + 1);
  return plan;
}

json to_json(const SeedPlan& plan) {
  json groups = json::array();
  for (const auto& g : plan.groups)
    groups.push_back({{"name", g.name},
                      {"patterns", g.patterns},
                      {"engine", g.engine},
                      {"usable", g.usable},
                      {"read", g.read},
                      {"needed", g.needed},
                      {"to_run", g.to_run},
                      {"seeds", g.seeds},
                      {"core_hours_per_run", g.core_hours_per_run},
                      {"claims", g.claims},
                      {"sweep", g.soil_cells ? json(nullptr) : json("sweeps/" + g.name + ".toml")},
                      {"command_line", g.command_line}});
  json left = json::array();
  for (const auto& [id, why] : plan.left_out) left.push_back({{"claim", id}, {"why", why}});
  return {{"budget_core_hours", plan.budget_core_hours},
          {"planned_core_hours", plan.planned_core_hours},
          {"groups", groups},
          {"left_out", left}};
}

std::string markdown(const SeedPlan& plan) {
  std::string s = fmt::format(
      "Seeds to add (`iwb claims --plan-seeds`): {:.1f} of a budget of {:.1f} engine core-hours "
      "(each run priced at its group's mean, a lower bound), claims taken cheapest first.\n\n",
      plan.planned_core_hours, plan.budget_core_hours);
  s +=
      "| group | runs kept / read | needed | runs to add | seeds | core-hours | claims | sweep |\n";
  s += "|---|---|---|---|---|---|---|---|\n";
  for (const auto& g : plan.groups) {
    std::string seeds, claims, patterns;
    for (int x : g.seeds) seeds += (seeds.empty() ? "" : ", ") + std::to_string(x);
    for (const auto& c : g.claims) claims += (claims.empty() ? "" : ", ") + c;
    for (const auto& p : g.patterns) patterns += (patterns.empty() ? "`" : "`, `") + p;
    const std::string how = g.soil_cells ? "soil cells: `iwb dem soiltest` as its runs were "
                                           "(plan.json's command_line), with these seeds"
                                         : fmt::format("`sweeps/{}.toml`", g.name);
    s += fmt::format("| {}` | {} / {} | {} | {} | {} | {:.1f} | {} | {} |\n", patterns, g.usable,
                     g.read, g.needed, g.to_run, seeds, g.to_run * g.core_hours_per_run, claims,
                     how);
  }
  if (plan.groups.empty()) s += "| (none) | | | | | | | |\n";
  if (!plan.left_out.empty()) {
    s += "\nLeft out:\n\n";
    for (const auto& [id, why] : plan.left_out) s += fmt::format("- {}: {}\n", id, why);
  }
  s += "\nRun each sweep with `iwb sweep sweeps/<name>.toml -o <campaign>/<name>` and add "
       "`<name>/runs/*` to the claims' patterns of that group.\n";
  return s;
}

void write_seed_plan(const SeedPlan& plan, const fs::path& dir) {
  fs::create_directories(dir / "scenes");
  fs::create_directories(dir / "sweeps");
  for (const auto& g : plan.groups) {
    if (g.soil_cells) continue;  // a sweep runs interface runs only
    io::write_atomically(dir / "scenes" / (g.name + ".toml"), g.scene_text);
    std::string seeds;
    for (int x : g.seeds) seeds += (seeds.empty() ? "" : ", ") + std::to_string(x);
    io::write_atomically(
        dir / "sweeps" / (g.name + ".toml"),
        fmt::format("# Seeds planned by `iwb claims --plan-seeds` for {} (runs kept {} of {}, "
                    "{} usable needed)\n"
                    "description = \"{}: seeds {}\"\nscene = \"../scenes/{}.toml\"\n"
                    "engines = [\"{}\"]\n\n[[axis]]\nkey = \"seed\"\nvalues = [{}]\n",
                    fmt::format("{}", fmt::join(g.claims, ", ")), g.usable, g.read, g.needed,
                    g.name, seeds, g.name, g.engine, seeds));
  }
  io::write_atomically(dir / "plan.json", to_json(plan).dump(2) + "\n");
  io::write_atomically(dir / "plan.md", markdown(plan));
}

}  // namespace iwb::claims
