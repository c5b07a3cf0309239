// Uses the installed headers: one 3D collision, exit 0 iff momentum is conserved.
#include <hypergas/collision.hpp>
#include <hypergas/rng.hpp>
#include <hypergas/sampling.hpp>

#include <cstdio>

int main() {
  hypergas::Rng rng(7);
  hypergas::Vec<3> v1 = hypergas::normal_vector<3>(rng), v2 = hypergas::normal_vector<3>(rng);
  const hypergas::Vec<3> p0 = v1 + 2.0 * v2;
  const hypergas::Vec<3> n = hypergas::hard_sphere_normal<3>(rng, v2 - v1);
  hypergas::collide<3>(v1, v2, 1.0, 0.5, n);
  const double dp = (v1 + 2.0 * v2 - p0).norm();
  std::printf("momentum change %.3g\n", dp);
  return dp < 1e-14 ? 0 : 1;
}
