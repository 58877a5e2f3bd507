// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/ffd/FfdLattice.h>
#include <crumple/ffd/GramPseudoInverse.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/QR>
#include <Eigen/SparseCore>

#include <limits>
#include <span>
#include <vector>

namespace crumple::ffd
{

/// Direct manipulation of an FFD lattice (Hughes & Kaufman 1992; D4MD eq. 3): for constrained points P
/// with wanted displacements dP, the control displacements are dC = B^+ dP, the minimum-norm
/// least-squares solution, where row r of B holds the 64 B-spline weights of point r over the controls
/// that reach it.
///
/// B is sparse (64 non-zeros per row) and, on a fine lattice, far wider than tall, so it is not formed
/// densely when it is wide. With fewer points than controls (every dent on a lattice fine enough for local
/// damage) the solve uses B^+ = B^T (B B^T)^+ and factors the #points by #points Gram matrix with a
/// rank-revealing pivoted Cholesky. B B^T is assembled from the tensor-product structure of the weights
/// (entry (i, j) is a product of three 1D overlaps, zero unless the points are within 4 cells per axis),
/// so a dent costs O(#points^2 + #points rank^2) instead of the O(#points^2 #controls) of a dense
/// decomposition of B. Pivots whose Gram diagonal falls to tau^2 of the largest are dropped: the same rank
/// decision as a column-pivoted QR of B^T with |R_kk| <= tau |R_00|. With more points than controls (many
/// contacts packed in a few cells) B is tall and narrow: it is formed densely and factored by a complete
/// orthogonal decomposition (column-pivoted QR then RQ), rank-revealing with the same tau, O(#points #controls^2),
/// which keeps the least-squares answer accurate where the Gram matrix B^T B would square a condition number
/// of up to 1e5. Coincident points (identical rows) or collinear points (rank-deficient B) therefore give a
/// bounded least-squares answer instead of blowing up.

/// Default relative pivot tolerance of the rank-revealing decomposition: pivots of B below 1e-3 of the
/// largest are treated as zero. A direction that B can only excite that weakly would need control
/// displacements over a thousand times the dent to satisfy, which is a blow-up, not a dent: dense or
/// planar contact sets (38 contacts plus interpolated samples on one car face) reach pivot ratios of 1e-6
/// and then ask for controls of 30 m to make a 0.1 m dent. Measured on that case (crumple-bench,
/// lattice_resolution): 1e-8 -> controls 33 m; 1e-5 -> 1.4 m and 135 % overshoot at the face corner;
/// 1e-3 -> 0.22 m, 5 % overshoot, contact error 0.24 %; 1e-2 -> no overshoot, contact error 1.2 %.
constexpr double cDefaultRankTolerance = 1.0e-3;

/// The smallest tolerance the Gram solve honours: its pivots are squared singular values of B, and a
/// squared relative pivot below ~1e-13 (tau ~ 3e-7) is round-off of the Gram matrix, not rank. Tolerances
/// below this act as this one on the Gram path (the tall path takes any tolerance).
constexpr double cMinRankTolerance = 3.0e-7;

struct CRUMPLE_API DirectManipulationData
{
    std::vector<int> mControls;      ///< Linear indices of B's columns, ascending (the controls reached)
    std::vector<int> mRowColumns;    ///< #points * 64: column (into mControls) of each weight of each row
    std::vector<double> mRowWeights; ///< #points * 64: B's non-zeros, row by row, in (c, b, a) order
    bool mGramOfPoints = true;       ///< True: B B^T is factored (#points <= #controls); false: dense B is
    Eigen::MatrixXd mL;              ///< #points by rank pivoted Cholesky factor of B B^T, pivot order
    std::vector<int> mPivots;        ///< #points pivot order of B B^T
    GramPseudoInverse mPseudoInverse; ///< (L L^T)^+ at mRank, ready to apply
    Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> mTall; ///< Of dense B, when #points > #controls
    double mTolerance = cDefaultRankTolerance; ///< The relative pivot tolerance the factor was computed with
    int mRank = 0;                   ///< Numerical rank of B under the tolerance
    int mPointCount = 0;             ///< Rows of B
};

/// Builds B for points given by their lattice locations and factorizes its Gram matrix (the precompute step).
/// @param[in] inLattice    the lattice the points are in
/// @param[in] inLocations  #points locations (cell and local parameter)
/// @param[in] inRelativeTolerance pivot threshold relative to the largest pivot of B, in (0, 1)
CRUMPLE_API DirectManipulationData DirectManipulationPrecompute(const FfdLattice& inLattice,
                                                    std::span<const LatticeLocation> inLocations,
                                                    double inRelativeTolerance = cDefaultRankTolerance);

/// What the solve minimizes among the control displacements that meet the points (or come closest).
enum class EDirectManipulationPrior
{
    /// |dC|: dC = B^+ dP, D4MD's minimum-norm solution. Its controls overshoot the wanted displacement
    /// (a single point at a knot asks its nearest control for 4/3 of its displacement along each axis), so a
    /// flat push comes out as a ripple.
    None,
    /// |dC - C0|: dC = C0 + B^+ (dP - B C0), where C0 is the quasi-interpolant (QuasiInterpolant below), a
    /// convex combination of the wanted displacements at each control. A push that is the same at every
    /// point is met by moving every reached control by exactly that push (partition of unity), so a flat
    /// impactor leaves a flat surface and no control overshoots; varying pushes get the minimum-norm
    /// correction of the remaining residual. Still least-squares optimal (B B^+ B = B), still exact when
    /// B has full row rank; only "minimum norm" becomes "nearest to C0".
    QuasiInterpolant,
};

/// What a solve used.
struct CRUMPLE_API DirectManipulationSolveInfo
{
    int mRank = 0;            ///< Rank of B the solution was computed with
    double mTolerance = 0.0;  ///< The relative pivot tolerance that gave that rank
};

/// Solves for the control displacements (the solve step).
///
/// Gain bound: wanted displacements that disagree between points closer than the spline can bend (per-contact
/// impulses that differ by 2x on neighbouring contacts, an edge snap beside an interpolated sample) are met
/// only through directions of B near the tolerance, with controls hundreds of times the dent (measured: a
/// 5.5 cm FEM-barrier dent on a 0.14 m lattice asked for controls of 10.9 m at tau = 1e-3, 1.7 m at 1e-2).
/// When the largest control displacement exceeds inMaxControlGain times the largest wanted displacement,
/// the tolerance is raised by factors of sqrt(10) (the pivots are already computed, so each step costs a
/// small re-solve, not a factorization) until it does not, or until only the strongest direction is
/// left: the least-squares answer of a lower rank instead of a blow-up. Infinity disables the bound.
/// @param[in] inData          from DirectManipulationPrecompute
/// @param[in] inDisplacements #points by 3 wanted displacements (m)
/// @param[in] inPrior         what the solution stays nearest to (see EDirectManipulationPrior)
/// @param[in] inMaxControlGain bound on max |dC| / max |dP|, >= 1, or infinity
/// @param[out] outInfo        rank and tolerance used, when not null
/// @return #controls by 3 control displacements (m), rows in the order of inData.mControls
CRUMPLE_API Eigen::MatrixX3d DirectManipulationSolve(const DirectManipulationData& inData, const Eigen::MatrixX3d& inDisplacements,
                                         EDirectManipulationPrior inPrior = EDirectManipulationPrior::None,
                                         double inMaxControlGain = std::numeric_limits<double>::infinity(),
                                         DirectManipulationSolveInfo* outInfo = nullptr);

/// The quasi-interpolant C0 of wanted displacements: each reached control takes the average of the wanted
/// displacements of the points it reaches, weighted by its B-spline weight at each point (column-normalized
/// B^T dP). A convex combination per control, so no control exceeds the largest wanted displacement.
/// @return #controls by 3 (m), rows in the order of inData.mControls
CRUMPLE_API Eigen::MatrixX3d QuasiInterpolant(const DirectManipulationData& inData, const Eigen::MatrixX3d& inDisplacements);

/// B itself (#points by #controls, sparse), for tests and diagnostics; the solve never forms it.
CRUMPLE_API Eigen::SparseMatrix<double, Eigen::RowMajor> DirectManipulationMatrix(const DirectManipulationData& inData);

} // namespace crumple::ffd
