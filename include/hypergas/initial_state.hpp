// hypergas/initial_state.hpp -- initial velocity states shared by the DSMC and EDMD engines.
//
// Every state is sampled, then each population is shifted to zero momentum and rescaled to
// its prescribed kinetic energy, so that (to round-off) the total momentum is exactly zero
// and the energy is exactly sum_i m_i |v_i|^2 / 2 = (D/2) sum_p n_p kT_p.
//
// Populations: particles i < n - n1 form population 0, the last n1 = round(fraction * n)
// form population 1. There is a second population only in species scenes (population =
// species, species 1 has mass `mass_ratio`, species 0 mass 1) and in the `two-temp` state;
// otherwise n1 = 0. Positions, if any, are not touched. Units: mass of species 0 = 1,
// temperature kT in energy units, so velocities are in units of sqrt(kT / m0) for kT = 1.
//
// States (names as on the command line):
//   maxwell    Maxwell-Boltzmann, every component normal with variance kT/m.
//   delta      delta shell: all speeds of a population equal, directions uniform; built from
//              antipodal pairs (v, -v) so momentum is zero without shifting (D = 1 then needs
//              an even count per population; D >= 2 closes an odd count with a triangle).
//   cube       velocities uniform in a cube [-c, c]^D.
//   beams      two counter-streaming beams +-u e_x with a small thermal spread
//              (`beam_spread` = kT_spread / kT before rescaling).
//   bimaxwell  Gaussian with T_x / T_perp = `anisotropy` (in D = 1 just a Maxwellian).
//   bkw        the Bobylev-Krook-Wu initial state for Maxwell molecules in D dimensions:
//              f0(v) ~ |v|^2 exp(-|v|^2 / (2 K0 kT/m)) with K0 = D/(D+2), i.e. the speed is
//              sqrt(K0 kT/m) times a chi variable with D+2 degrees of freedom (see
//              dsmc/models.hpp for the exact solution).
//   two-temp   two Maxwellian populations at kT_species[0], kT_species[1].
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "hypergas/error.hpp"
#include "hypergas/particles.hpp"
#include "hypergas/rng.hpp"
#include "hypergas/sampling.hpp"
#include "hypergas/vec.hpp"

namespace hypergas {

/// The initial velocity distributions (see the file comment; names and help texts in
/// registry.hpp).
enum class InitialState { maxwell, delta, cube, beams, bimaxwell, bkw, two_temp };

/// Parameters of the initial states. Temperatures in energy units (mass of species 0 = 1).
struct InitialParams {
  double kT = 1.0;  ///< temperature of every population, except in `two-temp`
  std::array<double, 2> kT_species = {1.5, 0.5};  ///< `two-temp`: kT of populations 0, 1
  double fraction = 0.5;      ///< number fraction of population (species) 1, in [0, 1]
  double mass_ratio = 1.0;    ///< species scenes: mass of species 1 / mass of species 0
  double anisotropy = 4.0;    ///< `bimaxwell`: T_x / T_perp (> 0)
  double beam_spread = 0.05;  ///< `beams`: thermal kT per beam / kinetic kT of the drift (>= 0)
};

/// Number of particles in population 1 for `n` particles (0 unless species or two-temp).
template <Features F>
std::size_t second_population_size(std::size_t n, InitialState s, const InitialParams& p) {
  if (!(F.species || s == InitialState::two_temp)) return 0;
  return static_cast<std::size_t>(std::llround(p.fraction * static_cast<double>(n)));
}

/// Mean kinetic temperature the state is given, (sum_p n_p kT_p) / n: the temperature the
/// gas relaxes to, in energy units.
template <Features F>
double initial_temperature(std::size_t n, InitialState s, const InitialParams& p) {
  if (s != InitialState::two_temp || n == 0) return p.kT;
  const double n1 = static_cast<double>(second_population_size<F>(n, s, p));
  return ((static_cast<double>(n) - n1) * p.kT_species[0] + n1 * p.kT_species[1]) /
         static_cast<double>(n);
}

namespace detail {

inline void check_initial_params(const InitialParams& p) {
  auto pos = [](double x) { return std::isfinite(x) && x > 0.0; };
  if (!pos(p.kT)) throw InvalidInput("initial kT must be finite and > 0");
  if (!pos(p.kT_species[0]) || !pos(p.kT_species[1]))
    throw InvalidInput("per-species temperatures must be finite and > 0");
  if (!(p.fraction >= 0.0 && p.fraction <= 1.0))
    throw InvalidInput("number fraction must be in [0, 1]");
  if (!pos(p.mass_ratio)) throw InvalidInput("mass ratio must be finite and > 0");
  if (!pos(p.anisotropy)) throw InvalidInput("bimaxwell anisotropy must be finite and > 0");
  if (!(std::isfinite(p.beam_spread) && p.beam_spread >= 0.0))
    throw InvalidInput("beam spread must be finite and >= 0");
}

/// Velocity of the raw (unscaled) state for one particle; `k` is its index in its population.
template <int D>
Vec<D> raw_velocity(InitialState s, std::size_t k, Rng& rng, const InitialParams& p) {
  switch (s) {
    case InitialState::cube: {
      Vec<D> v;
      for (int d = 0; d < D; ++d) v[d] = 2.0 * rng.uniform() - 1.0;
      return v;
    }
    case InitialState::beams: {
      Vec<D> v = std::sqrt(p.beam_spread) * normal_vector<D>(rng);
      v[0] += (k % 2 == 0) ? 1.0 : -1.0;
      return v;
    }
    case InitialState::bimaxwell: {
      Vec<D> v = normal_vector<D>(rng);
      if constexpr (D > 1) v[0] *= std::sqrt(p.anisotropy);
      return v;
    }
    case InitialState::bkw: {
      // speed ~ chi_{D+2}: the norm of D+2 standard normals; direction uniform.
      double r2 = 0.0;
      for (int d = 0; d < D + 2; ++d) {
        const double z = rng.normal();
        r2 += z * z;
      }
      return std::sqrt(r2) * unit_vector<D>(rng);
    }
    default:  // maxwell, two-temp (delta is built separately)
      return normal_vector<D>(rng);
  }
}

/// Fills population [b, e) with the delta shell of unit speed: antipodal pairs, and for an
/// odd count (D >= 2) a closing equilateral triangle, so the sum is zero without a shift.
template <int D, Features F>
void delta_shell(Particles<D, F>& ps, std::size_t b, std::size_t e, Rng& rng) {
  const std::size_t cnt = e - b;
  if (cnt == 0) return;
  if (cnt % 2 == 1 && (D == 1 || cnt < 3))
    throw InvalidInput(
        "delta state: in D = 1 (or with 1 particle) each population needs an "
        "even number of particles for zero momentum at equal speeds");
  const std::size_t pairs_end = (cnt % 2 == 1) ? e - 3 : e;
  for (std::size_t i = b; i < pairs_end; i += 2) {
    const Vec<D> u = unit_vector<D>(rng);
    ps.velocity(i) = u;
    ps.velocity(i + 1) = -u;
  }
  if constexpr (D >= 2) {
    if (cnt % 2 == 1) {
      const Vec<D> u = unit_vector<D>(rng);
      Vec<D> w = unit_vector<D>(rng);
      w -= w.dot(u) * u;
      while (w.squaredNorm() < 1e-6) {
        w = unit_vector<D>(rng);
        w -= w.dot(u) * u;
      }
      w.normalize();
      const double h = std::sqrt(3.0) / 2.0;
      ps.velocity(e - 3) = u;
      ps.velocity(e - 2) = -0.5 * u + h * w;
      ps.velocity(e - 1) = -0.5 * u - h * w;
    }
  }
}

}  // namespace detail

/// Samples the initial velocities of `ps` in state `s` (see the file comment). In species
/// scenes it also sets the species table (species 0 mass 1, species 1 mass `mass_ratio`) and
/// assigns species 1 to the last round(fraction * n) particles. Afterwards each population
/// has zero momentum and kinetic energy (D/2) n_p kT_p exactly (to round-off).
/// Throws InvalidInput for invalid parameters.
template <int D, Features F>
void initialize_velocities(Particles<D, F>& ps, InitialState s, Rng& rng,
                           const InitialParams& p = {}) {
  detail::check_initial_params(p);
  const std::size_t n = ps.size();
  const std::size_t n1 = second_population_size<F>(n, s, p);
  if constexpr (F.species) {
    ps.set_species_mass(0, 1.0);
    ps.set_species_mass(1, p.mass_ratio);
    for (std::size_t i = 0; i < n; ++i) ps.set_species(i, i < n - n1 ? 0 : 1);
  }
  const std::array<std::size_t, 3> bounds = {0, n - n1, n};
  for (int pop = 0; pop < 2; ++pop) {
    const std::size_t b = bounds[pop], e = bounds[pop + 1];
    if (b == e) continue;
    const double kT = (s == InitialState::two_temp) ? p.kT_species[pop] : p.kT;
    if (s == InitialState::delta) {
      detail::delta_shell(ps, b, e, rng);
    } else {
      for (std::size_t i = b; i < e; ++i)
        ps.velocity(i) = detail::raw_velocity<D>(s, i - b, rng, p);
      // Shift to zero population momentum (mass-weighted mean velocity).
      Vec<D> mom = Vec<D>::Zero();
      double mass = 0.0;
      for (std::size_t i = b; i < e; ++i) {
        mom += ps.mass(i) * ps.velocity(i);
        mass += ps.mass(i);
      }
      const Vec<D> vcm = mom / mass;
      for (std::size_t i = b; i < e; ++i) ps.velocity(i) -= vcm;
    }
    double ekin2 = 0.0;  // sum m |v|^2
    for (std::size_t i = b; i < e; ++i) ekin2 += ps.mass(i) * ps.velocity(i).squaredNorm();
    if (!(ekin2 > 0.0))  // e.g. one particle at zero momentum: no energy can be given
      throw InvalidInput("initial state: a population of " + std::to_string(e - b) +
                         " particle(s) cannot carry energy at zero momentum");
    const double scale = std::sqrt(D * static_cast<double>(e - b) * kT / ekin2);
    for (std::size_t i = b; i < e; ++i) ps.velocity(i) *= scale;
  }
}

}  // namespace hypergas
