#include "column/column.hpp"

#include <dlfcn.h>
#include <fmt/core.h>

#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "coarse_graining/band_measures.hpp"
#include "common/band_zone.hpp"
#include "common/errors.hpp"

namespace iwb::column {

namespace {

// LAPACK's band solver (Debian's liblapack3): A x = b for a band matrix in column-major band
// storage, overwritten by its LU factors; b by x. Loaded the first time a column solves, not
// linked: linked, LAPACK and the BLAS, gfortran and quadmath it pulls in were 5 of iwb's 17
// libraries and raised every command's start-up from 9 to 15 ms (`iwb bench element`).
using Dgbsv = void(const int* n, const int* kl, const int* ku, const int* nrhs, double* ab,
                   const int* ldab, int* ipiv, double* b, const int* ldb, int* info);

Dgbsv* lapack_dgbsv() {
  static Dgbsv* const dgbsv = [] {
    // RTLD_LOCAL: its symbols stay its own; loaded once, never unloaded
    void* lapack = dlopen("liblapack.so.3", RTLD_NOW | RTLD_LOCAL);
    void* f = lapack ? dlsym(lapack, "dgbsv_") : nullptr;
    if (f == nullptr)
      throw std::runtime_error(fmt::format(
          "the column solves with LAPACK, which did not load ({}): install Debian's liblapack3",
          dlerror()));
    return reinterpret_cast<Dgbsv*>(f);
  }();
  return dgbsv;
}

constexpr int kDofs = 3;  // per node: u1, u2, w
constexpr int kU1 = 0, kU2 = 1, kW = 2;
using Forces = Eigen::Matrix<double, 2 * kDofs, 1>;
using Increments = Eigen::Matrix<double, 2 * kDofs, 1>;

// An element's rate over the increment from its nodes' increments (lower node, then upper): the
// gradients over the element, the spin at its centre. The plain model's grains turn with the
// continuum (w = -du1/dy / 2), which makes D^c symmetric and the spin the continuum's.
PolarRate element_rate(const Increments& d, double h, bool polar) {
  const double du1 = (d(3 + kU1) - d(kU1)) / h, du2 = (d(3 + kU2) - d(kU2)) / h;
  PolarRate r;
  r.w = polar ? 0.5 * (d(kW) + d(3 + kW)) : -0.5 * du1;
  r.k = polar ? (d(3 + kW) - d(kW)) / h : 0.0;
  r.Dc(0, 1) = du1 + r.w;
  r.Dc(1, 0) = -r.w;
  r.Dc(1, 1) = du2;
  return r;
}

// The nodal forces of an element's stress, from the weak form (README, "The column")
//   int T12 dv1' + T22 dv2' + (T12 - T21) dw + m dw' dy
// at one point, the centre.
Forces element_forces(const PolarState& s, double h) {
  const double T12 = s.T(0, 1), T21 = s.T(1, 0), T22 = s.T(1, 1);
  const double moment = 0.5 * h * (T12 - T21);
  Forces f;
  f << -T12, -T22, moment - s.m, T12, T22, moment + s.m;
  return f;
}

class ColumnSolver {
 public:
  explicit ColumnSolver(const ColumnSpec& spec)
      : spec_(spec),
        c_(make_polar_constants(spec.soil, spec.d50_mm, spec.polar)),
        h_(spec.height_mm / spec.elements),
        nodes_(spec.elements + 1),
        u_(Eigen::VectorXd::Zero(kDofs * nodes_)),
        last_(Eigen::VectorXd::Zero(kDofs * nodes_)) {
    // the plate's K0 state: what a layer consolidated under it carries before shearing
    const double K0 = 1.0 - std::sin(spec.soil.phi_c);
    for (int j = 0; j < spec.elements; ++j) {
      PolarState s;
      s.T.diagonal() << -K0 * spec.sigma_n0_kPa, -spec.sigma_n0_kPa, -K0 * spec.sigma_n0_kPa;
      s.e = spec.e0 * (j == 0 ? 1.0 + spec.imperfection : 1.0);
      states_.push_back(s);
    }
  }

  // Advances the wall by dU, halving the increment where Newton's method does not converge.
  void advance(double dU, int depth = 0) {
    if (solve(dU)) return;
    if (depth >= kMaxCutbacks)
      throw DomainError(
          fmt::format("no convergence at a wall travel of {:.6g} mm ({})", wall_, last_failure_));
    ++cutbacks_;
    advance(0.5 * dU, depth + 1);
    advance(0.5 * dU, depth + 1);
  }

  ColumnRow row() const {
    return {wall_, -states_.front().T(0, 1), -states_.front().T(1, 1), u_(top(kU2)),
            slip_, zone_void_ratio()};
  }

  ColumnProfile profile() const {
    ColumnProfile p{wall_, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}};
    const double v = last_dU_ == 0.0 ? 1.0 : last_dU_;
    for (int j = 0; j < spec_.elements; ++j) {
      const Increments d = last_.segment<2 * kDofs>(kDofs * j);
      // the length the increment's gradients were taken over: the one at its start
      const double L = length(j) - (d(3 + kU2) - d(kU2));
      const auto r = element_rate(d, L, spec_.polar);
      const auto& s = states_[j];
      // heights in the deformed column, as the DEM's grains are binned
      p.z_over_d50.push_back(((j + 0.5) * h_ + 0.5 * (u_(dof(j, kU2)) + u_(dof(j + 1, kU2)))) /
                             spec_.d50_mm);
      p.length_mm.push_back(L);
      p.vx_over_vwall.push_back(0.5 * (d(kU1) + d(3 + kU1)) / v);
      p.spin.push_back(r.w * spec_.d50_mm / v);
      p.shear_rate.push_back(std::abs(d(3 + kU1) - d(kU1)) / L * spec_.d50_mm / v);
      p.e.push_back(s.e);
      p.tau_kPa.push_back(-s.T(0, 1));
      p.T21_kPa.push_back(-s.T(1, 0));
      p.sigma_zz_kPa.push_back(-s.T(1, 1));
      p.m_kPa_mm.push_back(s.m);
    }
    return p;
  }

  double wall() const { return wall_; }
  int iterations() const { return iterations_; }
  int cutbacks() const { return cutbacks_; }

 private:
  static constexpr int kMaxCutbacks = 8;
  static constexpr int kMaxIterations = 40;
  static constexpr int kMaxHalvings = 6;
  static constexpr int kStalledAfter = 15, kStalledLong = 30;

  int dof(int node, int k) const { return kDofs * node + k; }
  // An element's length now: an increment's gradients are taken over the length the soil has at
  // its start (updated Lagrangian), so that e, integrated from tr D, and the nodes' heights keep
  // the element's grains: (1 + e) / (1 + e0) = length / h to second order in the increment. Over
  // the reference length e drifted from the nodes by 1.3 % of the plate's rise at 4 mm of travel
  // (the test `column: the wall zone's void ratio carries the plate's rise, by mass alone`).
  double length(int j) const { return h_ + u_(dof(j + 1, kU2)) - u_(dof(j, kU2)); }

  // Voids over solids within the zone, in the deformed column: each element's soil in its
  // current length, cut at the zone's top.
  double zone_void_ratio() const {
    const double zone = wall_zone_of(spec_);
    double voids = 0.0, solids = 0.0;
    for (int j = 0; j < spec_.elements; ++j) {
      const double y0 = j * h_ + u_(dof(j, kU2)), y1 = (j + 1) * h_ + u_(dof(j + 1, kU2));
      const double inside = std::clamp(zone - y0, 0.0, y1 - y0);
      const double e = states_[j].e;
      voids += inside * e / (1.0 + e);
      solids += inside / (1.0 + e);
    }
    return solids > 0.0 ? voids / solids : states_.front().e;
  }
  int top(int k) const { return dof(nodes_ - 1, k); }
  bool slips() const { return std::isfinite(spec_.wall_friction); }

  // Which increments are prescribed, and to what: the wall drags node 0 (unless it slips under
  // it), the clamp holds the top still and unturned, the wall holds node 0 down.
  std::vector<std::pair<int, double>> prescribed(double dU) const {
    std::vector<std::pair<int, double>> p = {{top(kU1), 0.0}, {dof(0, kU2), 0.0}};
    if (!slips()) p.push_back({dof(0, kU1), dU});
    if (spec_.top == TopBoundary::kCV) p.push_back({top(kU2), 0.0});
    if (!spec_.polar) {
      for (int i = 0; i < nodes_; ++i) p.push_back({dof(i, kW), 0.0});  // not read: w = -du1/2
    } else {
      p.push_back({top(kW), 0.0});
      if (spec_.wall_rotation == WallRotation::kFixed) p.push_back({dof(0, kW), 0.0});
    }
    return p;
  }

  int substeps(const PolarRate& r) const {
    const double kd = r.k * spec_.d50_mm;
    const double norm = std::sqrt(r.Dc.squaredNorm() + kd * kd);
    return std::max(1, int(std::ceil(norm / spec_.substep_strain)));
  }

  // The residual (internal minus external forces) at the increments d, with its Jacobian by
  // differences element by element; the elements' states at the increment's end in `ends`.
  void assemble(const Eigen::VectorXd& d, double dU, Eigen::VectorXd& R,
                std::vector<Eigen::Triplet<double>>& J, std::vector<PolarState>& ends) const {
    R.setZero(kDofs * nodes_);
    J.clear();
    ends.resize(spec_.elements);
    const double eps = 1e-6 * std::max(std::abs(dU), 1e-9);
    for (int j = 0; j < spec_.elements; ++j) {
      const Increments de = d.segment<2 * kDofs>(kDofs * j);
      const double L = length(j);
      const auto rate = element_rate(de, L, spec_.polar);
      const int n = substeps(rate);
      ends[j] = integrate(states_[j], rate, c_, n);
      const Forces f = element_forces(ends[j], L);
      R.segment<2 * kDofs>(kDofs * j) += f;
      for (int a = 0; a < 2 * kDofs; ++a) {
        Increments dp = de;
        const double step = (a % kDofs == kW) ? eps / spec_.d50_mm : eps;
        dp(a) += step;
        const Forces fp =
            element_forces(integrate(states_[j], element_rate(dp, L, spec_.polar), c_, n), L);
        for (int b = 0; b < 2 * kDofs; ++b)
          J.emplace_back(kDofs * j + b, kDofs * j + a, (fp(b) - f(b)) / step);
      }
    }
    // the plate: sigma_n0 under CNL and CV (CV's u2 is prescribed), sigma_n0 + K u_n under CNS
    const double u_n = u_(top(kU2)) + d(top(kU2));
    const double K = spec_.top == TopBoundary::kCNS ? spec_.stiffness_kPa_per_mm : 0.0;
    R(top(kU2)) += spec_.sigma_n0_kPa + K * u_n;
    J.emplace_back(top(kU2), top(kU2), K);
    if (slips()) wall_traction(d, dU, -ends.front().T(1, 1), R, J);
  }

  // The wall's pull on node 0 where it may slip: a stiff spring from the wall to the soil (its
  // give 1e-3 d50 at tau = sigma_n0) whose force saturates smoothly at tan(delta) sigma_n,
  // tau = cap tanh(k_s g / cap) of the spring's stretch g. A hard cap (stick or slip) left Newton
  // cycling between the two at the onset of slip; the smooth one has a tangent everywhere.
  double spring_stiffness() const { return 1e3 * spec_.sigma_n0_kPa / spec_.d50_mm; }
  double stretch(const Eigen::VectorXd& d, double dU) const {
    return wall_ + dU - u_(dof(0, kU1)) - d(dof(0, kU1)) - slip_;
  }
  void wall_traction(const Eigen::VectorXd& d, double dU, double sigma_n, Eigen::VectorXd& R,
                     std::vector<Eigen::Triplet<double>>& J) const {
    const double k_s = spring_stiffness();
    const double cap = spec_.wall_friction * sigma_n;
    const double t = std::tanh(k_s * stretch(d, dU) / cap);
    R(dof(0, kU1)) -= cap * t;
    J.emplace_back(dof(0, kU1), dof(0, kU1), k_s * (1.0 - t * t));
  }

  double scaled_norm(const Eigen::VectorXd& R, const std::vector<int>& free) const {
    double sum = 0.0;
    for (int i : free) {
      const double r = (i % kDofs == kW) ? R(i) / spec_.d50_mm : R(i);
      sum += r * r;
    }
    return std::sqrt(sum);
  }

  bool solve(double dU) {
    const auto fixed = prescribed(dU);
    std::vector<char> is_fixed(kDofs * nodes_, 0);
    // the last increment's shape as the first guess: Newton starts near a band that has formed
    Eigen::VectorXd d =
        last_dU_ != 0.0 ? Eigen::VectorXd(last_ * (dU / last_dU_)) : first_guess(dU);
    for (const auto& [i, v] : fixed) {
      is_fixed[i] = 1;
      d(i) = v;
    }
    std::vector<int> free, index(kDofs * nodes_, -1);
    for (int i = 0; i < kDofs * nodes_; ++i)
      if (!is_fixed[i]) {
        index[i] = int(free.size());
        free.push_back(i);
      }
    Eigen::VectorXd R;
    std::vector<Eigen::Triplet<double>> J;
    std::vector<PolarState> ends;
    // Out of balance by at most 1e-6 sigma_n0; by 1e-4 (5e-3 kPa at 50 kPa) once Newton has taken
    // kStalledAfter iterations, by 1e-3 after 30. Its residual stalls where elements barely strain
    // (the law's kink at D = 0): near 1e-3 kPa at 8 elements per d50 as the band forms (tau, u_n
    // and the band then agree to 0.1 % with 4 per d50, which meets the strict one), and near 1e-2
    // kPa over a wall that slides under a soil that hardly shears (tau there within 0.2 % and
    // u_n within 0.02 mm between 500 and 1000 increments). The strict one first: past the peak a
    // uniform column is one of many balanced states, and a loose balance lets it drift into
    // another.
    const double strict = 1e-6 * spec_.sigma_n0_kPa, loose = 1e-4 * spec_.sigma_n0_kPa;
    try {
      // Newton's method with backtracking: outside the band the law unloads, where its rate is not
      // smooth (||D|| at D = 0), and a full step can overshoot; a step that raises the residual is
      // halved back.
      double previous = std::numeric_limits<double>::infinity();
      Eigen::VectorXd step = Eigen::VectorXd::Zero(d.size());
      for (int it = 0, halvings = 0; it < kMaxIterations; ++it) {
        assemble(d, dU, R, J, ends);
        ++iterations_;
        const double norm = scaled_norm(R, free);
        if (norm < (it < kStalledAfter ? strict : (it < kStalledLong ? loose : 10.0 * loose))) {
          accept(d, dU, ends);
          return true;
        }
        if (norm > previous && halvings < kMaxHalvings) {
          step *= 0.5;
          d -= step;
          ++halvings;
          continue;
        }
        halvings = 0;
        previous = norm;
        step = newton_step(R, J, free, index);
        d += step;
      }
    } catch (const DomainError& e) {
      // a trial increment left the law's domain: a smaller one may not
      last_failure_ = e.what();
      return false;
    }
    last_failure_ = fmt::format("the residual stayed above {:.3g} kPa after {} iterations", loose,
                                kMaxIterations);
    return false;
  }

  // The Newton step on the free increments: -J_ff^-1 R_f, J banded (a node couples only to its
  // neighbours), solved by LAPACK's band LU with partial pivoting (dgbsv).
  Eigen::VectorXd newton_step(const Eigen::VectorXd& R,
                              const std::vector<Eigen::Triplet<double>>& J,
                              const std::vector<int>& free, const std::vector<int>& index) const {
    const int n = int(free.size()), one = 1;
    int band = 0;
    for (const auto& t : J)
      if (index[t.row()] >= 0 && index[t.col()] >= 0)
        band = std::max(band, std::abs(index[t.row()] - index[t.col()]));
    const int kl = band, ku = band, ldab = 2 * kl + ku + 1;
    std::vector<double> ab(std::size_t(ldab) * n, 0.0);  // column-major band storage
    for (const auto& t : J) {
      const int i = index[t.row()], j = index[t.col()];
      if (i >= 0 && j >= 0) ab[std::size_t(kl + ku + i - j) + std::size_t(j) * ldab] += t.value();
    }
    std::vector<double> x(n);
    for (int k = 0; k < n; ++k) x[k] = -R(free[k]);
    std::vector<int> pivots(n);
    int info = 0;
    lapack_dgbsv()(&n, &kl, &ku, &one, ab.data(), &ldab, pivots.data(), x.data(), &n, &info);
    if (info != 0) throw DomainError("singular column stiffness");
    Eigen::VectorXd step = Eigen::VectorXd::Zero(R.size());
    for (int k = 0; k < n; ++k) step(free[k]) = x[k];
    return step;
  }

  // Before any increment: the wall's travel spread linearly over the height (simple shear).
  Eigen::VectorXd first_guess(double dU) const {
    Eigen::VectorXd d = Eigen::VectorXd::Zero(kDofs * nodes_);
    for (int i = 0; i < nodes_; ++i) d(dof(i, kU1)) = dU * (1.0 - double(i) / (nodes_ - 1));
    return d;
  }

  void accept(const Eigen::VectorXd& d, double dU, const std::vector<PolarState>& ends) {
    if (slips()) {  // the slip: what of the stretch the spring's force does not hold
      const double cap = spec_.wall_friction * -ends.front().T(1, 1);
      const double held = std::clamp(-ends.front().T(0, 1) / cap, -1.0 + 1e-12, 1.0 - 1e-12);
      slip_ += stretch(d, dU) - cap / spring_stiffness() * std::atanh(held);
    }
    u_ += d;
    wall_ += dU;
    states_ = ends;
    last_ = d;
    last_dU_ = dU;
  }

  const ColumnSpec& spec_;
  PolarConstants c_;
  double h_;
  int nodes_;
  std::vector<PolarState> states_;
  Eigen::VectorXd u_, last_;
  double last_dU_ = 0.0, wall_ = 0.0, slip_ = 0.0;
  int iterations_ = 0, cutbacks_ = 0;
  std::string last_failure_;
};

// The travels the profiles are written at: the spec's and the travel's end (where the band and
// the report's last profile are read), else the ends of equal windows.
std::vector<double> profile_travels(const ColumnSpec& spec) {
  std::vector<double> at = spec.profile_at_mm;
  if (!at.empty()) {
    if (at.back() < spec.travel_mm) at.push_back(spec.travel_mm);
    return at;
  }
  for (int k = 1; k <= spec.profiles; ++k) at.push_back(spec.travel_mm * k / spec.profiles);
  return at;
}

}  // namespace

void require_spec(const ColumnSpec& s) {
  if (!(s.elements >= 2)) throw InputError("a column needs at least 2 elements");
  if (!(s.height_mm > 0.0 && s.d50_mm > 0.0 && s.travel_mm > 0.0 && s.sigma_n0_kPa > 0.0))
    throw InputError("a column's height, d50, travel and sigma_n0 must be positive");
  if (!(s.increments >= 1 && s.profiles >= 1)) throw InputError("at least one increment");
  for (std::size_t k = 0; k < s.profile_at_mm.size(); ++k)
    if (!(s.profile_at_mm[k] > (k ? s.profile_at_mm[k - 1] : 0.0) &&
          s.profile_at_mm[k] <= s.travel_mm * (1.0 + 1e-9)))
      throw InputError(fmt::format(
          "profile at a travel of {:.6g} mm: the travels must rise within 0 .. {:.6g} mm (the "
          "column's travel)",
          s.profile_at_mm[k], s.travel_mm));
  // the start inside the law's domain: e_d < e0 < e_i at the plate's K0 state (eq. 5.13)
  const double K0 = 1.0 - std::sin(s.soil.phi_c);
  const double trace = s.sigma_n0_kPa * (1.0 + 2.0 * K0);
  const auto lim = models::limiting_void_ratios(trace, s.soil);
  const double e_wall = s.e0 * (1.0 + s.imperfection);
  if (!(s.e0 > lim.e_d && e_wall < lim.e_i))
    throw InputError(fmt::format(
        "e0 = {:.4g}{}: outside e_d = {:.4g} .. e_i = {:.4g}, the soil's limits at sigma_n0 = "
        "{:.4g} kPa",
        s.e0,
        s.imperfection > 0.0 ? fmt::format(" ({:.4g} in the element at the wall)", e_wall) : "",
        lim.e_d, lim.e_i, s.sigma_n0_kPa));
}

double wall_zone_of(const ColumnSpec& spec) {
  return spec.wall_zone_mm > 0.0 ? spec.wall_zone_mm
                                 : wall_zone_thickness(spec.d50_mm, spec.height_mm);
}

ColumnResult run_column(const ColumnSpec& spec, const std::function<void(long, long)>& progress) {
  require_spec(spec);
  ColumnSolver solver(spec);
  ColumnResult result;
  result.rows.push_back(solver.row());
  const double dU = spec.travel_mm / spec.increments;
  const auto at = profile_travels(spec);
  std::size_t next = 0;
  try {
    for (int i = 1; i <= spec.increments; ++i) {
      solver.advance(dU);
      result.rows.push_back(solver.row());
      // the increments' ends lie on i dU: a travel is passed when within a millionth of dU of it
      bool due = false;
      while (next < at.size() && at[next] <= i * dU + 1e-6 * dU) ++next, due = true;
      if (due) result.profiles.push_back(solver.profile());
      if (progress) progress(i, spec.increments);
    }
  } catch (const DomainError& e) {
    result.status = e.what();
    result.profiles.push_back(solver.profile());
  }
  result.newton_iterations = solver.iterations();
  result.cutbacks = solver.cutbacks();
  return result;
}

BandWidths band_widths(const ColumnProfile& p) {
  const coarse_graining::Span all{0.0, p.z_over_d50.back() + p.z_over_d50.front()};
  return {coarse_graining::peak_width_at_half_maximum(p.z_over_d50, p.shear_rate, all),
          coarse_graining::velocity_band_width(p.z_over_d50, p.vx_over_vwall, 0.0)};
}

}  // namespace iwb::column
