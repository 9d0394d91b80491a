#pragma once
// A LIGGGHTS shear stage that survives being stopped. The stage writes a checkpoint (a restart,
// written aside and renamed) every `checkpoint_every` steps; a run resumed after a crash or the end
// of a session (`iwb dem run --resume`) starts the stage again from its last checkpoint instead of
// from the consolidated specimen, and appends to the outputs the stopped attempt left:
// - timeseries.raw: rows from the stopped attempt after the checkpoint are superseded by the
//   resumed rows of the same time (contract_outputs.hpp reads a time that goes back as "later
//   wins");
// - profiles: each resumed attempt writes its own file (fix ave/spatial truncates the one it
//   opens), read in order, a later block replacing an earlier one of the same step;
// - snapshots: named by step, the resumed ones overwrite the stopped attempt's.
// A checkpoint is used only for the stage that wrote it: the shear input rendered now and the
// consolidated specimen's record must be those it started from (the basis), otherwise the stage
// starts afresh.
//
// Measured on the cyclic smoke scene (400 grains), resumed at u_x = +A: the first row after the
// checkpoint differs from the uninterrupted run's by 0.0002 % in sigma_n and 0.016 % in tau; the
// rows then diverge as two realisations do (granular pair styles do not restart bit for bit:
// LIGGGHTS's read_restart documentation), within 0.2 % of sigma_n over the next cycles. A wall mesh
// that were not restored would have jumped tau by its whole value.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/template.hpp"
#include "dem/scene/numerics.hpp"

namespace iwb::dem {

// The checkpoint and the record of where the shear started, in the work directory.
inline constexpr const char* kShearCheckpoint = "shear_checkpoint.restart";
inline constexpr const char* kShearStartRecord = "shear_start.facts";

// Steps between checkpoints: about 1/50 of the shear, a divisor of the profiles' period so that
// every checkpoint lies at least one sampling window before the next profile block (a fix
// ave/spatial resumed inside its window skips that block), and never fewer than 1000 steps.
long checkpoint_every(const Numerics& n);

// Where the stopped attempt's shear started: the step and plate height after the relaxation and
// the facts measured then (stress x volume of the grains), as the fresh attempt recorded them.
struct ShearStart {
  long step0 = 0;
  double z0_m = 0.0;
  nlohmann::json facts;
};

// What a shear stage starts from: the checkpoint when it is usable for `basis` (the rendered
// fresh input and the consolidated restart's record), or nothing (then the stage starts afresh).
std::optional<ShearStart> usable_checkpoint(const std::filesystem::path& work,
                                            const std::string& basis);

// Starts afresh: removes an earlier attempt's checkpoint, start record and resumed profiles, and
// records `basis` for a later resume.
void begin_fresh_shear(const std::filesystem::path& work, const std::string& basis);

// Before a resumed attempt: cuts a row the stopped attempt left half written (no newline) off
// timeseries.raw, so that the resumed rows start on a line of their own.
void prepare_resumed_shear(const std::filesystem::path& work);

// The shear template's values that differ between a fresh and a resumed attempt: the restart it
// reads, the relaxation (or the recorded plate height), the first rows, the profile file, the
// snapshots' first frame, where the run starts (`entry`, for the input's header).
TemplateValues shear_entry_values(const Numerics& n, const std::optional<ShearStart>& resumed,
                                  const std::filesystem::path& work);

// The profile files of the stage in the order they were written (profiles.raw, then one per
// resumed attempt).
std::vector<std::filesystem::path> shear_profile_files(const std::filesystem::path& work);

}  // namespace iwb::dem
