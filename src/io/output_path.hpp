#pragma once
// Where a command writes (issue 15, finding 6): the destination is checked before anything runs,
// and output that spans several files is built beside its destination and put in place whole, so
// that a failure leaves neither half of it nor a temporary file behind.
#include <filesystem>
#include <string>

namespace iwb::io {

// Refuses (InputError naming the option and the path) a file destination that is an existing
// directory or lies under an existing file.
void require_file_destination(const std::filesystem::path& file, const std::string& option);

// A directory built under a temporary sibling (<final>.tmp<pid>) and renamed to `final` by
// commit(), which replaces an earlier `final`; not committed, the sibling is removed.
class StagedDirectory {
 public:
  explicit StagedDirectory(std::filesystem::path final);
  StagedDirectory(const StagedDirectory&) = delete;
  StagedDirectory& operator=(const StagedDirectory&) = delete;
  ~StagedDirectory();
  const std::filesystem::path& path() const { return staging_; }  // write here
  const std::filesystem::path& final_path() const { return final_; }
  void commit();

 private:
  std::filesystem::path final_, staging_;
  bool committed_ = false;
};

}  // namespace iwb::io
