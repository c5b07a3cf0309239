// hypergas/dsmc/detail/self_check.hpp -- the debug self-check (Engine::set_self_check): the
// candidate loop re-tests every pending candidate of its batch before each step, and each
// parallel block is replayed one candidate at a time on a copy of the velocities. Both
// count disagreements in State::check_failures; a correct engine counts 0
// (tests/unit/test_dsmc_engine.cpp, test_dsmc_parallel.cpp).
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "hypergas/dsmc/detail/batch.hpp"
#include "hypergas/dsmc/detail/state.hpp"

namespace hypergas::dsmc::detail {

/// Every pending mask bit of batch b from candidate `from` on must equal a fresh test with
/// the state of now; counts and corrects the differences.
template <int D, class Model, Features F>
void verify_batch(State<D, Model, F>& s, const Batch& b, int from, double G,
                  std::uint32_t& mask) {
  for (int c = from; c < batch_size; ++c) {
    if ((b.skip >> c) & 1u) continue;
    const bool fresh = test(s, b, c, G);
    if (fresh != bool((mask >> c) & 1u)) {
      ++s.check_failures;
      mask ^= 1u << c;
    }
  }
}

/// The velocity components into / out of a flat copy.
template <int D, class Model, Features F>
void save_velocities(const State<D, Model, F>& s, std::vector<double>& to) {
  constexpr int stride = State<D, Model, F>::stride;
  to.resize(std::size_t(s.n) * D);
  const double* v = s.p.velocity_data().data();
  for (std::size_t q = 0; q < s.n; ++q)
    for (int d = 0; d < D; ++d) to[q * D + d] = v[q * stride + d];
}
template <int D, class Model, Features F>
void load_velocities(State<D, Model, F>& s, const std::vector<double>& from) {
  constexpr int stride = State<D, Model, F>::stride;
  double* v = s.p.velocity_data().data();
  for (std::size_t q = 0; q < s.n; ++q)
    for (int d = 0; d < D; ++d) v[q * stride + d] = from[q * D + d];
}

/// One parallel block: replays candidates base .. base + count - 1 one at a time on
/// `before` (the velocities at the block's start) and counts the particles whose
/// velocities differ from the engine's, plus one if the replay raises the bound elsewhere
/// than the engine (`raised`: the engine ended the epoch at the last one).
template <bool Exact, int D, class Model, Features F>
void check_block(State<D, Model, F>& s, const std::vector<double>& before, std::uint64_t base,
                 std::uint32_t count, bool raised, double G) {
  std::vector<double> after;
  save_velocities(s, after);
  load_velocities(s, before);
  bool replay_raised = false;
  for (std::uint32_t c = 0; c < count && !replay_raised; ++c) {
    std::uint32_t i, j;
    double u;
    s.draw(base + c, i, j, u);
    if (!s.accepts(i, j, u, G)) continue;
    const double s2 = s.collide(i, j, base + c);
    replay_raised = Exact && Model::needs_majorant && s.bound.exceeded_by(s2);
    if (replay_raised != (raised && c + 1 == count)) ++s.check_failures;
  }
  if (raised && !replay_raised) ++s.check_failures;
  std::vector<double> replay;
  save_velocities(s, replay);
  for (std::size_t q = 0; q < s.n; ++q)
    for (int d = 0; d < D; ++d)
      if (std::bit_cast<std::uint64_t>(replay[q * D + d]) !=
          std::bit_cast<std::uint64_t>(after[q * D + d])) {
        ++s.check_failures;
        break;
      }
  load_velocities(s, after);
}

}  // namespace hypergas::dsmc::detail
