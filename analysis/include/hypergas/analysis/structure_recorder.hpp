// hypergas/analysis/structure_recorder.hpp -- pair structure of a periodic hard-sphere fluid
// in D dimensions: the radial distribution function g(r), its contact value, and the static
// structure factor S(k).
//
// g(r). At every snapshot the recorder counts the neighbours at separation r (minimum
// image) of `centres` particles (all when N <= centres; else a block of ids that moves on
// each snapshot, so the cost per snapshot is bounded) in bins of width dr up to
// r_max <= L/2, through a grid of cells of side >= r_max (all particles when fewer than 3
// cells fit a side), and normalises by the ideal count of the same shells,
// g(r) = count / (centres (N - 1) / V * v_D (r_2^D - r_1^D)), so that g -> 1 at large r in
// the finite system. Each bin's g is assigned to the shell's volume-weighted mean radius.
// Contact value g(sigma+): a least-squares quadratic in (r - sigma) through ln g of the first
// `contact_bins` bins outside the core, at r = sigma (sigma = 1; sigma / dr should be whole).
//
// S(k) = |sum_j exp(i k . x_j)|^2 / N at the box's wave vectors k = 2 pi m / L (m integer,
// one of each pair +-m), grouped in shells s <= |m| < s + 1 up to |k| <= k_max: every vector
// of a shell when the shell is small, else `vectors_per_shell` of them (fewer when the
// shells would hold more than `max_vectors` in all, at least 4) drawn with a fixed seed (an
// isotropic fluid's S depends on |k| only). The shell's |k| is the mean over its
// vectors.
//
// Errors: the frames are cut into `error_blocks` consecutive stretches, and each result is
// computed per stretch; the standard error of the mean over stretches.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hypergas/observer.hpp"

namespace hypergas::analysis {

struct StructureSettings {
  double r_max = 5.0;         ///< g(r) range (sigma; reduced to L/2 if larger)
  double dr = 0.02;           ///< bin width (sigma)
  double k_max = 15.0;        ///< S(k) range (1 / sigma)
  int vectors_per_shell = 24; ///< wave vectors per |m| shell, at most
  int max_vectors = 512;      ///< wave vectors in all, at most (fewer per shell if needed)
  int centres = 1000;         ///< g(r) centres per snapshot, at most
  int contact_bins = 10;      ///< bins in the contact-value fit
  int error_blocks = 16;      ///< stretches for the standard errors
  std::uint64_t seed = 1;     ///< choice of the wave vectors of large shells
};

struct StructureResult {
  std::vector<double> r, g, g_error;         ///< g(r) at the bins' mean radii
  std::vector<double> k, s, s_error;         ///< S(k) per shell
  std::vector<int> vectors;                  ///< wave vectors per shell
  double contact = 0.0, contact_error = 0.0; ///< g(sigma+)
  double r_max = 0.0, k_max = 0.0;
  std::uint64_t frames = 0;
};

class StructureRecorder final : public Observer {
 public:
  /// Records snapshots at or after `start` (engine time) of a D-dimensional fluid of n
  /// particles in a periodic box. Throws InvalidInput on bad settings.
  StructureRecorder(const StructureSettings& s, int dim, std::size_t n, double start);
  void observe(const Snapshot& s) override;
  std::uint64_t frames() const { return frames_; }
  /// Computes g, g(sigma+) and S (after the run). Throws InvalidInput with fewer than two
  /// frames.
  const StructureResult& finish();
  /// rdf.csv: r, g, error. structure_factor.csv: k, S, error, vectors.
  void write_rdf_csv(const std::string& path) const;
  void write_structure_factor_csv(const std::string& path) const;

 private:
  void setup(double L);

  StructureSettings set_;
  int dim_;
  std::size_t n_;
  double start_;
  double L_ = 0.0, r_max_ = 0.0;
  std::size_t bins_ = 0;
  std::vector<std::vector<int>> kvec_;         // per shell: vectors (D ints each)
  std::vector<std::vector<double>> frames_g_;  // per frame: pair counts per bin
  std::vector<std::vector<double>> frames_s_;  // per frame: S per shell
  std::uint64_t frames_ = 0, centres_ = 0;
  StructureResult result_;
  bool finished_ = false;
};

}  // namespace hypergas::analysis
