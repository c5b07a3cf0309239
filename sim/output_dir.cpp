// sim/output_dir.cpp -- staging folder, commit by rename, cleanup on failure.
#include "output_dir.hpp"

#include <algorithm>
#include <fstream>
#include <stdexcept>
#include <system_error>
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

std::string not_writable(const fs::path& dir, const std::string& why) {
  return fmt::format("output folder '{}' is not writable: {}", dir.string(), why);
}

[[noreturn]] void unwritable(const fs::path& dir, const std::string& why) {
  throw InvalidInput(not_writable(dir, why));
}

/// The output folder's words for LockedDir's failures.
std::string words(LockedDir::Failure f, const fs::path& dir, const fs::path& missing,
                  const std::string& why) {
  switch (f) {
    case LockedDir::Failure::cannot_create:
      return not_writable(dir, fmt::format("cannot create '{}' ({})", missing.string(), why));
    case LockedDir::Failure::not_a_folder:
      return not_writable(dir, "it exists and is not a folder");
    case LockedDir::Failure::busy:
      return fmt::format("output folder '{}' is in use by another hypergas process",
                         dir.string());
    default:
      return not_writable(dir, "it cannot be opened");
  }
}
}  // namespace

OutputDir::OutputDir(fs::path dir) : dir_(std::move(dir)) {
  if (dir_.empty()) throw InvalidInput("output folder name is empty");
  // One process per output folder: a second run or resume on the same folder would write
  // the same checkpoint and files.
  folder_.open(dir_, words);
  remove_stale_staging(dir_);
  staging_ = dir_ / fmt::format(".hypergas-staging-{}", ::getpid());
  std::error_code ec;
  if (!fs::create_directory(staging_, ec) || ec || ::access(staging_.c_str(), W_OK) != 0) {
    folder_.unlock();
    fs::remove_all(staging_, ec);
    folder_.remove_created();
    unwritable(dir_, ec ? ec.message() : "permission denied");
  }
}

OutputDir::~OutputDir() {
  std::error_code ec;
  fs::remove_all(staging_, ec);
  folder_.unlock();
  if (!done_) folder_.remove_created();
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
