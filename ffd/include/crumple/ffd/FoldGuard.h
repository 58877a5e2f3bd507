// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/ffd/FfdLattice.h>

#include <cstdint>
#include <span>
#include <vector>

namespace crumple::ffd
{

/// Keeps a dent from folding the lattice: propagates the crush of a control pushed into its neighbour.
///
/// The derivative of a uniform cubic B-spline along a lattice axis a is a (quadratic) B-spline of the
/// differences of consecutive controls along a (de Boor, "A Practical Guide to Splines", ch. IX), so the
/// map stays monotone along a when along every lattice line in direction a the deformed control positions
/// keep increasing: each diagonal entry of the map's Jacobian stays positive, which keeps a crush along a
/// lattice axis from folding. It does not bound the Jacobian's determinant where the crush runs across the
/// axes: a crush of depth D along a unit n gives det = 1 - n . grad D, and each axis held to the gap below
/// still allows n . grad D past 1 at 45 degrees (measured instead: at least 0.148 at every vertex of the Toy
/// Car crushed 0.75 m into a 45-degree wall at 90 km/h, README known limits). This function enforces, for
/// every line of every axis a and consecutive controls j, j+1,
///     X_{j+1,a} - X_{j,a} >= inMinSpacing * h_a,
/// where X = axes^T (rest control position + displacement) is the deformed control position in the
/// lattice frame and h_a the lattice spacing along a.
///
/// In a violating pair, the control that moved toward the other during this dent (inAfter compared with
/// inBefore along a) is the pusher and keeps its position; the other one yields and is moved along a to
/// keep the gap, and so on down the line (a forward sweep for pushes toward higher index, a backward sweep
/// for pushes toward lower index). Two controls that moved into each other meet symmetrically around their
/// midpoint. Only the lattice-frame component a of a yielding control changes, so the three axes are
/// independent. The sweeps are repeated on a line (fixed order) until it is clean or a pass bound is
/// reached; then a strict forward sweep guarantees the invariant. A pushed gap is set a hair
/// (1e-9 h_a) above the bound, so round-off cannot take it back below.
///
/// Only lines through inChanged are checked (a line whose controls did not change cannot have started
/// to violate when inBefore is ordered), and when none violates nothing is written: ioAfter stays bit
/// identical and the result is empty.
/// @param[in] inLattice     the lattice (rest control grid: origin, axes, spacing, control counts)
/// @param[in] inBefore      #controls committed displacements before this dent (m, body frame,
///                          ControlIndex order), assumed to satisfy the bound already
/// @param[in,out] ioAfter   #controls proposed displacements after this dent (m, body frame); adjusted
/// @param[in] inChanged     indices of the controls this dent changed (any order, duplicates allowed)
/// @param[in] inMinSpacing  smallest gap as a fraction of the spacing, in [0, 1); 0 does nothing
/// @param[in] inMoves       per control, 1 when it moves a vertex (FfdDeformer's reach); empty: all do.
///                          Controls that move none are left out of their lines (neither pushed nor
///                          pushing); the gap between the remaining neighbours is then k spacings at rest
/// @return the indices of the controls this function moved, ascending
CRUMPLE_API std::vector<int> FoldGuard(const FfdLattice& inLattice, std::span<const Vec3> inBefore, std::span<Vec3> ioAfter,
                           std::span<const int> inChanged, double inMinSpacing,
                           std::span<const std::uint8_t> inMoves = {});

} // namespace crumple::ffd
