// Fuzz test of the `hypergas` command line against its contract (docs/design.md, "The command
// line and its files"): whatever the arguments, the command ends with exit code 0 or 2 (bad
// input, with a message on stderr starting with "hypergas:"), never with a signal, exit code
// 1 or a hang; nothing it prints on stdout or writes to a CSV or JSON file holds nan or inf;
// and the folder of --out is complete after exit 0 (moments.csv, speed_histogram.csv,
// summary.json, no staging folder, no checkpoint, no PNG without gnuplot) and untouched after
// exit 2 (no new folder or file, no staging folder, no checkpoint, nothing changed).
//
// Why: the hand-written cases of tests/cli/ cover the inputs someone thought of; this test
// throws a few thousand mutated argument vectors at the command: tiny valid runs of both
// engines, bench, resume and the default scene, each mutated by one to three of: non-finite,
// huge, tiny, negative, malformed and random values; repeated, dropped, unknown and
// value-less options; swapped values; the other engine's options; wrong names for --engine,
// --model and --init; wrong subcommands; --opt=value forms; random byte strings; and for
// `resume`, folders holding no, an empty, a garbage, a truncated, a corrupted or a crafted
// (re-checksummed) checkpoint.hgck.
//
// The generator is seeded (HYPERGAS_FUZZ_SEED, default below) and every case is derived from
// the seed, its area and its index, so a failure reproduces: its message gives the seed, the
// case and the command line. Mutations that would make a valid run long (more than ~2000
// particles, many samples, EDMD packings near jamming, large bench sizes, the full `report`)
// are replaced by others (`too_costly`), so the test takes well under a minute.
// HYPERGAS_FUZZ_CASES sets the number of cases (default 4000, split over the areas; fewer for
// sanitizer builds); HYPERGAS_FUZZ_VERBOSE=1 prints each area's exit codes and time. Each
// invocation gets 20 s (HYPERGAS_FUZZ_TIMEOUT_S) before it is killed and counted as a hang.
// The resume fixtures are real checkpoints, taken by killing a run as soon as its single
// checkpoint appears, so their content does not depend on timing. gnuplot is hidden (PATH)
// from most invocations, so that PNG plotting does not dominate the run time.
//
// The test is deterministic: its false-failure probability is 0. Each distinct kind of
// failure (check, subcommand, exit code, message) is reported once, with a command line that
// reproduces it, its count and the mutations that led to it. The hang guard (a case killed
// after its time limit) and the contract checks (exit code 0 or 2, one "hypergas:" line,
// no signal, no nan/inf, complete or untouched folders) are reported apart: a hang fails
// as "HANG" with its own count and assertion (hangs == 0), a broken contract as "CONTRACT"
// with its own (contract_failures == 0), so the one is never mistaken for the other.
#include <catch2/catch.hpp>

#ifdef HYPERGAS_CLI_PATH
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli/run_cli.hpp"
#include "hypergas/checkpoint.hpp"

extern char** environ;

namespace {

namespace fs = std::filesystem;
using Args = std::vector<std::string>;

// ---- settings ------------------------------------------------------------------------------

constexpr std::uint64_t default_seed = 20260417;

long env_long(const char* name, long fallback) {
  const char* v = std::getenv(name);
  if (!v || !*v) return fallback;
  char* end = nullptr;
  const long x = std::strtol(v, &end, 0);
  return (end && *end == '\0') ? x : fallback;
}

std::uint64_t fuzz_seed() {
  return static_cast<std::uint64_t>(env_long("HYPERGAS_FUZZ_SEED", default_seed));
}
long total_cases() { return std::max(6L, env_long("HYPERGAS_FUZZ_CASES", 4000)); }
double case_timeout_s() { return static_cast<double>(env_long("HYPERGAS_FUZZ_TIMEOUT_S", 20)); }
/// Cases of an area: `share` of the total, at least 1.
long cases_for(double share) {
  return std::max(1L, std::lround(share * static_cast<double>(total_cases())));
}

// ---- random numbers (std::mt19937_64 is specified exactly; the reductions are our own) ----

std::uint64_t splitmix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

struct Rng {
  explicit Rng(std::uint64_t seed) : g(seed) {}
  std::mt19937_64 g;
  /// Uniform in 0..n-1.
  std::size_t below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(g() % n); }
  int range(int lo, int hi) {
    return lo + static_cast<int>(below(static_cast<std::size_t>(hi - lo + 1)));
  }
  double unit() { return static_cast<double>(g() >> 11) * 0x1.0p-53; }
  bool chance(double p) { return unit() < p; }
  template <class T>
  const T& pick(const std::vector<T>& v) {
    return v[below(v.size())];
  }
};

// ---- running the command with a time limit --------------------------------------------------

struct Outcome {
  int code = -1;           // exit code, or 128 + signal
  bool timed_out = false;  // killed after the time limit
  std::string out, err;
  double wall_s = 0.0;
};

/// The environment of the child: ours, with PATH pointing nowhere unless `gnuplot`.
std::vector<std::string> child_env(bool gnuplot) {
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e) {
    const std::string s = *e;
    if (!gnuplot && s.rfind("PATH=", 0) == 0) continue;
    env.push_back(s);
  }
  if (!gnuplot) env.push_back("PATH=/nonexistent-hypergas-fuzz");
  return env;
}

/// Runs `hypergas args...` in `cwd` (stdin /dev/null, stdout and stderr captured in files in
/// `io`), in its own process group, killed with it after `timeout_s`. With `kill_when`, the
/// group is killed as soon as that path exists (used to take a checkpoint from a running run).
/// The process is the CLI tests' cli_test::Child (tests/cli/run_cli.hpp).
Outcome exec(const Args& args, const fs::path& cwd, const fs::path& io, bool gnuplot,
             double timeout_s, const fs::path& kill_when = {}) {
  cli_test::Spawn how;
  how.own_group = true;
  how.env = child_env(gnuplot);
  how.io = io;
  const auto t0 = std::chrono::steady_clock::now();
  cli_test::Child child(args, cwd, how);
  const pid_t pid = child.pid();
  Outcome r;
  if (pid < 0) {
    r.err = std::string("fork failed: ") + std::strerror(errno);
    return r;
  }
  // Wait on a pidfd where the kernel has them (woken at the exit), else poll.
  int pidfd = -1;
#ifdef SYS_pidfd_open
  pidfd = static_cast<int>(::syscall(SYS_pidfd_open, pid, 0));
#endif
  auto pause = std::chrono::microseconds(50);
  while (child.running()) {
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const bool stop = t > timeout_s || (!kill_when.empty() && fs::exists(kill_when));
    if (stop) {
      r.timed_out = t > timeout_s;
      child.kill_group(SIGKILL);
      child.signal(SIGKILL);
      break;
    }
    if (pidfd >= 0 && kill_when.empty()) {
      pollfd pf{pidfd, POLLIN, 0};
      ::poll(&pf, 1, static_cast<int>(std::ceil((timeout_s - t) * 1000)) + 1);
    } else {
      std::this_thread::sleep_for(pause);
      if (kill_when.empty()) pause = std::min(pause * 2, std::chrono::microseconds(2000));
    }
  }
  if (pidfd >= 0) ::close(pidfd);
  const cli_test::Result done = child.wait();
  child.kill_group(SIGKILL);  // anything the command started and left running
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.code = done.code;
  r.out = done.out;
  r.err = done.err;
  return r;
}

// ---- what a folder holds ---------------------------------------------------------------------

/// Relative path -> "d" (folder), "l" (link) or "f <size> <content hash>".
using Snapshot = std::map<std::string, std::string>;

Snapshot snapshot(const fs::path& root) {
  Snapshot s;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(root, ec); !ec && it != fs::end(it);
       it.increment(ec)) {
    const fs::path p = it->path();
    const std::string rel = p.lexically_relative(root).string();
    if (it->is_symlink()) {
      s[rel] = "l";
    } else if (it->is_directory()) {
      s[rel] = "d";
    } else {
      const std::string c = cli_test::slurp(p);
      s[rel] = "f " + std::to_string(c.size()) + " " + std::to_string(std::hash<std::string>{}(c));
    }
  }
  return s;
}

bool is_staging(const std::string& rel) {
  return rel.find(".hypergas-staging") != std::string::npos;
}

std::string base_name(const std::string& rel) { return fs::path(rel).filename().string(); }

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// ---- nan and inf in text ---------------------------------------------------------------------

bool word_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

/// The first "nan", "inf" or "infinity" (any case) standing as a word in `text`, with some
/// context; empty if none. Occurrences inside any of `skip` are not counted (on stdout, the
/// arguments: a run names its output folder there, which may be called "nan").
std::string nonfinite_word(std::string text, const Args& skip) {
  for (const auto& a : skip) {
    if (a.size() < 3 || nonfinite_word(a, {}).empty()) continue;
    std::string kept;
    for (std::size_t from = 0;;) {
      const std::size_t p = text.find(a, from);
      kept.append(text, from, p == std::string::npos ? std::string::npos : p - from);
      if (p == std::string::npos) break;
      kept += ' ';
      from = p + a.size();
    }
    text.swap(kept);
  }
  std::string low = text;
  for (char& c : low) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (std::size_t i = 0; i + 3 <= low.size(); ++i) {
    std::size_t len = 0;
    if (low.compare(i, 3, "nan") == 0) len = 3;
    else if (low.compare(i, 8, "infinity") == 0) len = 8;
    else if (low.compare(i, 3, "inf") == 0) len = 3;
    if (len == 0) continue;
    if (i > 0 && word_char(low[i - 1])) continue;
    if (i + len < low.size() && word_char(low[i + len])) continue;
    const std::size_t a = i > 60 ? i - 60 : 0;
    std::string context = "...";
    context.append(text, a, std::min<std::size_t>(140, text.size() - a));
    return context.append("...");
  }
  return {};
}

// ---- showing a case --------------------------------------------------------------------------

std::string quote(const std::string& s) {
  const bool plain = !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || std::strchr("_./=:,+-", c);
  });
  if (plain) return s;
  const bool printable = std::all_of(s.begin(), s.end(), [](char c) {
    return static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7f;
  });
  std::string q;
  if (printable) {
    q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
  }
  q = "$'";
  for (char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\\' || c == '\'') {
      q += '\\';
      q += c;
    } else if (u >= 0x20 && u < 0x7f) {
      q += c;
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", u);
      q += buf;
    }
  }
  return q + "'";
}

std::string command_line(const Args& a) {
  std::string s = "hypergas";
  for (const auto& x : a) s.append(" ").append(quote(x));
  return s;
}

std::string clip(const std::string& s, std::size_t n = 600) {
  if (s.size() <= n) return s;
  std::string c(s, 0, n);
  c.append("...[").append(std::to_string(s.size())).append(" bytes]");
  return c;
}

// ---- the options of the command ---------------------------------------------------------------

const std::vector<std::string> subcommands{"run", "bench", "resume", "report"};

const std::set<std::string> run_names{
    "--engine", "--dim", "-d", "--n", "-n", "--out", "-o", "--json", "--model",
    "--vhs-exponent", "--init", "--until", "--every", "--packing", "--mass-ratio", "--fraction",
    "--temperature", "--seed", "--threads", "-j", "--replicas", "--checkpoint-every",
    "--checkpoint-wall", "--transport", "--correlation-dt", "--correlation-time", "--tagged",
    "--restitution", "--drive", "--drive-dt", "--shear-rate", "--thermostat", "--tc-time",
    "--help", "-h"};
const std::set<std::string> bench_names{"--engine", "--dim", "-d", "--n", "-n", "--model",
                                        "--packing", "--reps", "--min-collisions", "--threads",
                                        "-j", "--seed", "--help", "-h"};
const std::set<std::string> report_names{"--out", "-o", "--quick", "--seed", "--threads",
                                         "-j", "--no-plot", "--help", "-h"};
const std::set<std::string> scene_names{"--out", "-o", "--seed", "--n", "-n", "--until",
                                        "--help", "-h"};
const std::set<std::string> flags{"--json", "--quick", "--no-plot", "--help", "-h"};

bool is_help(const std::string& t) { return t == "--help" || t == "-h"; }

/// "--name=value" -> ("--name", "value"); anything else -> (t, nullopt).
std::pair<std::string, std::optional<std::string>> split_eq(const std::string& t) {
  if (t.rfind("--", 0) == 0) {
    const auto eq = t.find('=');
    if (eq != std::string::npos) return {t.substr(0, eq), t.substr(eq + 1)};
  }
  return {t, std::nullopt};
}

/// A number as a lenient parser reads it (spaces, digit separators, hex, exponents, inf):
/// the guard below errs on the side of "this might be accepted".
std::optional<double> lenient(std::string s) {
  s.erase(std::remove_if(s.begin(), s.end(), [](char c) { return c == '_' || c == '\''; }),
          s.end());
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.erase(0, 1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
  if (s.empty()) return std::nullopt;
  char* end = nullptr;
  const double x = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size()) return std::nullopt;
  return x;
}

bool looks_like_option(const std::string& t) {
  return t.size() >= 2 && t[0] == '-' && !lenient(t).has_value();
}

/// Every value given to option `names` in `a`: the token after it, the part after '=', and
/// for list options (bench --n, --dim) all following tokens up to the next option.
std::vector<std::string> values_of(const Args& a, const std::set<std::string>& names,
                                   bool list = false) {
  std::vector<std::string> v;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto [name, inl] = split_eq(a[i]);
    if (!names.count(name)) continue;
    if (inl) v.push_back(*inl);
    std::size_t j = i + 1;
    if (!inl && j < a.size()) v.push_back(a[j++]);
    if (list)
      for (; j < a.size() && !looks_like_option(a[j]); ++j) v.push_back(a[j]);
  }
  return v;
}

bool given(const Args& a, const std::set<std::string>& names) {
  for (const auto& t : a)
    if (names.count(split_eq(t).first)) return true;
  return false;
}

/// The largest (or smallest) value of option `names` that lies in [lo, hi]; `fallback` when
/// the option is absent; nullopt when every value given lies outside (the command then
/// refuses it and ends quickly).
std::optional<double> extreme_value(const Args& a, const std::set<std::string>& names, double lo,
                                    double hi, double fallback, bool largest = true,
                                    bool list = false) {
  const auto vals = values_of(a, names, list);
  if (vals.empty()) return fallback;
  std::optional<double> best;
  for (const auto& s : vals) {
    const auto x = lenient(s);
    if (!x || !std::isfinite(*x) || *x < lo || *x > hi) continue;
    if (!best || (largest ? *x > *best : *x < *best)) best = *x;
  }
  return best;
}

/// Whether `a` (the tokens after a subcommand) holds a long option the subcommand does not
/// know, in a place where it cannot be taken as a value: the command then refuses it.
bool has_unknown_option(const Args& a, const std::set<std::string>& known) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::string name = split_eq(a[i]).first;
    if (name.size() < 3 || name.rfind("--", 0) != 0 ||
        !std::isalpha(static_cast<unsigned char>(name[2])))
      continue;
    if (known.count(name)) continue;
    const bool after_value_option =
        i > 0 && known.count(a[i - 1]) && !flags.count(a[i - 1]);
    if (!after_value_option) return true;
  }
  return false;
}

bool contains_nocase(const std::string& s, const std::string& part) {
  std::string l = s;
  for (char& c : l) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return l.find(part) != std::string::npos;
}

/// The jamming packing of hard spheres in D dimensions (edmd/box.hpp): the command refuses
/// packings at or above it.
double jamming(int d) {
  static const double j[] = {1.0, 0.82, 0.64, 0.46, 0.31, 0.20};
  return j[d - 1];
}

constexpr double max_n = 2147483648.0;  // 2^31, the largest --n the command accepts
constexpr double tiny = 1e-300;

/// Whether `hypergas run a...` might run longer than a fraction of a second. `n_cap` and
/// `until_cap` bound the accepted values (a resumed checkpoint brings its own).
bool run_costly(const Args& a, double n_cap = 2000, double until_cap = 20,
                double min_every = 0.0) {
  if (has_unknown_option(a, run_names)) return false;
  const auto n = extreme_value(a, {"--n", "-n"}, 2, max_n, 10000);
  const auto dim = extreme_value(a, {"--dim", "-d"}, 1, 6, 3);
  bool edmd = false;
  for (const auto& e : values_of(a, {"--engine"})) edmd = edmd || contains_nocase(e, "edmd");
  const auto until = extreme_value(a, {"--until"}, tiny, 1e12, edmd ? 20 : 10);
  const auto threads = extreme_value(a, {"--threads", "-j"}, 1, 256, 1);
  const auto copies = extreme_value(a, {"--replicas"}, 1, 64, 1);
  const auto packing = extreme_value(a, {"--packing"}, tiny, 1, 0.1);
  if (!n || !dim || !until || !threads || !copies || !packing) return false;  // refused
  const auto every = extreme_value(a, {"--every"}, tiny, 1e300, *until / 50, false);
  if (!every) return false;
  const double samples = *until / *every;
  if (samples > 1e6) return false;  // refused
  const bool checkpoints = given(a, {"--checkpoint-every", "--checkpoint-wall"});
  if (*n > n_cap || *until > until_cap) return true;
  if (min_every > 0.0 && *every < min_every) return true;
  if (samples > (checkpoints ? 60 : 2000)) return true;
  const double replicas = std::max(1.0, *copies / 2) * (*threads > 8 ? 2.0 : 1.0);
  if (*n * samples * replicas > 1e6) return true;
  if (*n * *until * replicas > 2e4 * (n_cap / 2000)) return true;
  // EDMD collisions per particle and time grow as 1 / (1 - packing / jamming) (1D: exactly).
  if (edmd) {
    double rate = 2 + 60 * *packing;
    const auto rate_in = [&](int d) {
      if (*packing < jamming(d))
        rate = std::max(rate, (2 + 60 * *packing) / (1 - *packing / jamming(d)));
    };
    rate_in(3);  // the default dimension
    for (const auto& ds : values_of(a, {"--dim", "-d"}))
      if (const auto d = lenient(ds); d && *d >= 1 && *d <= 6) rate_in(static_cast<int>(*d));
    if (*n * *until * rate > 2e5) return true;
  }
  if (edmd && *dim >= 6 && (*n > 150 || *until > 2)) return true;
  return false;
}

bool bench_costly(const Args& a) {
  if (has_unknown_option(a, bench_names)) return false;
  const auto n = extreme_value(a, {"--n", "-n"}, 2, max_n, 100000, true, true);
  const auto reps = extreme_value(a, {"--reps"}, 1, 100, 3);
  const auto coll = extreme_value(a, {"--min-collisions"}, 1000, 1e12, 5e6);
  const auto threads = extreme_value(a, {"--threads", "-j"}, 1, 256, 1, true, true);
  const auto dim = extreme_value(a, {"--dim", "-d"}, 1, 6, 6, true, true);
  if (!n || !reps || !coll || !threads || !dim) return false;
  bool edmd = false;
  for (const auto& e : values_of(a, {"--engine"}))
    edmd = edmd || contains_nocase(e, "edmd") || contains_nocase(e, "all");
  const std::size_t points = values_of(a, {"--n", "-n"}, true).size() *
                             std::max<std::size_t>(1, values_of(a, {"--dim", "-d"}, true).size()) *
                             std::max<std::size_t>(1, values_of(a, {"--threads", "-j"}, true).size());
  if (*n > 2000 || *reps > 3 || *coll > 1e4 || *threads > 8 || points > 12) return true;
  if (edmd && *dim >= 6 && (*n > 150 || *reps * *coll > 3000)) return true;
  return false;
}

bool scene_costly(const Args& a) {
  if (has_unknown_option(a, scene_names)) return false;
  const auto n = extreme_value(a, {"--n", "-n"}, 2, max_n, 20000);
  const auto until = extreme_value(a, {"--until"}, tiny, 1e300, 12);
  if (!n || !until) return false;
  return *n > 2000 || *n * *until > 5000;
}

bool report_costly(const Args& a) {
  // `report` takes 20 s (--quick) to minutes: only refused invocations are cheap.
  if (has_unknown_option(a, report_names)) return false;
  const auto t = values_of(a, {"--threads", "-j"});
  if (t.empty()) return true;
  for (const auto& s : t) {
    const auto x = lenient(s);
    if (x && *x >= 1 && *x <= 64) return true;
  }
  return false;
}

/// Whether `hypergas a...` might take long: a valid invocation of the default scene, `run`,
/// `bench` or `report` beyond the tiny sizes. Every token that names a subcommand might start
/// it; the tokens before the first are the default scene's.
bool too_costly(const Args& a) {
  if (std::any_of(a.begin(), a.end(), is_help)) return false;
  bool any_sub = false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Args rest(a.begin() + static_cast<long>(i) + 1, a.end());
    if (a[i] == "run" && run_costly(rest)) return true;
    if (a[i] == "bench" && bench_costly(rest)) return true;
    if (a[i] == "report" && report_costly(rest)) return true;
    any_sub = any_sub || std::find(subcommands.begin(), subcommands.end(), a[i]) !=
                             subcommands.end();
  }
  if (!any_sub || std::find(subcommands.begin(), subcommands.end(), a.empty() ? "" : a[0]) ==
                      subcommands.end())
    if (scene_costly(a)) return true;
  return false;
}

// ---- commands as option lists, and their mutations -----------------------------------------

struct Opt {
  std::string name;
  std::optional<std::string> value;
};

struct Command {
  Args head;              // the subcommand (and positional arguments)
  std::vector<Opt> opts;  // options in order
  Args flatten() const {
    Args a = head;
    for (const auto& o : opts) {
      a.push_back(o.name);
      if (o.value) a.push_back(*o.value);
    }
    return a;
  }
};

/// What a kind of command offers to the mutations.
struct Spec {
  std::vector<std::string> numeric;  // options with a number value
  std::vector<Opt> other_engine;     // options of the other engine (refused)
  std::vector<Opt> extra;            // further valid options to add, repeat or swap
};

const std::vector<std::string> bad_numbers{
    "NaN", "nan", "inf", "-inf", "-1", "0", "1e308", "-0", "1e-320", "10x", "0x10", "", " ",
    "1e3", "2147483649", "2147483648", "4294967297", "9223372036854775807",
    "9223372036854775808", "-9223372036854775809", "18446744073709551616",
    "99999999999999999999999999999", "1.5", "-1e-300", "+2", "0.0", "1e-5", "3 ", " 3",
    "0x1p-2", "Infinity", "-nan", "1,5", "7", "65", "100", "1e12", "1e13", "5e-324", "1e-310",
    "2e9", "0.999999999", "1.0000001", "-2147483649", "1e+3", ".5", "5.", "0b11", "1_000",
    "NAN(0x1)", "infinite", "nan ", "٣", "1e", "e5", "--5", "+-1"};
const std::vector<std::string> engine_names{"HS", "hs ", "maxwel", "DSMC", "Dsmc", "dsmc ",
                                            "edmd\t", "md", "all", "dsmc,edmd", "", "edm",
                                            "EDMD", "dsmc", "edmd", " edmd", "d"};
const std::vector<std::string> model_names{"HS", "hs ", "maxwel", "Maxwell", "vhs ", "hard",
                                           "", "maxwell", "vhs", "hs", "VHS", "hs,vhs"};
const std::vector<std::string> init_names{"maxwel", "Maxwell", "bkw ", "two_temp", "two-temp",
                                          "delta", "cube", "beams", "bimaxwell", "", "deltas",
                                          "maxwell", "bkw", "BKW", "beam", "none"};
const std::vector<std::string> subcommand_names{
    "Run", "run ", "runn", "ru", "RUN", "bench", "resume", "report", "help", "--run", "-run",
    "", "run\n", "version", "--version", "-v", "benchmark", "resum", "r"};
const std::vector<std::string> unknown_options{
    "--bogus", "--N", "--Engine", "---n", "--n2", "-x", "-", "--", "--=", "--out-dir",
    "--dims", "--jsonx", "--threads=", "-nn", "--h", "-?", "--vhs", "--pack", "--until=",
    "--dim=", "-", "--no-json", "--seed="};

std::string random_text(Rng& r, std::size_t max_len = 12) {
  static const std::string alphabet =
      "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_.,:;=+*~#%!?@$&()[]{} ";
  std::string s;
  const std::size_t len = 1 + r.below(max_len);
  for (std::size_t i = 0; i < len; ++i) s += alphabet[r.below(alphabet.size())];
  return s;
}

/// Random bytes 1..255 other than '/', so that a path made from them stays in its folder.
std::string random_bytes(Rng& r, std::size_t max_len = 40) {
  std::string s;
  const std::size_t len = r.below(max_len + 1);
  for (std::size_t i = 0; i < len; ++i) {
    char c = static_cast<char>(1 + r.below(255));
    if (c == '/') c = '_';
    s += c;
  }
  return s;
}

std::string fmt_double(double x, const char* f = "%.6g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

/// A number of any size and sign, written in one of several formats.
std::string random_number(Rng& r) {
  const double mag = std::pow(10.0, -12 + 26 * r.unit());
  const double x = r.chance(0.15) ? -mag : mag;
  switch (r.below(6)) {
    case 0: return std::to_string(static_cast<long long>(std::min(x, 9e18)));
    case 1: return fmt_double(x, "%.3f");
    case 2: return fmt_double(x, "%.4e");
    case 3: return fmt_double(x, "%a");
    case 4: return (r.chance(0.5) ? " " : "+") + fmt_double(x);
    default: return r.pick(bad_numbers);
  }
}

/// Applies one random mutation to `c`; returns its description ("kind option").
std::string mutate(Rng& r, Command& c, const Spec& spec) {
  auto numeric_index = [&]() -> std::optional<std::size_t> {
    std::vector<std::size_t> idx;
    for (std::size_t i = 0; i < c.opts.size(); ++i)
      if (c.opts[i].value && std::find(spec.numeric.begin(), spec.numeric.end(),
                                       c.opts[i].name) != spec.numeric.end())
        idx.push_back(i);
    if (idx.empty()) return std::nullopt;
    return r.pick(idx);
  };
  auto any_index = [&]() { return r.below(c.opts.size()); };
  const std::size_t kind = r.below(100);
  if (c.opts.empty() || kind < 26) {  // a bad number
    auto i = numeric_index();
    if (!i) {
      if (spec.numeric.empty()) return "none";
      c.opts.push_back({r.pick(spec.numeric), "1"});
      i = c.opts.size() - 1;
    }
    c.opts[*i].value = r.chance(0.85) ? r.pick(bad_numbers) : random_text(r);
    return "bad-number " + c.opts[*i].name;
  }
  if (kind < 34) {  // a number of any size (valid or not)
    auto i = numeric_index();
    if (!i) return "none";
    c.opts[*i].value = random_number(r);
    return "any-number " + c.opts[*i].name;
  }
  if (kind < 44) {  // an enum option with an unknown or almost right name
    const int which = r.range(0, 2);
    const char* name = which == 0 ? "--engine" : which == 1 ? "--model" : "--init";
    const auto& pool = which == 0 ? engine_names : which == 1 ? model_names : init_names;
    std::string v = r.chance(0.85) ? r.pick(pool) : random_text(r);
    auto it =
        std::find_if(c.opts.begin(), c.opts.end(), [&](const Opt& o) { return o.name == name; });
    if (it != c.opts.end())
      it->value = v;
    else
      c.opts.insert(c.opts.begin() + static_cast<long>(r.below(c.opts.size() + 1)), Opt{name, v});
    return std::string("enum ") + name;
  }
  if (kind < 50) {  // an option given twice
    Opt o = c.opts[any_index()];
    if (o.name == "--out" || o.name == "-o") o.value = "out2";
    else if (o.value && r.chance(0.5)) o.value = r.chance(0.5) ? random_number(r) : *o.value;
    c.opts.insert(c.opts.begin() + static_cast<long>(r.below(c.opts.size() + 1)), o);
    return "repeat " + o.name;
  }
  if (kind < 58) {  // an option dropped
    const std::size_t i = any_index();
    const std::string n = c.opts[i].name;
    c.opts.erase(c.opts.begin() + static_cast<long>(i));
    return "drop " + n;
  }
  if (kind < 64) {  // an unknown option, with or without a value
    Opt o{r.pick(unknown_options), std::nullopt};
    if (r.chance(0.5)) o.value = r.chance(0.5) ? "1" : random_text(r);
    c.opts.insert(c.opts.begin() + static_cast<long>(r.below(c.opts.size() + 1)), o);
    return "unknown " + o.name;
  }
  if (kind < 70) {  // values swapped between two options
    const std::size_t i = any_index(), j = any_index();
    std::swap(c.opts[i].value, c.opts[j].value);
    return "swap " + c.opts[i].name + " " + c.opts[j].name;
  }
  if (kind < 78 && !spec.other_engine.empty()) {  // an option of the other engine
    const Opt o = r.pick(spec.other_engine);
    c.opts.insert(c.opts.begin() + static_cast<long>(r.below(c.opts.size() + 1)), o);
    return "other-engine " + o.name;
  }
  if (kind < 82 && !c.head.empty()) {  // a wrong subcommand
    c.head[0] = r.chance(0.8) ? r.pick(subcommand_names) : random_text(r);
    return "subcommand";
  }
  if (kind < 87) {  // random byte strings as arguments
    const int k = r.range(1, 3);
    for (int m = 0; m < k; ++m) {
      Opt o{random_bytes(r), std::nullopt};
      c.opts.insert(c.opts.begin() + static_cast<long>(r.below(c.opts.size() + 1)), o);
    }
    return "bytes";
  }
  if (kind < 90) {  // --name=value
    const std::size_t i = any_index();
    if (c.opts[i].value) {
      c.opts[i].name += "=" + *c.opts[i].value;
      c.opts[i].value.reset();
    }
    return "equals " + split_eq(c.opts[i].name).first;
  }
  if (kind < 94) {  // an option without its value
    const std::size_t i = any_index();
    c.opts[i].value.reset();
    return "no-value " + c.opts[i].name;
  }
  if (kind < 97) {  // options in another order
    for (std::size_t i = c.opts.size(); i > 1; --i) std::swap(c.opts[i - 1], c.opts[r.below(i)]);
    return "shuffle";
  }
  if (kind < 98) {  // --help somewhere
    c.opts.insert(c.opts.begin() + static_cast<long>(r.below(c.opts.size() + 1)),
                  Opt{r.chance(0.5) ? "--help" : "-h", std::nullopt});
    return "help";
  }
  if (!spec.extra.empty()) {  // a further valid option
    const Opt o = r.pick(spec.extra);
    c.opts.insert(c.opts.begin() + static_cast<long>(r.below(c.opts.size() + 1)), o);
    return "extra " + o.name;
  }
  return "none";
}

/// `base` with one to three mutations (none with probability `p_none`), redrawn while the
/// result might run long; the description lists the mutations.
std::pair<Args, std::string> mutated(Rng& r, const Command& base, const Spec& spec,
                                     double p_none = 0.04) {
  for (int attempt = 0; attempt < 30; ++attempt) {
    Command c = base;
    std::string what;
    if (!r.chance(p_none)) {
      const double u = r.unit();
      const int k = u < 0.6 ? 1 : u < 0.9 ? 2 : 3;
      for (int m = 0; m < k; ++m) what += (what.empty() ? "" : "; ") + mutate(r, c, spec);
    }
    Args a = c.flatten();
    if (!too_costly(a)) return {a, what.empty() ? "base" : what};
  }
  return {base.flatten(), "base"};
}

// ---- the commands to mutate ------------------------------------------------------------------

const std::vector<std::string> run_numeric{
    "--dim", "--n", "--until", "--every", "--packing", "--mass-ratio", "--fraction",
    "--temperature", "--seed", "--threads", "--vhs-exponent", "--checkpoint-every",
    "--restitution", "--shear-rate"};
const std::vector<std::string> known_inits{"maxwell", "delta", "cube", "beams", "bimaxwell",
                                           "bkw", "two-temp"};

/// Optional valid extras shared by both engines' run commands.
void add_common_run_extras(Rng& r, Command& c, double until) {
  if (r.chance(0.2)) c.opts.push_back({"--init", r.pick(known_inits)});
  if (r.chance(0.2)) c.opts.push_back({"--every", fmt_double(until / r.range(2, 40))});
  if (r.chance(0.2)) c.opts.push_back({"--seed", std::to_string(r.below(1000000))});
  if (r.chance(0.15)) {
    c.opts.push_back({"--mass-ratio", fmt_double(0.2 + 5 * r.unit())});
    c.opts.push_back({"--fraction", fmt_double(r.unit())});
  }
  if (r.chance(0.2)) c.opts.push_back({"--json", std::nullopt});
  if (r.chance(0.08)) c.opts.push_back({"--checkpoint-every", fmt_double(until / 3)});
  if (r.chance(0.05)) c.opts.push_back({"--checkpoint-wall", r.chance(0.5) ? "1s" : "0.001s"});
}

Command dsmc_run(Rng& r) {
  const int d = r.range(1, 6);
  const double until = r.pick(std::vector<double>{0.5, 1, 2});
  Command c{{"run"},
            {{"--engine", "dsmc"},
             {"--dim", std::to_string(d)},
             {"--n", std::to_string(r.pick(std::vector<int>{50, 100, 200}))},
             {"--until", fmt_double(until)},
             {"--out", "out"}}};
  if (r.chance(0.25)) {
    const std::string m = r.pick(std::vector<std::string>{"hs", "maxwell", "vhs"});
    c.opts.push_back({"--model", m});
    if (m == "vhs" && r.chance(0.7)) c.opts.push_back({"--vhs-exponent", fmt_double(r.unit())});
  }
  if (r.chance(0.15)) c.opts.push_back({"--temperature", fmt_double(0.1 + 4 * r.unit())});
  if (r.chance(0.1)) c.opts.push_back({"--threads", std::to_string(r.range(1, 3))});
  if (r.chance(0.1)) c.opts.push_back({"--replicas", std::to_string(r.range(1, 3))});
  if (r.chance(0.15)) {  // a granular gas, cooling or driven
    c.opts.push_back({"--restitution", fmt_double(r.chance(0.2) ? 0.0 : r.unit(), "%.3f")});
    if (r.chance(0.4)) {
      c.opts.push_back({"--drive", "white-noise"});
      if (r.chance(0.5)) c.opts.push_back({"--drive-dt", fmt_double(0.01 + r.unit(), "%.3f")});
    }
  }
  if (r.chance(0.12)) {  // a shear flow, with or without thermostat (D = 1 is refused)
    c.opts.push_back({"--shear-rate", fmt_double(r.chance(0.1) ? 0.0 : 5 * r.unit(), "%.3f")});
    if (r.chance(0.4)) c.opts.push_back({"--thermostat", r.chance(0.8) ? "isokinetic" : "none"});
  }
  add_common_run_extras(r, c, until);
  return c;
}

Spec dsmc_spec() {
  return {run_numeric,
          {{"--packing", "0.2"}, {"--packing", "0.1"}, {"--packing", "0.5"},
           {"--tc-time", "0.01"}},
          {{"--json", std::nullopt}, {"--seed", "3"}, {"--model", "vhs"}, {"--vhs-exponent", "0.5"},
           {"--init", "bkw"}, {"--every", "0.1"}, {"--threads", "2"}, {"--temperature", "2"},
           {"--checkpoint-every", "0.2"}, {"--checkpoint-wall", "1min"},
           {"--restitution", "0.5"}, {"--drive", "white-noise"}, {"--drive", "none"},
           {"--drive-dt", "0.2"}, {"--shear-rate", "1.5"}, {"--thermostat", "isokinetic"}}};
}

Command edmd_run(Rng& r) {
  // 6D boxes need more spheres (side >= 2 contact distances) and cost most: drawn less often.
  static const int n_of_dim[] = {30, 30, 30, 40, 60, 120};
  const int d = r.chance(0.06) ? 6 : r.range(1, 5);
  const double until = r.pick(std::vector<double>{0.5, 1});
  const double packing = jamming(d) * (0.05 + 0.45 * r.unit());
  Command c{{"run"},
            {{"--engine", "edmd"},
             {"--dim", std::to_string(d)},
             {"--n", std::to_string(n_of_dim[d - 1])},
             {"--until", fmt_double(until)},
             {"--packing", fmt_double(packing, "%.3f")},
             {"--out", "out"}}};
  if (r.chance(0.15)) {  // a granular gas, quenched after its elastic equilibration
    c.opts.push_back({"--restitution", fmt_double(r.chance(0.2) ? 0.0 : r.unit(), "%.3f")});
    if (r.chance(0.3)) c.opts.push_back({"--tc-time", r.chance(0.5) ? "0" : "0.001"});
  }
  if (r.chance(0.1)) {  // Lees-Edwards: small dense boxes are refused (4 cells per side)
    c.opts.push_back({"--shear-rate", fmt_double(3 * r.unit(), "%.3f")});
    if (r.chance(0.4)) c.opts.push_back({"--thermostat", r.chance(0.8) ? "isokinetic" : "none"});
  }
  add_common_run_extras(r, c, until);
  return c;
}

Spec edmd_spec() {
  return {run_numeric,
          {{"--model", "maxwell"}, {"--model", "hs"}, {"--model", "vhs"}, {"--temperature", "2"},
           {"--temperature", "1"}, {"--threads", "2"}, {"--threads", "1"},
           {"--vhs-exponent", "0.5"}, {"--drive", "white-noise"}, {"--drive-dt", "0.1"}},
          {{"--json", std::nullopt}, {"--seed", "3"}, {"--init", "delta"}, {"--every", "0.1"},
           {"--mass-ratio", "2"}, {"--fraction", "0.3"}, {"--checkpoint-every", "0.3"},
           {"--packing", "0.05"}, {"--restitution", "0.8"}, {"--tc-time", "0.001"}}};
}

Command bench_cmd(Rng& r) {
  const std::string e = r.pick(std::vector<std::string>{"dsmc", "dsmc", "edmd", "all"});
  Command c{{"bench"},
            {{"--engine", e},
             {"--dim", std::to_string(e == "dsmc" ? r.range(1, 6) : r.range(1, 5))},
             {"--n", std::to_string(r.pick(std::vector<int>{100, 200}))},
             {"--reps", "1"},
             {"--min-collisions", "1000"}}};
  if (r.chance(0.2))
    c.opts.push_back({"--model", r.pick(std::vector<std::string>{"hs", "maxwell", "vhs"})});
  if (r.chance(0.2)) c.opts.push_back({"--packing", fmt_double(0.05 + 0.1 * r.unit(), "%.3f")});
  if (r.chance(0.1)) c.opts.push_back({"--threads", "2"});
  if (r.chance(0.2)) c.opts.push_back({"--seed", std::to_string(r.below(1000))});
  return c;
}

Spec bench_spec() {
  return {{"--dim", "--n", "--packing", "--reps", "--min-collisions", "--threads", "--seed"},
          {{"--until", "1"}, {"--out", "out"}, {"--json", std::nullopt}, {"--init", "bkw"},
           {"--temperature", "2"}},
          {{"--dim", "2"}, {"--n", "150"}, {"--seed", "5"}, {"--model", "maxwell"},
           {"--packing", "0.2"}, {"--reps", "2"}, {"--threads", "2"}}};
}

Command scene_cmd(Rng& r) {
  Command c{{}, {{"--n", std::to_string(r.range(50, 100))}, {"--until", "0.5"}, {"--out", "out"}}};
  if (r.chance(0.3)) c.opts.push_back({"--seed", std::to_string(r.below(1000))});
  return c;
}

Spec scene_spec() {
  return {{"--n", "--until", "--seed"},
          {{"--engine", "dsmc"}, {"--dim", "3"}, {"--json", std::nullopt}},
          {{"--seed", "9"}}};
}

Command report_cmd(Rng& r) {
  Command c{{"report"},
            {{"--threads", r.pick(std::vector<std::string>{"0", "65", "-1", "nan", "x"})},
             {"--out", "out"}}};
  if (r.chance(0.5)) c.opts.push_back({"--quick", std::nullopt});
  return c;
}

Spec report_spec() {
  return {{"--threads", "--seed"},
          {{"--engine", "dsmc"}, {"--n", "5"}},
          {{"--no-plot", std::nullopt}, {"--seed", "2"}}};
}

// ---- checking one invocation -------------------------------------------------------------------

struct Case {
  Args args;
  std::string what;       // the mutations
  bool gnuplot = false;   // gnuplot on PATH
};

/// Problems with one finished invocation: empty if it kept the contract. `case_dir` holds
/// everything the invocation may touch; `before` is its content before.
std::vector<std::string> check(const Case& c, const Outcome& o, const fs::path& case_dir,
                               const Snapshot& before) {
  std::vector<std::string> p;
  if (o.timed_out) {
    p.push_back("hang: killed after " + fmt_double(o.wall_s, "%.0f") + " s");
    return p;
  }
  const Snapshot after = snapshot(case_dir);
  const bool help = std::any_of(c.args.begin(), c.args.end(), is_help);
  if (o.code != 0 && o.code != 2) {
    p.push_back(o.code > 128 ? "signal " + std::to_string(o.code - 128)
                             : "exit code " + std::to_string(o.code));
  }
  if (o.code == 2 && o.err.rfind("hypergas:", 0) != 0)
    p.push_back("exit 2 without a 'hypergas:' message");
  if (o.code != 0) {
    // Nothing new, nothing changed, nothing removed except stale staging folders.
    std::string left;
    for (const auto& [rel, sig] : after) {
      const auto b = before.find(rel);
      if (b == before.end()) left += " +" + rel;
      else if (b->second != sig) left += " ~" + rel;
    }
    for (const auto& [rel, sig] : before)
      if (!after.count(rel) && !is_staging(rel)) left += " -" + rel;
    if (!left.empty())
      p.push_back("exit " + std::to_string(o.code) + " changed files:" + clip(left, 300));
  }
  const std::string w = nonfinite_word(o.out, c.args);
  if (!w.empty()) p.push_back("nan/inf on stdout: " + w);
  for (const auto& [rel, sig] : after) {
    const auto b = before.find(rel);
    if (b != before.end() && b->second == sig) continue;  // not written by this invocation
    if (sig[0] != 'f' || !(ends_with(rel, ".csv") || ends_with(rel, ".json"))) continue;
    const std::string fw = nonfinite_word(cli_test::slurp(case_dir / rel), {});
    if (!fw.empty()) p.push_back("nan/inf in " + base_name(rel) + ": " + fw);
  }
  if (o.code != 0 || help) return p;
  // Exit 0: no staging folder, no temporary file, no PNG without gnuplot.
  for (const auto& [rel, sig] : after) {
    if (is_staging(rel)) p.push_back("staging folder left: " + rel);
    if (ends_with(rel, ".tmp")) p.push_back("temporary file left: " + rel);
    if (!c.gnuplot && ends_with(rel, ".png")) p.push_back("PNG without gnuplot: " + rel);
  }
  const std::string sub = c.args.empty() ? "" : c.args[0];
  if (sub == "run" || sub == "resume") {
    // The output folder: where a new summary.json appeared.
    std::vector<fs::path> dirs;
    for (const auto& [rel, sig] : after)
      if (base_name(rel) == "summary.json" && (!before.count(rel) || before.at(rel) != sig))
        dirs.push_back(fs::path(rel).parent_path());
    if (dirs.size() != 1) {
      p.push_back("exit 0 but " + std::to_string(dirs.size()) + " output folders");
    } else {
      for (const char* f : {"moments.csv", "speed_histogram.csv", "summary.json"})
        if (!after.count((dirs[0] / f).string())) p.push_back(std::string("exit 0 without ") + f);
      if (after.count((dirs[0] / "checkpoint.hgck").string()))
        p.push_back("checkpoint left after a finished run");
    }
  }
  return p;
}

/// The first line of a message, numbers and quoted names replaced, for grouping failures.
std::string gist(const std::string& err) {
  std::string line = err.substr(0, err.find('\n')), g;
  for (std::size_t i = 0; i < line.size() && g.size() < 90; ++i) {
    const char ch = line[i];
    if (std::isdigit(static_cast<unsigned char>(ch))) {
      if (g.empty() || g.back() != '#') g += '#';
    } else if (ch == '\'') {
      const auto close = line.find('\'', i + 1);
      g += "'?'";
      if (close == std::string::npos) break;
      i = close;
    } else {
      g += ch;
    }
  }
  return g;
}

/// Collects the failures of an area and reports each distinct kind once (its first case in
/// full, how often it occurred and under which mutations).
class Failures {
 public:
  explicit Failures(std::string area) : area_(std::move(area)) {}
  void add(const Case& c, long index, std::uint64_t case_seed, const Outcome& o,
           const std::vector<std::string>& problems) {
    ++(o.timed_out ? hangs_ : contract_);
    for (const auto& problem : problems) {
      // Kind: the problem without its details, the command, the exit code and its message.
      const std::string cmd = c.args.empty() ? "" : c.args[0];
      const std::string key = std::string(o.timed_out ? "HANG" : "CONTRACT") + " | " +
                              problem.substr(0, problem.find(':')) + " | " +
                              (std::find(subcommands.begin(), subcommands.end(), cmd) !=
                                       subcommands.end()
                                   ? cmd
                                   : "(no subcommand)") +
                              " | exit " + std::to_string(o.code) +
                              (o.code == 0 ? std::string() : " | " + gist(o.err));
      Kind& k = kinds_[key];
      if (k.count++ == 0) {
        std::ostringstream s;
        s << (o.timed_out ? "HANG (killed after the time limit of " +
                                fmt_double(case_timeout_s(), "%.0f") + " s)"
                          : std::string("CONTRACT broken"))
          << ": " << area_ << " case " << index << " (HYPERGAS_FUZZ_SEED=" << fuzz_seed()
          << ", case seed " << case_seed << ")"
          << "\nproblem: " << problem << "\ncommand: " << command_line(c.args)
          << (c.gnuplot ? "   (gnuplot on PATH)" : "") << "\nexit code: " << o.code
          << "\nstderr: " << clip(o.err) << "\nstdout: " << clip(o.out, 300);
        k.example = s.str();
        k.order = kinds_.size();
      }
      if (k.whats.size() < 8) k.whats.insert(c.what);
    }
  }
  /// One failed check per distinct kind (at most 30), in the order first seen.
  void report() const {
    std::vector<const std::pair<const std::string, Kind>*> v;
    for (const auto& e : kinds_) v.push_back(&e);
    std::sort(v.begin(), v.end(),
              [](auto* a, auto* b) { return a->second.order < b->second.order; });
    for (std::size_t i = 0; i < v.size() && i < 30; ++i) {
      const Kind& k = v[i]->second;
      std::string whats;
      for (const auto& w : k.whats) whats += "\n  " + w;
      FAIL_CHECK(k.example << "\n(" << k.count << " cases of this kind; mutations:" << whats
                           << ")");
    }
  }
  /// Cases killed after the time limit (the hang guard).
  long hangs() const { return hangs_; }
  /// Cases that ended within the limit and broke the contract.
  long contract_failures() const { return contract_; }
  long count() const { return hangs_ + contract_; }
  std::size_t kinds() const { return kinds_.size(); }
  /// The two final assertions, one per guard, each with its own message.
  void require_none(const std::string& summary) const {
    {
      INFO("HANG guard, " << area_ << ": " << hangs_ << " case(s) ran past "
                          << fmt_double(case_timeout_s(), "%.0f") << " s and were killed ("
                          << summary << ")");
      CHECK(hangs() == 0);
    }
    {
      INFO("CONTRACT, " << area_ << ": " << contract_ << " case(s) broke the contract ("
                        << summary << ")");
      CHECK(contract_failures() == 0);
    }
  }

 private:
  struct Kind {
    long count = 0;
    std::size_t order = 0;
    std::string example;
    std::set<std::string> whats;
  };
  std::string area_;
  long hangs_ = 0, contract_ = 0;
  std::map<std::string, Kind> kinds_;
};

/// A fresh folder for the cases of an area, removed at scope exit.
class Area {
 public:
  explicit Area(const std::string& name) : scratch_("fuzz-" + name) {
    fs::create_directories(io());
  }
  fs::path root() const { return scratch_.path(); }
  fs::path io() const { return scratch_.path() / "io"; }

  /// Runs case `index` in a fresh case folder `case_dir` (prepared by `prepare`, which gets
  /// the folder): the command runs in case_dir/w.
  void run(const Case& c, long index, std::uint64_t case_seed, Failures& f,
           const std::function<void(const fs::path&)>& prepare = {}) {
    const fs::path dir = root() / ("c" + std::to_string(index));
    fs::create_directories(dir / "w");
    if (prepare) prepare(dir);
    const Snapshot before = snapshot(dir);
    const Outcome o = exec(c.args, dir / "w", io(), c.gnuplot, case_timeout_s());
    ++invocations_;
    ++codes_[o.timed_out ? -1 : o.code];
    const auto problems = check(c, o, dir, before);
    if (!problems.empty()) f.add(c, index, case_seed, o, problems);
    std::error_code ec;
    // HYPERGAS_FUZZ_KEEP=DIR keeps each failing case's folder as DIR/<area>-c<index>
    if (const char* keep = std::getenv("HYPERGAS_FUZZ_KEEP"); keep && *keep && !problems.empty())
      fs::copy(dir, fs::path(keep) / (root().filename().string() + "-c" + std::to_string(index)),
               fs::copy_options::recursive, ec);
    fs::remove_all(dir, ec);
  }
  long invocations() const { return invocations_; }
  /// "exit 0: n0, exit 2: n2, ..." over the cases run so far (-1: killed after the limit).
  std::string code_counts() const {
    std::string s;
    for (const auto& [code, n] : codes_)
      s += (s.empty() ? "" : ", ") + std::string("exit ") + std::to_string(code) + ": " +
           std::to_string(n);
    return s;
  }

 private:
  cli_test::Scratch scratch_;
  long invocations_ = 0;
  std::map<int, long> codes_;
};

std::uint64_t case_seed(std::uint64_t area, long index) {
  return splitmix(fuzz_seed() ^ splitmix(area * 1000003 + static_cast<std::uint64_t>(index)));
}

/// Runs `count` cases of an area, each made by `make` from its own generator.
void fuzz_area(const std::string& name, std::uint64_t area_id, long count,
               const std::function<Case(Rng&)>& make) {
  Area area(name);
  Failures f(name);
  const auto t0 = std::chrono::steady_clock::now();
  for (long k = 0; k < count; ++k) {
    const std::uint64_t s = case_seed(area_id, k);
    Rng r(s);
    Case c = make(r);
    c.gnuplot = r.chance(0.08);
    area.run(c, k, s, f);
  }
  const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  f.report();
  const std::string summary = name + ": " + std::to_string(count) + " cases in " +
                              fmt_double(t, "%.1f") + " s (" + area.code_counts() + "); " +
                              std::to_string(f.hangs()) + " hung, " +
                              std::to_string(f.contract_failures()) + " broke the contract, " +
                              std::to_string(f.kinds()) + " distinct kinds";
  if (env_long("HYPERGAS_FUZZ_VERBOSE", 0)) WARN(summary);
  f.require_none(summary);
}

// ---- resume: checkpoint fixtures -------------------------------------------------------------

/// A real checkpoint and what its header says.
struct Fixture {
  std::string name;
  std::string file;   // checkpoint.hgck, whole
  fs::path crashed;   // the folder of the killed run (checkpoint and stale staging folder)
  std::string tag, id;
  Args args;          // the run's arguments as stored
  std::string rest;   // the payload after the header
  double until = 0.0, every = 0.0, n = 0.0;
};

/// Reads a string record of a checkpoint payload at `pos`.
std::optional<std::string> read_str(const std::string& p, std::size_t& pos) {
  std::uint64_t n = 0;
  if (pos + 8 > p.size()) return std::nullopt;
  std::memcpy(&n, p.data() + pos, 8);
  pos += 8;
  if (n > p.size() - pos) return std::nullopt;
  std::string s = p.substr(pos, n);
  pos += n;
  return s;
}

void put_u64(std::string& s, std::uint64_t n) { s.append(reinterpret_cast<const char*>(&n), 8); }
void put_str(std::string& s, const std::string& x) {
  put_u64(s, x.size());
  s += x;
}

constexpr std::size_t ck_header = 24, ck_trailer = 16;  // hypergas/checkpoint.hpp

/// Writes `payload` as a complete checkpoint file at `path` (valid frame and checksum).
void write_framed(const fs::path& path, const std::string& payload) {
  hypergas::checkpoint::Writer w(path.string());
  w.bytes(payload.data(), payload.size());
  w.commit();
}

std::string header_payload(const std::string& tag, const std::string& id, const Args& args) {
  std::string p;
  put_str(p, tag);
  put_str(p, id);
  put_u64(p, args.size());
  for (const auto& a : args) put_str(p, a);
  return p;
}

/// Takes a checkpoint of `hypergas run args --out <dir>`: the run writes one checkpoint
/// (--checkpoint-every above half of --until) and is killed as soon as it appears, so the
/// checkpoint is the same on every machine. If the run ends first (a very fast machine), it
/// is tried again three times longer.
std::optional<Fixture> take_checkpoint(const std::string& name, Args args, const fs::path& root,
                                       const fs::path& io) {
  for (int attempt = 0; attempt < 4; ++attempt) {
    const fs::path dir = root / (name + std::to_string(attempt));
    Args a = args;
    a.push_back("--out");
    a.push_back(dir.string());
    const Outcome o = exec(a, root, io, false, 120.0, dir / "checkpoint.hgck");
    if (fs::exists(dir / "checkpoint.hgck")) {
      Fixture f;
      f.name = name;
      f.crashed = dir;
      f.file = cli_test::slurp(dir / "checkpoint.hgck");
      if (f.file.size() < ck_header + ck_trailer) return std::nullopt;
      const std::string payload = f.file.substr(ck_header, f.file.size() - ck_header - ck_trailer);
      std::size_t pos = 0;
      const auto tag = read_str(payload, pos), id = read_str(payload, pos);
      std::uint64_t count = 0;
      if (!tag || !id || pos + 8 > payload.size()) return std::nullopt;
      std::memcpy(&count, payload.data() + pos, 8);
      pos += 8;
      for (std::uint64_t k = 0; k < count; ++k) {
        const auto s = read_str(payload, pos);
        if (!s) return std::nullopt;
        f.args.push_back(*s);
      }
      f.tag = *tag;
      f.id = *id;
      f.rest = payload.substr(pos);
      f.until = lenient(values_of(f.args, {"--until"}).at(0)).value_or(0);
      f.every = lenient(values_of(f.args, {"--every"}).at(0)).value_or(0);
      f.n = lenient(values_of(f.args, {"--n"}).at(0)).value_or(0);
      return f;
    }
    // Too fast: three times longer, the single checkpoint at the same fraction of the run.
    for (std::size_t i = 0; i + 1 < args.size(); ++i)
      if (args[i] == "--until" || args[i] == "--checkpoint-every")
        args[i + 1] = fmt_double(*lenient(args[i + 1]) * 3, "%.17g");
    (void)o;
  }
  return std::nullopt;
}

Command stored_run(const Fixture& f) {
  Command c;
  for (std::size_t i = 0; i + 1 < f.args.size(); i += 2)
    c.opts.push_back({f.args[i], f.args[i + 1]});
  return c;
}

/// A resume case: the arguments, and how to fill the case folder (the command runs in
/// case_dir/w; "d" below is case_dir/w/d).
struct ResumeCase {
  Case c;
  std::function<void(const fs::path&)> prepare;
};

ResumeCase resume_case(Rng& r, const std::vector<Fixture>& fx) {
  ResumeCase rc;
  auto& args = rc.c.args;
  auto write = [](const fs::path& p, const std::string& s) {
    std::ofstream(p, std::ios::binary) << s;
  };
  const std::size_t kind = r.below(100);
  args = {"resume", "d"};
  if (r.chance(0.2)) args.insert(args.begin() + static_cast<long>(1 + r.below(2)), "--json");
  if (kind < 8 || fx.empty()) {  // odd arguments and folders
    const int w = r.range(0, 11);
    switch (w) {
      case 0: args = {"resume"}; break;
      case 1: args = {"resume", "d", "e"}; break;
      case 2: args = {"resume", ""}; break;
      case 3: args = {"resume", " "}; break;
      case 4: args = {"resume", "d", "--bogus"}; break;
      case 5: args = {"resume", "--out", "d"}; break;
      case 6: args = {"resume", random_bytes(r, 20)}; break;
      case 7: args = {"resume", "d", "--n", "5"}; break;
      default: break;
    }
    rc.c.what = "resume args " + std::to_string(w);
    rc.prepare = [w, write](const fs::path& dir) {
      if (w == 8) write(dir / "w" / "d", "plain file");  // not a folder
      if (w == 9) fs::create_directories(dir / "w" / "d");  // empty folder
      if (w == 10) fs::create_directories(dir / "w" / "d" / "checkpoint.hgck");  // a folder
      if (w == 11) {  // a dangling link
        fs::create_directories(dir / "w" / "d");
        fs::create_symlink("nowhere", dir / "w" / "d" / "checkpoint.hgck");
      }
    };
    return rc;
  }
  const Fixture& f = fx[r.below(fx.size())];
  std::string file;           // checkpoint.hgck to write, raw
  std::optional<std::string> payload;  // or a payload to frame with a valid checksum
  bool crashed = false;
  if (kind < 12) {
    file = "";
    rc.c.what = "resume empty checkpoint";
  } else if (kind < 18) {
    file = random_bytes(r, 4000);
    if (r.chance(0.5)) file = "HGCKPT\r\n" + file;
    rc.c.what = "resume garbage checkpoint";
  } else if (kind < 30) {
    file = f.file.substr(0, r.below(f.file.size()));
    rc.c.what = "resume truncated checkpoint";
  } else if (kind < 38) {
    file = f.file;
    for (int k = r.range(1, 4); k > 0; --k)
      file[r.below(file.size())] ^= static_cast<char>(1 + r.below(255));
    rc.c.what = "resume corrupted checkpoint";
  } else if (kind < 42) {
    file = f.file + random_bytes(r, 64) + "x";
    rc.c.what = "resume extended checkpoint";
  } else if (kind < 46) {
    file = f.file;
    std::uint64_t size = 0;
    std::memcpy(&size, file.data() + 16, 8);
    size = r.chance(0.5) ? size + 1 + r.below(100) : (r.chance(0.5) ? 0 : ~0ULL);
    std::memcpy(file.data() + 16, &size, 8);
    rc.c.what = "resume wrong size field";
  } else if (kind < 70) {
    // A valid frame around a header with mutated run arguments and the original state: the
    // arguments are parsed and validated again, the state must fit them.
    Args stored;
    std::string what;
    for (int attempt = 0; attempt < 30; ++attempt) {
      Command c = stored_run(f);
      what = mutate(r, c, dsmc_spec());
      if (r.chance(0.3)) what += "; " + mutate(r, c, edmd_spec());
      stored = c.flatten();
      Args probe = stored;
      probe.push_back("--out");
      probe.push_back("d");
      if (!run_costly(probe, f.n, f.until, f.every)) break;
      stored = f.args;
      what = "none";
    }
    payload = header_payload(f.tag, f.id, stored) + f.rest;
    rc.c.what = "resume " + f.name + " stored args: " + what;
  } else if (kind < 76) {
    const int w = r.range(0, 2);
    payload = header_payload(w == 0 ? "hypergas-runs" : f.tag,
                             w == 1 ? "hypergas 0.0.0 (other build)" : f.id,
                             w == 2 ? Args{} : f.args) +
              f.rest;
    rc.c.what = "resume " + f.name + " header " + std::to_string(w);
  } else if (kind < 86) {
    // The state cut short, framed validly.
    const std::string full = header_payload(f.tag, f.id, f.args) + f.rest;
    payload = full.substr(0, r.below(full.size()));
    rc.c.what = "resume " + f.name + " cut payload";
  } else if (kind < 90) {
    payload = header_payload(f.tag, f.id, f.args) + f.rest + random_bytes(r, 16) + "x";
    rc.c.what = "resume " + f.name + " payload with extra bytes";
  } else if (kind < 94) {
    // Bytes of the state changed, framed validly (a forged file): refused or run, not crash.
    std::string rest = f.rest;
    for (int k = r.range(1, 3); k > 0; --k)
      rest[r.below(rest.size())] ^= static_cast<char>(1 << r.below(8));
    payload = header_payload(f.tag, f.id, f.args) + rest;
    rc.c.what = "resume " + f.name + " forged state";
  } else if (kind < 98) {
    file = f.file;
    rc.c.what = "resume " + f.name + " valid";
  } else {
    crashed = true;
    rc.c.what = "resume " + f.name + " crashed folder";
  }
  const fs::path crashed_dir = f.crashed;
  rc.prepare = [file, payload, crashed, crashed_dir, write](const fs::path& dir) {
    const fs::path d = dir / "w" / "d";
    if (crashed) {
      fs::copy(crashed_dir, d, fs::copy_options::recursive);
      return;
    }
    fs::create_directories(d);
    if (payload) write_framed(d / "checkpoint.hgck", *payload);
    else write(d / "checkpoint.hgck", file);
  };
  return rc;
}

}  // namespace

TEST_CASE("run --engine dsmc with mutated arguments keeps the contract", "[fuzz]") {
  const Spec spec = dsmc_spec();
  fuzz_area("run-dsmc", 1, cases_for(0.30), [&](Rng& r) {
    const auto [a, what] = mutated(r, dsmc_run(r), spec);
    return Case{a, what};
  });
}

TEST_CASE("run --engine edmd with mutated arguments keeps the contract", "[fuzz]") {
  const Spec spec = edmd_spec();
  fuzz_area("run-edmd", 2, cases_for(0.25), [&](Rng& r) {
    const auto [a, what] = mutated(r, edmd_run(r), spec);
    return Case{a, what};
  });
}

TEST_CASE("bench with mutated arguments keeps the contract", "[fuzz]") {
  const Spec spec = bench_spec();
  fuzz_area("bench", 3, cases_for(0.12), [&](Rng& r) {
    const auto [a, what] = mutated(r, bench_cmd(r), spec);
    return Case{a, what};
  });
}

TEST_CASE("default scene, report, help and unknown subcommands keep the contract",
          "[fuzz]") {
  const Spec scene = scene_spec(), report = report_spec(), dsmc = dsmc_spec();
  fuzz_area("other", 4, cases_for(0.08), [&](Rng& r) {
    const std::size_t k = r.below(10);
    if (k < 4) {
      const auto [a, what] = mutated(r, scene_cmd(r), scene);
      return Case{a, "scene: " + what};
    }
    if (k < 6) {
      const auto [a, what] = mutated(r, report_cmd(r), report);
      return Case{a, "report: " + what};
    }
    if (k < 8) {  // help of every subcommand, with mutations
      Command c{{}, {{"--help", std::nullopt}}};
      if (r.chance(0.8)) c.head = {r.pick(subcommands)};
      const auto [a, what] = mutated(r, c, dsmc, 0.3);
      return Case{a, "help: " + what};
    }
    // An unknown subcommand with the options of a valid run.
    for (;;) {
      Command c = dsmc_run(r);
      c.head[0] = r.chance(0.7) ? r.pick(subcommand_names) : random_text(r);
      if (!too_costly(c.flatten())) return Case{c.flatten(), "subcommand " + c.head[0]};
    }
  });
}

TEST_CASE("random byte strings as arguments keep the contract", "[fuzz]") {
  fuzz_area("bytes", 5, cases_for(0.15), [&](Rng& r) {
    for (;;) {
      Args a;
      if (r.chance(0.6)) a.push_back(r.pick(subcommands));
      for (int k = r.range(r.chance(0.5) ? 1 : 0, 6); k > 0; --k)
        a.push_back(r.chance(0.7) ? random_bytes(r) : random_text(r, 20));
      if (r.chance(0.3)) {  // mixed with a valid run's options
        const Args base = dsmc_run(r).flatten();
        a.insert(a.begin() + static_cast<long>(r.below(a.size() + 1)), base.begin() + 1,
                 base.end());
      }
      if (!too_costly(a)) return Case{a, "random bytes"};
    }
  });
}

TEST_CASE("resume with missing, garbage, truncated or forged checkpoints keeps the "
          "contract",
          "[fuzz]") {
  Area area("resume");
  // Two real checkpoints, one per engine, each the only one its run writes.
  std::vector<Fixture> fx;
  const fs::path froot = area.root() / "fixtures";
  fs::create_directories(froot);
  if (auto f = take_checkpoint("dsmc",
                               {"run", "--engine", "dsmc", "--dim", "3", "--n", "5000", "--until",
                                "40", "--every", "0.2", "--checkpoint-every", "24"},
                               froot, area.io()))
    fx.push_back(*f);
  if (auto f = take_checkpoint("edmd",
                               {"run", "--engine", "edmd", "--dim", "3", "--n", "200",
                                "--packing", "0.2", "--until", "10", "--every", "0.1",
                                "--checkpoint-every", "6"},
                               froot, area.io()))
    fx.push_back(*f);
  CHECK(fx.size() == 2);  // else the command could not be stopped at a checkpoint

  Failures fail("resume");
  const long count = cases_for(0.10);
  for (long k = 0; k < count; ++k) {
    const std::uint64_t s = case_seed(6, k);
    Rng r(s);
    ResumeCase rc = resume_case(r, fx);
    rc.c.gnuplot = r.chance(0.08);
    area.run(rc.c, k, s, fail, rc.prepare);
  }
  fail.report();
  const std::string summary = "resume: " + std::to_string(count) + " cases (" +
                              area.code_counts() + "); " + std::to_string(fail.hangs()) +
                              " hung, " + std::to_string(fail.contract_failures()) +
                              " broke the contract, " + std::to_string(fail.kinds()) +
                              " distinct kinds";
  if (env_long("HYPERGAS_FUZZ_VERBOSE", 0)) WARN(summary);
  fail.require_none(summary);
}
#endif
