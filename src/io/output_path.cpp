#include "io/output_path.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include "common/errors.hpp"
#include "io/output_directory.hpp"

namespace iwb::io {

namespace fs = std::filesystem;

void require_file_destination(const fs::path& file, const std::string& option) {
  if (fs::is_directory(file))
    throw InputError(fmt::format("{} {}: is a directory; give the name of the file to write",
                                 option, file.string()));
  for (fs::path p = file.parent_path(); !p.empty() && p != p.parent_path(); p = p.parent_path())
    if (fs::exists(p) && !fs::is_directory(p))
      throw InputError(
          fmt::format("{} {}: {} is a file, not a directory", option, file.string(), p.string()));
}

StagedDirectory::StagedDirectory(fs::path final, std::string kind)
    : final_(std::move(final)),
      staging_(final_.string() + fmt::format(".tmp{}", ::getpid())),
      kind_(std::move(kind)) {
  fs::remove_all(staging_);  // left by a process of the same id that was killed
  fs::create_directories(staging_);
}

StagedDirectory::~StagedDirectory() {
  std::error_code ignored;
  if (!committed_) fs::remove_all(staging_, ignored);
}

std::vector<std::string> StagedDirectory::staged_files() const {
  std::vector<std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(staging_))
    if (!e.is_directory()) files.push_back(fs::relative(e.path(), staging_).generic_string());
  return files;
}

void StagedDirectory::move_in(const std::vector<std::string>& files) {
  for (const auto& f : files) {
    const fs::path target = final_ / f;
    fs::create_directories(target.parent_path());
    fs::rename(staging_ / f, target);
  }
  adopt_written_files(final_, kind_, files);
  fs::remove_all(staging_);
  committed_ = true;
}

void StagedDirectory::commit() {
  const auto files = staged_files();
  remove_written_files(final_, files);  // refuses a file of the user's in the way, removing none
  move_in(files);
}

void StagedDirectory::commit_into() {
  const auto files = staged_files();
  fs::create_directories(final_);
  for (const auto& f : files)  // a folder of the user's where a file goes is not removed
    if (fs::is_directory(final_ / f))
      throw InputError(fmt::format("{}: is a directory, where the workbench writes a file",
                                   (final_ / f).string()));
  move_in(files);
}

}  // namespace iwb::io
