#pragma once
// One interface stress point on the pile shaft, through the C interface (c_api/iwb_interface.h):
// the shaft's settlement relative to the soil is its shear displacement, and the soil around the
// shaft is a spring of constant normal stiffness K = 4G/D (Boulon & Foray): a local Newton
// iteration on the normal displacement keeps sigma_n = sigma_n,0 + K u_n (dilation raises it).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "iwb_interface.h"
#include "pile/pile_spec.hpp"

namespace iwb::pile {

// The interface model of a pile, made once from the file's [interface] (iwb_material_create).
class ShaftMaterial {
 public:
  explicit ShaftMaterial(const InterfaceSpec& spec, const std::string& where);
  const iwb_material* get() const { return material_.get(); }
  double thickness_mm() const { return thickness_mm_; }
  // The state of a stress point at normal stress sigma_n (kPa), the in-plane stress sigma_v
  // (kPa, for models with one) and the file's other initial inputs.
  std::vector<double> initial_state(double sigma_n, double sigma_v) const;

 private:
  struct Destroy {
    void operator()(iwb_material* m) const { iwb_material_destroy(m); }
  };
  std::unique_ptr<iwb_material, Destroy> material_;
  double thickness_mm_;
  std::map<std::string, double> initial_;
  std::string where_;
};

// The response of a stress point to a shear displacement increment from its committed state.
struct ShaftResponse {
  std::vector<double> state;
  double tau_kPa = 0.0, sigma_n_kPa = 0.0;
  double u_n_mm = 0.0;     // the normal displacement increment (opening positive)
  double stiffness = 0.0;  // d tau / d w at the spring's K, kPa per mm (condensed tangent)
};

class ShaftPoint {
 public:
  ShaftPoint(const ShaftMaterial& m, double sigma_n0, double sigma_v0, double K_kPa_per_mm);
  // From the committed state, the shear increment dw (mm, the pile moving down against the soil).
  // Throws ConvergenceError when the normal Newton iteration or the model fails.
  ShaftResponse trial(double dw_mm) const;
  void commit(const ShaftResponse& r);
  const ShaftResponse& committed() const { return committed_; }

 private:
  const ShaftMaterial* m_;
  double K_;
  ShaftResponse committed_;
};

}  // namespace iwb::pile
