// sim/run_observer.hpp -- the observer a command hands to an engine: forwards each snapshot
// to the analysis recorders, draws the progress bar, honours Ctrl-C, and keeps the total
// energy and momentum of the first and the latest snapshot for the drift figures.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "hypergas/observer.hpp"
#include "hypergas/particles.hpp"
#include "progress.hpp"

namespace hypergas::cli {

/// Total kinetic energy sum m v^2 / 2 and momentum sum m v of a snapshot, in long double,
/// plus the momentum scale sum m |v| that the momentum drift is measured against.
struct Conserved {
  long double energy = 0.0L;
  std::array<long double, 6> momentum{};
  long double momentum_scale = 0.0L;
};

/// Sums over particles of finite mass (infinite masses carry no energy).
template <int D, Features F>
Conserved conserved(const Particles<D, F>& p) {
  Conserved c;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double w = p.inv_mass(i);
    if (!(w > 0.0)) continue;
    const long double m = 1.0L / w;
    long double v2 = 0.0L;
    for (int k = 0; k < D; ++k) {
      const long double vk = p.velocity(i)[k];
      v2 += vk * vk;
      c.momentum[k] += m * vk;
    }
    c.energy += 0.5L * m * v2;
    c.momentum_scale += m * std::sqrt(v2);
  }
  return c;
}

/// Relative energy drift |E1 - E0| / E0 (dimensionless).
double energy_rel_drift(const Conserved& a, const Conserved& b);
/// Momentum drift |P1 - P0| / sum m |v| at the start (dimensionless).
double momentum_drift(const Conserved& a, const Conserved& b);

/// Forwards snapshots to `targets`, updates a progress bar over [0, end_time], throws
/// Interrupted after SIGINT/SIGTERM, and measures the wall time spent in the targets.
class RunObserver final : public Observer {
 public:
  RunObserver(std::vector<Observer*> targets, const char* label, double end_time,
              bool show_progress = true);
  void observe(const Snapshot& s) override;

  std::size_t snapshots() const { return count_; }
  /// Wall seconds spent in the targets (analysis), to subtract from the engine's time.
  double analysis_seconds() const { return analysis_s_; }

 private:
  std::vector<Observer*> targets_;
  Progress progress_;
  bool show_;
  std::size_t count_ = 0;
  double analysis_s_ = 0.0;
};

}  // namespace hypergas::cli
