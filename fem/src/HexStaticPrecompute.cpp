// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "HexFormat.h"

#include <crumple/fem/HexSourceCrc.h>
#include <crumple/fem/HexStaticPrecompute.h>
#include <crumple/fem/HexStiffness.h>

#include <algorithm>
#include <string>

namespace crumple::fem
{

namespace
{

std::string DofName(int inDof)
{
    return "node " + std::to_string(inDof / 3) + " along " + std::string(1, static_cast<char>('x' + inDof % 3));
}

} // namespace

Result<HexStaticData> HexStaticPrecompute(const HexMesh& inMesh, const HexMaterial& inMaterial,
                                          std::span<const int> inFixedNodes)
{
    const int node_count = inMesh.GetNodeCount();

    // Fixed nodes: in range, merged, not empty and not everything.
    std::vector<int> fixed(inFixedNodes.begin(), inFixedNodes.end());
    for (int node : fixed)
        if (node < 0 || node >= node_count)
            return MakeError(EError::OutOfRange, "HexStaticPrecompute: fixed node " + std::to_string(node) +
                                                     " is not a node of the mesh (0.." + std::to_string(node_count - 1) +
                                                     ")");
    std::sort(fixed.begin(), fixed.end());
    fixed.erase(std::unique(fixed.begin(), fixed.end()), fixed.end());
    if (fixed.empty())
        return MakeError(EError::DegenerateGeometry,
                         "HexStaticPrecompute: no fixed nodes, so the stiffness is singular (6 rigid-body modes); "
                         "fix at least 3 non-collinear nodes of every connected part");
    if (static_cast<int>(fixed.size()) == node_count)
        return MakeError(EError::InvalidArgument, "HexStaticPrecompute: every node is fixed, nothing can move");

    // A node outside every element has no stiffness at all.
    std::vector<char> is_fixed(node_count, 0);
    for (int node : fixed)
        is_fixed[node] = 1;
    std::vector<char> is_used(node_count, 0);
    for (int e = 0; e < inMesh.GetElementCount(); ++e)
        for (int c = 0; c < 8; ++c)
            is_used[inMesh.GetElements()(e, c)] = 1;
    for (int n = 0; n < node_count; ++n)
        if (!is_used[n] && !is_fixed[n])
            return MakeError(EError::DegenerateGeometry, "HexStaticPrecompute: node " + std::to_string(n) +
                                                             " belongs to no element and is not fixed (zero stiffness)");

    Result<Eigen::SparseMatrix<double>> assembled = HexStiffness(inMesh, inMaterial);
    if (assembled.HasError())
        return assembled.GetError();
    const Eigen::SparseMatrix<double>& k = assembled.Get();

    // Number the free and the fixed dofs in ascending global order.
    HexStaticData data;
    data.mNodeCount = node_count;
    data.mFreeIndex.assign(3 * node_count, -1);
    std::vector<int> fixed_index(3 * node_count, -1);
    for (int dof = 0; dof < 3 * node_count; ++dof)
    {
        if (is_fixed[dof / 3])
        {
            fixed_index[dof] = static_cast<int>(data.mFixedDofs.size());
            data.mFixedDofs.push_back(dof);
        }
        else
        {
            data.mFreeIndex[dof] = static_cast<int>(data.mFreeDofs.size());
            data.mFreeDofs.push_back(dof);
        }
    }

    // Split K into K_ff and K_fb, column by column (rows stay ascending within each column).
    const int free_count = static_cast<int>(data.mFreeDofs.size());
    const int fixed_count = static_cast<int>(data.mFixedDofs.size());
    Eigen::SparseMatrix<double> k_ff(free_count, free_count);
    Eigen::SparseMatrix<double> k_fb(free_count, fixed_count);
    Eigen::VectorXi ff_sizes = Eigen::VectorXi::Zero(free_count);
    Eigen::VectorXi fb_sizes = Eigen::VectorXi::Zero(fixed_count);
    for (int col = 0; col < k.outerSize(); ++col)
        for (Eigen::SparseMatrix<double>::InnerIterator it(k, col); it; ++it)
            if (data.mFreeIndex[it.row()] >= 0)
            {
                if (data.mFreeIndex[col] >= 0)
                    ++ff_sizes[data.mFreeIndex[col]];
                else
                    ++fb_sizes[fixed_index[col]];
            }
    k_ff.reserve(ff_sizes);
    k_fb.reserve(fb_sizes);
    for (int col = 0; col < k.outerSize(); ++col)
        for (Eigen::SparseMatrix<double>::InnerIterator it(k, col); it; ++it)
        {
            const int row = data.mFreeIndex[it.row()];
            if (row < 0)
                continue;
            if (data.mFreeIndex[col] >= 0)
                k_ff.insert(row, data.mFreeIndex[col]) = it.value();
            else
                k_fb.insert(row, fixed_index[col]) = it.value();
        }
    k_ff.makeCompressed();
    k_fb.makeCompressed();

    // Factorize; Eigen flags only exactly zero pivots, so check every pivot against its diagonal entry.
    auto factorization = std::make_unique<HexStiffnessFactorization>();
    factorization->compute(k_ff);
    const Eigen::VectorXd& pivots = factorization->vectorD();
    if (factorization->info() != Eigen::Success || pivots.size() != free_count)
        return MakeError(EError::DegenerateGeometry,
                         "HexStaticPrecompute: the stiffness is singular (zero pivot): part of the mesh can move "
                         "rigidly; fix at least 3 non-collinear nodes of every connected part");
    const Eigen::VectorXd diagonal = k_ff.diagonal();
    const auto& permutation = factorization->permutationP().indices();
    Eigen::VectorXd permuted_diagonal(free_count);
    for (int i = 0; i < free_count; ++i)
        permuted_diagonal[permutation[i]] = diagonal[i];
    const auto& inverse_permutation = factorization->permutationPinv().indices();
    data.mSmallestPivotRatio = 1.0;
    for (int i = 0; i < free_count; ++i)
    {
        const double ratio = pivots[i] / permuted_diagonal[i];
        if (!(ratio >= cHexSingularPivotRatio))
            return MakeError(EError::DegenerateGeometry,
                             "HexStaticPrecompute: the stiffness is singular (pivot ratio " + HexFormat(ratio) +
                                 " at " + DofName(data.mFreeDofs[inverse_permutation[i]]) +
                                 "): part of the mesh can move rigidly; fix at least 3 non-collinear nodes of "
                                 "every connected part");
        data.mSmallestPivotRatio = std::min(data.mSmallestPivotRatio, ratio);
    }

    data.mFixedNodes = std::move(fixed);
    data.mFreeFixedStiffness = std::move(k_fb);
    data.mFactorization = std::move(factorization);
    data.mSourceCrc = HexSourceCrc(inMesh, inMaterial, data.mFixedNodes);
    return data;
}

} // namespace crumple::fem
