#include "common/subprocess.hpp"

#include <fcntl.h>
#include <fmt/core.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstring>
#include <stdexcept>

namespace iwb {

namespace {
void stop_group(pid_t pid) {
  ::kill(-pid, SIGTERM);
  for (int i = 0; i < 50; ++i) {  // up to 5 s to exit cleanly, then kill
    if (::waitpid(pid, nullptr, WNOHANG) == pid) return;
    ::usleep(100000);
  }
  ::kill(-pid, SIGKILL);
}
}  // namespace

ProcessResult run_process(const std::vector<std::string>& argv, const std::filesystem::path& cwd,
                          const std::function<bool(const std::string&)>& on_line,
                          const std::atomic<bool>* interrupt) {
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error(fmt::format("pipe: {}", std::strerror(errno)));
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error(fmt::format("fork: {}", std::strerror(errno)));
  if (pid == 0) {
    ::setpgid(0, 0);
    ::dup2(fds[1], STDOUT_FILENO);
    ::dup2(fds[1], STDERR_FILENO);
    ::close(fds[0]);
    ::close(fds[1]);
    if (::chdir(cwd.c_str()) != 0) _exit(126);
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    ::execvp(args[0], args.data());
    dprintf(STDERR_FILENO, "cannot start %s: %s\n", args[0], std::strerror(errno));
    _exit(127);
  }
  ::setpgid(pid, pid);
  ::close(fds[1]);
  ProcessResult result;
  std::string buffer;
  char chunk[4096];
  bool open = true;
  while (open) {
    pollfd p{fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, 200);
    if (interrupt != nullptr && interrupt->load()) {
      result.stopped = true;
      break;
    }
    if (ready <= 0) continue;
    const ssize_t n = ::read(fds[0], chunk, sizeof chunk);
    if (n <= 0) break;
    buffer.append(chunk, std::size_t(n));
    for (auto nl = buffer.find('\n'); nl != std::string::npos; nl = buffer.find('\n')) {
      const std::string line = buffer.substr(0, nl);
      buffer.erase(0, nl + 1);
      if (!on_line(line)) {
        result.stopped = true;
        open = false;
        break;
      }
    }
  }
  if (!buffer.empty() && !result.stopped) on_line(buffer);
  ::close(fds[0]);
  if (result.stopped) {
    stop_group(pid);
    return result;
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) result.signal_name = strsignal(WTERMSIG(status));
  return result;
}

}  // namespace iwb
