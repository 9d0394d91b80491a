// Cyclic verdicts on a constructed cyclic run: an elastic-perfectly plastic loop under a sigma_n
// that decays and a u_n that ratchets, replayed by a "model" that is the run itself, then one
// whose sigma_n falls faster by a known share, then one that stops early.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "comparison/replay/metrics.hpp"
#include "comparison/replay/seed_scatter.hpp"
#include "comparison/verdicts/cyclic_verdicts.hpp"

using namespace iwb;

namespace {

constexpr double kA = 1.0, kV = 1.0;  // mm, mm/s: the travel in mm is t in s
constexpr int kCycles = 3;
constexpr double kPost = 1.0, kRow = 0.00713;

// `offset`: the rows after the first fall this share of a row spacing later, as another seed's do
// `decay`: sigma_n = 50 exp(-travel / decay) kPa
comparison::DemRun cyclic_run(driver::BoundaryKind bc, double offset = 0.0, double decay = 20.0) {
  comparison::DemRun d;
  d.boundary = bc;
  d.d50_mm = 2.0;
  d.scene_but_seed = {{"shear",
                       {{"amplitude_mm", kA},
                        {"cycles", kCycles},
                        {"post_cyclic_mm", kPost},
                        {"velocity_mm_s", kV}}}};
  double tau = 0.0;
  std::vector<double> travel = {0.0};  // every run has its row at the start of shear
  for (double s = offset > 0.0 ? offset * kRow : kRow; s <= 4 * kA * kCycles + kPost; s += kRow)
    travel.push_back(s);
  const auto u_at = [](double s) {
    return s >= 4 * kA * kCycles ? s - 4 * kA * kCycles
                                 : kA * (std::abs(std::fmod(s / kA + 3.0, 4.0) - 2.0) - 1.0);
  };
  double s_before = 0.0;
  for (double s : travel) {
    // the interface follows the wall between rows too (through the reversals), in steps of 1e-4 mm
    for (double x = s_before; x < s; x = std::min(s, x + 1e-4))
      tau = std::clamp(tau + 80.0 * (u_at(std::min(s, x + 1e-4)) - u_at(x)), -10.0, 10.0);
    s_before = s;
    d.t_s.push_back(s / kV), d.u_x_mm.push_back(u_at(s)), d.tau_kPa.push_back(tau);
    d.sigma_n_kPa.push_back(50.0 * std::exp(-s / decay)), d.u_n_mm.push_back(0.01 * s),
        d.e_band.push_back(0.7);
  }
  return d;
}

comparison::Replay replay_of(const comparison::DemRun& d) {
  comparison::Replay r;
  r.u_x_mm = d.u_x_mm, r.tau_kPa = d.tau_kPa, r.sigma_n_kPa = d.sigma_n_kPa, r.u_n_mm = d.u_n_mm;
  return r;
}

std::vector<comparison::CyclicVerdict> judged(const comparison::DemRun& d,
                                              const comparison::Replay& r) {
  const auto program = comparison::cyclic_program(d);
  REQUIRE(program.has_value());
  return comparison::judge_cycles(d, {comparison::dem_cycles(d, *program)},
                                  comparison::replay_cycles(d, r, *program));
}

const comparison::CyclicVerdict& find(const std::vector<comparison::CyclicVerdict>& v,
                                      const std::string& q, const std::string& where) {
  for (const auto& x : v)
    if (x.quantity == q && x.where == where) return x;
  FAIL("no verdict " << q << " at " << where);
  return v.front();
}

}  // namespace

TEST_CASE(
    "a replay that is the DEM run holds on every cyclic quantity, at cycles 1, 2 and the last",
    "[comparison][cyclic]") {
  const auto d = cyclic_run(driver::BoundaryKind::kCNS);
  const auto v = judged(d, replay_of(d));
  // CNS: peaks both ways, sigma_n ratio, u_n, reversal stiffness at cycles 1, 2, 3 (5 is beyond)
  // and their changes from cycle 1 to 3, and the post-cyclic peak and u_n change
  CHECK(v.size() == 3 * 5 + 5 + 2);
  for (const auto& x : v) {
    INFO(x.quantity << " at " << x.where);
    CHECK(x.verdict == "holds");
    CHECK(x.error.value() == Approx(0.0).margin(1e-12));
  }
}

TEST_CASE("a model whose sigma_n falls faster breaks the degradation where the miss exceeds 10 %",
          "[comparison][cyclic]") {
  const auto d = cyclic_run(driver::BoundaryKind::kCNS);
  auto r = replay_of(d);
  // sigma_n lower by 20 % of the travel's share of the cycles: the ratio misses by -6.7 %, -13.3 %
  // and -20 % at the ends of cycles 1, 2, 3
  for (std::size_t i = 0; i < r.sigma_n_kPa.size(); ++i)
    r.sigma_n_kPa[i] *= 1.0 - 0.2 * std::min(1.0, d.t_s[i] * kV / 12.0);
  const auto v = judged(d, r);
  CHECK(find(v, "sigma_n_ratio", "cycle 1").error.value() == Approx(-0.2 / 3).epsilon(1e-3));
  CHECK(find(v, "sigma_n_ratio", "cycle 1").verdict == "holds");
  CHECK(find(v, "sigma_n_ratio", "cycle 2").error.value() == Approx(-0.4 / 3).epsilon(1e-3));
  CHECK(find(v, "sigma_n_ratio", "cycle 2").verdict == "breaks");
  CHECK(find(v, "sigma_n_ratio", "cycle 3").verdict == "breaks");
  CHECK(find(v, "u_n_end_mm", "cycle 3").verdict == "holds");  // untouched
  // the change over the cycles: the DEM's ratio falls from exp(-4/20) to exp(-12/20), the model's
  // from (1 - 0.2/3) exp(-4/20) to 0.8 exp(-12/20); the miss is taken against the DEM's level at
  // cycle 1, which is larger than its change
  const double first = std::exp(-4.0 / 20), last = std::exp(-12.0 / 20);
  const double miss = (0.8 * last - (1.0 - 0.2 / 3) * first) - (last - first);
  const auto& change = find(v, "sigma_n_ratio_change", "cycle 1 to 3");
  CHECK(change.dem.value() == Approx(last - first).epsilon(1e-3));
  CHECK(change.error.value() == Approx(miss / first).epsilon(1e-2));
  CHECK(change.verdict == "holds");  // -6.7 % of the level, while cycle 3 itself misses by 20 %
}

TEST_CASE("a cyclic run's scene states its tolerances in [requirements]", "[comparison][cyclic]") {
  auto d = cyclic_run(driver::BoundaryKind::kCNS);
  auto r = replay_of(d);
  for (std::size_t i = 0; i < r.sigma_n_kPa.size(); ++i)  // as above: -13.3 % at cycle 2
    r.sigma_n_kPa[i] *= 1.0 - 0.2 * std::min(1.0, d.t_s[i] * kV / 12.0);
  CHECK(find(judged(d, r), "sigma_n_ratio", "cycle 2").verdict == "breaks");  // the default 10 %
  d.scene_text = "[requirements]\ncycle_sigma_n_ratio = 0.15\nreversal_secant = \"not needed\"\n";
  const auto v = judged(d, r);
  CHECK(find(v, "sigma_n_ratio", "cycle 2").tolerance == 0.15);
  CHECK(find(v, "sigma_n_ratio", "cycle 2").verdict == "holds");
  for (const auto& x : v) CHECK(x.quantity.find("secant") == std::string::npos);
  CHECK(find(v, "peak_friction_positive", "cycle 2").tolerance == 0.10);  // not stated: default
  const auto t = comparison::cyclic_tolerances(cyclic_run(driver::BoundaryKind::kCV));
  CHECK(t.count("cycle_sigma_n_ratio") == 1);
  CHECK(t.count("cycle_u_n") == 0);  // CV holds u_n
  CHECK(comparison::cyclic_tolerances(cyclic_run(driver::BoundaryKind::kCNL))
            .count("cycle_sigma_n_ratio") == 0);  // CNL holds sigma_n
}

TEST_CASE(
    "a replay that stopped in cycle 2 is not reached beyond, and the BC decides what is judged",
    "[comparison][cyclic]") {
  const auto d = cyclic_run(driver::BoundaryKind::kCNL);
  auto r = replay_of(d);
  const std::size_t keep = std::size_t(6.0 * kA / kRow);  // a cycle and a half
  for (auto* x : {&r.u_x_mm, &r.tau_kPa, &r.sigma_n_kPa, &r.u_n_mm}) x->resize(keep);
  const auto v = judged(d, r);
  CHECK(find(v, "peak_friction_positive", "cycle 1").verdict == "holds");
  CHECK(find(v, "peak_friction_positive", "cycle 2").verdict == "not reached");
  CHECK(find(v, "post_cyclic_peak_friction", "after the cycles").verdict == "not reached");
  for (const auto& x : v) CHECK(x.quantity != "sigma_n_ratio");  // CNL holds sigma_n
  const auto cv = judged(cyclic_run(driver::BoundaryKind::kCV),
                         replay_of(cyclic_run(driver::BoundaryKind::kCV)));
  for (const auto& x : cv) CHECK(x.quantity.find("u_n") == std::string::npos);  // CV holds u_n
  CHECK_FALSE(comparison::cyclic_program(comparison::DemRun{}).has_value());    // a monotonic run
}

TEST_CASE("seeds of a cyclic run are aligned by their travel v t, not by summed |du_x|",
          "[comparison][cyclic]") {
  // the same path sampled 0.4 rows later: summing |du_x| cuts each reversal's corner by a
  // different amount in each (up to a row, 0.007 mm), so that the elastic branches (80 kPa/mm)
  // after each reversal would be compared a little apart
  auto a = cyclic_run(driver::BoundaryKind::kCNS), b = cyclic_run(driver::BoundaryKind::kCNS, 0.4);
  a.dir = "a", b.dir = "b";
  const auto s = comparison::seed_scatter(a, {b});
  CHECK(s.tau.rms_sd < 0.01);  // kPa: interpolation alone (0.004); aligned by summed |du_x|: 0.023
}

TEST_CASE(
    "cyclic verdicts rest on the seeds: their mean, its t-interval, and a miss inside it is DEM "
    "scatter",
    "[comparison][cyclic]") {
  // three seeds whose sigma_n decays over 15, 20 and 25 mm of travel: after cycle 3 (12 mm) the
  // ratio is exp(-12/L); a model decaying over 12.5 mm misses their mean by 29 %
  std::vector<comparison::DemRun> seeds;
  for (double decay : {15.0, 20.0, 25.0})
    seeds.push_back(cyclic_run(driver::BoundaryKind::kCNS, 0.0, decay));
  const auto program = *comparison::cyclic_program(seeds[0]);
  std::vector<cycles::CyclicQuantities> q;
  for (const auto& s : seeds) q.push_back(comparison::dem_cycles(s, program));
  const auto model = comparison::replay_cycles(
      seeds[0], replay_of(cyclic_run(driver::BoundaryKind::kCNS, 0.0, 12.5)), program);
  const double r1 = std::exp(-12.0 / 15), r2 = std::exp(-12.0 / 20), r3 = std::exp(-12.0 / 25);
  const double mean = (r1 + r2 + r3) / 3;
  const double sd =
      std::sqrt((std::pow(r1 - mean, 2) + std::pow(r2 - mean, 2) + std::pow(r3 - mean, 2)) / 2);
  const auto all = comparison::judge_cycles(seeds[0], q, model);
  const auto& v = find(all, "sigma_n_ratio", "cycle 3");
  CHECK(v.seeds == 3);
  CHECK(v.dem.value() == Approx(mean).epsilon(1e-3));
  CHECK(v.dem_sd.value() == Approx(sd).epsilon(1e-2));
  CHECK(v.dem_ci.value() == Approx(4.302653 * sd / std::sqrt(3.0)).epsilon(1e-2));  // t(0.975, 2)
  CHECK(v.error.value() == Approx((std::exp(-12.0 / 12.5) - mean) / mean).epsilon(1e-2));
  CHECK(v.verdict == "within DEM scatter");
  // one seed alone: no interval, and the same model breaks
  const auto one = comparison::judge_cycles(seeds[1], {q[1]}, model);
  const auto& alone = find(one, "sigma_n_ratio", "cycle 3");
  CHECK(alone.seeds == 1);
  CHECK_FALSE(alone.dem_ci.has_value());
  CHECK(alone.verdict == "breaks");
}

TEST_CASE("a cyclic run's last fifth is recorded as its end of path, never as a residual",
          "[comparison][cyclic]") {
  const auto d = cyclic_run(driver::BoundaryKind::kCNL);
  const auto m = comparison::to_json(comparison::compare(d, replay_of(d)));
  CHECK(m.contains("end_of_path_friction"));
  CHECK_FALSE(m.contains("residual_friction"));
  // the end of path is the mean |tau|/sigma_n over the last fifth of the wall's travel v t (the
  // path returns through u_x, so u_x's own last fifth would take rows from every cycle)
  const double v = d.scene_but_seed.at("/shear/velocity_mm_s"_json_pointer).get<double>();
  const double from = 0.8 * v * d.t_s.back();
  double sum = 0.0;
  int rows = 0;
  for (std::size_t i = 0; i < d.t_s.size(); ++i)
    if (v * d.t_s[i] >= from) sum += std::abs(d.tau_kPa[i]) / d.sigma_n_kPa[i], ++rows;
  CHECK(rows < int(d.t_s.size()) / 4);
  CHECK(m["end_of_path_friction"]["dem"].get<double>() == Approx(sum / rows).epsilon(1e-12));
  CHECK(m["end_of_path_friction"]["error"].get<double>() == Approx(0.0).margin(1e-12));
}
