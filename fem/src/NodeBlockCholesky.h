// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Math.h>

#include <Eigen/SparseCore>

#include <span>
#include <utility>
#include <vector>

namespace crumple::fem
{

/// One 3 x 3 block A_ij of a symmetric matrix of nodes (A_ji = A_ij^T is implied). Entries with the same
/// (mRow, mColumn) are summed, in the order given.
struct NodeBlock
{
    int mRow = 0;    ///< Node i
    int mColumn = 0; ///< Node j <= i
    Mat3 mBlock = Mat3::Zero();
};

/// Sparse Cholesky factorisation A = P^T L L^T P of a symmetric positive definite matrix made of 3 x 3 node
/// blocks (FEM systems: three degrees of freedom per node), with a precompute (ordering, symbolic analysis,
/// numeric factorisation) and an allocation-free solve.
///
/// Why not Eigen's SimplicialLLT: it factors scalar entries, one index per number, and its triangular solves
/// ran at about 1.2 GFLOP/s on a 9,000-tet prop, 41 % of an implicit step. The same algorithm on 3 x 3 blocks
/// reads one index per nine numbers and does its arithmetic in small dense products: the solves of a prop's
/// implicit step are the hot loop, and they run several times faster this way.
///
/// Algorithm: approximate minimum degree ordering of the node graph (Eigen's AMD, Amestoy, Davis & Duff
/// 1996); elimination tree and column counts (Liu 1990); up-looking Cholesky, row by row, each row a sparse
/// triangular solve over the elimination-tree reach of A's column (Davis, "Direct Methods for Sparse Linear
/// Systems", 2006, section 4.8), with 3 x 3 blocks in place of numbers. Deterministic: no threads, sums in a
/// fixed order.
///
/// Memory is kept between factorisations, and a buffer that must grow gets half again its size: a prop
/// refactored after each crack (a few more nodes each time) touches few fresh pages (Eigen's ordering still
/// allocates its own). On this project's virtual machines a page fault costs microseconds: replaying the
/// racing fence's cracks, the two refactorisations took 18 and 13 ms when every buffer was new, 8-9 and
/// 5 ms with these kept (448 and 69 faults left).
class NodeBlockCholesky
{
public:
    /// Orders, analyses and factors A. Returns false, and holds no factor, when A is not positive definite.
    /// @param[in] inNodeCount  n, the number of block rows
    /// @param[in] inBlocks     the blocks of the lower triangle (mRow >= mColumn) in any order
    bool Factor(int inNodeCount, std::span<const NodeBlock> inBlocks);

    /// Factors new values of the last Factor()'s matrix: inBlocks has the same (mRow, mColumn) sequence as the
    /// blocks Factor() was given (the same element pass over the same mesh), so the ordering and the symbolic
    /// analysis are reused and only the numeric factorisation is redone: about 40 % of a Factor() on a prop
    /// of a few thousand tetrahedra. When the sequence differs, or no analysis is held, it is a Factor().
    /// Returns false, and holds no factor, when A is not positive definite.
    bool Refactor(int inNodeCount, std::span<const NodeBlock> inBlocks);

    /// True after a successful Factor()
    bool IsFactored() const { return mFactored; }
    /// Number of 3 x 3 blocks in L, diagonal included (0 without a factor)
    std::int64_t GetBlockCount() const;

    /// 3 x 3 block products of a numeric factorisation of the analysed pattern: the sum over the columns of L
    /// of c (c + 1) / 2, c the column's blocks below the diagonal (the up-looking factorisation's inner loop
    /// runs over each column's blocks of the rows before the current one). 0 without an analysis.
    std::int64_t GetNumericBlockProducts() const { return mAnalyzed ? mNumericBlockProducts : 0; }
    /// The ordering of the last Factor(): node i is row GetNodeRows()[i] of L (empty before one)
    const std::vector<int>& GetNodeRows() const { return mNewOfOld; }
    /// ioX = A^-1 ioX (#n; no allocation).
    void Solve(std::span<Vec3> ioX) const;

private:
    // The lower triangle of P A P^T by rows: row k holds its strictly lower blocks (column, block), sorted by
    // column, and its diagonal block.
    struct PermutedRows
    {
        std::vector<int> mStart;     // #n + 1
        std::vector<int> mColumn;    // column of each strictly lower block
        std::vector<Mat3> mBlock;    // A_kj, j < k
        std::vector<Mat3> mDiagonal; // #n A_kk
    };
    // A block moved to its permuted place (row >= column), from input block mSource.
    struct Placed
    {
        int mRow;
        int mColumn;
        int mSource;
        bool mTransposed;
    };

    // Approximate minimum degree ordering of the node graph into mNewOfOld.
    void OrderMinimumDegree(int inNodeCount, std::span<const NodeBlock> inBlocks);
    // Where each block goes under the ordering, sorted by permuted position (mPlacedByRow), and the
    // elimination tree and column counts of L: everything that depends on the pattern alone.
    void Analyze(int inNodeCount, std::span<const NodeBlock> inBlocks);
    // The blocks summed into their permuted places in mRows (in input order), then L by the up-looking
    // factorisation over the analysed pattern.
    bool FactorNumeric(int inNodeCount, std::span<const NodeBlock> inBlocks);
    // True when inBlocks has the (row, column) sequence Analyze() was given.
    bool IsAnalyzedPattern(int inNodeCount, std::span<const NodeBlock> inBlocks) const;

    bool mFactored = false;
    bool mAnalyzed = false;
    int mAnalyzedNodeCount = 0;
    std::int64_t mNumericBlockProducts = 0; // GetNumericBlockProducts of the analysed pattern (Analyze)
    std::vector<std::pair<int, int>> mAnalyzedPattern; // (row, column) of each input block
    std::vector<int> mNewOfOld;          // #n permutation P: node i is row mNewOfOld[i] of L
    std::vector<int> mColumnStart;       // #n + 1, strictly lower part of L by column
    std::vector<int> mRowIndex;          // row of each off-diagonal block
    std::vector<Mat3> mLower;            // L_rc, off-diagonal blocks by column
    std::vector<Mat3> mDiagonalInverse;  // #n, L_kk^-1 (lower triangular)
    mutable std::vector<Vec3> mWork;     // #n, permuted right-hand side

    // Factor()'s scratch, kept for the next factorisation.
    PermutedRows mRows;
    std::vector<Placed> mPlaced, mPlacedByRow;
    std::vector<int> mRowStart, mRowFill, mParent, mFlag, mCount, mNext, mPattern, mStack;
    std::vector<Mat3> mColumnWork;
};

} // namespace crumple::fem
