// The hypergas command. Until the engines land it runs the kernel demo: random elastic
// collisions in D = 1..6 with a 1:10 mass ratio, printing the conservation errors.
#include <fmt/core.h>

#include <cmath>

#include "hypergas/collision.hpp"
#include "hypergas/sampling.hpp"

namespace {
template <int D>
void demo(hypergas::Rng& rng) {
  using namespace hypergas;
  double worst_e = 0.0, worst_p = 0.0;
  for (int k = 0; k < 100000; ++k) {
    Vec<D> v1 = normal_vector<D>(rng), v2 = normal_vector<D>(rng);
    const double m1 = 1.0, m2 = 10.0;
    const Vec<D> p0 = m1 * v1 + m2 * v2;
    const double e0 = m1 * v1.squaredNorm() + m2 * v2.squaredNorm();
    collide<D>(v1, v2, 1.0 / m1, 1.0 / m2, hard_sphere_normal<D>(rng, v2 - v1));
    worst_p = std::max(worst_p, (m1 * v1 + m2 * v2 - p0).norm() / std::sqrt(e0));
    worst_e = std::max(worst_e, std::abs(m1 * v1.squaredNorm() + m2 * v2.squaredNorm() - e0) / e0);
  }
  fmt::print("{:>3} {:>12} {:>16.3e} {:>16.3e}\n", D, 100000, worst_p, worst_e);
}
}  // namespace

int main() {
  hypergas::Rng rng(2026);
  fmt::print("{:>3} {:>12} {:>16} {:>16}\n", "D", "collisions", "max |dp|/p_scale", "max |dE|/E");
  hypergas::for_each_dim([&](auto d) { demo<decltype(d)::value>(rng); });
  return 0;
}
