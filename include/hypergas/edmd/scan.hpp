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
//   ListScan (scan_lists.hpp): neighbour lists renewed as events; a prediction tests only
//     the listed particles, at the price of list renewals and more bytes per particle.
// All find every collision (docs/design.md, "The EDMD event loop"); trajectories agree to
// round-off. AutoScan<D> and DenseScan<D> take the fastest in docs/benchmarks.md ("EDMD
// throughput"): AutoScan<D> for dilute and moderately dense gases (slab in D <= 2, horizon
// in 3D, filtered from 4D), DenseScan<D> from packing list_packing(D) on (lists in 3D,
// AutoScan<D> elsewhere).
#pragma once

#include <type_traits>

#include "hypergas/edmd/scan_filtered.hpp"
#include "hypergas/edmd/scan_horizon.hpp"
#include "hypergas/edmd/scan_lists.hpp"
#include "hypergas/edmd/scan_slab.hpp"

namespace hypergas::edmd {

/// The fastest scan policy for dimension D in dilute and moderately dense gases (see the
/// file comment).
template <int D>
using AutoScan = std::conditional_t<(D <= 2), SlabScan,
                                    std::conditional_t<(D == 3), HorizonScan, FilteredScan>>;

/// The packing fraction from which DenseScan<D> is used: in 3D between the packings where
/// lists lose and win against horizon (docs/benchmarks.md); above 1, never, elsewhere.
constexpr double list_packing(int D) { return D == 3 ? 0.43 : 2.0; }

/// The fastest scan policy for dense states, packing >= list_packing(D).
template <int D>
using DenseScan = std::conditional_t<(D == 3), ListScan, AutoScan<D>>;

}  // namespace hypergas::edmd
