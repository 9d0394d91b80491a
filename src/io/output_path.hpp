#pragma once
// Where a command writes (issue 15, finding 6): the destination is checked before anything runs,
// and output that spans several files is built beside its destination and put in place whole, so
// that a failure leaves neither half of it nor a temporary file behind.
#include <filesystem>
#include <string>
#include <vector>

namespace iwb::io {

// Refuses (InputError naming the option and the path) a file destination that is an existing
// directory or lies under an existing file.
void require_file_destination(const std::filesystem::path& file, const std::string& option);

// A directory built under a temporary sibling (<final>.tmp<pid>), whose files are moved into
// `final` and entered in its ledger (output_directory.hpp) when committed. commit() replaces the
// files an earlier commit put there (a report's figures; a file the workbench did not write is
// kept, and one in the way of a new file refuses the commit); commit_into() adds them, replacing
// same-named ones (a directory the user named, which may hold other things). Not committed, the
// sibling is removed: the files of one result appear together or not at all. `kind` names the
// ledger of a `final` that has none.
class StagedDirectory {
 public:
  explicit StagedDirectory(std::filesystem::path final, std::string kind = "staged-output");
  StagedDirectory(const StagedDirectory&) = delete;
  StagedDirectory& operator=(const StagedDirectory&) = delete;
  ~StagedDirectory();
  const std::filesystem::path& path() const { return staging_; }  // write here
  const std::filesystem::path& final_path() const { return final_; }
  void commit();
  void commit_into();

 private:
  std::vector<std::string> staged_files() const;  // relative to staging_
  void move_in(const std::vector<std::string>& files);

  std::filesystem::path final_, staging_;
  std::string kind_;
  bool committed_ = false;
};

}  // namespace iwb::io
