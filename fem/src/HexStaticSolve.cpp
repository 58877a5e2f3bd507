// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/Math.h>
#include <crumple/fem/HexStaticSolve.h>

#include <string>

namespace crumple::fem
{

Result<Eigen::VectorXd> HexStaticSolve(const HexStaticData& inData, const Eigen::VectorXd& inForces)
{
    return HexStaticSolve(inData, inForces, Eigen::VectorXd::Zero(3 * static_cast<Eigen::Index>(inData.mNodeCount)));
}

Result<Eigen::VectorXd> HexStaticSolve(const HexStaticData& inData, const Eigen::VectorXd& inForces,
                                       const Eigen::VectorXd& inFixedDisplacements)
{
    // Refuse an empty precomputation, wrong lengths and non-finite input.
    if (!inData.mFactorization)
        return MakeError(EError::InvalidArgument, "HexStaticSolve: the HexStaticData is empty; call HexStaticPrecompute");
    const Eigen::Index dof_count = 3 * static_cast<Eigen::Index>(inData.mNodeCount);
    if (inForces.size() != dof_count || inFixedDisplacements.size() != dof_count)
        return MakeError(EError::InvalidArgument, "HexStaticSolve: forces (" + std::to_string(inForces.size()) +
                                                      ") and displacements (" +
                                                      std::to_string(inFixedDisplacements.size()) +
                                                      ") must have 3 x #nodes = " + std::to_string(dof_count) +
                                                      " entries");
    if (!IsFinite(inForces) || !IsFinite(inFixedDisplacements))
        return MakeError(EError::NonFinite, "HexStaticSolve: a force or a prescribed displacement is NaN or infinite");

    // Right-hand side F_f - K_fb U_b.
    const int free_count = static_cast<int>(inData.mFreeDofs.size());
    const int fixed_count = static_cast<int>(inData.mFixedDofs.size());
    Eigen::VectorXd rhs(free_count);
    for (int i = 0; i < free_count; ++i)
        rhs[i] = inForces[inData.mFreeDofs[i]];
    Eigen::VectorXd fixed_displacements(fixed_count);
    for (int i = 0; i < fixed_count; ++i)
        fixed_displacements[i] = inFixedDisplacements[inData.mFixedDofs[i]];
    if (!fixed_displacements.isZero(0.0))
        rhs -= inData.mFreeFixedStiffness * fixed_displacements;

    // Two triangular solves, then scatter back to all nodes.
    const Eigen::VectorXd free_displacements = inData.mFactorization->solve(rhs);
    // intent: a very soft material under a large force overflows: refused, not handed on as infinite
    if (!IsFinite(free_displacements))
        return MakeError(EError::NonFinite, "HexStaticSolve: the displacements are not finite (forces too large for "
                                            "the material's stiffness)");
    Eigen::VectorXd displacements(dof_count);
    for (int i = 0; i < free_count; ++i)
        displacements[inData.mFreeDofs[i]] = free_displacements[i];
    for (int i = 0; i < fixed_count; ++i)
        displacements[inData.mFixedDofs[i]] = fixed_displacements[i];
    return displacements;
}

} // namespace crumple::fem
