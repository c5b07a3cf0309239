// hypergas/analysis/output.hpp -- atomic CSV and JSON files.
//
// Every file is written to a temporary name in the destination folder and renamed over the
// destination when complete (rename(2) is atomic within one file system), so a reader sees
// the old file or the whole new one, never a partial file; on failure the temporary is
// removed and the destination is untouched.
#pragma once

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace hypergas::analysis {

/// Writes `path` atomically with the text that `write` puts into the stream. Throws
/// InvalidInput naming the path if its folder does not exist or is not writable, and
/// re-throws whatever `write` throws (in both cases no file is left behind).
void write_file_atomic(const std::string& path, const std::function<void(std::ostream&)>& write);

/// A CSV file: a header line of `columns` joined by commas, then one line per row (each
/// row exactly columns.size() values, 17 significant digits; a value that is not finite is
/// written as an empty field, the CSV mark of a missing value: "undefined here", such as the
/// temperature of an absent species or a threshold never reached).
void write_csv(const std::string& path, const std::vector<std::string>& columns,
               const std::vector<std::vector<double>>& rows);

/// A JSON value of a summary field.
using JsonValue = std::variant<bool, std::int64_t, std::uint64_t, double, std::string>;
/// An ordered list of (key, value) pairs: one flat JSON object.
using JsonObject = std::vector<std::pair<std::string, JsonValue>>;

/// The object on one line, keys in the given order; non-finite doubles become null.
std::string to_json(const JsonObject& fields);

/// Writes to_json(fields) and a newline to `path` atomically (summary.json).
void write_json(const std::string& path, const JsonObject& fields);

}  // namespace hypergas::analysis
