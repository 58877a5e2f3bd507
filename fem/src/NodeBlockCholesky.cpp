// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "NodeBlockCholesky.h"

#include <Eigen/Cholesky>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>

#include <algorithm>
#include <numeric>

namespace crumple::fem
{

namespace
{

// The lower triangle of P A P^T by rows: row k holds its strictly lower blocks (column, block), sorted by
// column, and its diagonal block.
struct PermutedRows
{
    std::vector<int> mStart;        // #n + 1
    std::vector<int> mColumn;       // column of each strictly lower block
    std::vector<Mat3> mBlock;       // A_kj, j < k
    std::vector<Mat3> mDiagonal;    // #n A_kk
};

// Approximate minimum degree ordering of the node graph; returns new index of each old node.
std::vector<int> MinimumDegreeOrder(int inNodeCount, std::span<const NodeBlock> inBlocks)
{
    std::vector<Eigen::Triplet<int>> pattern;
    pattern.reserve(2 * inBlocks.size());
    for (const NodeBlock& block : inBlocks)
    {
        pattern.emplace_back(block.mRow, block.mColumn, 1);
        pattern.emplace_back(block.mColumn, block.mRow, 1);
    }
    Eigen::SparseMatrix<int> graph(inNodeCount, inNodeCount);
    graph.setFromTriplets(pattern.begin(), pattern.end());
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inverse;
    Eigen::AMDOrdering<int>()(graph, inverse);
    // AMD gives P^-1 (old index of each new row), as Eigen's simplicial solvers use it.
    std::vector<int> new_of_old(inNodeCount);
    for (int row = 0; row < inNodeCount; ++row)
        new_of_old[inverse.indices()[row]] = row;
    return new_of_old;
}

// The blocks moved to their permuted places in the lower triangle, duplicates summed in input order.
PermutedRows PermuteLower(int inNodeCount, std::span<const NodeBlock> inBlocks, const std::vector<int>& inNewOfOld)
{
    struct Placed
    {
        int mRow;
        int mColumn;
        int mSource;
        bool mTransposed;
    };
    std::vector<Placed> placed(inBlocks.size());
    for (std::size_t index = 0; index < inBlocks.size(); ++index)
    {
        const int row = inNewOfOld[inBlocks[index].mRow];
        const int column = inNewOfOld[inBlocks[index].mColumn];
        placed[index] = row >= column ? Placed{row, column, static_cast<int>(index), false}
                                      : Placed{column, row, static_cast<int>(index), true};
    }
    std::stable_sort(placed.begin(), placed.end(), [](const Placed& inA, const Placed& inB)
                     { return inA.mRow != inB.mRow ? inA.mRow < inB.mRow : inA.mColumn < inB.mColumn; });

    PermutedRows rows;
    rows.mStart.assign(inNodeCount + 1, 0);
    rows.mDiagonal.assign(inNodeCount, Mat3::Zero());
    for (std::size_t index = 0; index < placed.size();)
    {
        // Sum a run of equal positions.
        const Placed& first = placed[index];
        Mat3 sum = Mat3::Zero();
        for (; index < placed.size() && placed[index].mRow == first.mRow && placed[index].mColumn == first.mColumn;
             ++index)
        {
            const Mat3& block = inBlocks[placed[index].mSource].mBlock;
            sum += placed[index].mTransposed ? Mat3(block.transpose()) : block;
        }
        if (first.mRow == first.mColumn)
            rows.mDiagonal[first.mRow] = 0.5 * (sum + sum.transpose());
        else
        {
            rows.mColumn.push_back(first.mColumn);
            rows.mBlock.push_back(sum);
            ++rows.mStart[first.mRow + 1];
        }
    }
    std::partial_sum(rows.mStart.begin(), rows.mStart.end(), rows.mStart.begin());
    return rows;
}

} // namespace

bool NodeBlockCholesky::Factor(int inNodeCount, std::span<const NodeBlock> inBlocks)
{
    mFactored = false;
    const int n = inNodeCount;
    if (n <= 0)
        return false;
    mNewOfOld = MinimumDegreeOrder(n, inBlocks);
    const PermutedRows a = PermuteLower(n, inBlocks, mNewOfOld);

    // Symbolic: elimination tree and the number of blocks below the diagonal in each column of L.
    std::vector<int> parent(n, -1), flag(n, -1), count(n, 0);
    for (int k = 0; k < n; ++k)
    {
        flag[k] = k;
        for (int entry = a.mStart[k]; entry < a.mStart[k + 1]; ++entry)
            for (int i = a.mColumn[entry]; flag[i] != k; i = parent[i])
            {
                if (parent[i] == -1)
                    parent[i] = k;
                ++count[i];
                flag[i] = k;
            }
    }
    mColumnStart.assign(n + 1, 0);
    std::partial_sum(count.begin(), count.end(), mColumnStart.begin() + 1);
    mRowIndex.assign(mColumnStart[n], 0);
    mLower.assign(mColumnStart[n], Mat3::Zero());
    mDiagonalInverse.assign(n, Mat3::Zero());

    // Numeric, up-looking: row k of L solves L(0:k, 0:k) y = A(0:k, k) over the reach of A's column k in the
    // elimination tree, visited in topological order; then L_kk = chol(A_kk - sum L_ki L_ki^T).
    std::vector<int> next(mColumnStart.begin(), mColumnStart.end() - 1); // fill position of each column
    std::vector<Mat3> x(n, Mat3::Zero());
    std::vector<int> pattern(n), stack(n);
    std::fill(flag.begin(), flag.end(), -1);
    for (int k = 0; k < n; ++k)
    {
        int top = n;
        flag[k] = k;
        for (int entry = a.mStart[k]; entry < a.mStart[k + 1]; ++entry)
        {
            const int j = a.mColumn[entry];
            x[j] = a.mBlock[entry].transpose(); // A(j, k) = A_kj^T
            int length = 0;
            for (int i = j; flag[i] != k; i = parent[i])
            {
                stack[length++] = i;
                flag[i] = k;
            }
            while (length > 0)
                pattern[--top] = stack[--length];
        }
        Mat3 diagonal = a.mDiagonal[k];
        for (int position = top; position < n; ++position)
        {
            const int i = pattern[position];
            const Mat3 y = mDiagonalInverse[i] * x[i]; // L_ii^-1 (A(i,k) - sum of earlier rows)
            x[i].setZero();
            for (int block = mColumnStart[i]; block < next[i]; ++block)
                x[mRowIndex[block]].noalias() -= mLower[block] * y;
            diagonal.noalias() -= y.transpose() * y;
            mRowIndex[next[i]] = k;
            mLower[next[i]] = y.transpose(); // L_ki
            ++next[i];
        }
        const Eigen::LLT<Mat3> pivot(0.5 * (diagonal + diagonal.transpose()));
        if (pivot.info() != Eigen::Success)
            return false;
        const Mat3 lower = pivot.matrixL();
        if (!(lower.diagonal().minCoeff() > 0.0) || !lower.allFinite())
            return false;
        mDiagonalInverse[k] = lower.triangularView<Eigen::Lower>().solve(Mat3::Identity());
    }
    mWork.assign(n, Vec3::Zero());
    mFactored = true;
    return true;
}

std::int64_t NodeBlockCholesky::GetBlockCount() const
{
    return mFactored ? static_cast<std::int64_t>(mLower.size() + mDiagonalInverse.size()) : 0;
}

void NodeBlockCholesky::Solve(std::span<Vec3> ioX) const
{
    const int n = static_cast<int>(mDiagonalInverse.size());
    for (int node = 0; node < n; ++node)
        mWork[mNewOfOld[node]] = ioX[node];

    // L y = P b, column by column.
    for (int i = 0; i < n; ++i)
    {
        const Vec3 y = mDiagonalInverse[i] * mWork[i];
        mWork[i] = y;
        for (int block = mColumnStart[i]; block < mColumnStart[i + 1]; ++block)
            mWork[mRowIndex[block]].noalias() -= mLower[block] * y;
    }
    // L^T z = y, backwards.
    for (int i = n - 1; i >= 0; --i)
    {
        Vec3 sum = mWork[i];
        for (int block = mColumnStart[i]; block < mColumnStart[i + 1]; ++block)
            sum.noalias() -= mLower[block].transpose() * mWork[mRowIndex[block]];
        mWork[i] = mDiagonalInverse[i].transpose() * sum;
    }
    for (int node = 0; node < n; ++node)
        ioX[node] = mWork[mNewOfOld[node]];
}

} // namespace crumple::fem
