// bench/bench_tally.cpp -- what the collision-level observer costs the DSMC engine.
// Usage: bench_tally [--dims 3,6] [--ns 1000000] [--until 10] [--reps 3]
// Per (D, N): `reps` interleaved pairs of the same run (hard spheres, beams, seed 1, to
// `until`) without and with a tally installed (what `hypergas run` records), and one
// streaming read of the velocity array (the floor of any pass over the particles), all in
// this process. Prints one JSON line per (D, N): the medians, the tally's overhead as a
// fraction of the unrecorded engine time, and the read's time per particle.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "hypergas/analysis/moments_recorder.hpp"
#include "hypergas/dsmc/engine.hpp"
#include "hypergas/error.hpp"
#include "hypergas/registry.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  return x[x.size() / 2];
}

template <int D>
void measure(std::size_t n, double until, int reps) {
  using Engine = hypergas::dsmc::Engine<D, hypergas::dsmc::HardSpheres>;
  hypergas::dsmc::Config cfg;
  cfg.n = n;
  cfg.seed = 1;
  cfg.init = hypergas::InitialState::beams;
  std::vector<double> plain, kept, read;
  double collisions = 0.0;
  for (int r = 0; r < reps; ++r)
    for (int with = 0; with < 2; ++with) {
      Engine e(cfg);
      hypergas::analysis::MomentsRecorder rec;
      if (with) e.observe(rec);  // installs the tally
      const auto t0 = Clock::now();
      e.run_until(until);
      const double s = std::chrono::duration<double>(Clock::now() - t0).count();
      (with ? kept : plain).push_back(s);
      collisions = static_cast<double>(e.collisions());
      if (with) {  // the floor: one streaming read of the velocity array
        const auto& v = e.particles().velocity_data();
        const auto r0 = Clock::now();
        double sum[8] = {};  // eight chains: the read, not the additions, is the limit
        const std::size_t m = v.size() / 8 * 8;
        for (std::size_t i = 0; i < m; i += 8)
          for (int k = 0; k < 8; ++k) sum[k] += v[i + k] * v[i + k];
        read.push_back(std::chrono::duration<double>(Clock::now() - r0).count());
        if (sum[0] + sum[7] < 0.0) std::puts("");  // keeps the read
      }
    }
  const double p = median(plain), k = median(kept);
  std::printf(
      "{\"bench\":\"tally\",\"dim\":%d,\"n\":%zu,\"until\":%g,\"reps\":%d,"
      "\"collisions\":%.0f,\"engine_s\":%.4f,\"engine_tally_s\":%.4f,"
      "\"tally_overhead\":%.3f,\"ns_per_collision\":%.2f,\"read_ns_per_particle\":%.3f}\n",
      D, n, until, reps, collisions, p, k, k / p - 1.0, 1e9 * (k - p) / collisions,
      1e9 * median(read) / static_cast<double>(n));
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::size_t a = 0;
  for (std::size_t b; (b = s.find(',', a)) != std::string::npos; a = b + 1)
    out.push_back(s.substr(a, b - a));
  out.push_back(s.substr(a));
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::vector<int> dims{3, 6};
    std::vector<std::size_t> ns{1000000};
    double until = 10.0;
    int reps = 3;
    for (int i = 1; i < argc; i += 2) {
      const std::string k = argv[i];
      if (k == "-h" || k == "--help") {
        std::cout << "Usage: bench_tally [--dims 3,6] [--ns 1000000] [--until 10] [--reps 3]\n";
        return 0;
      }
      if (i + 1 >= argc) throw hypergas::InvalidInput(k + " needs a value");
      const std::string v = argv[i + 1];
      if (k == "--dims") {
        dims.clear();
        for (const auto& d : split(v)) dims.push_back(std::stoi(d));
      } else if (k == "--ns") {
        ns.clear();
        for (const auto& x : split(v)) ns.push_back(static_cast<std::size_t>(std::stod(x)));
      } else if (k == "--until") {
        until = std::stod(v);
      } else if (k == "--reps") {
        reps = std::stoi(v);
      } else {
        throw hypergas::InvalidInput("unknown option " + k);
      }
    }
    if (reps < 1 || !(until > 0.0)) throw hypergas::InvalidInput("need reps >= 1, until > 0");
    for (int d : dims)
      for (std::size_t n : ns) {
        if (d == 3) measure<3>(n, until, reps);
        else if (d == 6) measure<6>(n, until, reps);
        else if (d == 2) measure<2>(n, until, reps);
        else throw hypergas::InvalidInput("--dims: 2, 3 or 6");
      }
  } catch (const std::exception& e) {
    std::cerr << "bench_tally: " << e.what() << "\n";
    return 2;
  }
}
