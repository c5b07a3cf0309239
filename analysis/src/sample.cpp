// Per-particle values, masses and temperatures of a snapshot.
#include "hypergas/analysis/sample.hpp"

#include <cmath>
#include <string>

#include "hypergas/error.hpp"

namespace hypergas::analysis {

namespace {
bool selected(const Snapshot& s, std::size_t i, int species) {
  return species < 0 || (s.species ? s.species[i] : 0) == species;
}
double speed_sq(const Snapshot& s, std::size_t i) {
  const double* v = s.velocities + i * static_cast<std::size_t>(s.stride);
  double vv = 0.0;
  for (int k = 0; k < s.dim; ++k) vv += v[k] * v[k];
  return vv;
}
}  // namespace

void validate(const Snapshot& s) {
  if (s.dim < 1)
    throw InvalidInput("snapshot: dimension must be >= 1, got " + std::to_string(s.dim));
  if (s.stride < s.dim)
    throw InvalidInput("snapshot: stride " + std::to_string(s.stride) + " < dimension " +
                       std::to_string(s.dim));
  if (s.n > 0 && !s.velocities) throw InvalidInput("snapshot: no velocity array");
  if (s.n_species < 1) throw InvalidInput("snapshot: n_species must be >= 1");
  if (s.species && !s.species_inv_mass && !s.inv_mass)
    throw InvalidInput("snapshot: species given without species_inv_mass");
  if (s.species)
    for (std::size_t i = 0; i < s.n; ++i)
      if (s.species[i] >= s.n_species)
        throw InvalidInput("snapshot: particle " + std::to_string(i) + " has species " +
                           std::to_string(int(s.species[i])) + " >= n_species " +
                           std::to_string(s.n_species));
}

std::size_t count(const Snapshot& s, int species) {
  if (species < 0) return s.n;
  std::size_t c = 0;
  for (std::size_t i = 0; i < s.n; ++i) c += selected(s, i, species);
  return c;
}

double mean_mass(const Snapshot& s, int species) {
  double sum = 0.0;
  std::size_t c = 0;
  for (std::size_t i = 0; i < s.n; ++i)
    if (selected(s, i, species)) {
      const double w = s.inverse_mass(i);
      if (!(w > 0.0 && std::isfinite(w)))
        throw InvalidInput("snapshot: particle " + std::to_string(i) + " has inverse mass " +
                           std::to_string(w) + " (the analysis needs finite, positive masses)");
      sum += 1.0 / w;
      ++c;
    }
  if (c == 0) throw InvalidInput("snapshot: no particle of species " + std::to_string(species));
  return sum / static_cast<double>(c);
}

double temperature(const Snapshot& s, int species) {
  double twice_e = 0.0;
  std::size_t c = 0;
  for (std::size_t i = 0; i < s.n; ++i)
    if (selected(s, i, species)) {
      twice_e += speed_sq(s, i) / s.inverse_mass(i);
      ++c;
    }
  if (c == 0) throw InvalidInput("snapshot: no particle of species " + std::to_string(species));
  return twice_e / (static_cast<double>(s.dim) * static_cast<double>(c));
}

std::vector<double> values(const Snapshot& s, Quantity q, int species) {
  validate(s);
  const double m_mean = (species < 0 && q != Quantity::energy) ? mean_mass(s, -1) : 0.0;
  std::vector<double> out;
  out.reserve(count(s, species));
  for (std::size_t i = 0; i < s.n; ++i) {
    if (!selected(s, i, species)) continue;
    const double w = s.inverse_mass(i);
    // Pooled velocities are mass-weighted: v sqrt(m_i / m_mean) = v / sqrt(w m_mean).
    const double f = (species < 0 && q != Quantity::energy) ? 1.0 / std::sqrt(w * m_mean) : 1.0;
    switch (q) {
      case Quantity::speed:
        out.push_back(f * std::sqrt(speed_sq(s, i)));
        break;
      case Quantity::component:
        out.push_back(f * s.velocities[i * static_cast<std::size_t>(s.stride)]);
        break;
      case Quantity::energy:
        out.push_back(0.5 * speed_sq(s, i) / w);
        break;
    }
  }
  return out;
}

MaxwellReference reference(const Snapshot& s, Quantity q, int species) {
  validate(s);
  MaxwellReference r{q, s.dim, temperature(s, -1), mean_mass(s, species)};
  r.validate();
  return r;
}

}  // namespace hypergas::analysis
