// tests/cli/run_cli.hpp -- runs the built `hypergas` binary (path from HYPERGAS_CLI_PATH), or
// another program such as an MPI launcher running it, with given arguments and captures its
// exit code, stdout and stderr, for the CLI tests.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <catch2/catch.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace cli_test {

namespace fs = std::filesystem;

/// What a finished run of the command left: exit code (128 + signal if killed) and output.
struct Result {
  int code = -1;
  int signal = 0;  // the signal that ended the command, 0 if it exited
  std::string out, err;
};

inline std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

/// A fresh, empty scratch folder under the system temp folder, removed at scope exit.
class Scratch {
 public:
  explicit Scratch(const std::string& tag) {
    static int counter = 0;
    path_ = fs::temp_directory_path() /
            ("hypergas-cli-" + tag + "-" + std::to_string(::getpid()) + "-" +
             std::to_string(counter++));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }
  /// Number of entries (files and folders, recursively) below the scratch folder.
  std::size_t entries() const {
    std::size_t k = 0;
    for ([[maybe_unused]] const auto& e : fs::recursive_directory_iterator(path_)) ++k;
    return k;
  }

 private:
  fs::path path_;
};

/// How a Child starts: which program, whether in a session or process group of its own,
/// with which environment, and where its output is captured.
struct Spawn {
  /// The program to run with the arguments (argv[0]); by default the `hypergas` command.
  std::string program = HYPERGAS_CLI_PATH;
  /// setsid() in the child before exec: the program and every process it starts (that does
  /// not leave the session itself) share a session and a process group whose id is the
  /// child's pid, so that Child::kill_session() reaches all of them. An MPI launcher moves
  /// each rank into a process group of its own (Open MPI does), but not out of the session.
  bool own_session = false;
  /// setpgid() in the child and the parent: a process group of its own whose id is the
  /// child's pid, so that Child::kill_group() reaches what the program starts.
  bool own_group = false;
  /// The environment ("NAME=value" each) instead of this process's.
  std::optional<std::vector<std::string>> env = std::nullopt;
  /// The folder of the files that capture stdout and stderr, instead of the child's `cwd`.
  fs::path io = {};
};

/// A running `hypergas args...` (or `how.program args...`) in folder `cwd`, stdin /dev/null
/// (so stderr is not a terminal: no progress bar), stdout and stderr captured in files of
/// `cwd` (or `how.io`). The tests send it a signal only once a readiness signal holds
/// (wait_until), never after a guessed time. A child still running at destruction is killed
/// (SIGKILL, with its whole session or process group if it has one of its own) and reaped.
/// pid() is negative if fork failed.
class Child {
 public:
  Child(const std::vector<std::string>& args, const fs::path& cwd, const Spawn& how = {})
      : own_session_(how.own_session), own_group_(how.own_group) {
    static int counter = 0;
    const std::string tag = std::to_string(::getpid()) + "-" + std::to_string(counter++);
    const fs::path& io = how.io.empty() ? cwd : how.io;
    out_ = io / (".stdout-" + tag + ".txt");
    err_ = io / (".stderr-" + tag + ".txt");
    std::vector<std::string> argv_s{how.program};
    argv_s.insert(argv_s.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : argv_s) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::vector<std::string> env_s = how.env.value_or(std::vector<std::string>{});
    std::vector<char*> envp;
    for (auto& e : env_s) envp.push_back(e.data());
    envp.push_back(nullptr);
    const std::string cwd_s = cwd.string(), out_s = out_.string(), err_s = err_.string();
    pid_ = ::fork();
    if (pid_ == 0) {
      if (how.own_session && ::setsid() < 0) ::_exit(126);
      if (how.own_group) ::setpgid(0, 0);
      const int fo = ::open(out_s.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      const int fe = ::open(err_s.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      const int fi = ::open("/dev/null", O_RDONLY);
      if (fo < 0 || fe < 0 || fi < 0 || ::chdir(cwd_s.c_str()) != 0) ::_exit(126);
      ::dup2(fi, 0);
      ::dup2(fo, 1);
      ::dup2(fe, 2);
      if (how.env) ::execve(argv[0], argv.data(), envp.data());
      else ::execv(argv[0], argv.data());
      ::_exit(127);
    }
    if (how.own_group && pid_ > 0) ::setpgid(pid_, pid_);
  }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;
  ~Child() {
    if (own_session_ && pid_ > 0) kill_session(SIGKILL);
    if (pid_ > 0 && !reaped_) {
      if (own_group_) ::kill(-pid_, SIGKILL);
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, &status_, 0);
    }
    std::error_code ec;
    fs::remove(out_, ec);
    fs::remove(err_, ec);
  }

  pid_t pid() const { return pid_; }

  /// Whether the command still runs (reaps it if it has ended).
  bool running() {
    if (reaped_ || pid_ <= 0) return false;
    if (::waitpid(pid_, &status_, WNOHANG) == pid_) reaped_ = true;
    return !reaped_;
  }

  /// Polls `ready()` every millisecond while the command runs. Returns true as soon as it
  /// holds with the command still running; false if the command ended first or `limit_s`
  /// passed (the command is then left running; wait() or the destructor ends it).
  template <class Ready>
  bool wait_until(Ready&& ready, double limit_s = 300.0) {
    const auto start = std::chrono::steady_clock::now();
    for (;;) {
      if (!running()) return false;
      if (ready()) return running();
      const std::chrono::duration<double> t = std::chrono::steady_clock::now() - start;
      if (t.count() > limit_s) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  }

  /// Waits `seconds` of wall time, or less if the command ends; returns whether it still runs.
  bool running_after(double seconds) {
    const auto start = std::chrono::steady_clock::now();
    while (running()) {
      const std::chrono::duration<double> t = std::chrono::steady_clock::now() - start;
      if (t.count() >= seconds) return true;
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    return false;
  }

  void signal(int sig) {
    if (running()) ::kill(pid_, sig);
  }

  /// For a child started with Spawn::own_group: sends `sig` to its process group (the
  /// command and what it started), also after the command itself has ended.
  void kill_group(int sig) {
    if (own_group_ && pid_ > 0) ::kill(-pid_, sig);
  }

  /// For a child started with Spawn::own_session: sends `sig` to its process group and to
  /// every live process of its session, again and again until none is left alive (zombies
  /// aside: they hold no files or locks), or `limit_s` passes; returns whether none is
  /// left. With SIGKILL this ends an MPI job as a whole: the launcher and every rank, and
  /// what they started. Reap the child with wait() after.
  bool kill_session(int sig = SIGKILL, double limit_s = 60.0) {
    if (!own_session_ || pid_ <= 0) return false;
    const auto start = std::chrono::steady_clock::now();
    for (;;) {
      if (!reaped_) ::kill(-pid_, sig);
      bool alive = false;
      std::error_code ec;
      for (const auto& e : fs::directory_iterator("/proc", ec)) {
        const std::string name = e.path().filename().string();
        if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
        // /proc/<pid>/stat: pid (comm) state ppid pgrp session ...; comm may hold spaces.
        const std::string st = slurp(e.path() / "stat");
        const auto close = st.rfind(')');
        if (close == std::string::npos) continue;
        std::istringstream fields(st.substr(close + 1));
        char state = 0;
        long ppid = 0, pgrp = 0, session = 0;
        if (!(fields >> state >> ppid >> pgrp >> session)) continue;
        if (session != pid_ || state == 'Z' || state == 'X') continue;
        alive = true;
        ::kill(static_cast<pid_t>(std::stol(name)), sig);
      }
      if (!alive) return true;
      const std::chrono::duration<double> t = std::chrono::steady_clock::now() - start;
      if (t.count() > limit_s) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  }

  /// Waits for the command to end and returns its exit code and output.
  Result wait() {
    if (!reaped_ && pid_ > 0) {
      ::waitpid(pid_, &status_, 0);
      reaped_ = true;
    }
    Result r;
    r.signal = WIFSIGNALED(status_) ? WTERMSIG(status_) : 0;
    r.code = WIFEXITED(status_) ? WEXITSTATUS(status_) : 128 + r.signal;
    r.out = slurp(out_);
    r.err = slurp(err_);
    return r;
  }

 private:
  pid_t pid_ = -1;
  bool own_session_ = false;
  bool own_group_ = false;
  int status_ = 0;
  bool reaped_ = false;
  fs::path out_, err_;
};

/// The number of key `key` in summary.json's text (one object on one line); NaN for null, and
/// a failed REQUIRE when the key is absent.
inline double json_number(const std::string& json, const std::string& key) {
  const std::string k = "\"" + key + "\": ";
  const auto pos = json.find(k);
  INFO("key " << key << " in " << json);
  REQUIRE(pos != std::string::npos);
  if (json.compare(pos + k.size(), 4, "null") == 0)
    return std::numeric_limits<double>::quiet_NaN();
  return std::strtod(json.c_str() + pos + k.size(), nullptr);
}

/// Runs `hypergas args...` in folder `cwd` to its end.
inline Result run(const std::vector<std::string>& args, const fs::path& cwd) {
  return Child(args, cwd).wait();
}

/// summary.json without the fields that measure the process rather than the physics (wall
/// and stage times, speed, memory, checkpoint and resume counts).
inline std::string physics_summary(const fs::path& file) {
  static const std::vector<std::string> skip = {
      "\"wall_s\"",   "\"collisions_per_s\"", "\"engine_s\"",  "\"analysis_s\"",
      "\"checkpoints\"", "\"resumes\"",       "\"peak_rss_bytes_per_particle\"",
      "\"output_s\"",  "\"setup_s\""};
  std::string text = slurp(file), out;
  // The file is one object on one line, pairs separated by `, "` (analysis/output.cpp).
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t next = text.find(", \"", pos);
    if (next == std::string::npos) next = text.size();
    const std::string pair = text.substr(pos, next - pos);
    const bool drop = std::any_of(skip.begin(), skip.end(), [&](const std::string& k) {
      return pair.find(k) != std::string::npos;
    });
    if (!drop) out += pair + "\n";
    pos = next + 2;
  }
  return out;
}

/// The identity of a file's current content as the tests see it (inode, modification time
/// to the nanosecond, size), or all zeros if it does not exist. A checkpoint is written to a
/// temporary file and renamed over the previous one, so each new checkpoint changes it.
struct FileStamp {
  std::uint64_t ino = 0, size = 0;
  std::int64_t sec = 0, nsec = 0;
  bool operator==(const FileStamp&) const = default;
  bool exists() const { return ino != 0; }
};

inline FileStamp stamp(const fs::path& p) {
  struct ::stat st {};
  if (::stat(p.c_str(), &st) != 0) return {};
  return {static_cast<std::uint64_t>(st.st_ino), static_cast<std::uint64_t>(st.st_size),
          static_cast<std::int64_t>(st.st_mtim.tv_sec),
          static_cast<std::int64_t>(st.st_mtim.tv_nsec)};
}

/// Whether `dir` holds a staging folder (.hypergas-staging-<pid>): the command has the
/// folder's lock (it creates the staging folder right after taking it) and its Ctrl-C
/// handler is installed (main installs it before any command starts).
inline bool has_staging(const fs::path& dir) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.path().filename().string().rfind(".hypergas-staging-", 0) == 0) return true;
  return false;
}

/// Lines of a text, without the newline characters.
inline std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> v;
  std::istringstream s(text);
  for (std::string l; std::getline(s, l);) v.push_back(l);
  return v;
}

/// The fields of a CSV line.
inline std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> f;
  std::size_t from = 0;
  for (;;) {
    const auto comma = line.find(',', from);
    f.push_back(line.substr(from, comma == std::string::npos ? std::string::npos : comma - from));
    if (comma == std::string::npos) return f;
    from = comma + 1;
  }
}

/// Column `name` of a CSV file, as numbers.
inline std::vector<double> column(const fs::path& csv, const std::string& name) {
  const auto rows = lines(slurp(csv));
  REQUIRE(!rows.empty());
  const auto head = fields(rows.front());
  const auto at = std::find(head.begin(), head.end(), name);
  INFO("column " << name << " of " << rows.front());
  REQUIRE(at != head.end());
  const auto i = static_cast<std::size_t>(at - head.begin());
  std::vector<double> v;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const auto f = fields(rows[r]);
    REQUIRE(f.size() == head.size());
    v.push_back(std::strtod(f[i].c_str(), nullptr));
  }
  return v;
}

}  // namespace cli_test
