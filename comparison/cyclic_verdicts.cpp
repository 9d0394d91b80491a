#include "comparison/cyclic_verdicts.hpp"

#include <algorithm>
#include <cmath>

namespace iwb::comparison {

namespace {

constexpr double kPeakTolerance = 0.10, kRatioTolerance = 0.10, kUnTolerance = 0.20, kStiffnessTolerance = 0.30;
constexpr double kUnFloorD50 = 0.02;  // as the monotonic dilation's floor (quantities.cpp)
constexpr double kFrictionFloor = 0.01;

// The cycles a reader looks at first: 1, 2, 5 and the last (those that exist).
std::vector<int> judged_cycles(int cycles) {
  std::vector<int> out;
  for (int c : {1, 2, 5, cycles})
    if (c <= cycles && std::find(out.begin(), out.end(), c) == out.end()) out.push_back(c);
  return out;
}

struct Judge {
  std::vector<CyclicVerdict>& out;
  void operator()(const std::string& quantity, const std::string& where, std::optional<double> dem,
                  std::optional<double> model, double tolerance, double floor) {
    CyclicVerdict v{quantity, where, dem, model, std::nullopt, tolerance, "not reached"};
    if (dem && model) {
      v.error = (*model - *dem) / std::max(std::abs(*dem), floor);
      v.verdict = std::abs(*v.error) <= tolerance ? "holds" : "breaks";
    }
    out.push_back(v);
  }
};

const cycles::Cycle* cycle_of(const cycles::CyclicQuantities& q, int c) {
  for (const auto& x : q.cycles)
    if (x.number == c) return &x;
  return nullptr;
}

double peak_plus(const cycles::Cycle& c) { return c.peak_friction_positive; }
double peak_minus(const cycles::Cycle& c) { return c.peak_friction_negative; }
double ratio(const cycles::Cycle& c) { return c.sigma_n_ratio; }
double u_n_end(const cycles::Cycle& c) { return c.u_n_end_mm; }
double stiffness(const cycles::Cycle& c) {
  return 0.5 * (c.at_plus.secant_50_kPa_per_mm + c.at_minus.secant_50_kPa_per_mm);
}

// A quantity judged per cycle: its name, how it is read, its tolerance and floor.
struct PerCycle {
  const char* name;
  double (*get)(const cycles::Cycle&);
  double tolerance;
  double floor;
};

std::optional<double> at_cycle(const cycles::CyclicQuantities& q, int c, double (*get)(const cycles::Cycle&)) {
  const auto* x = cycle_of(q, c);
  return x ? std::optional(get(*x)) : std::nullopt;
}

}  // namespace

std::vector<double> cyclic_travel(const DemRun& dem) {
  return cycles::travel_at_speed(dem.t_s, dem.scene_but_seed.value("/shear/velocity_mm_s"_json_pointer, 0.0));
}

std::optional<cycles::Program> cyclic_program(const DemRun& dem) {
  if (!dem.scene_but_seed.is_object()) return std::nullopt;
  const auto& sh = dem.scene_but_seed.value("shear", nlohmann::json::object());
  const int n = sh.value("cycles", 0);
  if (n < 1) return std::nullopt;
  return cycles::Program{sh.value("amplitude_mm", 0.0), n, sh.value("post_cyclic_mm", 0.0)};
}

cycles::CyclicQuantities dem_cycles(const DemRun& dem, const cycles::Program& program) {
  return cycles::cyclic_quantities({cyclic_travel(dem), dem.u_x_mm, dem.u_n_mm, dem.sigma_n_kPa, dem.tau_kPa,
                                    dem.e_band},
                                   program);
}

cycles::CyclicQuantities replay_cycles(const DemRun& dem, const Replay& r, const cycles::Program& program) {
  auto travel = cyclic_travel(dem);
  travel.resize(r.u_x_mm.size());  // the rows the replay reached
  if (travel.size() < 2) return {};
  return cycles::cyclic_quantities({travel, r.u_x_mm, r.u_n_mm, r.sigma_n_kPa, r.tau_kPa, {}}, program);
}

std::vector<CyclicVerdict> judge_cycles(const DemRun& dem, const cycles::CyclicQuantities& d,
                                        const cycles::CyclicQuantities& m) {
  std::vector<CyclicVerdict> out;
  Judge judge{out};
  const bool normal_stress_free = dem.boundary != driver::BoundaryKind::kCNL;  // CNS, CV
  const bool u_n_free = dem.boundary != driver::BoundaryKind::kCV;             // CNL, CNS
  std::vector<PerCycle> judged = {{"peak_friction_positive", peak_plus, kPeakTolerance, kFrictionFloor},
                                  {"peak_friction_negative", peak_minus, kPeakTolerance, kFrictionFloor}};
  if (normal_stress_free) judged.push_back({"sigma_n_ratio", ratio, kRatioTolerance, kFrictionFloor});
  if (u_n_free) judged.push_back({"u_n_end_mm", u_n_end, kUnTolerance, kUnFloorD50 * dem.d50_mm});
  judged.push_back({"reversal_secant_50_kPa_per_mm", stiffness, kStiffnessTolerance, 1.0});
  for (int c : judged_cycles(int(d.cycles.size())))
    for (const auto& q : judged)
      judge(q.name, "cycle " + std::to_string(c), at_cycle(d, c, q.get), at_cycle(m, c, q.get), q.tolerance, q.floor);
  if (d.post_cyclic) {
    const auto mp = m.post_cyclic;
    judge("post_cyclic_peak_friction", "after the cycles", d.post_cyclic->peak_friction,
          mp ? std::optional(mp->peak_friction) : std::nullopt, kPeakTolerance, kFrictionFloor);
    if (u_n_free)
      judge("post_cyclic_u_n_change_mm", "after the cycles", d.post_cyclic->u_n_change_mm,
            mp ? std::optional(mp->u_n_change_mm) : std::nullopt, kUnTolerance, kUnFloorD50 * dem.d50_mm);
  }
  return out;
}

nlohmann::json to_json(const std::vector<CyclicVerdict>& verdicts) {
  auto opt = [](const std::optional<double>& x) { return x ? nlohmann::json(*x) : nlohmann::json(nullptr); };
  nlohmann::json out = nlohmann::json::array();
  for (const auto& v : verdicts)
    out.push_back({{"quantity", v.quantity}, {"where", v.where}, {"dem", opt(v.dem)}, {"model", opt(v.model)},
                   {"relative_error", opt(v.error)}, {"tolerance", v.tolerance}, {"verdict", v.verdict}});
  return out;
}

}  // namespace iwb::comparison
