// One process at a time in a run directory (issue 15, item 2): a real second `iwb` is refused with
// exit 2 naming the holder and touches nothing; a lock left by a process that died is taken over
// and reported as stale; a holder that ends removes its lock file.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>

#include "common/errors.hpp"
#include "common/subprocess.hpp"
#include "io/directory_lock.hpp"
#include "io/run_directory.hpp"

using namespace iwb;
namespace fs = std::filesystem;

namespace {

struct Command {
  int exit_code;
  std::string output;
};

Command iwb_command(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {IWB_BINARY};
  argv.insert(argv.end(), args.begin(), args.end());
  Command c{-1, ""};
  c.exit_code = run_process(argv, fs::current_path(), [&c](const std::string& l) {
                  c.output += l + "\n";
                  return true;
                }).exit_code;
  return c;
}

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(IWB_TEST_RUNS_DIR) / "io" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace

TEST_CASE(
    "a second iwb in a locked run directory is refused with exit 2, the holder named, nothing "
    "touched",
    "[io][lock]") {
  const fs::path dir = fresh_dir("locked_run");
  const std::string manifest = "{\"status\": \"interrupted at stage shear\"}\n";
  io::write_atomically(dir / "manifest.json", manifest);
  const auto lock = io::DirectoryLock::take(dir, "the test holding it");
  const std::string pid = fmt::format("PID {}", ::getpid());
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"dem", "run", "data/scenes/smoke.toml", "--engine", "liggghts",
                                 "--out", dir.string(), "--resume"},
        {"dem", "run", "data/scenes/smoke.toml", "--engine", "liggghts", "--out", dir.string(),
         "--force"},
        {"dem", "summary", dir.string()}}) {
    INFO(fmt::format("iwb {}", fmt::join(args, " ")));
    const Command c = iwb_command(args);
    CHECK(c.exit_code == 2);
    CHECK_THAT(c.output, Catch::Contains(dir.string() + ": in use by another iwb") &&
                             Catch::Contains(pid) && Catch::Contains("since ") &&
                             Catch::Contains("the test holding it"));
    CHECK(io::read_file(dir / "manifest.json") == manifest);  // --force did not empty it
    CHECK_FALSE(fs::exists(dir / "liggghts"));
  }
}

TEST_CASE(
    "a lock left by a process that died is taken over and reported as stale, a released one is "
    "gone",
    "[io][lock]") {
  const fs::path dir = fresh_dir("stale_lock");
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {  // takes the lock and dies without releasing it, as a killed iwb would
    auto lock = io::DirectoryLock::take(dir, "a run that crashed");
    ::_exit(0);
  }
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  REQUIRE(fs::exists(dir / io::kLockFileName));
  {
    const auto lock = io::DirectoryLock::take(dir, "the test");
    REQUIRE(lock.stale());
    CHECK(lock.stale()->pid == child);
    CHECK_THAT(lock.stale_message(), Catch::Contains(fmt::format("stale lock of PID {}", child)) &&
                                         Catch::Contains("a run that crashed") &&
                                         Catch::Contains("taken over"));
    // while held: refused, in this process too
    CHECK_THROWS_AS(io::DirectoryLock::take(dir, "again"), InputError);
  }
  CHECK_FALSE(fs::exists(dir / io::kLockFileName));  // released: no lock file left behind
  const auto again = io::DirectoryLock::take(dir, "the test");
  CHECK_FALSE(again.stale());
}
