#pragma once
// Runs an external program (the DEM engines), handing each line of its merged stdout/stderr to a
// callback as it arrives, so progress and failures are seen live. The callback can ask to stop
// the program; an interrupt flag does the same. The whole process group is terminated, so MPI
// ranks go with their launcher.
#include <atomic>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace iwb {

struct ProcessResult {
  int exit_code = -1;       // -1 if it did not exit normally
  bool stopped = false;     // stopped by the callback or the interrupt flag
  std::string signal_name;  // if it died by a signal
};

// on_line returns false to stop the program.
ProcessResult run_process(const std::vector<std::string>& argv, const std::filesystem::path& cwd,
                          const std::function<bool(const std::string&)>& on_line,
                          const std::atomic<bool>* interrupt = nullptr);

}  // namespace iwb
