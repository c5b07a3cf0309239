// sim/locked_dir.cpp -- create the missing folders, flock the folder, undo on failure.
#include "locked_dir.hpp"

#include <algorithm>
#include <system_error>
#include <cerrno>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include "hypergas/error.hpp"

namespace fs = std::filesystem;

namespace hypergas::cli {

void LockedDir::open(const fs::path& dir, Wording words) {
  std::error_code ec;
  // Find the missing ancestors so that exactly those can be removed on failure.
  std::vector<fs::path> missing;
  for (fs::path p = fs::absolute(dir, ec); !p.empty(); p = p.parent_path()) {
    if (fs::exists(fs::symlink_status(p, ec)) || p == p.parent_path()) break;
    missing.push_back(p);
  }
  std::reverse(missing.begin(), missing.end());
  for (const fs::path& p : missing) {
    if (!fs::create_directory(p, ec) || ec) {
      remove_created();
      throw InvalidInput(words(Failure::cannot_create, dir, p, ec ? ec.message() : "exists"));
    }
    created_.push_back(p);
  }
  if (!fs::is_directory(dir, ec)) {
    remove_created();
    throw InvalidInput(words(Failure::not_a_folder, dir, {}, {}));
  }
  // One process per folder: a second run or resume on the same output folder would write
  // the same checkpoint and files, a second sweep the same cases.
  fd_ = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ < 0 || ::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const bool busy = fd_ >= 0 && errno == EWOULDBLOCK;
    unlock();
    remove_created();
    throw InvalidInput(words(busy ? Failure::busy : Failure::cannot_open, dir, {}, {}));
  }
}

void LockedDir::unlock() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

void LockedDir::remove_created() {
  std::error_code ec;
  for (auto it = created_.rbegin(); it != created_.rend(); ++it) fs::remove(*it, ec);
  created_.clear();
}

}  // namespace hypergas::cli
