// sim/output_dir.cpp -- staging folder, commit by rename, cleanup on failure.
#include "output_dir.hpp"

#include <algorithm>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

#include <fmt/core.h>

#include "hypergas/error.hpp"
#include "outputs/output.hpp"
#include "run_driver.hpp"

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

/// The names listed in `dir`'s manifest (none without one).
std::vector<std::string> read_manifest(const fs::path& dir) {
  std::vector<std::string> names;
  std::ifstream f(dir / OutputDir::manifest);
  for (std::string line; std::getline(f, line);)
    if (!line.empty()) names.push_back(line);
  return names;
}

/// Writes `names` as dir's manifest (through a temporary file and a rename).
void write_manifest(const fs::path& dir, const std::vector<std::string>& names) {
  const fs::path tmp = dir / (std::string(OutputDir::manifest) + ".tmp");
  {
    std::ofstream f(tmp, std::ios::binary);
    for (const std::string& n : names) f << n << '\n';
    if (!f) throw std::runtime_error(fmt::format("cannot write '{}'", tmp.string()));
  }
  fs::rename(tmp, dir / OutputDir::manifest);
}

/// The first entry of `dir` that no commit listed in `owned` wrote, or "".
std::string foreign_entry(const fs::path& dir, const std::vector<std::string>& owned) {
  const std::string manifest = OutputDir::manifest;
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) names.push_back(e.path().filename());
  std::sort(names.begin(), names.end());
  for (const std::string& n : names) {
    // the run's own bookkeeping: its checkpoint (and the checkpoint's temporary file), the
    // files its outputs write as it goes (OutputKind::partial) and the manifest
    if (n == manifest || n == manifest + ".tmp" || n.rfind(Checkpointer::file_name, 0) == 0 ||
        partial_output_file(n))
      continue;
    if (std::find(owned.begin(), owned.end(), n) == owned.end()) return n;
  }
  return {};
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
  previous_ = read_manifest(dir_);
  if (const std::string n = foreign_entry(dir_, previous_); !n.empty()) {
    folder_.unlock();
    throw InvalidInput(fmt::format("output folder '{}' holds '{}', which hypergas did not "
                                   "write there: give a new or empty folder",
                                   dir_.string(), n));
  }
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

std::vector<std::string> OutputDir::staged_names() const {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(staging_))
    if (e.is_regular_file()) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

void OutputDir::commit() {
  // summary.json last: where it is present, every other file of the run is in place (a
  // sweep takes a case folder with a summary.json and no checkpoint as finished).
  std::vector<std::string> names = staged_names();
  std::stable_partition(names.begin(), names.end(),
                        [](const std::string& n) { return n != "summary.json"; });
  std::vector<fs::path> files;
  for (const std::string& n : names) files.push_back(staging_ / n);
  // the manifest lists the old and the new files while both may be present, so a process
  // killed in between leaves a folder the next run accepts
  std::vector<std::string> both = previous_;
  for (const std::string& n : names)
    if (std::find(both.begin(), both.end(), n) == both.end()) both.push_back(n);
  write_manifest(dir_, both);
  committed_.clear();
  const auto move = [&](std::size_t k) {
    fs::rename(files[k], dir_ / names[k]);  // throws filesystem_error on failure
    committed_.push_back(names[k]);
  };
  const bool summary = !names.empty() && names.back() == "summary.json";  // sorted last
  for (std::size_t k = 0; k + (summary ? 1 : 0) < files.size(); ++k) move(k);
  // the previous run's files that this one did not write go before summary.json arrives
  std::error_code ec;
  for (const std::string& n : previous_)
    if (std::find(names.begin(), names.end(), n) == names.end()) fs::remove(dir_ / n, ec);
  write_manifest(dir_, names);
  if (summary) move(files.size() - 1);
  previous_ = names;
  fs::remove_all(staging_, ec);
  done_ = true;
}

}  // namespace hypergas::cli
