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

// inVector resized to inSize, with half again as much capacity when it must grow: the next, slightly larger
// factorisation of a cracking prop then fits (see the class comment).
template <class T>
void FitSize(std::vector<T>& ioVector, std::size_t inSize)
{
    if (ioVector.capacity() < inSize)
        ioVector.reserve(inSize + inSize / 2);
    ioVector.resize(inSize);
}

// FitSize, every element set to inValue.
template <class T>
void FitAssign(std::vector<T>& ioVector, std::size_t inSize, const T& inValue)
{
    FitSize(ioVector, inSize);
    std::fill(ioVector.begin(), ioVector.end(), inValue);
}

} // namespace

// The node graph goes to Eigen's AMD routine (internal::minimum_degree_ordering: what AMDOrdering calls once
// it has formed the symmetric pattern; Eigen 3.3 and 3.4 have it with this signature) as the matrix
// AMDOrdering would form: compressed columns, each column's rows ascending, each node pair once (an element
// edge is shared by about five elements, so the blocks repeat its pair), the diagonal where the blocks have
// it. So AMD's answer is AMDOrdering's bit for bit (TetFactoredSolveTest), without its triplet sort and its
// transpose and sparse sum (a third of the ordering's time on the cracking racing fence). The graph is
// symmetric, so a column's rows are its row's columns: each row's distinct columns are counted, then each
// receives the row, rows visited in ascending order.
void NodeBlockCholesky::OrderMinimumDegree(int inNodeCount, std::span<const NodeBlock> inBlocks)
{
    // intent: every block's node pair in both rows, repeats included
    const auto size = static_cast<std::size_t>(inNodeCount);
    FitAssign(mRowStart, size + 1, 0);
    for (const NodeBlock& block : inBlocks)
    {
        ++mRowStart[static_cast<std::size_t>(block.mRow) + 1];
        if (block.mRow != block.mColumn)
            ++mRowStart[static_cast<std::size_t>(block.mColumn) + 1];
    }
    std::partial_sum(mRowStart.begin(), mRowStart.end(), mRowStart.begin());
    FitSize(mPattern, static_cast<std::size_t>(mRowStart[size]));
    FitSize(mRowFill, size);
    std::copy(mRowStart.begin(), mRowStart.end() - 1, mRowFill.begin());
    for (const NodeBlock& block : inBlocks)
    {
        mPattern[static_cast<std::size_t>(mRowFill[static_cast<std::size_t>(block.mRow)]++)] = block.mColumn;
        if (block.mRow != block.mColumn)
            mPattern[static_cast<std::size_t>(mRowFill[static_cast<std::size_t>(block.mColumn)]++)] = block.mRow;
    }
    // intent: each row's distinct columns packed at the front of its segment and counted (its column's
    // length in the graph); the write never passes the read
    FitAssign(mFlag, size, -1);
    FitAssign(mCount, size, 0);
    for (int row = 0; row < inNodeCount; ++row)
    {
        const int first = mRowStart[static_cast<std::size_t>(row)];
        int& distinct = mCount[static_cast<std::size_t>(row)];
        for (int entry = first; entry < mRowStart[static_cast<std::size_t>(row) + 1]; ++entry)
        {
            const int column = mPattern[static_cast<std::size_t>(entry)];
            if (mFlag[static_cast<std::size_t>(column)] == row)
                continue;
            mFlag[static_cast<std::size_t>(column)] = row;
            mPattern[static_cast<std::size_t>(first + distinct++)] = column;
        }
    }
    Eigen::SparseMatrix<int> graph(inNodeCount, inNodeCount);
    int* const outer = graph.outerIndexPtr();
    outer[0] = 0;
    for (std::size_t column = 0; column < size; ++column)
        outer[column + 1] = outer[column] + mCount[column];
    graph.resizeNonZeros(outer[size]);
    int* const inner = graph.innerIndexPtr();
    std::fill(graph.valuePtr(), graph.valuePtr() + outer[size], 1); // intent: defined values (AMD reads none)
    // intent: each row given to its distinct columns, rows ascending: each column's rows sorted
    std::copy(outer, outer + size, mRowFill.begin());
    for (int row = 0; row < inNodeCount; ++row)
    {
        const int first = mRowStart[static_cast<std::size_t>(row)];
        for (int entry = first; entry < first + mCount[static_cast<std::size_t>(row)]; ++entry)
            inner[mRowFill[static_cast<std::size_t>(mPattern[static_cast<std::size_t>(entry)])]++] = row;
    }
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inverse;
    Eigen::internal::minimum_degree_ordering(graph, inverse);
    // AMD gives P^-1 (old index of each new row), as Eigen's simplicial solvers use it.
    FitSize(mNewOfOld, static_cast<std::size_t>(inNodeCount));
    for (int row = 0; row < inNodeCount; ++row)
        mNewOfOld[inverse.indices()[row]] = row;
}

void NodeBlockCholesky::Analyze(int inNodeCount, std::span<const NodeBlock> inBlocks)
{
    mAnalyzed = false;
    const std::size_t size = static_cast<std::size_t>(inNodeCount);
    OrderMinimumDegree(inNodeCount, inBlocks);
    FitSize(mPlaced, inBlocks.size());
    FitSize(mAnalyzedPattern, inBlocks.size());
    for (std::size_t index = 0; index < inBlocks.size(); ++index)
    {
        const int row = mNewOfOld[inBlocks[index].mRow];
        const int column = mNewOfOld[inBlocks[index].mColumn];
        mPlaced[index] = row >= column ? Placed{row, column, static_cast<int>(index), false}
                                       : Placed{column, row, static_cast<int>(index), true};
        mAnalyzedPattern[index] = {inBlocks[index].mRow, inBlocks[index].mColumn};
    }
    // intent: the order of a stable sort by (row, column), in linear time: a counting sort by row (stable),
    // then each row's few blocks by column with an insertion sort (stable). Equal positions keep their input
    // order, so their sums in FactorNumeric are the same numbers whatever sort made the order.
    FitAssign(mRowStart, size + 1, 0);
    for (const Placed& block : mPlaced)
        ++mRowStart[static_cast<std::size_t>(block.mRow) + 1];
    std::partial_sum(mRowStart.begin(), mRowStart.end(), mRowStart.begin());
    FitSize(mPlacedByRow, mPlaced.size());
    FitSize(mRowFill, size);
    std::copy(mRowStart.begin(), mRowStart.end() - 1, mRowFill.begin());
    for (const Placed& block : mPlaced)
        mPlacedByRow[static_cast<std::size_t>(mRowFill[static_cast<std::size_t>(block.mRow)]++)] = block;
    std::vector<Placed>& placed = mPlacedByRow;
    for (int row = 0; row < inNodeCount; ++row)
        for (int index = mRowStart[row] + 1; index < mRowStart[row + 1]; ++index)
        {
            const Placed moving = placed[index];
            int slot = index;
            for (; slot > mRowStart[row] && placed[slot - 1].mColumn > moving.mColumn; --slot)
                placed[slot] = placed[slot - 1];
            placed[slot] = moving;
        }

    // Symbolic: elimination tree and the number of blocks below the diagonal in each column of L, from the
    // distinct strictly lower positions of each permuted row.
    std::vector<int>& parent = mParent;
    std::vector<int>& flag = mFlag;
    std::vector<int>& count = mCount;
    FitAssign(parent, size, -1);
    FitAssign(flag, size, -1);
    FitAssign(count, size, 0);
    for (int k = 0, index = 0; k < inNodeCount; ++k)
    {
        flag[k] = k;
        for (; index < mRowStart[k + 1]; ++index)
            for (int i = placed[index].mColumn; flag[i] != k; i = parent[i])
            {
                if (parent[i] == -1)
                    parent[i] = k;
                ++count[i];
                flag[i] = k;
            }
    }
    FitAssign(mColumnStart, size + 1, 0);
    std::partial_sum(count.begin(), count.end(), mColumnStart.begin() + 1);
    // intent: counted once per pattern here, not by every caller that weighs a refactorisation
    mNumericBlockProducts = 0;
    for (const int below : count)
        mNumericBlockProducts += static_cast<std::int64_t>(below) * (below + 1) / 2;
    mAnalyzedNodeCount = inNodeCount;
    mAnalyzed = true;
}

bool NodeBlockCholesky::IsAnalyzedPattern(int inNodeCount, std::span<const NodeBlock> inBlocks) const
{
    if (!mAnalyzed || inNodeCount != mAnalyzedNodeCount || inBlocks.size() != mAnalyzedPattern.size())
        return false;
    for (std::size_t index = 0; index < inBlocks.size(); ++index)
        if (inBlocks[index].mRow != mAnalyzedPattern[index].first || inBlocks[index].mColumn != mAnalyzedPattern[index].second)
            return false;
    return true;
}

bool NodeBlockCholesky::Factor(int inNodeCount, std::span<const NodeBlock> inBlocks)
{
    mFactored = false;
    mAnalyzed = false;
    if (inNodeCount <= 0)
        return false;
    Analyze(inNodeCount, inBlocks);
    return FactorNumeric(inNodeCount, inBlocks);
}

bool NodeBlockCholesky::Refactor(int inNodeCount, std::span<const NodeBlock> inBlocks)
{
    if (!IsAnalyzedPattern(inNodeCount, inBlocks))
        return Factor(inNodeCount, inBlocks);
    mFactored = false;
    return FactorNumeric(inNodeCount, inBlocks);
}

bool NodeBlockCholesky::FactorNumeric(int inNodeCount, std::span<const NodeBlock> inBlocks)
{
    const int n = inNodeCount;
    const std::size_t size = static_cast<std::size_t>(n);

    // The lower triangle of P A P^T by rows, each run of equal positions summed in input order.
    const std::vector<Placed>& placed = mPlacedByRow;
    PermutedRows& rows = mRows;
    FitAssign(rows.mStart, size + 1, 0);
    FitAssign(rows.mDiagonal, size, Mat3(Mat3::Zero()));
    rows.mColumn.clear();
    rows.mBlock.clear();
    if (rows.mBlock.capacity() < placed.size())
    {
        rows.mColumn.reserve(placed.size());
        rows.mBlock.reserve(placed.size());
    }
    for (std::size_t index = 0; index < placed.size();)
    {
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
    const PermutedRows& a = mRows;

    const std::vector<int>& parent = mParent;
    std::vector<int>& flag = mFlag;
    const std::size_t lower_count = static_cast<std::size_t>(mColumnStart[n]);
    FitAssign(mRowIndex, lower_count, 0);
    FitAssign(mLower, lower_count, Mat3(Mat3::Zero()));
    FitAssign(mDiagonalInverse, size, Mat3(Mat3::Zero()));

    // Numeric, up-looking: row k of L solves L(0:k, 0:k) y = A(0:k, k) over the reach of A's column k in the
    // elimination tree, visited in topological order; then L_kk = chol(A_kk - sum L_ki L_ki^T).
    std::vector<int>& next = mNext; // fill position of each column
    FitSize(next, size);
    std::copy(mColumnStart.begin(), mColumnStart.end() - 1, next.begin());
    std::vector<Mat3>& x = mColumnWork;
    FitAssign(x, size, Mat3(Mat3::Zero()));
    std::vector<int>& pattern = mPattern;
    std::vector<int>& stack = mStack;
    FitSize(pattern, size);
    FitSize(stack, size);
    FitAssign(flag, size, -1);
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
    FitAssign(mWork, size, Vec3(Vec3::Zero()));
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
