#include "driver/path.hpp"

#include <fmt/core.h>

#include <cmath>

#include "common/errors.hpp"

namespace iwb::driver {

namespace {
PathSegment shear(const std::string& label, double gamma, ShearDirection dir,
                  const NormalControlRow& row, int increments) {
  PathSegment s{label, 0.0, 0.0, row, increments};
  (dir == ShearDirection::kX ? s.gamma_x : s.gamma_y) = gamma;
  return s;
}

// A ramp of sigma_n (CNL rows) from `from` to `to` kPa in `n` increments at fixed shear.
PathSegment sigma_ramp(const std::string& label, double from, double to, int n) {
  return {label, 0.0, 0.0, BoundaryCondition{BoundaryKind::kCNL, 0.0}.row((to - from) / n), n};
}

void require_positive(int n, const char* what) {
  if (n < 1) throw InputError(fmt::format("{} must be at least 1; got {}", what, n));
}
}  // namespace

Path monotonic_path(const BoundaryCondition& bc, double gamma, ShearDirection dir, int increments) {
  require_positive(increments, "path.increments");
  return {shear("shear", gamma, dir, bc.row(), increments)};
}

void append_cycle(Path& p, int c, const BoundaryCondition& bc, double amplitude, ShearDirection dir,
                  int per_quarter) {
  p.push_back(shear(fmt::format("cycle {} to +A", c), amplitude, dir, bc.row(), per_quarter));
  p.push_back(
      shear(fmt::format("cycle {} to -A", c), -2.0 * amplitude, dir, bc.row(), 2 * per_quarter));
  p.push_back(shear(fmt::format("cycle {} to 0", c), amplitude, dir, bc.row(), per_quarter));
  for (std::size_t i = p.size() - 3; i < p.size(); ++i) p[i].cycle = c;
  p[p.size() - 3].ends_at_reversal = p[p.size() - 2].ends_at_reversal = true;
}

Path cyclic_path(const BoundaryCondition& bc, double amplitude, int cycles, ShearDirection dir,
                 int per_quarter) {
  require_positive(cycles, "path.cycles");
  require_positive(per_quarter, "path.increments_per_quarter");
  Path p;
  for (int c = 1; c <= cycles; ++c) append_cycle(p, c, bc, amplitude, dir, per_quarter);
  return p;
}

Path staged_cyclic_path(double sigma_n0, double amplitude, int cycles,
                        const std::vector<CyclicStage>& stages, ShearDirection dir, int per_quarter,
                        int step_increments) {
  require_positive(cycles, "path.cycles");
  require_positive(per_quarter, "path.increments_per_quarter");
  require_positive(step_increments, "path.step_increments");
  const BoundaryCondition cnl{BoundaryKind::kCNL, 0.0};
  Path p;
  double sigma = sigma_n0;
  std::size_t next = 0;
  for (int c = 1; c <= cycles; ++c) {
    for (; next < stages.size() && stages[next].from_cycle == c; ++next) {
      const auto& st = stages[next];
      p.push_back(sigma_ramp(
          fmt::format("sigma_n {:g} -> {:g} kPa before cycle {}", sigma, st.sigma_n_kPa, c), sigma,
          st.sigma_n_kPa, step_increments));
      sigma = st.sigma_n_kPa;
    }
    append_cycle(p, c, cnl, amplitude, dir, per_quarter);
  }
  if (next < stages.size())  // a stage was skipped: out of order or beyond the last cycle
    throw InputError(
        fmt::format("staged cyclic path: stages must name cycles in [1, {}] in "
                    "increasing order; stage {} (from_cycle = {}) does not",
                    cycles, next + 1, stages[next].from_cycle));
  return p;
}

Path staged_path(double sigma_n0, double gamma, const std::vector<StagedStep>& steps,
                 ShearDirection dir, int increments, int step_increments) {
  require_positive(increments, "path.increments");
  require_positive(step_increments, "path.step_increments");
  const BoundaryCondition cnl{BoundaryKind::kCNL, 0.0};
  Path p;
  double at = 0.0, sigma = sigma_n0;
  auto shear_to = [&](double target) {
    if (target <= at) return;
    const int n = std::max(1, int(std::lround(increments * (target - at) / gamma)));
    p.push_back(shear(fmt::format("shear at {:g} kPa", sigma), target - at, dir, cnl.row(), n));
    at = target;
  };
  for (const auto& step : steps) {
    if (!(step.at_gamma > at - 1e-15) || step.at_gamma > gamma)
      throw InputError(
          fmt::format("staged path: steps must be ordered within (0, {:g}]; step at "
                      "gamma = {:g} is not",
                      gamma, step.at_gamma));
    shear_to(step.at_gamma);
    p.push_back(sigma_ramp(fmt::format("sigma_n {:g} -> {:g} kPa", sigma, step.sigma_n_kPa), sigma,
                           step.sigma_n_kPa, step_increments));
    sigma = step.sigma_n_kPa;
  }
  shear_to(gamma);
  return p;
}

Path oedometric_path(double sigma_from, double sigma_to, int increments) {
  require_positive(increments, "path.increments");
  return {{fmt::format("oedometric {:g} -> {:g} kPa", sigma_from, sigma_to), 0.0, 0.0,
           BoundaryCondition{BoundaryKind::kCNL, 0.0}.row((sigma_to - sigma_from) / increments),
           increments}};
}

Path stage_path(const std::vector<Stage>& stages, ShearDirection dir) {
  Path path;
  for (const auto& st : stages) {
    require_positive(st.increments, "path.stage.increments");
    int cycles = 0, cycling = -1;
    for (int i = 0; i < models::kExternalSlots; ++i)
      if (st.external[std::size_t(i)].kind == ExternalPath::Kind::kCycle) {
        if (cycling >= 0)
          throw InputError(fmt::format(
              "stage '{}' cycles two external variables; cycle one per stage", st.label));
        cycling = i, cycles = st.external[std::size_t(i)].cycles;
      }
    const int parts = cycling < 0 ? 1 : 4 * cycles;
    if (st.increments % parts != 0)
      throw InputError(fmt::format(
          "stage '{}': {} increments do not split into the {} quarters of {} cycles; give a "
          "multiple of {}",
          st.label, st.increments, parts, cycles, parts));
    const int n = st.increments / parts;
    static constexpr double kQuarter[4] = {1.0, -1.0, -1.0, 1.0};  // 0 -> +A -> 0 -> -A -> 0
    for (int q = 0; q < parts; ++q) {
      PathSegment seg;
      seg.label = cycling < 0
                      ? st.label
                      : fmt::format("{}, cycle {} quarter {}", st.label, q / 4 + 1, q % 4 + 1);
      (dir == ShearDirection::kX ? seg.gamma_x : seg.gamma_y) = st.gamma / parts;
      seg.row = st.bc.row(st.d_sigma_n / st.increments);
      seg.increments = n;
      seg.cycle = cycling < 0 ? 0 : q / 4 + 1;
      for (int i = 0; i < models::kExternalSlots; ++i) {
        const auto& x = st.external[std::size_t(i)];
        seg.external[std::size_t(i)] =
            i == cycling ? kQuarter[q % 4] * x.amplitude : x.change / parts;
      }
      path.push_back(seg);
    }
  }
  return path;
}

}  // namespace iwb::driver
