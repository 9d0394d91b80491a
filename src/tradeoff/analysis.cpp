// analyse(): errors against the reference, the seed noise floor, knob effects, tolerances met.
#include <fmt/core.h>

#include <cmath>

#include "dem/run/crosscheck.hpp"
#include "dem/scene/requirements.hpp"
#include "tradeoff/tradeoff.hpp"

namespace iwb::tradeoff {

using nlohmann::json;

namespace {

const std::vector<double> kTolerances = {0.05, 0.01};

std::optional<double> qoi(const json& row, const std::string& key) {
  const auto it = row.find("qoi");
  if (it == row.end() || !it->contains(key) || (*it)[key].is_null()) return std::nullopt;
  return (*it)[key].get<double>();
}

json optional_json(std::optional<double> v) {
  return v ? json(*v) : json(nullptr);
}

// The base setting as one row: the mean of its seeds, their mean cost, and each QoI's scatter.
json base_setting(const json& rows, json& noise) {
  json base = {{"name", "base"},
               {"kind", "base"},
               {"knob", ""},
               {"factor", 1.0},
               {"status", "complete"},
               {"qoi", json::object()},
               {"settings", "the scene as given (mean over the seeds)"}};
  std::vector<const json*> seeds;
  for (const auto& r : rows)
    if (r["kind"] == "base" && completed(r)) seeds.push_back(&r);
  base["seeds_complete"] = seeds.size();
  if (seeds.empty()) return base["status"] = "no complete seed", base;
  for (const char* cost : {"particle_steps", "wall_seconds", "particles", "timestep_s",
                           "stiffness_level", "inertial_number"}) {
    double sum = 0.0;
    for (const auto* r : seeds) sum += (*r)[cost].get<double>();
    base[cost] = sum / double(seeds.size());
  }
  for (const auto& q : dem::quantities_of_interest()) {
    std::vector<double> v;
    for (const auto* r : seeds)
      if (const auto x = qoi(*r, q.key)) v.push_back(*x);
    const auto s = dem::scatter_of(v);
    base["qoi"][q.key] = v.empty() ? json(nullptr) : json(s.mean);
    // Identical seeds (a band thickness is counted in profile bins) say nothing about the
    // scatter: a floor of 0 would let any setting "meet" any tolerance on that quantity.
    const bool known = s.n >= 2 && s.mean != 0.0 && s.sd > 0.0;
    noise[q.key] = {{"mean", v.empty() ? json(nullptr) : json(s.mean)},
                    {"sd", s.sd},
                    {"n", s.n},
                    {"relative", known ? json(s.sd / std::abs(s.mean)) : json(nullptr)}};
  }
  return base;
}

std::optional<double> relative(std::optional<double> v, std::optional<double> ref) {
  if (!v || !ref || *ref == 0.0) return std::nullopt;
  return std::abs(*v - *ref) / std::abs(*ref);
}

// Errors against the reference and, per tolerance, whether error + noise floor is within it.
void score(json& setting, const json& reference, const json& noise) {
  setting["error"] = json::object();
  setting["meets"] = json::object();
  for (double tol : kTolerances) {
    const std::string t = fmt::format("{:g}", tol);
    setting["meets"][t] = json::object();
    for (const auto& q : dem::quantities_of_interest()) {
      const auto e = relative(qoi(setting, q.key), qoi(reference, q.key));
      const auto n = noise[q.key]["relative"];
      setting["error"][q.key] = optional_json(e);
      setting["meets"][t][q.key] = e && !n.is_null() && *e + n.get<double>() <= tol;
    }
  }
}

// Per knob and factor: how far each QoI moved from the base mean, relative and in noise floors.
json knob_effects(const json& settings, const json& base, const json& noise) {
  json out = json::array();
  for (const auto& s : settings) {
    if (s["kind"] != "knob" || !completed(s)) continue;
    json e = {
        {"knob", s["knob"]},
        {"factor", s["factor"]},
        {"name", s["name"]},
        {"shift", json::object()},
        {"shift_in_noise", json::object()},
        {"cost_ratio", s["particle_steps"].get<double>() / base.value("particle_steps", 1.0)}};
    for (const auto& q : dem::quantities_of_interest()) {
      const auto v = qoi(s, q.key), b = qoi(base, q.key);
      const bool ok = v && b && *b != 0.0;
      const double shift = ok ? (*v - *b) / std::abs(*b) : 0.0;
      e["shift"][q.key] = ok ? json(shift) : json(nullptr);
      const auto n = noise[q.key]["relative"];
      e["shift_in_noise"][q.key] = ok && !n.is_null() && n.get<double>() > 0
                                       ? json(std::abs(shift) / n.get<double>())
                                       : json(nullptr);
    }
    out.push_back(e);
  }
  return out;
}

// Per tolerance: for each QoI, and for all of them together, the cheapest setting that meets it.
json cheapest_meeting(const json& settings) {
  json out = json::object();
  for (double tol : kTolerances) {
    const std::string t = fmt::format("{:g}", tol);
    json per = json::object();
    auto cheapest = [&](auto&& meets) {
      const json* best = nullptr;
      for (const auto& s : settings)
        if (completed(s) && s.contains("meets") && meets(s["meets"][t]) &&
            (!best || s["particle_steps"].get<double>() < (*best)["particle_steps"].get<double>()))
          best = &s;
      return best ? json{{"name", (*best)["name"]},
                         {"particle_steps", (*best)["particle_steps"]},
                         {"wall_seconds", (*best)["wall_seconds"]}}
                  : json(nullptr);
    };
    for (const auto& q : dem::quantities_of_interest())
      per[q.key] = cheapest([&](const json& m) { return m[q.key].get<bool>(); });
    per["all"] = cheapest([](const json& m) {
      for (const auto& [k, v] : m.items())
        if (!v.get<bool>()) return false;
      return true;
    });
    out[t] = per;
  }
  return out;
}

}  // namespace

namespace {

constexpr const char* kWhyRefined =
    "every knob of the tradeoff at its refining factor at once (of box, kappa, dt, I: a "
    "larger box, stiffer grains, a smaller step, slower shear): the most resolved setting "
    "run, nearest the quasi-static, rigid-grain, large-specimen limit; one seed, so its "
    "own scatter is of the size of the noise floor";
constexpr const char* kWhyBase =
    "the scene as given, the mean over its seeds: a scene shown converged by a convergence "
    "study (data/convergence/), so only cheaper settings are run and measured against it; its "
    "own error is 0 and its seed scatter is the noise floor";

// The setting the errors are measured against, if it completed.
const json* find_reference(const json& settings, Reference mode) {
  const std::string kind = mode == Reference::kBase ? "base" : "refined";
  for (const auto& s : settings)
    if (s["kind"] == kind && completed(s)) return &s;
  return nullptr;
}

}  // namespace

json analyse(const json& rows, Reference mode) {
  json noise = json::object();
  json settings = json::array();
  settings.push_back(base_setting(rows, noise));
  for (const auto& r : rows)
    if (r["kind"] != "base") settings.push_back(r);
  const json* reference = find_reference(settings, mode);
  json out = {{"runs", rows}, {"noise_floor", noise}, {"settings", settings}};
  if (!reference) {
    out["reference"] = nullptr;
    return out;
  }
  out["reference"] = {{"name", (*reference)["name"]},
                      {"settings", (*reference)["settings"]},
                      {"why", mode == Reference::kBase ? kWhyBase : kWhyRefined}};
  const json ref = *reference;
  for (auto& s : out["settings"])
    if (completed(s)) score(s, ref, noise);
  out["knob_effects"] = knob_effects(out["settings"], out["settings"][0], noise);
  out["cheapest"] = cheapest_meeting(out["settings"]);
  return out;
}

}  // namespace iwb::tradeoff
