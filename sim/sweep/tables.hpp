// sim/sweep/tables.hpp -- DIR/sweep.csv, DIR/groups.csv and DIR/sweep.png from the cases'
// summary.json files.
//
// sweep.csv has one row per finished case, in case order: `case`, the swept options (a
// swept seed as `plan_seed`), then `replica` and `seed` (the case's own), then the summary's fields (the union over the cases, in order of
// first appearance; numbers verbatim from summary.json, null as an empty field). Fields that
// measure the process rather than the physics (wall_s, collisions_per_s, engine_s,
// analysis_s, output_s, checkpoints, resumes, peak_rss_bytes_per_particle) are left out, so
// that the file depends on the plan alone: the same for any number of ranks, for a sweep
// killed and resumed, for any machine load. groups.csv (plans with replicas > 1) has one
// row per group of replicas: `group`, the swept options, `replicas` (finished), the numeric
// fields with one value in every group's replicas (the fixed options and what follows from
// them: dim, n, time, ...) once under their own names, and for each other numeric field its
// mean and standard error (`_mean`, `_se`; se empty below 2 replicas).
// Both are written atomically (a temporary file renamed over the old one).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "plan.hpp"

namespace hypergas::cli::sweep {

/// A flat JSON object's fields as their JSON text ("0.25", "\"hs\"", "null", "true").
using Fields = std::vector<std::pair<std::string, std::string>>;
/// Reads a one-level JSON object (summary.json); throws std::runtime_error naming the file.
Fields read_summary(const std::filesystem::path& file);

/// The keys of `summary` that sweep.csv holds (all but the process measures): what a plan's
/// plot may name.
std::vector<std::string> table_keys(const std::vector<std::string>& summary_keys);

class Tables {
 public:
  Tables(const Plan& plan, const std::vector<Case>& cases, std::filesystem::path dir);
  /// Records case i as finished (reads its summary.json).
  void add(std::size_t i);
  bool finished(std::size_t i) const { return bool(rows_[i]); }
  /// Writes sweep.csv (and groups.csv) from the finished cases.
  void write() const;
  /// Writes sweep.png with gnuplot, if the plan asks for it; false (with a warning on
  /// stderr) if the column is missing or gnuplot is absent.
  bool plot() const;

 private:
  std::vector<std::string> fields() const;  ///< the summary columns, union order
  const Plan& plan_;
  const std::vector<Case>& cases_;
  std::filesystem::path dir_;
  std::vector<std::optional<Fields>> rows_;
};

}  // namespace hypergas::cli::sweep
