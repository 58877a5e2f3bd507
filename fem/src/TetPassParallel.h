// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/JobSystem.h>
#include <crumple/fem/TetMesh.h>

#include <array>
#include <span>
#include <vector>

namespace crumple::fem
{

/// What the element passes need to run on the host's job system and still give, bit for bit, what the
/// serial passes give (private to the solvers).
///
/// A serial pass scatters each element's four corner forces onto its nodes in element order. In parallel the
/// elements write their corners into mCorners instead (each element its own slots), then each node sums the
/// slots of its elements in ascending element order (mIncidence): the same additions in the same order, so
/// the same bits, whatever the number of workers and however the host schedules the pieces. Energies are
/// summed the same way from mElementEnergy.
struct TetPassParallel
{
    const JobSystem* mJobs = nullptr;
    std::vector<int> mIncidenceStart;          ///< #N + 1: node n's slots are mIncidence[start[n] .. start[n+1])
    std::vector<int> mIncidence;               ///< 4 #T slots 4 tet + corner, ascending per node
    std::vector<std::array<Vec3, 4>> mCorners; ///< #T corner values of the current pass
    std::vector<double> mElementEnergy;        ///< #T element energies of the current pass
    std::vector<TetIndices> mTets;             ///< The connectivity the incidence was built for

    /// Rebuilds the incidence when inTets differ from the connectivity it was built for; sizes the slots.
    void Prepare(std::span<const TetIndices> inTets, int inNodeCount);

    /// outValues[n] = sum of the slots of node n in ascending element order (starting from zero), the nodes
    /// split into pieces on mJobs.
    void Gather(std::span<Vec3> outValues) const;

    /// Runs inKernel(first, last) on pieces [first, last) of [0, inCount) through mJobs, at least
    /// inMinPerPiece items per piece.
    template <class Kernel>
    void ForPieces(std::size_t inCount, std::size_t inMinPerPiece, const Kernel& inKernel) const
    {
        const int pieces = PieceCount(mJobs, inCount, inMinPerPiece);
        struct Context
        {
            const Kernel* mKernel;
            std::size_t mCount;
            int mPieces;
        } context{&inKernel, inCount, pieces};
        // One captured pointer: std::function keeps it without allocating.
        ParallelFor(mJobs, pieces,
                    [ctx = &context](int inPiece)
                    {
                        const std::size_t first = ctx->mCount * static_cast<std::size_t>(inPiece) / ctx->mPieces;
                        const std::size_t last = ctx->mCount * static_cast<std::size_t>(inPiece + 1) / ctx->mPieces;
                        (*ctx->mKernel)(first, last);
                    });
    }
};

} // namespace crumple::fem
