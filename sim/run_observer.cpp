// sim/run_observer.cpp -- the forwarding observer.
#include "run_observer.hpp"

#include <chrono>

namespace hypergas::cli {

RunObserver::RunObserver(std::vector<Observer*> targets, const char* label, double end_time,
                         bool show_progress)
    : targets_(std::move(targets)), progress_(label, end_time), show_(show_progress) {}

void RunObserver::observe(const Snapshot& s) {
  ++count_;
  const auto t0 = std::chrono::steady_clock::now();
  for (Observer* t : targets_) t->observe(s);
  analysis_s_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (show_) progress_.update(s.time);
}

void RunObserver::request(tally::Requests& r) {
  for (Observer* t : targets_) t->request(r);
}

}  // namespace hypergas::cli
