// gnuplot subprocess (fork + exec, script on its stdin).
#include "hypergas/studies/gnuplot.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "plot_report_gp.hpp"  // generated from scripts/plot_report.gp

namespace hypergas::studies {

bool gnuplot_available() {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::string p(path);
  for (std::size_t start = 0; start <= p.size();) {
    const std::size_t end = std::min(p.find(':', start), p.size());
    const std::string dir = p.substr(start, end - start);
    const std::string exe = (dir.empty() ? std::string(".") : dir) + "/gnuplot";
    if (::access(exe.c_str(), X_OK) == 0) return true;
    start = end + 1;
  }
  return false;
}

namespace {
void warn_missing() {
  static bool warned = false;
  if (!warned)
    std::fprintf(stderr, "hypergas: gnuplot not found; skipping PNG plots (CSV written)\n");
  warned = true;
}
}  // namespace

GnuplotProcess::GnuplotProcess(const std::filesystem::path& dir) {
  if (!gnuplot_available()) return;
  int fds[2];
  if (::pipe(fds) != 0) return;
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return;
  }
  if (pid == 0) {  // child: stdin from the pipe, stdout discarded, stderr kept
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // dies with a killed parent: no orphan plotting
    ::signal(SIGINT, SIG_IGN);           // Ctrl-C is the parent's to handle
    ::dup2(fds[0], STDIN_FILENO);
    ::close(fds[0]);
    ::close(fds[1]);
    const int null = ::open("/dev/null", O_WRONLY);
    if (null >= 0) ::dup2(null, STDOUT_FILENO);
    if (::chdir(dir.c_str()) != 0) ::_exit(127);
    ::execlp("gnuplot", "gnuplot", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(fds[0]);
  ::fcntl(fds[1], F_SETFD, FD_CLOEXEC);  // later children (another plot) do not inherit it
  pid_ = pid;
  fd_ = fds[1];
}

GnuplotProcess::~GnuplotProcess() {
  if (pid_ < 0) return;
  ::close(fd_);
  ::kill(pid_, SIGKILL);
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
}

bool GnuplotProcess::finish(std::string_view script) {
  if (pid_ < 0) {
    if (!gnuplot_available()) warn_missing();
    return false;
  }
  std::signal(SIGPIPE, SIG_IGN);  // gnuplot may exit before reading everything
  const char* p = script.data();
  std::size_t left = script.size();
  while (left > 0) {
    const ssize_t w = ::write(fd_, p, left);
    if (w <= 0) break;
    p += w;
    left -= static_cast<std::size_t>(w);
  }
  ::close(fd_);
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (!ok) std::fprintf(stderr, "hypergas: gnuplot failed; PNG plots may be missing\n");
  return ok;
}

bool run_gnuplot(std::string_view script, const std::filesystem::path& dir) {
  if (!gnuplot_available()) {
    warn_missing();
    return false;
  }
  return GnuplotProcess(dir).finish(script);
}

std::string_view report_plot_script() { return embedded::plot_report_gp; }

}  // namespace hypergas::studies
