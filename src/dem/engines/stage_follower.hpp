#pragma once
// Runs one engine stage as a child process and follows its output: both engines' scripts print
// the same IWB_ lines (particle count, consolidation windows, shear progress, stage ends,
// failures, cost; IWB_FACT key value, IWB_ROW table values..., IWB_LEVEL i n sigma_Pa for the
// soil cell), so reading them, logging and turning the process's end into a StageResult is
// one piece of code. An engine adds only what its own output says beyond that (`extra`).
#include <functional>
#include <string>
#include <vector>

#include "dem/engines/engine.hpp"

namespace iwb::dem {

struct EngineCost {
  double loop_seconds = 0.0;    // time the engine spent stepping
  double particle_steps = 0.0;  // particles x steps
};

// Reads an engine-specific line (e.g. LIGGGHTS's "Loop time of ..."); may add to the cost.
using ExtraLineReader =
    std::function<void(const std::vector<std::string>& words, EngineCost& cost)>;

StageResult run_followed_stage(const std::vector<std::string>& command, const std::string& stage,
                               const StageContext& ctx, const ExtraLineReader& extra = {});

}  // namespace iwb::dem
