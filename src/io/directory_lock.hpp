#pragma once
// One process at a time in a run directory (issue 15): DIR/iwb.lock, held with flock(2), says who
// holds it (PID, host, since when, command). The flock lives as long as the open file does, so a
// crashed holder releases it; the file is inherited by the engines a holder starts, so an engine
// left running by a killed `iwb` still keeps a second one out. A holder that ends normally
// removes the file. A lock file whose flock is free was therefore left by a holder that died: it
// is reported as stale and taken over.
#include <atomic>
#include <filesystem>
#include <optional>
#include <string>

namespace iwb::io {

inline constexpr const char* kLockFileName = "iwb.lock";

struct LockHolder {
  long pid = 0;
  std::string host, since, command;
  // "PID 1234 on host h since 2025-01-01T10:00:00Z (iwb dem run ...)"
  std::string describe() const;
};

class DirectoryLock {
 public:
  // Throws InputError naming the holder if another process holds the lock of `dir`; creates
  // nothing (a check before a command decides whether it may write there at all).
  static void require_free(const std::filesystem::path& dir);
  // Takes the lock of `dir` (created if missing), or throws InputError naming the holder.
  static DirectoryLock take(const std::filesystem::path& dir, const std::string& command);
  // Waits until the lock of `dir` is free (another process is working in it); nothing when
  // *interrupt is set first.
  static std::optional<DirectoryLock> wait(const std::filesystem::path& dir,
                                           const std::string& command,
                                           const std::atomic<bool>* interrupt);

  DirectoryLock(DirectoryLock&& other) noexcept;
  DirectoryLock& operator=(DirectoryLock&& other) noexcept;
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;
  ~DirectoryLock();  // removes the lock file, then releases the flock

  const std::filesystem::path& file() const { return file_; }
  // The dead holder whose lock file this one took over, if any, and a line saying so.
  const std::optional<LockHolder>& stale() const { return stale_; }
  std::string stale_message() const;

 private:
  DirectoryLock(std::filesystem::path file, int fd, std::optional<LockHolder> stale)
      : file_(std::move(file)), fd_(fd), stale_(std::move(stale)) {}
  void release();

  std::filesystem::path file_;
  int fd_ = -1;
  std::optional<LockHolder> stale_;
};

}  // namespace iwb::io
