// tests/cli/run_cli.hpp -- runs the built `hypergas` binary (path from HYPERGAS_CLI_PATH) with
// given arguments and captures its exit code, stdout and stderr, for the CLI tests.
#pragma once

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace cli_test {

namespace fs = std::filesystem;

/// What a finished run of the command left: exit code (128 + signal if killed) and output.
struct Result {
  int code = -1;
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

/// Runs `hypergas args...` in folder `cwd`; if `signal_after_s` > 0 and the command still
/// runs after that many seconds, sends it `sig` (SIGINT: Ctrl-C; SIGKILL: a kill). stdin is
/// /dev/null, so stderr is not a terminal (no progress bar).
inline Result run(const std::vector<std::string>& args, const fs::path& cwd,
                  double signal_after_s = 0.0, int sig = SIGINT) {
  const fs::path out = cwd / ".stdout.txt", err = cwd / ".stderr.txt";
  std::vector<std::string> argv_s{HYPERGAS_CLI_PATH};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int fo = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int fe = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int fi = ::open("/dev/null", O_RDONLY);
    if (fo < 0 || fe < 0 || fi < 0 || ::chdir(cwd.c_str()) != 0) ::_exit(126);
    ::dup2(fi, 0);
    ::dup2(fo, 1);
    ::dup2(fe, 2);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  int status = 0;
  if (signal_after_s > 0.0) {
    const auto start = std::chrono::steady_clock::now();
    for (;;) {
      if (::waitpid(pid, &status, WNOHANG) == pid) break;
      const std::chrono::duration<double> t = std::chrono::steady_clock::now() - start;
      if (t.count() >= signal_after_s) {
        ::kill(pid, sig);
        ::waitpid(pid, &status, 0);
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  } else {
    ::waitpid(pid, &status, 0);
  }
  Result r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = slurp(out);
  r.err = slurp(err);
  fs::remove(out);
  fs::remove(err);
  return r;
}

/// Lines of a text, without the newline characters.
inline std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> v;
  std::istringstream s(text);
  for (std::string l; std::getline(s, l);) v.push_back(l);
  return v;
}

}  // namespace cli_test
