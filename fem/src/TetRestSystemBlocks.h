// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "NodeBlockCholesky.h"
#include "TetElementPass.h"

#include <array>
#include <vector>

#include <cstdint>
#include <span>

namespace crumple::fem
{

/// The symmetrised B^T C B + (B^T C B)^T of each element, its ten corner blocks of the lower triangle, kept
/// between TetRestSystemBlocks calls by a solver that refactors after cracks: a crack renumbers the nodes of
/// a few elements and changes no element's rest shape, and recomputing every element took 1.3-1.5 ms of the
/// 4.8 ms refactorisation of the racing fence (4,000 tetrahedra). An element's entry is recomputed when its
/// rest edge inverse (plastic flow) or the material matrix differs from the one it was made from, compared
/// exactly, so the blocks are bitwise those computed afresh. About 800 bytes per element.
struct TetRestStiffnessCache
{
    std::vector<std::array<Mat3, 10>> mBlocks; ///< #T, corner pairs (row >= column) in row-major order
    std::vector<Mat3> mEdgeInverse;            ///< #T, the rest edge inverse each entry was made from
    Matrix6 mMaterial = Matrix6::Zero();       ///< The material matrix the entries were made from
};

/// The implicit system at the rest shape, A0 = a M + b K0, restricted to the free nodes: M the lumped masses,
/// K0 = sum_e V0 B_e^T C B_e the linear stiffness of the rest mesh (B_e the 6 x 12 strain-displacement matrix of
/// the linear tetrahedron, engineering shear as in C). K0 is the tangent of both elastic models at rest and
/// the corotated model's tangent is R K0 R^T for a rigidly rotated element, so A0 is the implicit Euler
/// system of a body near rest (a = 1 + h alpha, b = h^2 + h beta) or the static stiffness (a = 0, b = 1).
/// With element frames R_e (inFrames) each element's stiffness is rotated into its frame, R_e K0_e R_e^T:
/// the corotated model's implicit system at those frames, exactly.
/// Block rows and columns are the free nodes' indices inFreeIndex[n]; anchored nodes (inFreeIndex -1) and
/// their couplings are left out. The blocks of the lower triangle, one per element and node pair plus one per
/// free node's mass, in element order (NodeBlockCholesky sums them). The (row, column) sequence depends on
/// the connectivity and the free nodes only, not on the frames: NodeBlockCholesky::Refactor reuses its
/// analysis.
/// @param[in] inInput      connectivity, rest data and material
/// @param[in] inMasses     #N lumped node masses (kg)
/// @param[in] inFreeIndex  #N index of each free node among the free nodes, -1 for an anchored node
/// @param[in] inMassScale       a (1)
/// @param[in] inStiffnessScale  b (s^2 for the implicit system, 1 for the static one)
/// @param[out] outBlocks  blocks of a #free by #free block matrix, units of inMassScale x kg (its memory is
///                         reused: a refactorisation after a crack touches no fresh page)
/// @param[in,out] ioCache  each element's B^T C B kept between calls (null: none kept); see TetRestStiffnessCache
/// @param[in] inFrames     #T element frames (unit quaternions), or empty for the rest frames (identity)
void TetRestSystemBlocks(const TetElementPassInput& inInput, std::span<const double> inMasses,
                         std::span<const int> inFreeIndex, double inMassScale, double inStiffnessScale,
                         std::vector<NodeBlock>& outBlocks, TetRestStiffnessCache* ioCache = nullptr,
                         std::span<const Quat> inFrames = {});

} // namespace crumple::fem
