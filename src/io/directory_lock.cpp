#include "io/directory_lock.hpp"

#include <fcntl.h>
#include <fmt/core.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <nlohmann/json.hpp>
#include <thread>
#include <variant>

#include "common/errors.hpp"
#include "io/run_directory.hpp"

namespace iwb::io {

namespace fs = std::filesystem;

namespace {

// How often a waiting process tries the lock again.
constexpr auto kWaitPoll = std::chrono::milliseconds(200);

std::string this_host() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "?";
  return name;
}

std::string read_fd(int fd) {
  std::string text;
  char buffer[4096];
  for (off_t at = 0;;) {
    const ssize_t n = ::pread(fd, buffer, sizeof buffer, at);
    if (n <= 0) break;
    text.append(buffer, std::size_t(n));
    at += n;
  }
  return text;
}

// The holder a lock file names; a file being written or not ours reads as an unknown holder.
std::optional<LockHolder> holder_in(const std::string& text) {
  if (text.empty()) return std::nullopt;
  LockHolder h;
  try {
    const auto j = nlohmann::json::parse(text);
    h = {j.value("pid", 0L), j.value("host", std::string("?")), j.value("since", std::string("?")),
         j.value("command", std::string())};
  } catch (const nlohmann::json::exception&) {
    h.host = h.since = "?";
  }
  return h;
}

bool same_file(int fd, const fs::path& path) {
  struct stat open_file {
  }, at_path{};
  if (::fstat(fd, &open_file) != 0 || ::stat(path.c_str(), &at_path) != 0) return false;
  return open_file.st_dev == at_path.st_dev && open_file.st_ino == at_path.st_ino;
}

void write_holder(int fd, const fs::path& file, const std::string& command) {
  const std::string text = nlohmann::json{{"pid", long(::getpid())},
                                          {"host", this_host()},
                                          {"since", utc_timestamp()},
                                          {"command", command}}
                               .dump(2) +
                           "\n";
  if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, text.data(), text.size(), 0) != ssize_t(text.size()))
    throw std::runtime_error(
        fmt::format("{}: cannot write the lock file: {}", file.string(), std::strerror(errno)));
}

struct Busy {
  std::optional<LockHolder> holder;
};

// One attempt. The file is opened afresh each time: a holder that ends removes it before it lets
// go, and a lock on the removed file would guard nothing.
std::variant<int, Busy> try_lock(const fs::path& file) {
  for (;;) {
    // Not O_CLOEXEC: the engines inherit the lock (see the header).
    const int fd = ::open(file.c_str(), O_RDWR | O_CREAT, 0644);
    if (fd <
        0)  // the directory is not writable (permissions, a read-only file system): the input's
      throw InputError(
          fmt::format("{}: cannot create the lock file ({}); choose a directory you can write to",
                      file.string(), std::strerror(errno)));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      Busy busy{holder_in(read_fd(fd))};
      ::close(fd);
      if (error == EWOULDBLOCK) return busy;
      throw std::runtime_error(fmt::format("{}: flock: {}", file.string(), std::strerror(error)));
    }
    if (same_file(fd, file)) return fd;
    ::close(fd);  // removed (or replaced) by its last holder between our open and our flock
  }
}

// The refusal of a directory another iwb holds.
InputError in_use(const fs::path& dir, const Busy& busy) {
  std::string who =
      busy.holder ? busy.holder->describe() : "a process that has not yet said who it is";
  if (busy.holder && busy.holder->host == this_host() && busy.holder->pid > 0 &&
      ::kill(pid_t(busy.holder->pid), 0) != 0 && errno == ESRCH)
    who += "; that process has ended, an engine it started still works there";
  return InputError(
      fmt::format("{}: in use by another iwb, {}; wait for it to end or choose another directory",
                  dir.string(), who));
}

}  // namespace

void DirectoryLock::require_free(const fs::path& dir) {
  const int fd = ::open((dir / kLockFileName).c_str(), O_RDONLY);
  if (fd < 0) return;  // no lock file: nobody holds it
  const bool held = ::flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  const Busy busy{held ? holder_in(read_fd(fd)) : std::nullopt};
  ::close(fd);
  const bool by_us = busy.holder && busy.holder->pid == long(::getpid()) &&
                     busy.holder->host == this_host();  // a command checking its own directory
  if (held && !by_us) throw in_use(dir, busy);
}

std::string LockHolder::describe() const {
  std::string s = fmt::format("PID {} on host {} since {}", pid, host, since);
  if (!command.empty()) s += fmt::format(" ({})", command);
  return s;
}

DirectoryLock DirectoryLock::take(const fs::path& dir, const std::string& command) {
  fs::create_directories(dir);
  const fs::path file = dir / kLockFileName;
  auto attempt = try_lock(file);
  if (auto* busy = std::get_if<Busy>(&attempt)) throw in_use(dir, *busy);
  const int fd = std::get<int>(attempt);
  std::optional<LockHolder> stale = holder_in(read_fd(fd));
  write_holder(fd, file, command);
  return DirectoryLock(file, fd, std::move(stale));
}

std::optional<DirectoryLock> DirectoryLock::wait(const fs::path& dir, const std::string& command,
                                                 const std::atomic<bool>* interrupt) {
  for (;;) {
    try {
      return take(dir, command);
    } catch (const InputError&) {
      if (interrupt && interrupt->load()) return std::nullopt;
      std::this_thread::sleep_for(kWaitPoll);
    }
  }
}

DirectoryLock::DirectoryLock(DirectoryLock&& other) noexcept
    : file_(std::move(other.file_)), fd_(other.fd_), stale_(std::move(other.stale_)) {
  other.fd_ = -1;
}

DirectoryLock& DirectoryLock::operator=(DirectoryLock&& other) noexcept {
  if (this != &other) {
    release();
    file_ = std::move(other.file_);
    fd_ = other.fd_;
    stale_ = std::move(other.stale_);
    other.fd_ = -1;
  }
  return *this;
}

DirectoryLock::~DirectoryLock() {
  release();
}

void DirectoryLock::release() {
  if (fd_ < 0) return;
  ::unlink(file_.c_str());  // first: whoever opens the path from now on gets a new file
  ::close(fd_);
  fd_ = -1;
}

std::string DirectoryLock::stale_message() const {
  if (!stale_) return "";
  return fmt::format("{}: stale lock of {} (that process is gone): taken over",
                     file_.parent_path().string(), stale_->describe());
}

}  // namespace iwb::io
