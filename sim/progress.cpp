// sim/progress.cpp -- terminal progress bar and interrupt flag.
#include "progress.hpp"

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <unistd.h>

#include <fmt/core.h>

namespace hypergas::cli {

namespace {
volatile std::sig_atomic_t g_interrupted = 0;
// First signal: ask the run to stop at its next snapshot (cleaning up its output folder).
// The handler then resets itself, so a second Ctrl-C terminates at once.
extern "C" void on_signal(int sig) {
  g_interrupted = 1;
  std::signal(sig, SIG_DFL);
}
}  // namespace

bool interrupted() { return g_interrupted != 0; }

void install_interrupt_handler() {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
}

namespace {
/// Returns to the start of the stderr line and erases it.
void erase_line() {
  fmt::print(stderr, "\r\033[K");
  std::fflush(stderr);
}
}  // namespace

bool Progress::enabled() { return ::isatty(STDERR_FILENO) == 1; }

Progress::Progress(std::string label, double total)
    : label_(std::move(label)), total_(total), on_(enabled()),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

Progress::~Progress() { finish(); }

void Progress::update(double done) {
  if (!on_) return;
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  const double f = total_ > 0.0 ? std::clamp(done / total_, 0.0, 1.0) : 1.0;
  constexpr int width = 30;
  const int filled = static_cast<int>(f * width);
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double eta = f > 0.0 ? elapsed * (1.0 - f) / f : 0.0;
  fmt::print(stderr, "\r{} [{}{}] {:3.0f}%  t = {:.4g} of {:.4g}  eta {:.0f} s ", label_,
             std::string(filled, '#'), std::string(width - filled, '.'), 100.0 * f, done, total_,
             eta);
  std::fflush(stderr);
  drawn_ = true;
}

SetupLine::SetupLine(const std::string& text, bool show) : on_(show && Progress::enabled()) {
  if (!on_) return;
  fmt::print(stderr, "\r{} ...", text);
  std::fflush(stderr);
}

SetupLine::~SetupLine() {
  if (on_) erase_line();
}

void Progress::finish() {
  if (!on_ || !drawn_) return;
  erase_line();
  drawn_ = false;
}

}  // namespace hypergas::cli
