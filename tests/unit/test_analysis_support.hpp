// Test helpers for the analysis tests: owned particle arrays seen through a Snapshot, and a
// scratch folder for the tests that write files.
#pragma once

#include <catch2/catch.hpp>

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "hypergas/observer.hpp"
#include "hypergas/rng.hpp"

namespace hypergas::test {

/// n particles in `dim` dimensions with a padded stride, per-species masses optional.
struct OwnedState {
  int dim = 3;
  int stride = 4;
  std::vector<double> v;
  std::vector<std::uint8_t> species;
  std::vector<double> species_inv_mass;

  OwnedState(int d, std::size_t n) : dim(d), stride(d + 1), v(n * (d + 1), -7.0) {}
  std::size_t size() const { return v.size() / stride; }
  double* velocity(std::size_t i) { return v.data() + i * stride; }

  Snapshot snapshot() const {
    Snapshot s;
    s.dim = dim;
    s.n = size();
    s.stride = stride;
    s.velocities = v.data();
    if (!species.empty()) {
      s.species = species.data();
      s.species_inv_mass = species_inv_mass.data();
      s.n_species = static_cast<int>(species_inv_mass.size());
    }
    return s;
  }
};

/// Maxwell–Boltzmann velocities with variance kT * inv_mass per component. The padding
/// slot is filled with garbage (-7) to prove that analysis never reads it.
inline void fill_maxwell(OwnedState& st, Rng& rng, double kT, double inv_mass = 1.0,
                         std::size_t from = 0, std::size_t to = SIZE_MAX) {
  const double s = std::sqrt(kT * inv_mass);
  for (std::size_t i = from; i < std::min(to, st.size()); ++i)
    for (int k = 0; k < st.dim; ++k) st.velocity(i)[k] = s * rng.normal();
}

/// A fresh empty folder under the system temporary folder, removed at scope exit.
struct TempDir {
  std::filesystem::path path;
  TempDir() {
    std::string p = (std::filesystem::temp_directory_path() / "hypergas_test_XXXXXX").string();
    REQUIRE(::mkdtemp(p.data()) != nullptr);
    path = p;
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::permissions(path, std::filesystem::perms::owner_all, ec);
    std::filesystem::remove_all(path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  /// Entries directly in the folder.
  std::size_t entries() const {
    return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(path),
                                                  std::filesystem::directory_iterator{}));
  }
};

/// The whole content of file `p` ("" if it cannot be read).
inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace hypergas::test
