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
// The inverse mass of particle i; throws unless it is finite and positive.
double checked_inverse_mass(const Snapshot& s, std::size_t i) {
  const double w = s.inverse_mass(i);
  if (!(w > 0.0 && std::isfinite(w)))
    throw InvalidInput("snapshot: particle " + std::to_string(i) + " has inverse mass " +
                       std::to_string(w) + " (the analysis needs finite, positive masses)");
  return w;
}
[[noreturn]] void no_particles(int species) {
  throw InvalidInput("snapshot: no particle of species " + std::to_string(species));
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

double mean_mass(const Snapshot& s, int species, Summation how) {
  RunningSum sum;
  std::size_t c = 0;
  for (std::size_t i = 0; i < s.n; ++i)
    if (selected(s, i, species)) {
      sum.add(1.0 / checked_inverse_mass(s, i));
      ++c;
    }
  if (c == 0) no_particles(species);
  return sum.value(how) / static_cast<double>(c);
}

double temperature(const Snapshot& s, int species, Summation how) {
  RunningSum twice_e;
  std::size_t c = 0;
  for (std::size_t i = 0; i < s.n; ++i)
    if (selected(s, i, species)) {
      twice_e.add(speed_sq(s, i) / s.inverse_mass(i));
      ++c;
    }
  if (c == 0) no_particles(species);
  return twice_e.value(how) / (static_cast<double>(s.dim) * static_cast<double>(c));
}

std::vector<double> values(const Snapshot& s, Quantity q, int species, Summation how) {
  validate(s);
  const double m_mean = (species < 0 && q != Quantity::energy) ? mean_mass(s, -1, how) : 0.0;
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

MaxwellReference reference(const Snapshot& s, Quantity q, int species, Summation how) {
  validate(s);
  MaxwellReference r{q, s.dim, temperature(s, -1, how), mean_mass(s, species, how)};
  r.validate();
  return r;
}

SnapshotTotals::SnapshotTotals(const Snapshot& s) : SnapshotTotals(s, 0, s.n) {}

SnapshotTotals::SnapshotTotals(const Snapshot& s, std::size_t begin, std::size_t end)
    : dim_(s.dim), t_(1 + static_cast<std::size_t>(s.n_species)) {
  if (!s.species && !s.inv_mass) {
    // Unit masses, one species: m = 1 and m v^2 = v^2 exactly, so the mass sum is n and the
    // energy sum the same additions as below, done once (a third of the pass at N = 1e7).
    Totals t;
    for (std::size_t i = begin; i < end; ++i) t.twice_e.add(speed_sq(s, i));
    t.mass = RunningSum::exact(static_cast<double>(end - begin));
    t.n = end - begin;
    for (Totals& x : t_) x = t;
    return;
  }
  Totals& all = t_[0];
  for (std::size_t i = begin; i < end; ++i) {
    Totals& mine = t_[1 + (s.species ? s.species[i] : 0u)];
    const double w = checked_inverse_mass(s, i);
    const double m = 1.0 / w, e = speed_sq(s, i) / w;
    all.mass.add(m);
    all.twice_e.add(e);
    ++all.n;
    mine.mass.add(m);
    mine.twice_e.add(e);
    ++mine.n;
  }
}

void SnapshotTotals::merge(const SnapshotTotals& o) {
  for (std::size_t k = 0; k < t_.size() && k < o.t_.size(); ++k) {
    t_[k].n += o.t_[k].n;
    t_[k].mass.merge(o.t_[k].mass);
    t_[k].twice_e.merge(o.t_[k].twice_e);
  }
}

const SnapshotTotals::Totals* SnapshotTotals::of(int species) const {
  const std::size_t k = species < 0 ? 0 : 1 + static_cast<std::size_t>(species);
  return k < t_.size() ? &t_[k] : nullptr;
}

std::size_t SnapshotTotals::count(int species) const {
  const Totals* t = of(species);
  return t ? t->n : 0;
}

double SnapshotTotals::mean_mass(int species, Summation how) const {
  const Totals* t = of(species);
  if (!t || t->n == 0) no_particles(species);
  return t->mass.value(how) / static_cast<double>(t->n);
}

double SnapshotTotals::temperature(int species, Summation how) const {
  const Totals* t = of(species);
  if (!t || t->n == 0) no_particles(species);
  return t->twice_e.value(how) / (static_cast<double>(dim_) * static_cast<double>(t->n));
}

}  // namespace hypergas::analysis
