#include "calibration/pareto.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "common/errors.hpp"

namespace iwb::calibration {

const ParetoPoint& ParetoFront::given() const {
  for (const auto& p : points)
    if (p.given) return p;
  throw std::logic_error("a Pareto front without its given point");
}

std::pair<ObjectiveGroup, ObjectiveGroup> parse_pareto_groups(const std::string& text) {
  const auto comma = text.find(',');
  if (comma == std::string::npos)
    throw InputError(fmt::format("--pareto {}: expected two groups A,B", text));
  const auto where = "--pareto " + text;
  const auto a = objective_group(text.substr(0, comma), where);
  const auto b = objective_group(text.substr(comma + 1), where);
  if (a == b) throw InputError(fmt::format("{}: the two groups must differ", where));
  return {a, b};
}

namespace {

// A group's residual count over the tests: what it appends for a model that reached no row (one
// residual per measured value, whatever the parameters).
std::size_t residual_count(ObjectiveGroup g, const std::vector<soil_test::SoilTest>& tests) {
  std::vector<double> r;
  for (const auto& t : tests) append_group_residuals(g, t, Simulated{{}, {}, {}, {}, ""}, r);
  return r.size();
}

double rms_of(const CalibrationResult& r, ObjectiveGroup g) {
  for (const auto& f : r.objectives)
    if (f.group == g) return f.rms;
  return NAN;
}

// The share s of a weight ratio s / (1 - s).
double share_of_ratio(double ratio) {
  return ratio / (1.0 + ratio);
}

struct FrontPlan {
  ObjectiveGroup a, b;
  ObjectiveWeights given;
  double total = 0.0, count_a = 0.0, count_b = 0.0;

  double given_share() const { return given[a] * count_a / total; }
  ObjectiveWeights at(double share) const {
    ObjectiveWeights w = given;
    w[a] = share * total / count_a;
    w[b] = (1.0 - share) * total / count_b;
    return w;
  }
};

ParetoPoint point_of(const FrontPlan& plan, double share, bool given, CalibrationResult r) {
  ParetoPoint p{share, plan.at(share), given, std::move(r), 0.0, 0.0};
  if (given) p.weights = plan.given;
  p.rms_a = rms_of(p.result, plan.a), p.rms_b = rms_of(p.result, plan.b);
  return p;
}

// Where the path is not monotonic: with more weight on a, a's RMS must not grow nor b's shrink
// (beyond the fits' own tolerance).
std::vector<std::string> monotonicity_notes(const ParetoFront& f) {
  constexpr double kSlack = 1e-6;
  std::vector<std::string> out;
  for (std::size_t i = 1; i < f.points.size(); ++i) {
    const auto &lo = f.points[i - 1], &hi = f.points[i];
    if (hi.rms_a > lo.rms_a * (1 + kSlack) + kSlack || hi.rms_b < lo.rms_b * (1 - kSlack) - kSlack)
      out.push_back(fmt::format(
          "shares {:.3f} -> {:.3f}: {} RMS {:.4g} -> {:.4g}, {} RMS {:.4g} -> {:.4g}: not "
          "monotonic (a local optimum; the front there is not the best trade-off)",
          lo.share, hi.share, to_string(f.a), lo.rms_a, hi.rms_a, to_string(f.b), lo.rms_b,
          hi.rms_b));
  }
  return out;
}

}  // namespace

ParetoFront trace_front(const std::vector<soil_test::SoilTest>& tests,
                        const CalibrationOptions& options, ObjectiveGroup a, ObjectiveGroup b,
                        int points, const std::function<void(const std::string&)>& progress) {
  if (a == b) throw InputError("--pareto: the two groups must differ");
  if (points < kMinParetoPoints || points > kMaxParetoPoints)
    throw InputError(fmt::format("--points {}: a front needs {} to {} points", points,
                                 kMinParetoPoints, kMaxParetoPoints));
  FrontPlan plan{a, b, options.weights};
  plan.count_a = double(residual_count(a, tests)), plan.count_b = double(residual_count(b, tests));
  for (const auto g : {a, b})
    if (residual_count(g, tests) == 0)
      throw InputError(fmt::format("--pareto: no test given has residuals of group '{}' ({})",
                                   to_string(g), describe(g)));
  plan.total = options.weights[a] * plan.count_a + options.weights[b] * plan.count_b;
  if (plan.total == 0.0) plan.total = plan.count_a + plan.count_b;  // both given 0: even shares

  const double s0 = plan.given_share();
  // a group given weight 0 leaves no ratio to centre on: the front is centred on even weights
  const double given_ratio = s0 > 0.0 && s0 < 1.0 ? s0 / (1.0 - s0) : 1.0;
  std::vector<double> up, down;
  for (int k = 0; k < points; ++k) {
    const double s = share_of_ratio(
        given_ratio *
        std::pow(10.0, -kParetoRatioDecades / 2 + kParetoRatioDecades * k / double(points - 1)));
    if (std::abs(s - s0) < 1e-9) continue;
    (s > s0 ? up : down).push_back(s);
  }
  const auto t0 = std::chrono::steady_clock::now();
  ParetoFront front{a, b, {}, 0.0, 0, {}};
  const int total = int(1 + up.size() + down.size());
  const auto report = [&](const ParetoPoint& p) {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const int done = int(front.points.size());
    if (progress)
      progress(
          fmt::format("point {}/{} (share {:.3f}{}): {} RMS {:.4g}, {} RMS {:.4g}; {:.0f} s, "
                      "ETA ~{:.0f} s",
                      done, total, p.share, p.given ? ", the given weights" : "", to_string(a),
                      p.rms_a, to_string(b), p.rms_b, s, s / done * (total - done)));
  };
  front.points.push_back(point_of(plan, s0, true, calibrate(tests, options)));
  report(front.points.back());
  std::reverse(down.begin(), down.end());  // outwards from the given point
  for (const auto* side : {&up, &down}) {
    models::ParameterValues previous = front.points.front().result.values();
    for (const double s : *side) {
      CalibrationOptions o = options;
      o.weights = plan.at(s);
      o.start = previous;
      front.points.push_back(point_of(plan, s, false, calibrate(tests, o)));
      previous = front.points.back().result.values();
      report(front.points.back());
    }
  }
  std::sort(front.points.begin(), front.points.end(),
            [](const auto& x, const auto& y) { return x.share < y.share; });
  for (const auto& p : front.points) front.evaluations += p.result.evaluations;
  front.notes = monotonicity_notes(front);
  front.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return front;
}

}  // namespace iwb::calibration
