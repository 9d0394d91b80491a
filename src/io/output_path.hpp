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

// A directory built under a temporary sibling (<final>.tmp<pid>): commit() renames it to `final`,
// replacing an earlier `final` whole (a directory that is all ours, such as a report's figures);
// commit_into() moves its entries into `final`, replacing same-named ones and keeping the rest (a
// directory the user named, which may hold other things). Not committed, the sibling is removed:
// the files of one result appear together or not at all.
class StagedDirectory {
 public:
  explicit StagedDirectory(std::filesystem::path final);
  StagedDirectory(const StagedDirectory&) = delete;
  StagedDirectory& operator=(const StagedDirectory&) = delete;
  ~StagedDirectory();
  const std::filesystem::path& path() const { return staging_; }  // write here
  const std::filesystem::path& final_path() const { return final_; }
  void commit();
  void commit_into();

 private:
  std::filesystem::path final_, staging_;
  bool committed_ = false;
};

}  // namespace iwb::io
