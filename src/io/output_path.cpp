#include "io/output_path.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include "common/errors.hpp"

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

StagedDirectory::StagedDirectory(fs::path final)
    : final_(std::move(final)), staging_(final_.string() + fmt::format(".tmp{}", ::getpid())) {
  fs::remove_all(staging_);  // left by a process of the same id that was killed
  fs::create_directories(staging_);
}

StagedDirectory::~StagedDirectory() {
  std::error_code ignored;
  if (!committed_) fs::remove_all(staging_, ignored);
}

void StagedDirectory::commit() {
  fs::remove_all(final_);
  fs::rename(staging_, final_);
  committed_ = true;
}

void StagedDirectory::commit_into() {
  fs::create_directories(final_);
  for (const auto& entry : fs::directory_iterator(staging_)) {
    const fs::path target = final_ / entry.path().filename();
    if (entry.is_directory()) fs::remove_all(target);  // a file is replaced by the rename itself
    fs::rename(entry.path(), target);
  }
  fs::remove(staging_);
  committed_ = true;
}

}  // namespace iwb::io
