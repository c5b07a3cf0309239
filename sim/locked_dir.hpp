// sim/locked_dir.hpp -- a folder created if missing and locked against a second hypergas
// process: what a run's output folder (output_dir.hpp) and a sweep's folder
// (sweep_command.cpp) share.
//
// open() creates the folder and its missing parents (remembering exactly those), checks that
// it is a folder and takes an flock on the folder itself (no file to leave behind; the
// kernel drops the lock when the process ends, however it ends). Each failure removes the
// folders it created and throws InvalidInput in the owner's words.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace hypergas::cli {

class LockedDir {
 public:
  /// What open() could not do.
  enum class Failure { cannot_create, not_a_folder, busy, cannot_open };
  /// The owner's message for a failure of `dir`; for cannot_create `missing` is the folder
  /// that could not be made and `why` the reason.
  using Wording = std::string (*)(Failure f, const std::filesystem::path& dir,
                                  const std::filesystem::path& missing, const std::string& why);

  LockedDir() = default;
  LockedDir(const LockedDir&) = delete;
  LockedDir& operator=(const LockedDir&) = delete;
  /// Drops the lock; the folders created stay (remove_created removes them).
  ~LockedDir() { unlock(); }

  /// Creates `dir` (and missing parents), checks that it is a folder and locks it. Throws
  /// InvalidInput(words(...)) otherwise, after removing the folders it created; a folder
  /// held by another process is Failure::busy.
  void open(const std::filesystem::path& dir, Wording words);
  /// Drops the lock (nothing if not held).
  void unlock();
  /// Removes the folders open() created (innermost first, only if empty: never a user's
  /// file).
  void remove_created();

 private:
  std::vector<std::filesystem::path> created_;  // folders we made, outermost first
  int fd_ = -1;  // flock held on the folder itself: one process per folder
};

}  // namespace hypergas::cli
