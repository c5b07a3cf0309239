// sim/output_dir.cpp -- staging folder, commit by rename, cleanup on failure.
#include "output_dir.hpp"

#include <algorithm>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <cerrno>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <fmt/core.h>

#include "hypergas/error.hpp"

namespace fs = std::filesystem;

namespace hypergas::cli {

namespace {
/// Removes staging folders left in `dir` by runs that were killed (SIGKILL leaves no chance
/// to clean up). Called with the folder's lock held, so no live process owns one.
void remove_stale_staging(const fs::path& dir) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.path().filename().string().rfind(".hypergas-staging-", 0) == 0)
      fs::remove_all(e.path(), ec);
}

[[noreturn]] void unwritable(const fs::path& dir, const std::string& why) {
  throw InvalidInput(fmt::format("output folder '{}' is not writable: {}", dir.string(), why));
}
}  // namespace

OutputDir::OutputDir(fs::path dir) : dir_(std::move(dir)) {
  if (dir_.empty()) throw InvalidInput("output folder name is empty");
  std::error_code ec;
  // Find the missing ancestors so that exactly those can be removed on failure.
  std::vector<fs::path> missing;
  for (fs::path p = fs::absolute(dir_, ec); !p.empty(); p = p.parent_path()) {
    if (fs::exists(fs::symlink_status(p, ec)) || p == p.parent_path()) break;
    missing.push_back(p);
  }
  std::reverse(missing.begin(), missing.end());
  for (const fs::path& p : missing) {
    if (!fs::create_directory(p, ec) || ec) {
      remove_created();
      unwritable(dir_, fmt::format("cannot create '{}' ({})", p.string(),
                                   ec ? ec.message() : "exists"));
    }
    created_.push_back(p);
  }
  if (!fs::is_directory(dir_, ec)) unwritable(dir_, "it exists and is not a folder");
  // One process per output folder: a second run or resume on the same folder would write
  // the same checkpoint and files. The lock is on the folder itself (no file to leave
  // behind) and the kernel drops it when the process ends, however it ends.
  dir_fd_ = ::open(dir_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd_ < 0 || ::flock(dir_fd_, LOCK_EX | LOCK_NB) != 0) {
    const bool busy = dir_fd_ >= 0 && errno == EWOULDBLOCK;
    if (dir_fd_ >= 0) ::close(dir_fd_);
    dir_fd_ = -1;
    remove_created();
    if (busy)
      throw InvalidInput(fmt::format("output folder '{}' is in use by another hypergas process",
                                     dir_.string()));
    unwritable(dir_, "it cannot be opened");
  }
  remove_stale_staging(dir_);
  staging_ = dir_ / fmt::format(".hypergas-staging-{}", ::getpid());
  if (!fs::create_directory(staging_, ec) || ec || ::access(staging_.c_str(), W_OK) != 0) {
    ::close(dir_fd_);
    dir_fd_ = -1;
    fs::remove_all(staging_, ec);
    remove_created();
    unwritable(dir_, ec ? ec.message() : "permission denied");
  }
}

OutputDir::~OutputDir() {
  std::error_code ec;
  fs::remove_all(staging_, ec);
  if (dir_fd_ >= 0) ::close(dir_fd_);
  if (!done_) remove_created();
}

void OutputDir::remove_created() {
  // Innermost first, and only if still empty (never a user's file).
  std::error_code ec;
  for (auto it = created_.rbegin(); it != created_.rend(); ++it) fs::remove(*it, ec);
  created_.clear();
}

fs::path OutputDir::staged(std::string_view name) { return staging_ / fs::path(name); }

void OutputDir::write(std::string_view name, std::string_view content) {
  const fs::path p = staged(name);
  std::ofstream f(p, std::ios::binary);
  f.write(content.data(), static_cast<std::streamsize>(content.size()));
  f.close();
  if (!f) throw std::runtime_error(fmt::format("cannot write '{}'", p.string()));
}

void OutputDir::commit() {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(staging_))
    if (e.is_regular_file()) files.push_back(e.path());
  // summary.json last: where it is present, every other file of the run is in place (a
  // sweep takes a case folder with a summary.json and no checkpoint as finished).
  std::sort(files.begin(), files.end(), [](const fs::path& a, const fs::path& b) {
    const bool sa = a.filename() == "summary.json", sb = b.filename() == "summary.json";
    return sa != sb ? sb : a < b;
  });
  committed_.clear();
  for (const fs::path& p : files) {
    fs::rename(p, dir_ / p.filename());  // throws filesystem_error on failure
    committed_.push_back(p.filename().string());
  }
  std::error_code ec;
  fs::remove_all(staging_, ec);
  done_ = true;
}

}  // namespace hypergas::cli
