#include "comparison/verdicts/cyclic_verdicts.hpp"

#include <algorithm>
#include <cmath>

#include "comparison/verdicts/verdicts.hpp"

namespace iwb::comparison {

const Tolerances& cyclic_default_tolerances() {
  static const Tolerances t = {{"cycle_peak_friction", 0.10},
                               {"cycle_sigma_n_ratio", 0.10},
                               {"cycle_u_n", 0.20},
                               {"reversal_secant", 0.30},
                               {"post_cyclic_peak_friction", 0.10},
                               {"post_cyclic_u_n_change", 0.20}};
  return t;
}

namespace {

constexpr double kUnFloorD50 = 0.02;  // as the monotonic dilation's floor (quantities.cpp)
constexpr double kFrictionFloor = 0.01;

// Mean and SD (n - 1) of the values the seeds have; the SD needs two.
struct SeedValues {
  std::optional<double> mean, sd;
  std::size_t n = 0;
};

SeedValues over_seeds(const std::vector<std::optional<double>>& values) {
  SeedValues s;
  double sum = 0.0;
  for (const auto& v : values)
    if (v) sum += *v, ++s.n;
  if (s.n == 0) return s;
  s.mean = sum / double(s.n);
  if (s.n < 2) return s;
  double square = 0.0;
  for (const auto& v : values)
    if (v) square += (*v - *s.mean) * (*v - *s.mean);
  s.sd = std::sqrt(square / double(s.n - 1));
  return s;
}

struct Judge {
  std::vector<CyclicVerdict>& out;
  // `floor`: the least |DEM mean| the error is taken against (and at least `level`, a trend's)
  void operator()(const std::string& quantity, const std::string& where,
                  const std::vector<std::optional<double>>& dem, std::optional<double> model,
                  double tolerance, double floor, double level = 0.0) {
    const SeedValues d = over_seeds(dem);
    CyclicVerdict v{quantity,     where,        d.mean,        model,
                    std::nullopt, tolerance,    "not reached", std::max<std::size_t>(d.n, 1),
                    d.sd,         std::nullopt, std::nullopt,  std::nullopt};
    const double scale = d.mean ? std::max({std::abs(*d.mean), floor, level}) : 1.0;
    const SeedInterval i = seed_interval(d.sd, v.seeds, tolerance, scale);
    v.dem_ci = i.ci, v.detection_limit = i.detection_limit, v.seeds_needed = i.seeds_needed;
    if (d.mean && model) v.error = (*model - *d.mean) / scale;
    v.verdict = verdict_word(v.error, tolerance, scale, v.dem_ci);
    out.push_back(v);
  }
};

const cycles::Cycle* cycle_of(const cycles::CyclicQuantities& q, int c) {
  for (const auto& x : q.cycles)
    if (x.number == c) return &x;
  return nullptr;
}

double peak_plus(const cycles::Cycle& c) {
  return c.peak_friction_positive;
}
double peak_minus(const cycles::Cycle& c) {
  return c.peak_friction_negative;
}
double ratio(const cycles::Cycle& c) {
  return c.sigma_n_ratio;
}
double u_n_end(const cycles::Cycle& c) {
  return c.u_n_end_mm;
}
double stiffness(const cycles::Cycle& c) {
  return 0.5 * (c.at_plus.secant_50_kPa_per_mm + c.at_minus.secant_50_kPa_per_mm);
}

// A quantity judged per cycle: its name, how it is read, its [requirements] key and floor.
struct PerCycle {
  const char* name;
  double (*get)(const cycles::Cycle&);
  const char* key;
  double floor;
};

std::optional<double> at_cycle(const cycles::CyclicQuantities& q, int c,
                               double (*get)(const cycles::Cycle&)) {
  const auto* x = cycle_of(q, c);
  return x ? std::optional(get(*x)) : std::nullopt;
}

}  // namespace

std::vector<int> judged_cycles(int cycles) {
  std::vector<int> out;
  for (int c : {1, 2, 5, cycles})
    if (c <= cycles && std::find(out.begin(), out.end(), c) == out.end()) out.push_back(c);
  return out;
}

cycles::CyclicQuantities dem_cycles(const DemRun& dem, const cycles::Program& program) {
  return cycles::cyclic_quantities(
      {cyclic_travel(dem), dem.u_x_mm, dem.u_n_mm, dem.sigma_n_kPa, dem.tau_kPa, dem.e_band},
      program);
}

cycles::CyclicQuantities replay_cycles(const DemRun& dem, const Replay& r,
                                       const cycles::Program& program) {
  auto travel = cyclic_travel(dem);
  travel.resize(r.u_x_mm.size());  // the rows the replay reached
  if (travel.size() < 2) return {};
  // the band's void ratio the model gives the DEM's wall zone, reported beside the DEM's at each
  // reversal (where the replay has it for every row)
  const auto e_band = r.e_band.size() == r.u_x_mm.size() ? r.e_band : std::vector<double>{};
  return cycles::cyclic_quantities({travel, r.u_x_mm, r.u_n_mm, r.sigma_n_kPa, r.tau_kPa, e_band},
                                   program);
}

Tolerances cyclic_tolerances(const DemRun& dem) {
  Tolerances t = cyclic_default_tolerances();
  if (dem.boundary == driver::BoundaryKind::kCNL) t.erase("cycle_sigma_n_ratio");  // held
  if (dem.boundary == driver::BoundaryKind::kCV)                                   // u_n held
    t.erase("cycle_u_n"), t.erase("post_cyclic_u_n_change");
  return scene_tolerances(dem, t);
}

namespace {

using SeedReads = std::vector<std::optional<double>>;

// `get` read from each seed's quantities.
template <typename Get>
SeedReads each_seed(const std::vector<cycles::CyclicQuantities>& seeds, Get get) {
  SeedReads values;
  for (const auto& s : seeds) values.push_back(get(s));
  return values;
}

// Each per-cycle quantity the tolerances keep, at the cycles a reader looks at first, and its
// change from the first cycle to the last, judged against the larger of the DEM's first-cycle
// level and its change (a friction or a stiffness is judged on its level, a ratchet of u_n that
// starts near zero on its change).
void judge_per_cycle(Judge& judge, const DemRun& dem, const Tolerances& tol,
                     const std::vector<cycles::CyclicQuantities>& seeds,
                     const cycles::CyclicQuantities& m) {
  const std::vector<PerCycle> all = {
      {"peak_friction_positive", peak_plus, "cycle_peak_friction", kFrictionFloor},
      {"peak_friction_negative", peak_minus, "cycle_peak_friction", kFrictionFloor},
      {"sigma_n_ratio", ratio, "cycle_sigma_n_ratio", kFrictionFloor},
      {"u_n_end_mm", u_n_end, "cycle_u_n", kUnFloorD50 * dem.d50_mm},
      {"reversal_secant_50_kPa_per_mm", stiffness, "reversal_secant", 1.0}};
  const auto judged = judged_cycles(int(seeds.front().cycles.size()));
  for (int c : judged)
    for (const auto& q : all)
      if (tol.count(q.key))
        judge(q.name, "cycle " + std::to_string(c),
              each_seed(seeds, [&](const auto& s) { return at_cycle(s, c, q.get); }),
              at_cycle(m, c, q.get), tol.at(q.key), q.floor);
  const int last = judged.back();
  if (last < 2) return;
  for (const auto& q : all) {
    if (!tol.count(q.key)) continue;
    const auto change = [&](const cycles::CyclicQuantities& s) -> std::optional<double> {
      const auto first = at_cycle(s, 1, q.get), end = at_cycle(s, last, q.get);
      return first && end ? std::optional(*end - *first) : std::nullopt;
    };
    const SeedValues first =
        over_seeds(each_seed(seeds, [&](const auto& s) { return at_cycle(s, 1, q.get); }));
    judge(std::string(q.name) + "_change", "cycle 1 to " + std::to_string(last),
          each_seed(seeds, change), change(m), tol.at(q.key), q.floor,
          first.mean ? std::abs(*first.mean) : 0.0);
  }
}

void judge_post_cyclic(Judge& judge, const DemRun& dem, const Tolerances& tol,
                       const std::vector<cycles::CyclicQuantities>& seeds,
                       const cycles::CyclicQuantities& m) {
  const auto peak = [](const auto& s) {
    return s.post_cyclic ? std::optional(s.post_cyclic->peak_friction) : std::nullopt;
  };
  const auto u_n = [](const auto& s) {
    return s.post_cyclic ? std::optional(s.post_cyclic->u_n_change_mm) : std::nullopt;
  };
  if (tol.count("post_cyclic_peak_friction"))
    judge("post_cyclic_peak_friction", "after the cycles", each_seed(seeds, peak), peak(m),
          tol.at("post_cyclic_peak_friction"), kFrictionFloor);
  if (tol.count("post_cyclic_u_n_change"))
    judge("post_cyclic_u_n_change_mm", "after the cycles", each_seed(seeds, u_n), u_n(m),
          tol.at("post_cyclic_u_n_change"), kUnFloorD50 * dem.d50_mm);
}

}  // namespace

std::vector<CyclicVerdict> judge_cycles(const DemRun& dem,
                                        const std::vector<cycles::CyclicQuantities>& seeds,
                                        const cycles::CyclicQuantities& m) {
  std::vector<CyclicVerdict> out;
  Judge judge{out};
  const Tolerances tol = cyclic_tolerances(dem);
  judge_per_cycle(judge, dem, tol, seeds, m);  // the cycles judged: those of the compared run
  if (seeds.front().post_cyclic) judge_post_cyclic(judge, dem, tol, seeds, m);
  return out;
}

nlohmann::json to_json(const std::vector<CyclicVerdict>& verdicts) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& v : verdicts) {
    auto j = shared_verdict_json(v);
    j["quantity"] = v.quantity;
    j["where"] = v.where;
    j["unit"] = "";
    out.push_back(j);
  }
  return out;
}

}  // namespace iwb::comparison
