#include "coarse_graining/fields.hpp"

#include <array>
#include <cmath>
#include <deque>
#include <iterator>
#include <numbers>
#include <stdexcept>

namespace iwb::coarse_graining {

namespace {

// The kernel sums, per grid point. Tensor components are stored as a*3+b.
enum Sum : std::size_t {
  kRho,
  kSolid,
  kPx,
  kPy,
  kPz,
  kDRhoDx,
  kDRhoDz,
  kDPxDx,
  kDPxDz,
  kDPzDx,
  kDPzDz,
  kSpinY,
  kContact = kSpinY + 1,         // 9 components
  kMomentumFlux = kContact + 9,  // 9 components: sum m v_a v_b phi
  kSumCount = kMomentumFlux + 9
};

using Sums = std::vector<std::array<double, kSumCount>>;

void add_grains(const std::vector<Grain>& grains, const SamplingGrid& grid, Sums& s) {
  std::vector<CellWeight> around;
  for (const Grain& g : grains) {
    grid.around_point(g.position, around);
    const double m = g.mass, volume = 4.0 / 3.0 * std::numbers::pi * g.radius * g.radius * g.radius;
    const Eigen::Vector3d& v = g.velocity;
    for (const auto& [cell, k] : around) {
      auto& c = s[cell];
      c[kRho] += m * k.phi, c[kSolid] += volume * k.phi;
      c[kPx] += m * v.x() * k.phi, c[kPy] += m * v.y() * k.phi, c[kPz] += m * v.z() * k.phi;
      c[kDRhoDx] += m * k.dphi_dx, c[kDRhoDz] += m * k.dphi_dz;
      c[kDPxDx] += m * v.x() * k.dphi_dx, c[kDPxDz] += m * v.x() * k.dphi_dz;
      c[kDPzDx] += m * v.z() * k.dphi_dx, c[kDPzDz] += m * v.z() * k.dphi_dz;
      c[kSpinY] += m * g.spin.y() * k.phi;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) c[kMomentumFlux + 3 * a + b] += m * v[a] * v[b] * k.phi;
    }
  }
}

void add_contacts(const std::vector<Contact>& contacts, const SamplingGrid& grid, Sums& s) {
  std::vector<CellWeight> along;
  for (const Contact& c : contacts) {
    grid.along_branch(c.from, c.to, along);
    const Eigen::Vector3d branch = c.from - c.to;
    for (const auto& [cell, k] : along)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) s[cell][kContact + 3 * a + b] += c.force[a] * branch[b] * k.phi;
  }
}

// The fields as they are derived, each added by the reference `add` returns. A deque, because
// growing a vector would move the fields already handed out and leave those references dangling
// (undefined behaviour that GCC's code happened to survive and clang's did not).
struct Derived {
  std::deque<Field> fields;
  std::vector<double>& add(const std::string& name, std::size_t n) {
    fields.push_back({name, std::vector<double>(n, 0.0)});
    return fields.back().values;
  }
};

FieldSet derive(const Sums& s) {
  const std::size_t n = s.size();
  Derived d;
  auto& rho = d.add("density_kg_m3", n);
  auto& nu = d.add("solid_fraction", n);
  auto& vx = d.add("velocity_x_m_s", n);
  auto& vz = d.add("velocity_z_m_s", n);
  auto& gxz = d.add("shear_rate_dvx_dz_1_s", n);
  auto& dxz = d.add("strain_rate_xz_1_s", n);
  auto& dxx = d.add("strain_rate_xx_1_s", n);
  auto& dzz = d.add("strain_rate_zz_1_s", n);
  auto& vort = d.add("vorticity_y_1_s", n);
  auto& spin = d.add("grain_spin_y_rad_s", n);
  auto& cosserat = d.add("cosserat_rotation_y_rad_s", n);
  const char* names[] = {"stress_xx_Pa", "stress_yy_Pa", "stress_zz_Pa", "stress_xz_Pa",
                         "stress_zx_Pa", "stress_xy_Pa", "stress_yz_Pa"};
  const int comps[][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 2}, {2, 0}, {0, 1}, {1, 2}};
  std::vector<std::vector<double>*> stress;
  for (const char* name : names) stress.push_back(&d.add(name, n));
  auto& kinetic = d.add("kinetic_pressure_Pa", n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& c = s[i];
    rho[i] = c[kRho], nu[i] = c[kSolid];
    const bool material = c[kSolid] >= kMinSolidFraction;
    const Eigen::Vector3d V =
        material ? Eigen::Vector3d(Eigen::Vector3d(c[kPx], c[kPy], c[kPz]) / c[kRho])
                 : Eigen::Vector3d(Eigen::Vector3d::Zero());
    for (std::size_t k = 0; k < std::size(comps); ++k) {
      const int a = comps[k][0], b = comps[k][1];
      const double flux = material ? c[kMomentumFlux + 3 * a + b] - c[kRho] * V[a] * V[b] : 0.0;
      (*stress[k])[i] = c[kContact + 3 * a + b] + flux;
    }
    if (!material) continue;
    kinetic[i] = (c[kMomentumFlux] + c[kMomentumFlux + 4] + c[kMomentumFlux + 8] -
                  c[kRho] * V.squaredNorm()) /
                 3.0;
    vx[i] = V.x(), vz[i] = V.z();
    const double dvx_dx = (c[kDPxDx] - V.x() * c[kDRhoDx]) / c[kRho],
                 dvx_dz = (c[kDPxDz] - V.x() * c[kDRhoDz]) / c[kRho];
    const double dvz_dx = (c[kDPzDx] - V.z() * c[kDRhoDx]) / c[kRho],
                 dvz_dz = (c[kDPzDz] - V.z() * c[kDRhoDz]) / c[kRho];
    gxz[i] = dvx_dz, dxz[i] = 0.5 * (dvx_dz + dvz_dx), dxx[i] = dvx_dx, dzz[i] = dvz_dz;
    vort[i] = dvx_dz - dvz_dx;  // (curl V)_y
    spin[i] = c[kSpinY] / c[kRho];
    cosserat[i] = spin[i] - 0.5 * vort[i];
  }
  return FieldSet{
      {std::make_move_iterator(d.fields.begin()), std::make_move_iterator(d.fields.end())}};
}

}  // namespace

const std::vector<double>& FieldSet::operator[](const std::string& name) const {
  for (const auto& f : fields)
    if (f.name == name) return f.values;
  throw std::out_of_range("no coarse-grained field " + name);
}

FieldSet coarse_grain(const Snapshot& snapshot, const SamplingGrid& grid) {
  Sums sums(grid.size());
  for (auto& c : sums) c.fill(0.0);
  add_grains(snapshot.grains, grid, sums);
  add_contacts(snapshot.contacts, grid, sums);
  return derive(sums);
}

}  // namespace iwb::coarse_graining
