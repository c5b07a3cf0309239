// MomentsRecorder's passes over a snapshot: the thread team and its chunks, the tally pass
// and the KS subsample (moments_recorder.hpp).
#include "hypergas/analysis/moments_recorder.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <utility>

#include "hypergas/error.hpp"

namespace hypergas::analysis {

void MomentsRecorder::set_threads(int threads) {
  if (threads < 1 || threads > 256)
    throw InvalidInput("MomentsRecorder: threads must be in 1..256, got " + std::to_string(threads));
  if (threads == 1)
    team_.p.reset();
  else if (!team_ || team_->size() != threads)
    team_.p = std::make_unique<ThreadTeam>(threads);
}

int MomentsRecorder::threads() const { return team_ ? team_->size() : 1; }

void MomentsRecorder::for_chunks(std::size_t chunks,
                                 const std::function<void(int, std::size_t)>& f) const {
  if (!team_ || chunks < 2) {
    for (std::size_t c = 0; c < chunks; ++c) f(0, c);
    return;
  }
  const int T = team_->size();
  std::vector<std::exception_ptr> failed(static_cast<std::size_t>(T));
  team_->run([&](int t) {
    try {
      for (std::size_t c = static_cast<std::size_t>(t); c < chunks; c += static_cast<std::size_t>(T))
        f(t, c);
    } catch (...) {
      failed[static_cast<std::size_t>(t)] = std::current_exception();
    }
  });
  for (const auto& e : failed)
    if (e) std::rethrow_exception(e);
}

tally::Tally MomentsRecorder::pass(const Snapshot& s) const {
  const std::size_t chunks = (s.n + chunk_size - 1) / chunk_size;
  const int T = chunks > 1 ? threads() : 1;
  std::vector<tally::Tally> part(static_cast<std::size_t>(T), tally::Tally(cfg_.layout));
  for_chunks(chunks, [&](int t, std::size_t c) {
    part[static_cast<std::size_t>(t)].add_snapshot(s, c * chunk_size,
                                                   std::min(s.n, (c + 1) * chunk_size));
  });
  for (int t = 1; t < T; ++t) part[0].merge(part[static_cast<std::size_t>(t)]);
  return std::move(part[0]);
}

std::vector<double> MomentsRecorder::ks_sample(const Snapshot& s, double m_mean,
                                               std::size_t row) const {
  const auto stride = static_cast<std::size_t>(s.stride);
  const auto speed = [&](std::size_t i) {
    const double* v = s.velocities + i * stride;
    double vv = 0.0;
    for (int k = 0; k < s.dim; ++k) vv += v[k] * v[k];
    return std::sqrt(vv) / std::sqrt(s.inverse_mass(i) * m_mean);
  };
  std::vector<double> out;
  if (s.n <= ks_cap_) {
    out.reserve(s.n);
    for (std::size_t i = 0; i < s.n; ++i) out.push_back(speed(i));
    return out;
  }
  const Rng stream = ks_rng_.split(row);
  const std::size_t chunks = (s.n + chunk_size - 1) / chunk_size;
  std::vector<std::vector<double>> part(chunks);
  for_chunks(chunks, [&](int, std::size_t c) {
    const std::size_t b = c * chunk_size, e = std::min(s.n, (c + 1) * chunk_size);
    // chunk c's share: floor(k e / n) - floor(k b / n) particles, drawn without
    // replacement (Floyd's algorithm) from its own stream, taken in particle order
    __extension__ using u128 = unsigned __int128;  // k e may exceed 2^64
    const u128 k = ks_cap_, n = s.n;
    const auto want = static_cast<std::size_t>(k * e / n - k * b / n);
    std::vector<bool> chosen(e - b, false);
    Rng r = stream.split(c);
    for (std::size_t j = e - b - want; j < e - b; ++j) {
      const std::size_t x = static_cast<std::size_t>(r.below(j + 1));
      chosen[chosen[x] ? j : x] = true;
    }
    part[c].reserve(want);
    for (std::size_t i = b; i < e; ++i)
      if (chosen[i - b]) part[c].push_back(speed(i));
  });
  out.reserve(ks_cap_);
  for (const auto& p : part) out.insert(out.end(), p.begin(), p.end());
  return out;
}

}  // namespace hypergas::analysis
