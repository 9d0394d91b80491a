#include "driver/element_test.hpp"

#include <fmt/core.h>

#include <cmath>
#include <optional>
#include <utility>

#include "common/errors.hpp"

namespace iwb::driver {

double ShearZone::gamma_of(double u_mm) const {
  return measure == ShearStrainMeasure::kLinear ? u_mm / d_s_mm : std::atan(u_mm / d_s_mm);
}

double ShearZone::u_of(double gamma) const {
  return measure == ShearStrainMeasure::kLinear ? gamma * d_s_mm : d_s_mm * std::tan(gamma);
}

std::string ShearZone::describe() const {
  return fmt::format(
      "d_s = {:g} mm, {}", d_s_mm,
      measure == ShearStrainMeasure::kLinear ? "gamma = u/d_s" : "tan(gamma) = u/d_s");
}

namespace {

// Thrown by the walker when the interrupt flag is set; ends the run with its message as status.
struct Interrupted : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Walker {
  const models::Model& model;
  const RunSettings& set;
  ElementTestResult& result;
  HistoryRow current;
  long total = 0;
  double first_step = 1.0;
  // The row (a, b) of the previous segment and the total a sigma_n + b eps_n it aimed at by its
  // end. A segment with the same (a, b) continues from that aim, not from the state reached, so
  // the residuals within the Newton tolerance do not add up from segment to segment either (a
  // cyclic path under CNL is thousands of segments).
  std::optional<std::pair<NormalControlRow, double>> aimed;

  std::string where(const PathSegment& seg) const {
    return fmt::format("increment {} ('{}', gamma_x = {:.6g}, gamma_y = {:.6g}, eps_n = {:.6g})",
                       current.increment + 1, seg.label, current.gamma_x, current.gamma_y,
                       current.eps_n);
  }

  // Guess for the normal strain increment: the last one within a segment, else one Euler step
  // of the closed form (cheap and usually within a few percent).
  double guess(const NormalControlRow& row, double gx, double gy, int k, double last) {
    if (k > 0) return last;
    try {
      return closed_form_normal_strain(model, current.state, gx, gy, row, result.counters);
    } catch (const std::exception&) {
      return 0.0;
    }
  }

  // The row's value a sigma_n + b eps_n, compression positive sigma_n.
  static double row_value(const NormalControlRow& row, const HistoryRow& h) {
    return row.a * models::normal_stress(h.state) + row.b * h.eps_n;
  }

  void segment(int index, const PathSegment& seg) {
    const double gx = seg.gamma_x / seg.increments, gy = seg.gamma_y / seg.increments;
    const HistoryRow at_start = current;
    const bool continues = aimed && aimed->first.a == seg.row.a && aimed->first.b == seg.row.b;
    const double row_start = continues ? aimed->second : row_value(seg.row, at_start);
    aimed = {seg.row, row_start + seg.increments * seg.row.c};
    double last = 0.0;
    for (int k = 0; k < seg.increments; ++k) {
      if (set.interrupt != nullptr && set.interrupt->load())
        throw Interrupted("interrupted at " + where(seg));
      // Aim at the row's total after k+1 increments, not at its increment: residuals within the
      // tolerance then never accumulate over a long path.
      NormalControlRow row = seg.row;
      row.c = row_start + (k + 1) * seg.row.c - row_value(seg.row, current);
      IncrementRequest rq{gx, gy, row, guess(row, gx, gy, k, last)};
      for (std::size_t i = 0; i < rq.external.size(); ++i)
        rq.external[i] = seg.external[i] / seg.increments;
      IncrementSolution sol;
      try {
        sol = solve_increment(model, current.state, rq, set.integrator, set.mixed, first_step);
      } catch (const DomainError& e) {
        throw DomainError(fmt::format("{}: {}", where(seg), e.what()));
      } catch (const ConvergenceError& e) {
        throw ConvergenceError(fmt::format("{}: {}", where(seg), e.what()));
      }
      if (const auto why = model.domain_violation(sol.state); !why.empty())
        throw DomainError(fmt::format("{}: {}", where(seg), why));
      last = sol.eps_n;
      // Strains from the segment start, so a closed cycle ends exactly where it began.
      const double fraction = double(k + 1) / seg.increments;
      commit(index, at_start.gamma_x + fraction * seg.gamma_x,
             at_start.gamma_y + fraction * seg.gamma_y, sol);
      if (seg.cycle > 0) track_cycle(seg, at_start, k + 1 == seg.increments);
      if (current.increment % set.output_every == 0) result.rows.push_back(current);
      if (set.on_increment) set.on_increment(current.increment, total);
    }
  }

  // Per-cycle summary (cycles.csv) from every accepted increment of a cycle's segments.
  void track_cycle(const PathSegment& seg, const HistoryRow& segment_start, bool segment_end) {
    if (result.cycles.empty() || result.cycles.back().cycle != seg.cycle) {
      result.cycles.push_back({});
      result.cycles.back().cycle = seg.cycle;
      result.cycles.back().eps_n_start = segment_start.eps_n;  // the cycle's first segment
    }
    CycleSummary& c = result.cycles.back();
    const auto st = model.stress(current.state);
    const double tau = seg.gamma_y != 0.0 ? st.tau_y : st.tau_x;
    c.tau_max_kPa = std::max(c.tau_max_kPa, tau);
    c.tau_min_kPa = std::min(c.tau_min_kPa, tau);
    if (segment_end && seg.ends_at_reversal)
      (seg.gamma_x + seg.gamma_y > 0.0 ? c.sigma_n_at_plus_kPa : c.sigma_n_at_minus_kPa) =
          st.sigma_n;
    c.eps_n_end = current.eps_n;
    c.sigma_n_end_kPa = st.sigma_n;
    c.e_end = model.void_ratio(current.state);
    c.complete = segment_end && !seg.ends_at_reversal;
  }

  void commit(int index, double gamma_x, double gamma_y, const IncrementSolution& sol) {
    current.increment += 1;  // the final increment is appended by run_element_test
    current.segment = index;
    current.gamma_x = gamma_x;
    current.gamma_y = gamma_y;
    current.eps_n += sol.eps_n;
    current.state = sol.state;
    model.flush_negligible_components(current.state);
    current.newton_iterations = sol.iterations;
    current.rate_evaluations = sol.counters.rate_evaluations;
    current.rejected_substeps = sol.counters.rejected_substeps;
    result.counters += sol.counters;
    result.increments += 1;
    result.newton_iterations += sol.iterations;
  }
};

}  // namespace

void check_path(const models::Model& model, const Path& path) {
  static const char* const kExternalNames[models::kExternalSlots] = {"temperature", "suction",
                                                                     "time"};
  for (const auto& seg : path) {
    if ((seg.gamma_y != 0.0) && !model.has_second_shear_direction())
      throw InputError(
          fmt::format("model {} has one shear direction; use direction = \"x\"", model.name()));
    for (int i = 0; i < models::kExternalSlots; ++i)
      if (seg.external[std::size_t(i)] != 0.0 && !model.reads_external(models::External(i)))
        throw InputError(
            fmt::format("stage '{}' changes the {}, which model {} does not read (`iwb models {}` "
                        "lists what it reads)",
                        seg.label, kExternalNames[i], model.name(), model.name()));
  }
}

ElementTestResult run_element_test(const models::Model& model, const models::StateVector& initial,
                                   const Path& path, const RunSettings& settings) {
  ElementTestResult result;
  Walker w{model, settings, result, HistoryRow{}, 0, 1.0, std::nullopt};
  for (const auto& seg : path) w.total += seg.increments;
  w.current.state = initial;
  result.rows.push_back(w.current);
  check_path(model, path);
  try {
    for (std::size_t i = 0; i < path.size(); ++i) w.segment(int(i), path[i]);
  } catch (const DomainError& e) {
    result.status = fmt::format("failed: domain error at {}", e.what());
  } catch (const ConvergenceError& e) {
    result.status = fmt::format("failed: no convergence at {}", e.what());
  } catch (const Interrupted& e) {
    result.status = e.what();
  }
  if (result.rows.back().increment != w.current.increment) result.rows.push_back(w.current);
  return result;
}

}  // namespace iwb::driver
