// sim/default_scene.cpp -- `hypergas` with no subcommand: relaxation to Maxwell–Boltzmann
// in every D = 1..6.
//
// The story: N hard spheres start on a delta shell (all speeds equal, directions uniform),
// as far from Maxwell–Boltzmann as an isotropic gas gets. Velocity-space DSMC (the Kac
// process, exact in time) lets them collide. In D >= 2 one mass suffices; in D = 1 equal
// masses only swap velocities, so the 1D gas is a 1:3 two-mass mixture. For each D the table
// gives the collisions per particle until the L1 distance of the speed histogram from MB
// first falls below a stated threshold, then the final KS p-value of the speeds against MB,
// the final kurtosis of v_x (MB: 3) and the engine's throughput. The 1D gas runs to three
// times --until, which a note on stderr says.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <thread>

#include <fmt/core.h>

#include "commands.hpp"
#include "engine_runs.hpp"
#include "hypergas/analysis/output.hpp"
#include "hypergas/error.hpp"
#include "hypergas/options/from_given.hpp"
#include "hypergas/rng.hpp"
#include "hypergas/vec.hpp"
#include "hypergas/studies/gnuplot.hpp"
#include "output_dir.hpp"
#include "plot_scripts.hpp"
#include "run_summary.hpp"
#include "progress.hpp"

namespace hypergas::cli {

namespace {

/// The stated distance: L1 distance sum |p_i - P_i| of the 50-bin speed histogram from MB
/// (0..2). Its sampling-noise floor is about 0.025 at N = 20000 (analysis/statistics.hpp:
/// E[L1] ~ sum_i sqrt(2 P_i / (pi N))), so 0.05 is reached only by a relaxed gas.
constexpr double l1_threshold = 0.05;
/// Mass ratio of the 1D two-mass gas (fraction 1/2 of each).
constexpr double mass_ratio_1d = 3.0;
/// The 1D run's time in units of --until: the two-mass 1D gas relaxes more slowly.
constexpr double until_factor_1d = 3.0;

/// First time (in the units of x) at which y falls below `level`, linearly interpolated;
/// NaN if it never does.
double first_crossing(const std::vector<double>& x, const std::vector<double>& y, double level) {
  for (std::size_t k = 0; k < y.size(); ++k)
    if (y[k] < level) {
      if (k == 0) return x[0];
      const double f = (y[k - 1] - level) / (y[k - 1] - y[k]);
      return x[k - 1] + f * (x[k] - x[k - 1]);
    }
  return std::numeric_limits<double>::quiet_NaN();
}

/// The run of dimension d, validated as the command's (options::make): a scene that cannot
/// build an invalid run.
RunOptions scene_run(const SceneOptions& s, int d) {
  return options::make(registry::EngineKind::dsmc, [&](RunOptions& o) {
    o.dim = d;
    o.model = dsmc::HardSpheres::name;
    o.init = InitialState::delta;
    o.n = s.n;
    o.seed = Rng(s.seed).split(static_cast<std::uint64_t>(d))();
    o.until = d == 1 ? until_factor_1d * s.until : s.until;
    o.every = o.until / 80.0;
    if (d == 1) {
      o.mass_ratio = mass_ratio_1d;
      o.fraction = 0.5;
      o.n -= o.n % 4;  // delta shell in 1D: an even number of particles per species
    }
  });
}

void validate(const SceneOptions& s) {
  if (s.n < 8) throw InvalidInput(fmt::format("--n must be at least 8 particles, got {}", s.n));
  if (s.n > (1LL << 31)) throw InvalidInput(fmt::format("--n must be at most 2^31, got {}", s.n));
  if (!(std::isfinite(s.until) && s.until > 0.0))
    throw InvalidInput(fmt::format("--until must be a finite time > 0, got {}", s.until));
}

}  // namespace

int default_scene(const SceneOptions& s) {
  validate(s);
  OutputDir out(s.out);

  std::vector<int> dims;
  for (int d = min_dim; d <= max_dim; ++d) dims.push_back(d);
  std::vector<RunRecord> records(dims.size());

  // The dimensions are independent: run them on up to two threads (the machine the default
  // scene is timed on has two cores). Each run keeps its own recorders.
  const unsigned workers = std::clamp(std::thread::hardware_concurrency(), 1u, 2u);
  std::atomic<std::size_t> next{0}, done{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  Progress bar("relaxing D = 1..6", static_cast<double>(dims.size()));
  auto work = [&] {
    for (std::size_t k; (k = next++) < dims.size();) {
      try {
        records[k] = simulate(scene_run(s, dims[k]), false);
      } catch (...) {
        std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
        next = dims.size();
      }
      ++done;
    }
  };
  std::vector<std::thread> pool;
  for (unsigned w = 1; w < workers; ++w) pool.emplace_back(work);
  std::thread watcher([&] {
    while (done < dims.size() && !error) {
      bar.update(static_cast<double>(done));
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  });
  work();
  for (auto& t : pool) t.join();
  watcher.join();
  bar.finish();
  if (error) std::rethrow_exception(error);
  // D = 1 runs longer than the others: say so, on stderr (stdout is the table)
  fmt::print(stderr,
             "hypergas: note: D = 1 runs to t = {:g}, {:g} times --until {:g}: its 1:{:g} "
             "two-mass gas relaxes more slowly than the one-mass gases of D >= 2\n",
             scene_run(s, 1).until, until_factor_1d, s.until, mass_ratio_1d);

  fmt::print("Relaxation of a hard-sphere gas from a delta shell (all speeds equal) to "
             "Maxwell-Boltzmann,\nvelocity-space DSMC, N = {} per dimension (D = 1: masses "
             "1:{:g}, half each; equal masses never relax in 1D).\n",
             s.n, mass_ratio_1d);
  fmt::print("t_{:g}: collisions per particle until the L1 distance of the speed histogram "
             "from MB first drops below {:g}.\n\n",
             l1_threshold, l1_threshold);
  fmt::print("{:>2}  {:>8}  {:>6}  {:>8}  {:>12}  {:>8}  {:>14}  {:>12}\n", "D", "N", "masses",
             "t_" + fmt::format("{:g}", l1_threshold), "coll/particle", "KS p", "kurtosis_x",
             "collisions/s");
  std::vector<std::vector<double>> table;
  for (std::size_t k = 0; k < dims.size(); ++k) {
    const int d = dims[k];
    const RunRecord& r = records[k];
    const auto cpp = r.moments().recorder().column("collisions_per_particle");
    const double t_reach = first_crossing(cpp, r.moments().recorder().column("l1_speed"), l1_threshold);
    const double ks = r.moments().recorder().column("ks_p_speed").back();
    const double kurt = r.moments().recorder().column("kurtosis_x").back();
    const double kurt_err = r.moments().recorder().column("kurtosis_x_err").back();
    const double rate = summary_number(r.summary, "collisions_per_s");
    const double n = summary_number(r.summary, "n");
    const std::string reach =
        std::isnan(t_reach) ? fmt::format("> {:.1f}", cpp.back()) : fmt::format("{:.2f}", t_reach);
    fmt::print("{:>2}  {:>8}  {:>6}  {:>8}  {:>12.2f}  {:>8.3f}  {:>6.3f} ± {:<5.3f}  {:>12.3e}\n", d,
               n, d == 1 ? fmt::format("1:{:g}", mass_ratio_1d) : "1", reach, cpp.back(), ks, kurt,
               kurt_err, rate);
    table.push_back({static_cast<double>(d), n, d == 1 ? mass_ratio_1d : 1.0, t_reach,
                     cpp.back(), ks, kurt, kurt_err, rate});
    r.moments().recorder().write_moments_csv(out.staged(fmt::format("relaxation_D{}.csv", d)).string());
    r.moments().recorder().write_speed_histogram_csv(
        out.staged(fmt::format("speed_histogram_D{}.csv", d)).string());
  }
  analysis::write_csv(out.staged("summary.csv").string(),
                      {"dim", "n", "mass_ratio", "collisions_per_particle_to_threshold",
                       "collisions_per_particle", "ks_p_speed", "kurtosis_x", "kurtosis_x_err",
                       "collisions_per_s"},
                      table);
  studies::run_gnuplot(scene_plot_script(dims, l1_threshold), out.staging());
  out.commit();
  fmt::print("\nwrote {}/: {} files (summary.csv, relaxation_D<d>.csv, speed_histogram_D<d>.csv",
             out.dir().string(), out.committed().size());
  const bool pngs = std::any_of(out.committed().begin(), out.committed().end(),
                                [](const std::string& f) { return f.ends_with(".png"); });
  fmt::print("{})\n", pngs ? ", relaxation.png, kurtosis.png, speed_histograms.png" : "");
  return 0;
}

}  // namespace hypergas::cli
