// sim/output_dir.hpp -- an output folder that receives all of a run's files or none.
//
// Files are written into a hidden staging folder inside the output folder and moved into
// place by `commit()` (one rename per file, atomic on POSIX). If the run fails or is
// interrupted before `commit()`, the destructor removes the staging folder and every
// folder this object created, so nothing partial is left behind.
//
// A folder holds one run. `commit()` records the names it moved in `.hypergas-files` and
// removes the files of the previous commit that this one did not write (a DSMC run into a
// folder that held an EDMD --structure run leaves no rdf.csv behind). A folder holding a
// file that no commit wrote (nor a run's checkpoint) is refused before anything changes.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "locked_dir.hpp"

namespace hypergas::cli {

class OutputDir {
 public:
  /// Creates `dir` (and missing parents), checks that files can be created in it and makes
  /// the staging folder (removing those left by killed runs). Holds a lock on the folder
  /// while it lives (locked_dir.hpp). Throws InvalidInput naming the folder and the reason
  /// otherwise: also when another hypergas process holds the folder, and when it holds a
  /// file that hypergas did not write there.
  explicit OutputDir(std::filesystem::path dir);
  OutputDir(const OutputDir&) = delete;
  OutputDir& operator=(const OutputDir&) = delete;
  /// Without a commit: removes the staging folder and the folders created by the constructor.
  ~OutputDir();

  /// Where file `name` is written before commit (inside the staging folder).
  std::filesystem::path staged(std::string_view name);
  /// The names of the files in the staging folder, sorted.
  std::vector<std::string> staged_names() const;
  /// Writes `content` to the staged file `name` (throws std::runtime_error on I/O failure).
  void write(std::string_view name, std::string_view content);
  /// Moves every file of the staging folder into the output folder, removes the previous
  /// commit's files that this one did not write, and removes staging; summary.json moves
  /// last, so its presence means the others are in place.
  void commit();

  const std::filesystem::path& dir() const { return dir_; }
  const std::filesystem::path& staging() const { return staging_; }
  /// Names of the files moved by the last commit, in order.
  const std::vector<std::string>& committed() const { return committed_; }
  /// The file in which a commit lists the names it wrote.
  static constexpr const char* manifest = ".hypergas-files";

 private:
  std::filesystem::path dir_;
  std::filesystem::path staging_;
  std::vector<std::string> committed_;
  std::vector<std::string> previous_;  // the names the folder's last commit wrote
  bool done_ = false;
  LockedDir folder_;  // the folders we made and the flock on dir_ itself
};

}  // namespace hypergas::cli
