// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/HexCompliancePrecompute.h>

#include <algorithm>
#include <numeric>
#include <string>

namespace crumple::fem
{

namespace
{

// Checks one node list: indices in range, no repeats.
Status CheckNodeList(std::span<const int> inNodes, int inNodeCount, const char* inName)
{
    std::vector<char> seen(inNodeCount, 0);
    for (int node : inNodes)
    {
        if (node < 0 || node >= inNodeCount)
            return MakeError(EError::OutOfRange, std::string("HexCompliancePrecompute: ") + inName + " node " +
                                                     std::to_string(node) + " is not a node of the mesh (0.." +
                                                     std::to_string(inNodeCount - 1) + ")");
        if (seen[node])
            return MakeError(EError::InvalidArgument, std::string("HexCompliancePrecompute: ") + inName + " node " +
                                                          std::to_string(node) + " is listed twice");
        seen[node] = 1;
    }
    return Status::Ok();
}

} // namespace

Result<HexCompliance> HexCompliancePrecompute(const HexStaticData& inData, std::span<const int> inLoadNodes,
                                              std::span<const int> inOutputNodes)
{
    // Validate the precomputation and both node lists before any work.
    if (!inData.mFactorization)
        return MakeError(EError::InvalidArgument,
                         "HexCompliancePrecompute: the HexStaticData is empty; call HexStaticPrecompute");
    if (inLoadNodes.empty())
        return MakeError(EError::InvalidArgument, "HexCompliancePrecompute: no load nodes");
    std::vector<int> outputs(inOutputNodes.begin(), inOutputNodes.end());
    if (outputs.empty())
    {
        outputs.resize(inData.mNodeCount);
        std::iota(outputs.begin(), outputs.end(), 0);
    }
    if (Status status = CheckNodeList(inLoadNodes, inData.mNodeCount, "load"); !status)
        return status.GetError();
    if (Status status = CheckNodeList(outputs, inData.mNodeCount, "output"); !status)
        return status.GetError();
    const long long rows = 3LL * static_cast<long long>(outputs.size());
    const long long cols = 3LL * static_cast<long long>(inLoadNodes.size());
    if (rows * cols > cHexMaxComplianceEntries)
        return MakeError(EError::InvalidArgument, "HexCompliancePrecompute: " + std::to_string(rows) + " x " +
                                                      std::to_string(cols) + " entries exceed the limit of " +
                                                      std::to_string(cHexMaxComplianceEntries) +
                                                      "; choose fewer load or output nodes");

    HexCompliance compliance;
    compliance.mNodeCount = inData.mNodeCount;
    compliance.mSourceCrc = inData.mSourceCrc;
    compliance.mLoadNodes.assign(inLoadNodes.begin(), inLoadNodes.end());
    compliance.mOutputNodes = std::move(outputs);
    compliance.mMatrix = Eigen::MatrixXd::Zero(rows, cols);

    // Free rows of the output dofs (-1: fixed, the row stays zero).
    std::vector<int> output_rows(static_cast<std::size_t>(rows));
    for (std::size_t o = 0; o < compliance.mOutputNodes.size(); ++o)
        for (int b = 0; b < 3; ++b)
            output_rows[3 * o + b] = inData.mFreeIndex[3 * compliance.mOutputNodes[o] + b];

    // Unit-force columns in batches, so the dense right-hand side stays small (#free x cBatch doubles).
    constexpr int cBatch = 64;
    const Eigen::Index free_count = static_cast<Eigen::Index>(inData.mFreeDofs.size());
    std::vector<int> batch_columns;
    Eigen::MatrixXd rhs;
    for (int first = 0; first < cols; first += cBatch)
    {
        // Collect the free load dofs of this batch (fixed ones keep a zero column).
        batch_columns.clear();
        const int last = std::min<int>(static_cast<int>(cols), first + cBatch);
        for (int col = first; col < last; ++col)
            if (inData.mFreeIndex[3 * compliance.mLoadNodes[col / 3] + col % 3] >= 0)
                batch_columns.push_back(col);
        if (batch_columns.empty())
            continue;
        rhs.setZero(free_count, static_cast<Eigen::Index>(batch_columns.size()));
        for (std::size_t i = 0; i < batch_columns.size(); ++i)
        {
            const int col = batch_columns[i];
            rhs(inData.mFreeIndex[3 * compliance.mLoadNodes[col / 3] + col % 3], static_cast<Eigen::Index>(i)) = 1.0;
        }
        const Eigen::MatrixXd solution = inData.mFactorization->solve(rhs);

        // Keep the output rows.
        for (std::size_t i = 0; i < batch_columns.size(); ++i)
            for (long long row = 0; row < rows; ++row)
                if (output_rows[row] >= 0)
                    compliance.mMatrix(row, batch_columns[i]) = solution(output_rows[row], static_cast<Eigen::Index>(i));
    }
    return compliance;
}

} // namespace crumple::fem
