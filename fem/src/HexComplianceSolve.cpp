// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/Math.h>
#include <crumple/fem/HexComplianceSolve.h>

#include <string>

namespace crumple::fem
{

Result<Eigen::VectorXd> HexComplianceSolve(const HexCompliance& inCompliance, const Eigen::VectorXd& inLoadForces)
{
    // The matrix must match its node lists, the forces the load list.
    const Eigen::Index rows = 3 * static_cast<Eigen::Index>(inCompliance.mOutputNodes.size());
    const Eigen::Index cols = 3 * static_cast<Eigen::Index>(inCompliance.mLoadNodes.size());
    if (inCompliance.mMatrix.rows() != rows || inCompliance.mMatrix.cols() != cols || cols == 0)
        return MakeError(EError::InvalidArgument, "HexComplianceSolve: the HexCompliance is empty or its matrix (" +
                                                      std::to_string(inCompliance.mMatrix.rows()) + " x " +
                                                      std::to_string(inCompliance.mMatrix.cols()) +
                                                      ") does not match its node lists (" + std::to_string(rows) +
                                                      " x " + std::to_string(cols) + ")");
    if (inLoadForces.size() != cols)
        return MakeError(EError::InvalidArgument, "HexComplianceSolve: " + std::to_string(inLoadForces.size()) +
                                                      " forces, expected 3 x #load nodes = " + std::to_string(cols));
    if (!IsFinite(inLoadForces))
        return MakeError(EError::NonFinite, "HexComplianceSolve: a force is NaN or infinite");

    // One dense product.
    Eigen::VectorXd displacements = inCompliance.mMatrix * inLoadForces;
    // intent: a non-finite entry of a hand-made matrix, or forces whose product overflows, show here (checking the
    // displacements costs O(#output), the matrix O(#output #load))
    if (!IsFinite(displacements))
        return MakeError(EError::NonFinite, "HexComplianceSolve: the displacements are not finite (a non-finite compliance "
                                            "entry, or forces too large for it)");
    return displacements;
}

} // namespace crumple::fem
