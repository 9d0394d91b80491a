#pragma once
// Element-test paths as data: a list of segments, each a number of equal increments of shear
// strain with one normal-control row per increment. Monotonic, staged, cyclic and oedometric
// paths are built from it; the driver only walks segments.
#include <array>
#include <string>
#include <vector>

#include "driver/control.hpp"
#include "models/model.hpp"

namespace iwb::driver {

struct PathSegment {
  std::string label;
  double gamma_x = 0.0;  // engineering shear strain over the whole segment
  double gamma_y = 0.0;
  NormalControlRow row;  // per increment
  int increments = 1;
  // Changes of the external variables over the whole segment (dT in K, ds in kPa, dt in s), in
  // equal parts per increment; only models that read a variable may be given a change of it.
  std::array<double, models::kExternalSlots> external{};
  int cycle = 0;                  // 1-based cycle it belongs to; 0 outside cyclic paths
  bool ends_at_reversal = false;  // its end is a shear reversal (+A or -A) of a cycle
};

using Path = std::vector<PathSegment>;

enum class ShearDirection { kX, kY };

struct StagedStep {
  double at_gamma;     // shear strain at which sigma_n changes
  double sigma_n_kPa;  // new normal stress
};

struct CyclicStage {
  int from_cycle;      // sigma_n is ramped to the new value before this cycle (1-based)
  double sigma_n_kPa;  // new normal stress
};

// Shear to `gamma` under `bc`.
Path monotonic_path(const BoundaryCondition& bc, double gamma, ShearDirection dir, int increments);
// `cycles` cycles 0 -> +A -> -A -> 0 under `bc`, `per_quarter` increments per quarter cycle.
Path cyclic_path(const BoundaryCondition& bc, double amplitude, int cycles, ShearDirection dir,
                 int per_quarter);
// The same under CNL from sigma_n0 with the normal stress staged between cycles: before each
// stage's cycle, a ramp of `step_increments` pure normal-stress increments at zero shear.
Path staged_cyclic_path(double sigma_n0, double amplitude, int cycles,
                        const std::vector<CyclicStage>& stages, ShearDirection dir, int per_quarter,
                        int step_increments);
// CNL shear to `gamma` with sigma_n stepped to new values at given strains; each step is a
// ramp of `step_increments` pure normal-stress increments at fixed shear.
Path staged_path(double sigma_n0, double gamma, const std::vector<StagedStep>& steps,
                 ShearDirection dir, int increments, int step_increments);
// Normal loading without shear from sigma_from to sigma_to (oedometric for the interface).
Path oedometric_path(double sigma_from, double sigma_to, int increments);

// How an external variable (temperature, suction, time) moves over a stage: held, ramped by a
// change, or cycled about its value at the stage's start, 0 -> +A -> 0 -> -A -> 0 per cycle.
struct ExternalPath {
  enum class Kind { kHold, kRamp, kCycle };
  Kind kind = Kind::kHold;
  double change = 0.0;     // kRamp: over the whole stage
  double amplitude = 0.0;  // kCycle
  int cycles = 0;
};

// One stage of a test given as data (a test file's [[path.stage]]): a shear strain in the
// path's direction, the normal control (with a change of sigma_n for CNL), the paths of the
// external variables, all spread evenly over `increments`.
struct Stage {
  std::string label;
  int increments = 1;
  double gamma = 0.0;
  BoundaryCondition bc;
  double d_sigma_n = 0.0;  // CNL only
  std::array<ExternalPath, models::kExternalSlots> external{};
};

// The segments of `stages`. A stage that cycles an external variable becomes 4 x cycles segments
// of increments / (4 x cycles) each (InputError unless that divides); one that does not becomes
// one.
Path stage_path(const std::vector<Stage>& stages, ShearDirection dir);

}  // namespace iwb::driver
