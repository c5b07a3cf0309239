// sim/sweep/tables.cpp -- sweep.csv, groups.csv, sweep.png.
#include "tables.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include <fmt/core.h>

#include "hypergas/studies/gnuplot.hpp"

namespace fs = std::filesystem;

namespace hypergas::cli::sweep {

namespace {

/// Summary fields that measure the process, not the physics: never in the tables.
const std::set<std::string> process_fields = {
    "wall_s",      "collisions_per_s", "engine_s",  "analysis_s",
    "output_s",    "checkpoints",      "resumes",   "peak_rss_bytes_per_particle",
    "setup_s"};

/// Decodes a JSON string literal (with its quotes) to its text.
std::string unquote(const std::string& j) {
  std::string s;
  for (std::size_t i = 1; i + 1 < j.size(); ++i) {
    if (j[i] != '\\') {
      s += j[i];
      continue;
    }
    const char e = j[++i];
    switch (e) {
      case 'n': s += '\n'; break;
      case 't': s += '\t'; break;
      case 'r': s += '\r'; break;
      case 'b': s += '\b'; break;
      case 'f': s += '\f'; break;
      case 'u': {  // ASCII only; anything else is kept escaped
        const long c = std::strtol(j.substr(i + 1, 4).c_str(), nullptr, 16);
        if (c > 0 && c < 128) s += static_cast<char>(c);
        else s += "\\u" + j.substr(i + 1, 4);
        i += 4;
        break;
      }
      default: s += e;
    }
  }
  return s;
}

/// Text as a CSV field: quoted (quotes doubled) where it holds a comma, quote or newline.
std::string csv_text(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

/// A JSON value as a CSV field: strings decoded and quoted where needed, null empty.
std::string csv_field(const std::string& json) {
  if (json == "null") return "";
  if (json.empty() || json[0] != '"') return json;
  return csv_text(unquote(json));
}

/// The number a JSON value holds, or nothing (strings, null, booleans).
std::optional<double> number(const std::string& json) {
  if (json.empty() || json == "null" || json == "true" || json == "false" || json[0] == '"')
    return std::nullopt;
  char* end = nullptr;
  const double x = std::strtod(json.c_str(), &end);
  if (end != json.c_str() + json.size() || !std::isfinite(x)) return std::nullopt;
  return x;
}

const std::string* lookup(const Fields& f, const std::string& k) {
  for (const auto& [key, v] : f)
    if (key == k) return &v;
  return nullptr;
}

/// Writes `text` to dir/name through a temporary file and a rename.
void write_atomic(const fs::path& dir, const std::string& name, const std::string& text) {
  const fs::path tmp = dir / ("." + name + ".tmp"), file = dir / name;
  {
    std::ofstream f(tmp, std::ios::binary);
    f << text;
    f.close();
    if (!f) throw std::runtime_error(fmt::format("cannot write '{}'", tmp.string()));
  }
  fs::rename(tmp, file);
}

/// The column of swept option `s`: its Python name, except `seed`, whose column is
/// `plan_seed` (the plan's value; `seed` is the case's own, derived for replicas).
std::string column(const Swept& s) {
  const std::string n = options::python_name(*s.option);
  return n == "seed" ? "plan_seed" : n;
}


}  // namespace

Fields read_summary(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string t = ss.str();
  if (!in && !in.eof()) throw std::runtime_error(fmt::format("cannot read '{}'", file.string()));
  Fields out;
  std::size_t i = 0;
  const auto fail = [&](const char* what) {
    throw std::runtime_error(
        fmt::format("'{}' is not a flat JSON object ({} at byte {})", file.string(), what, i));
  };
  const auto skip_ws = [&] {
    while (i < t.size() && std::isspace(static_cast<unsigned char>(t[i]))) ++i;
  };
  const auto string_end = [&](std::size_t from) {  // index one past the closing quote
    std::size_t j = from + 1;
    while (j < t.size() && t[j] != '"') j += t[j] == '\\' ? 2 : 1;
    if (j >= t.size()) fail("unterminated string");
    return j + 1;
  };
  skip_ws();
  if (i >= t.size() || t[i] != '{') fail("no '{'");
  ++i;
  skip_ws();
  if (i < t.size() && t[i] == '}') return out;
  for (;;) {
    skip_ws();
    if (i >= t.size() || t[i] != '"') fail("no key");
    const std::size_t kend = string_end(i);
    std::string key = unquote(t.substr(i, kend - i));
    i = kend;
    skip_ws();
    if (i >= t.size() || t[i] != ':') fail("no ':'");
    ++i;
    skip_ws();
    std::size_t vend = i;
    if (i < t.size() && t[i] == '"') vend = string_end(i);
    else
      while (vend < t.size() && t[vend] != ',' && t[vend] != '}' &&
             !std::isspace(static_cast<unsigned char>(t[vend])))
        ++vend;
    if (vend == i) fail("no value");
    const std::string v = t.substr(i, vend - i);
    if (v[0] == '{' || v[0] == '[') fail("nested value");
    out.emplace_back(std::move(key), v);
    i = vend;
    skip_ws();
    if (i < t.size() && t[i] == ',') {
      ++i;
      continue;
    }
    if (i < t.size() && t[i] == '}') break;
    fail("no ',' or '}'");
  }
  return out;
}

std::vector<std::string> table_keys(const std::vector<std::string>& summary_keys) {
  std::vector<std::string> out;
  for (const auto& k : summary_keys)
    if (!process_fields.count(k)) out.push_back(k);
  return out;
}

Tables::Tables(const Plan& plan, const std::vector<Case>& cases, fs::path dir)
    : plan_(plan), cases_(cases), dir_(std::move(dir)), rows_(cases.size()) {}

void Tables::add(std::size_t i) {
  rows_[i] = read_summary(cases_[i].options.out / fs::path("summary.json"));
}

std::vector<std::string> Tables::fields() const {
  std::set<std::string> taken = {"case", "replica", "seed", "group", "replicas"};
  for (const Swept& s : plan_.swept) taken.insert(column(s));
  std::vector<std::string> out;
  for (const auto& row : rows_)
    if (row)
      for (const auto& [k, v] : *row)
        if (!process_fields.count(k) && taken.insert(k).second) out.push_back(k);
  return out;
}

void Tables::write() const {
  const std::vector<std::string> cols = fields();
  std::string head = "case";
  for (const Swept& s : plan_.swept) head.append(",").append(column(s));
  head += ",replica,seed";
  std::string csv = head;
  for (const auto& c : cols) csv.append(",").append(c);
  csv += "\n";
  for (std::size_t i = 0; i < cases_.size(); ++i) {
    if (!rows_[i]) continue;
    const Case& c = cases_[i];
    csv += c.id;
    for (const std::string& v : c.values) csv.append(",").append(csv_text(v));
    csv += fmt::format(",{},{}", c.replica, c.options.seed);
    for (const auto& k : cols) {
      const std::string* v = lookup(*rows_[i], k);
      csv.append(",").append(v ? csv_field(*v) : std::string());
    }
    csv += "\n";
  }
  write_atomic(dir_, "sweep.csv", csv);
  if (plan_.replicas < 2) return;

  // groups.csv: the numeric fields (a field that is a number in every finished case)
  std::vector<std::string> numeric;
  for (const auto& k : cols) {
    bool all = true, any = false;
    for (const auto& row : rows_)
      if (row) {
        const std::string* v = lookup(*row, k);
        if (v && *v != "null") {
          any = true;
          all = all && number(*v).has_value();
        }
      }
    if (any && all) numeric.push_back(k);
  }
  // A numeric field with one value (the same text) in all the finished replicas of each
  // group, seen in at least one group of two or more, is a setting or a function of the
  // settings (dim, n, time, packing, ...): one plain column under its own name. The others
  // vary between replicas: <key>_mean, <key>_se.
  std::vector<std::string> fixed, varying;
  for (const auto& k : numeric) {
    bool same = true, seen_two = false;
    for (std::size_t first = 0; first < cases_.size() && same; first += plan_.replicas) {
      const std::string* v0 = nullptr;
      int count = 0;
      for (int r = 0; r < plan_.replicas && same; ++r) {
        if (!rows_[first + r]) continue;
        const std::string* v = lookup(*rows_[first + r], k);
        ++count;
        if (count == 1) v0 = v;
        else same = v && v0 && *v == *v0;
      }
      seen_two = seen_two || count >= 2;
    }
    (same && seen_two ? fixed : varying).push_back(k);
  }
  std::string g = "group";
  for (const Swept& s : plan_.swept) g.append(",").append(column(s));
  g += ",replicas";
  for (const auto& k : fixed) g.append(",").append(k);
  for (const auto& k : varying) g += fmt::format(",{}_mean,{}_se", k, k);
  g += "\n";
  const int width = id_width(cases_.size() / static_cast<std::size_t>(plan_.replicas));
  for (std::size_t first = 0; first < cases_.size(); first += plan_.replicas) {
    int count = 0;
    for (int r = 0; r < plan_.replicas; ++r) count += rows_[first + r] ? 1 : 0;
    if (count == 0) continue;
    const Case& c = cases_[first];
    g += fmt::format("{:0{}}", c.group, width);
    for (const std::string& v : c.values) g.append(",").append(csv_text(v));
    g += fmt::format(",{}", count);
    for (const auto& k : fixed) {
      const std::string* v = nullptr;
      for (int r = 0; r < plan_.replicas && !v; ++r)
        if (rows_[first + r]) v = lookup(*rows_[first + r], k);
      g.append(",").append(v ? csv_field(*v) : std::string());
    }
    for (const auto& k : varying) {
      std::vector<double> xs;
      for (int r = 0; r < plan_.replicas; ++r)
        if (rows_[first + r])
          if (const std::string* v = lookup(*rows_[first + r], k))
            if (auto x = number(*v)) xs.push_back(*x);
      if (xs.empty()) {
        g += ",,";
        continue;
      }
      double mean = 0.0;
      for (double x : xs) mean += x;
      mean /= static_cast<double>(xs.size());
      g += fmt::format(",{}", mean);
      if (xs.size() < 2) {
        g += ",";
        continue;
      }
      double ss = 0.0;
      for (double x : xs) ss += (x - mean) * (x - mean);
      const double n = static_cast<double>(xs.size());
      g += fmt::format(",{}", std::sqrt(ss / (n - 1.0) / n));
    }
    g += "\n";
  }
  write_atomic(dir_, "groups.csv", g);
}

bool Tables::plot() const {
  if (plan_.plot_y.empty()) return true;
  std::size_t xi = 0;
  for (std::size_t j = 0; j < plan_.swept.size(); ++j)
    if (options::python_name(*plan_.swept[j].option) == plan_.plot_x) xi = j;
  const Swept& xs = plan_.swept[xi];
  bool numeric_x = true;
  for (const auto& v : xs.values) numeric_x = numeric_x && number(v).has_value();
  // One curve per combination of the other swept values, in case order; with replicas each
  // point is the mean over the group's finished replicas with its standard error.
  std::vector<std::string> titles;
  std::vector<std::string> blocks;
  bool any = false;
  for (std::size_t first = 0; first < cases_.size(); first += plan_.replicas) {
    const Case& c = cases_[first];
    std::string title;
    for (std::size_t j = 0; j < c.values.size(); ++j)
      if (j != xi)
        title += fmt::format("{}{}={}", title.empty() ? "" : " ",
                             options::python_name(*plan_.swept[j].option), c.values[j]);
    std::size_t k = std::find(titles.begin(), titles.end(), title) - titles.begin();
    if (k == titles.size()) {
      titles.push_back(title);
      blocks.emplace_back();
    }
    std::vector<double> ys;
    for (int r = 0; r < plan_.replicas; ++r)
      if (rows_[first + r])
        if (const std::string* v = lookup(*rows_[first + r], plan_.plot_y))
          if (auto y = number(*v)) ys.push_back(*y);
    if (ys.empty()) continue;
    any = true;
    double mean = 0.0, ss = 0.0;
    for (double y : ys) mean += y;
    mean /= static_cast<double>(ys.size());
    for (double y : ys) ss += (y - mean) * (y - mean);
    const double n = static_cast<double>(ys.size());
    const double se = n > 1 ? std::sqrt(ss / (n - 1.0) / n) : 0.0;
    const std::size_t pos =
        std::find(xs.values.begin(), xs.values.end(), c.values[xi]) - xs.values.begin();
    blocks[k] += numeric_x ? fmt::format("{} {} {}\n", c.values[xi], mean, se)
                           : fmt::format("{} {} {} \"{}\"\n", pos, mean, se, c.values[xi]);
  }
  if (!any) {
    fmt::print(stderr, "hypergas sweep: no plot: no finished case has a number in column '{}'\n",
               plan_.plot_y);
    return false;
  }
  std::string s = "set terminal pngcairo size 900,600 noenhanced\nset output '.sweep.png.tmp'\n";
  s += fmt::format("set xlabel '{}'\nset ylabel '{}'\nset grid\nset key outside right\n"
                   "set offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05\n",
                   options::python_name(*xs.option), plan_.plot_y);
  if (plan_.replicas > 1)
    s += fmt::format("set title 'mean and standard error of {} replicas'\n", plan_.replicas);
  for (std::size_t k = 0; k < blocks.size(); ++k)
    s += fmt::format("$c{} << EOD\n{}EOD\n", k, blocks[k]);
  s += "plot ";
  bool first_curve = true;
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    if (blocks[k].empty()) continue;
    s += fmt::format("{}$c{} using 1:2:3{} with yerrorlines pt 7 title '{}'",
                     first_curve ? "" : ", ", k,
                     numeric_x ? "" : ":xticlabels(4)",
                     titles[k].empty() ? plan_.plot_y : titles[k]);
    first_curve = false;
  }
  s += "\nunset output\n";
  if (!studies::run_gnuplot(s, dir_)) return false;
  std::error_code ec;
  fs::rename(dir_ / ".sweep.png.tmp", dir_ / "sweep.png", ec);
  return !ec;
}

}  // namespace hypergas::cli::sweep
