// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/HexElementStiffness.h>
#include <crumple/fem/HexStiffness.h>

#include <algorithm>
#include <string>
#include <vector>

namespace crumple::fem
{

Result<Eigen::SparseMatrix<double>> HexStiffness(const HexMesh& inMesh, const HexMaterial& inMaterial)
{
    const int node_count = inMesh.GetNodeCount();
    const HexElementMatrix& elements = inMesh.GetElements();

    // Node adjacency (nodes sharing an element), sorted: it fixes the sparsity pattern without triplets.
    std::vector<std::vector<int>> neighbours(node_count);
    for (int e = 0; e < elements.rows(); ++e)
        for (int a = 0; a < 8; ++a)
            for (int b = 0; b < 8; ++b)
                neighbours[elements(e, a)].push_back(elements(e, b));
    for (std::vector<int>& list : neighbours)
    {
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
    }

    // Column 3 n + a holds rows 3 m + b for every neighbour m of n, ascending; fill the pattern with zeros.
    const int dof_count = 3 * node_count;
    Eigen::SparseMatrix<double> stiffness(dof_count, dof_count);
    Eigen::VectorXi column_sizes(dof_count);
    for (int n = 0; n < node_count; ++n)
        for (int a = 0; a < 3; ++a)
            column_sizes[3 * n + a] = 3 * static_cast<int>(neighbours[n].size());
    stiffness.reserve(column_sizes);
    for (int n = 0; n < node_count; ++n)
        for (int a = 0; a < 3; ++a)
            for (int m : neighbours[n])
                for (int b = 0; b < 3; ++b)
                    stiffness.insert(3 * m + b, 3 * n + a) = 0.0;
    stiffness.makeCompressed();

    // Scatter each element block into its slots, in element order (bitwise reproducible sums).
    const int* outer = stiffness.outerIndexPtr();
    double* values = stiffness.valuePtr();
    for (int e = 0; e < elements.rows(); ++e)
    {
        Result<HexElementStiffnessMatrix> element = HexElementStiffness(inMesh.GetCorners(e), inMaterial);
        if (element.HasError())
            return MakeError(element.GetError().mCode,
                             "HexStiffness: element " + std::to_string(e) + ": " + element.GetError().mMessage);
        const HexElementStiffnessMatrix& k = element.Get();
        for (int c = 0; c < 8; ++c)
        {
            const int n = elements(e, c);
            const std::vector<int>& list = neighbours[n];
            for (int r = 0; r < 8; ++r)
            {
                const int m = elements(e, r);
                const int slot = static_cast<int>(std::lower_bound(list.begin(), list.end(), m) - list.begin());
                for (int a = 0; a < 3; ++a)
                    for (int b = 0; b < 3; ++b)
                        values[outer[3 * n + a] + 3 * slot + b] += k(3 * r + b, 3 * c + a);
            }
        }
    }
    return stiffness;
}

} // namespace crumple::fem
