// hypergas/edmd/scan.hpp -- the neighbour-scan policies of the EDMD engine and the
// automatic choice by dimension.
//
// Which stencil cells a prediction scans (grids of 3 or more cells per side; the one-cell
// box takes scan_small_box under every policy, prediction.hpp):
//   SlabScan (scan_slab.hpp): the whole 3^D stencil, and a cell crossing keeps the
//     still-valid pair events and scans only the newly adjacent slab of 3^(D-1) cells.
//   HorizonScan (scan_horizon.hpp): every prediction (crossings included) scans only the
//     stencil cells within a contact distance of the box bounding the particle's path
//     until its next cell crossing (0.86 of the 3^D cells in 3D, 0.46 in 6D on average).
//   FilteredScan (scan_filtered.hpp; 5 or more cells per side, else as HorizonScan): the
//     horizon scan, and a cell, then a particle, is skipped when the box bounding its
//     members' paths (a particle's path until its next crossing; kept per particle and as
//     a union per cell, 8 bits per bound) is farther than a contact distance from the
//     scanner's box.
// All find every collision; trajectories agree to round-off. Measured (3D, eta = 0.26; 6D,
// eta = 0.05): horizon/slab 1.08-1.18x in 3D, 1.26-1.46x in 5D; in 6D ~1130 (slab), 642
// (horizon) and 63 (filtered) pair times per collision, and filtered/horizon about 2.3x;
// equal in 3D, where the filter is off. AutoScan<D> is the fastest for dilute and moderately
// dense gases: slab in D <= 2, horizon in 3D, filtered from 4D.
//   - ListScan (scan_lists.hpp): neighbour lists renewed as events; a prediction tests
//     only the listed particles (3D eta = 0.45: 29 pairs per collision against 47 for
//     horizon), at the price of list renewals and ~90 more bytes per particle. Measured
//     against horizon (3D, N = 32 000, interleaved; docs/benchmarks.md): 0.61x at
//     eta = 0.26, 0.82x at 0.38, 1.05x at 0.45, 1.44x at 0.55; in 6D at eta = 0.10, 0.31x of
//     filtered (74 pairs per collision). DenseScan<D> is the scan from packing
//     list_packing(D) on: lists in 3D, AutoScan<D> elsewhere.
#pragma once

#include <type_traits>

#include "hypergas/edmd/scan_filtered.hpp"
#include "hypergas/edmd/scan_horizon.hpp"
#include "hypergas/edmd/scan_lists.hpp"
#include "hypergas/edmd/scan_slab.hpp"

namespace hypergas::edmd {

/// The measured fastest scan policy for dimension D (see the file comment).
template <int D>
using AutoScan = std::conditional_t<(D <= 2), SlabScan,
                                    std::conditional_t<(D == 3), HorizonScan, FilteredScan>>;

/// The packing fraction from which DenseScan<D> is used (the measured crossover in 3D lies
/// between 0.38 and 0.45; above 1, never, where lists were not found faster).
constexpr double list_packing(int D) { return D == 3 ? 0.43 : 2.0; }

/// The measured fastest scan policy for dense states, packing >= list_packing(D).
template <int D>
using DenseScan = std::conditional_t<(D == 3), ListScan, AutoScan<D>>;

}  // namespace hypergas::edmd
