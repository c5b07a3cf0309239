// sim/run_observer.cpp -- conserved sums and the forwarding observer.
#include "run_observer.hpp"

#include <chrono>

namespace hypergas::cli {

double energy_rel_drift(const Conserved& a, const Conserved& b) {
  return a.energy > 0.0L ? static_cast<double>(std::fabs(b.energy - a.energy) / a.energy) : 0.0;
}

double momentum_drift(const Conserved& a, const Conserved& b) {
  long double d2 = 0.0L;
  for (std::size_t k = 0; k < a.momentum.size(); ++k) {
    const long double dp = b.momentum[k] - a.momentum[k];
    d2 += dp * dp;
  }
  return a.momentum_scale > 0.0L ? static_cast<double>(std::sqrt(d2) / a.momentum_scale) : 0.0;
}

RunObserver::RunObserver(std::vector<Observer*> targets, const char* label, double end_time,
                         bool show_progress)
    : targets_(std::move(targets)), progress_(label, end_time), show_(show_progress) {}

void RunObserver::observe(const Snapshot& s) {
  if (interrupted()) throw Interrupted{};
  ++count_;
  const auto t0 = std::chrono::steady_clock::now();
  for (Observer* t : targets_) t->observe(s);
  analysis_s_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (show_) progress_.update(s.time);
}

}  // namespace hypergas::cli
