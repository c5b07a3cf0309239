// hypergas/particles.hpp -- structure-of-arrays particle storage with compile-time fields.
//
// A scene states at compile time which optional fields it has (`Features`). A field that is
// absent is an empty member marked [[no_unique_address]]: it takes no bytes, and every
// accessor for it is removed by a `requires` clause, so code that would touch it does not
// compile. The kinematic state lives in one flat array with a fixed stride per particle
// (`Particles::stride`, doubles):
//  * velocity-space scenes: the velocity, padded to a power of two for D = 3, 5, 6
//    (strides 1, 2, 4, 4, 8, 8), so that one particle never straddles two cache lines
//    (the array starts on a cache line: CacheLineAllocator);
//  * scenes with positions: one record [position (D), local clock (1), velocity (D)]
//    padded to a power of two (strides 4, 8, 8, 16, 16, 16): event-driven MD reads all
//    three of a neighbour at once, and one 64-byte record in 3D is one cache miss where
//    three separate arrays would be three (docs/benchmarks.md, "Kept designs").
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <new>
#include <string>
#include <vector>

#include "hypergas/error.hpp"
#include "hypergas/vec.hpp"

namespace hypergas {

/// The optional per-particle fields of a scene. A C++20 structural type, so it can be a
/// template argument: `Particles<3, Features{.positions = true}>`.
struct Features {
  bool positions = false;  ///< positions (event-driven MD); velocity-space scenes have none
  bool species = false;    ///< a small species index per particle; mass from a species table
  constexpr bool operator==(const Features&) const = default;
};

/// Most species a scene may have (species index is one byte).
inline constexpr int max_species = 4;

namespace detail {
/// Empty stand-in for an absent field; the tag keeps absent fields distinct types so that
/// several of them can share one address under [[no_unique_address]].
template <int Tag>
struct Absent {};

template <bool Present, class T, int Tag>
using Field = std::conditional_t<Present, T, Absent<Tag>>;

/// Doubles per particle in a flat vector array: D rounded up to a power of two for D = 3,
/// 5, 6 (32- and 64-byte records stay inside one cache line when the array is aligned).
constexpr int padded_stride(int d) {
  return d == 3 ? 4 : (d == 5 || d == 6) ? 8 : d;
}
/// Doubles per [position, clock, velocity] record: 2D + 1 rounded up to a power of two.
constexpr int record_stride(int d) {
  int s = 1;
  while (s < 2 * d + 1) s *= 2;
  return s;
}

/// Allocator that starts every array on a cache line (64 bytes). Eigen's aligned_allocator
/// only guarantees its vector alignment (16 bytes without AVX): glibc then returns large
/// arrays at 16 bytes past a page boundary, and every other 32-byte record would straddle
/// two cache lines (docs/benchmarks.md, "Kept designs").
template <class T>
struct CacheLineAllocator {
  using value_type = T;
  static constexpr std::align_val_t alignment{64};
  CacheLineAllocator() = default;
  template <class U>
  CacheLineAllocator(const CacheLineAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) { return static_cast<T*>(::operator new(n * sizeof(T), alignment)); }
  void deallocate(T* p, std::size_t) noexcept { ::operator delete(p, alignment); }
  template <class U>
  bool operator==(const CacheLineAllocator<U>&) const noexcept {
    return true;
  }
};

template <class T>
using AlignedVector = std::vector<T, CacheLineAllocator<T>>;
}  // namespace detail

/// Reorders an array of records of `width` entries each: afterwards record i is the former
/// record from[i] (`from` a permutation of the record indices). In place, cycle by cycle,
/// with one bit per record of extra memory (a copy of the array would double the peak
/// memory of the engines that renumber their particles).
template <class Array>
void permute_records(Array& a, const std::vector<std::uint32_t>& from, std::size_t width) {
  const std::size_t n = from.size();
  std::vector<bool> done(n, false);
  std::vector<typename Array::value_type> tmp(width);
  for (std::size_t s = 0; s < n; ++s) {
    if (done[s]) continue;
    for (std::size_t k = 0; k < width; ++k) tmp[k] = a[s * width + k];
    std::size_t j = s;
    for (;;) {
      done[j] = true;
      const std::size_t f = from[j];
      if (f == s) {
        for (std::size_t k = 0; k < width; ++k) a[j * width + k] = tmp[k];
        break;
      }
      for (std::size_t k = 0; k < width; ++k) a[j * width + k] = a[f * width + k];
      j = f;
    }
  }
}

/// Particle storage for `n` particles in D dimensions with optional fields `F`.
/// Units are those of the engine that owns it (see the engines' docs).
template <int D, Features F = Features{}>
requires Dimension<D>
class Particles {
 public:
  static constexpr int dim = D;
  static constexpr Features features = F;
  static constexpr int stride = F.positions ? detail::record_stride(D) : detail::padded_stride(D);
  /// Offset of the velocity within a particle's record (0 without positions).
  static constexpr int velocity_offset = F.positions ? D + 1 : 0;

  using VecMap = Eigen::Map<Vec<D>>;
  using ConstVecMap = Eigen::Map<const Vec<D>>;
  using FlatArray = detail::AlignedVector<double>;
  using SpeciesArray = detail::Field<F.species, std::vector<std::uint8_t>, 3>;
  using SpeciesTable = detail::Field<F.species, std::array<double, max_species>, 4>;

  Particles() = default;
  /// `n` particles at rest, unit mass; positions (if any) at the origin.
  explicit Particles(std::size_t n) { resize(n); }

  /// Sets the number of particles; new entries are zero (velocity, position), species 0
  /// of mass 1.
  void resize(std::size_t n) {
    n_ = n;
    v_.assign(n * stride, 0.0);
    if constexpr (F.species) {
      s_.assign(n, 0);
      species_w_.fill(1.0);
    }
  }

  std::size_t size() const { return n_; }

  /// Exchanges the records (and species) of particles i and j.
  void swap(std::size_t i, std::size_t j) {
    double* a = v_.data() + i * stride;
    double* b = v_.data() + j * stride;
    for (int k = 0; k < stride; ++k) std::swap(a[k], b[k]);
    if constexpr (F.species) std::swap(s_[i], s_[j]);
  }

  /// Velocity of particle i as an assignable Eigen view.
  VecMap velocity(std::size_t i) { return VecMap(v_.data() + i * stride + velocity_offset); }
  ConstVecMap velocity(std::size_t i) const {
    return ConstVecMap(v_.data() + i * stride + velocity_offset);
  }

  /// Position of particle i (only in scenes with positions).
  VecMap position(std::size_t i) requires(F.positions) { return VecMap(v_.data() + i * stride); }
  ConstVecMap position(std::size_t i) const requires(F.positions) {
    return ConstVecMap(v_.data() + i * stride);
  }
  /// Local clock of particle i: the time at which position(i) holds (event-driven MD
  /// moves a particle only when it has an event; only in scenes with positions).
  double& local_time(std::size_t i) requires(F.positions) { return v_[i * stride + D]; }
  double local_time(std::size_t i) const requires(F.positions) { return v_[i * stride + D]; }

  /// Inverse mass of particle i (1/mass; 0 for an infinite mass). Unit mass when the scene
  /// has no species: a constant the compiler folds away.
  double inv_mass(std::size_t i) const {
    if constexpr (F.species)
      return species_w_[s_[i]];
    else {
      (void)i;
      return 1.0;
    }
  }
  /// Mass of particle i (infinity for inverse mass 0).
  double mass(std::size_t i) const { return 1.0 / inv_mass(i); }

  /// Species index of particle i (only in scenes with species).
  int species(std::size_t i) const requires(F.species) { return s_[i]; }
  void set_species(std::size_t i, int s) requires(F.species) {
    if (s < 0 || s >= max_species) throw InvalidInput("species index out of range");
    s_[i] = static_cast<std::uint8_t>(s);
  }
  /// Mass of every particle of species s; throws InvalidInput unless m > 0 (infinity
  /// allowed).
  void set_species_mass(int s, double m) requires(F.species) {
    if (s < 0 || s >= max_species) throw InvalidInput("species index out of range");
    check_mass(m);
    species_w_[s] = 1.0 / m;
  }
  double species_inv_mass(int s) const requires(F.species) { return species_w_[s]; }

  /// Raw flat state array (n * stride doubles; the velocity of particle i starts at
  /// i * stride + velocity_offset; padding entries stay 0).
  FlatArray& velocity_data() { return v_; }
  const FlatArray& velocity_data() const { return v_; }
  /// Raw species indices, one byte per particle (only in scenes with species).
  const SpeciesArray& species_data() const
    requires(F.species)
  {
    return s_;
  }

  /// Reorders the particles: afterwards particle i is the former particle from[i]
  /// (`from` must be a permutation of 0..n-1). Engines use it to keep particles that are
  /// near in space near in memory.
  void permute(const std::vector<std::uint32_t>& from) {
    if (from.size() != n_) throw InvalidInput("permute: size mismatch");
    permute_records(v_, from, stride);
    if constexpr (F.species) permute_records(s_, from, 1);
  }

  /// Saves or restores every field (hypergas/checkpoint.hpp).
  template <class Archive>
  void io(Archive& a) {
    a.tag("particles");
    a(n_, v_);
    if constexpr (F.species) a(s_, species_w_);
    if (v_.size() != n_ * stride) throw InvalidInput("checkpoint: particle arrays do not match");
  }

  /// Bytes of per-particle storage (capacity of all arrays divided by n).
  double bytes_per_particle() const {
    if (n_ == 0) return 0.0;
    std::size_t b = v_.capacity() * sizeof(double);
    if constexpr (F.species) b += s_.capacity();
    return static_cast<double>(b) / static_cast<double>(n_);
  }

 private:
  static void check_mass(double m) {
    if (!(m > 0.0) || std::isnan(m))
      throw InvalidInput("mass must be > 0 (infinity allowed), got " + std::to_string(m));
  }

  std::size_t n_ = 0;
  FlatArray v_;  // velocities, or [position, clock, velocity] records (see file comment)
  [[no_unique_address]] SpeciesArray s_;
  [[no_unique_address]] SpeciesTable species_w_;
};

}  // namespace hypergas
