// hypergas/h5md/h5md.hpp -- trajectories and states in H5MD 1.1 (HDF5): the writer that
// `hypergas run --trajectory-every` and Python's run(..., trajectory=...) use, and the
// reader behind --init-file and hg.read_trajectory.
//
// The layout (docs/h5md.md; P. de Buyl, P. H. Colberg and F. Hoefling, Comput. Phys. Commun.
// 185, 1546 (2014); H5MD 1.1):
//   /h5md                          version = [1, 1]; groups author (name), creator (name =
//                                  hypergas, version)
//   /particles/all/box             dimension = D; boundary = D strings, "periodic" (EDMD)
//                                  or "none" (DSMC: a velocity-space gas has no positions,
//                                  so its box has no edges)
//   /particles/all/box/edges       EDMD: time-dependent, value [frames, D, D] (diagonal: the
//                                  cube's side; the matrix form is the one MDAnalysis reads)
//   /particles/all/position        EDMD: step [frames], time [frames], value [frames, N, D]:
//                                  positions wrapped into [0, L)
//   /particles/all/image           EDMD: the same, integer images: unwrapped = position +
//                                  image * edges
//   /particles/all/velocity        step, time, value [frames, N, D]
//   /particles/all/species, mass   [N]: integer species and masses (time-independent)
//   /particles/all/id              [N]: particle identity (absent where array slots carry
//                                  none: the DSMC lanes scheme deals particles between slots)
//   /observables/NAME              step, time, value [frames]: scalar series of the run
//   /parameters/hypergas           attributes: the run's options (text)
// Every time-dependent dataset is chunked and grows by one frame per write; the writer
// holds no more than one frame. Object time stamps are off, so two runs that write the
// same frames write the same datasets (h5diff) and, where the library allows, the same
// bytes. Units are the engine's reduced units (docs/units.md): HDF5 carries no unit
// attribute here.
//
// No HDF5 type appears in this header: the library keeps HDF5 private.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace hypergas::h5md {

/// What a trajectory file holds besides its frames.
struct Layout {
  int dim = 0;
  std::size_t n = 0;
  bool positions = false;           ///< position, image and box edges (EDMD)
  bool ids = true;                  ///< the id dataset (0 .. N - 1)
  std::vector<std::int32_t> species;  ///< per particle; empty: all 0
  std::vector<double> mass;         ///< per particle; empty: all 1
  std::vector<std::string> observables;  ///< names of scalar series, one value per frame
  std::string creator_version;      ///< hypergas's version
  std::vector<std::pair<std::string, std::string>> parameters;  ///< /parameters/hypergas
};

/// One frame, packed: velocities[i * D + k]; EDMD also positions in [0, box) and images.
struct FrameData {
  std::int64_t step = 0;
  double time = 0.0;
  const double* velocities = nullptr;
  const double* positions = nullptr;     ///< wrapped (Layout::positions)
  const std::int32_t* images = nullptr;  ///< (Layout::positions)
  double box = 0.0;                      ///< the cube's side (Layout::positions)
  const double* observables = nullptr;   ///< one value per Layout::observables name
};

/// Appends frames to an H5MD file. Throws InvalidInput (hypergas/error.hpp) with one line
/// on any failure.
class Writer {
 public:
  /// Creates `path` (replacing a file there) with no frames.
  Writer(const std::string& path, const Layout& layout);
  /// Opens a file this writer made with the same layout, keeps its first `frames` frames
  /// and appends after them (a resumed run: frames written after its checkpoint go).
  static Writer resume(const std::string& path, const Layout& layout, std::uint64_t frames);
  ~Writer();
  Writer(Writer&&) noexcept;
  Writer& operator=(Writer&&) noexcept;

  void append(const FrameData& f);
  /// Writes HDF5's buffers to the file (a checkpoint does this before it saves the frame
  /// count).
  void flush();
  std::uint64_t frames() const;
  /// Closes the file (the destructor does too, without throwing).
  void close();

 private:
  struct Impl;
  explicit Writer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

/// A state read from an H5MD file.
struct State {
  int dim = 0;
  std::size_t n = 0;
  std::uint64_t frames = 0;    ///< frames in the file
  std::uint64_t frame = 0;     ///< the frame read
  std::int64_t step = 0;
  double time = 0.0;
  std::vector<double> velocities;  ///< [n * dim]
  std::vector<double> positions;   ///< [n * dim], wrapped into [0, box); empty: none
  double box = 0.0;                ///< cube side of a periodic box (with positions), else 0
  std::vector<std::int32_t> species;  ///< empty: none in the file
  std::vector<double> mass;           ///< empty: none in the file
};

/// Reads frame `frame` of /particles/all (or the file's only particle group); negative
/// counts from the end (-1: the last). Throws InvalidInput with one line naming the file
/// and what is wrong: not HDF5 (or truncated), not H5MD, no velocity, shapes that do not
/// agree, a frame out of range, values that are not finite, a box that is not a cube.
State read_state(const std::string& path, std::int64_t frame = -1);

/// The frames of the observable `name` of a file: (time, value) pairs; empty if absent.
std::vector<std::pair<double, double>> read_observable(const std::string& path,
                                                       const std::string& name);

}  // namespace hypergas::h5md
