// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/HexCompliance.h>
#include <crumple/fem/HexStaticData.h>

#include <span>

namespace crumple::fem
{

/// Largest compliance matrix HexCompliancePrecompute builds: 2^28 entries (2 GiB of doubles).
constexpr long long cHexMaxComplianceEntries = 1LL << 28;

/// Precomputes the compliance of load nodes onto output nodes: one pair of triangular solves with the
/// factorization of inData per load dof (3 #load solves, in batches), keeping the output rows.
/// Each load dof costs one sparse solve, about 4 flops per non-zero of L (HexStaticData::GetFactorNonZeros()).
/// Measured after HexStaticPrecompute (Release, x86-64, one thread):
/// - 40 x 4 x 4 cantilever (1025 nodes), 25 tip nodes onto all nodes: 75 solves in 34 ms, 1.8 MB;
///   205 top-surface nodes onto all nodes: 615 solves in 0.23 s, 15 MB;
/// - 20 x 20 x 5 plate (1 x 1 x 0.05 m, 2646 nodes, four sides clamped), 441 top nodes onto the same 441: 1323 solves in 3.6 s, 14 MB;
///   onto all 2646 nodes: 4.2 s, 84 MB.
/// Choose the output nodes that are drawn (the visible surface): the product then beats the sparse solve by
/// about 14 x on the plate, while onto all nodes it is no faster (see HexComplianceSolve).
/// Refused: an empty inData (InvalidArgument), no load node, an index out of range (OutOfRange), a node listed
/// twice (InvalidArgument), more than cHexMaxComplianceEntries entries (InvalidArgument).
/// @param[in] inData         from HexStaticPrecompute
/// @param[in] inLoadNodes    nodes that may carry forces (a fixed node gives a zero column)
/// @param[in] inOutputNodes  nodes whose displacements are wanted (a fixed node gives a zero row); empty means
///                           all nodes in index order
CRUMPLE_API Result<HexCompliance> HexCompliancePrecompute(const HexStaticData& inData, std::span<const int> inLoadNodes,
                                              std::span<const int> inOutputNodes);

} // namespace crumple::fem
