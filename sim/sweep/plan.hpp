// sim/sweep/plan.hpp -- a sweep plan (PLAN.toml) and the cases it makes.
//
// A plan is a TOML file. Its top-level keys are `hypergas run` options in their Python
// spelling (mass_ratio, not --mass-ratio); the table [sweep] holds the swept options, each a
// list of values or a range, and three keys of its own:
//
//   engine = "edmd"                 # fixed options: one value each
//   dim = 3
//   until = 5
//   [sweep]
//   packing = [0.1, 0.2, 0.3]       # a list
//   n = { from = 500, to = 2000, count = 3, scale = "log" }   # a range (see below)
//   replicas = 2                    # each case K times, seeds derived from `seed`
//   plot = "Z"                      # sweep.png: this summary column ...
//   plot_x = "packing"              # ... against this swept option (default: the first)
//
// Ranges: { from = a, to = b, count = k } gives k evenly spaced values from a to b (both
// included; scale = "log" spaces them evenly in log); { from = a, to = b, step = s } gives
// a, a + s, ... up to b (included within 1e-9 of a step). Range values are rounded to 15
// significant digits (0.15, not 0.15000000000000002); integer options take integers only.
//
// The cases are the product of the swept lists, the first swept key varying slowest and the
// replica fastest, numbered from 0 in that order (case ids "0000", "0001", ...). Replica r of
// a case runs with seed studies::replica_seed(seed, r), the rule of `run --replicas`, so
// replica 0 keeps the plan's seed. Every case is validated as `hypergas run` validates its
// options (options/table.hpp) before anything runs: one bad case, a duplicate case or an
// unknown key throws InvalidInput naming it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "hypergas/options/table.hpp"

namespace hypergas::cli::sweep {

/// One swept option: its table entry and its values as command-line text.
struct Swept {
  const options::Option* option = nullptr;
  std::vector<std::string> values;
};

/// A parsed plan: the fixed options (as command-line text, in file order), the swept ones
/// (in file order), the replicas and the plot.
struct Plan {
  std::vector<std::pair<const options::Option*, std::string>> fixed;
  std::vector<Swept> swept;
  int replicas = 1;
  std::string plot_y;  ///< a summary column, or "" for no plot
  std::string plot_x;  ///< a swept option (Python spelling), or "" for the first
};

/// One run of the sweep.
struct Case {
  std::string id;                   ///< "0003": the folder cases/<id> and the csv's `case`
  std::size_t group = 0;            ///< index of its combination of swept values
  int replica = 0;                  ///< 0 .. replicas-1
  std::vector<std::string> values;  ///< its swept values, as Plan::swept
  options::RunOptions options;      ///< validated; out = DIR/cases/<id>
  std::string label;                ///< "packing=0.3 replica=1", for messages
};

/// Parses the text of a plan (`name` is the file, for messages). Throws InvalidInput for TOML
/// errors (with line and column), unknown keys, values of the wrong type and bad ranges.
Plan parse_plan(const std::string& text, const std::string& name);

/// Every case of `plan`, validated, writing under `dir`. Throws InvalidInput naming the
/// first bad case (its id and values) or the first duplicate (two cases with the same
/// options). With no checkpoint option in the plan, cases that can checkpoint get
/// --checkpoint-wall 60s, so that a killed sweep resumes them from at most a minute back.
std::vector<Case> make_cases(const Plan& plan, const std::filesystem::path& dir);

/// The width of case and group ids for `count` of them: 4, or more digits if needed.
int id_width(std::size_t count);

}  // namespace hypergas::cli::sweep
