// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "TetPassParallel.h"

#include <algorithm>

namespace crumple::fem
{

namespace
{

// Nodes per piece of a gather, elements per piece of an element pass: below this a piece costs more to hand
// out than to run.
constexpr std::size_t cMinNodesPerPiece = 512;

} // namespace

void TetPassParallel::Prepare(std::span<const TetIndices> inTets, int inNodeCount)
{
    mCorners.resize(inTets.size());
    mElementEnergy.resize(inTets.size());
    if (std::equal(inTets.begin(), inTets.end(), mTets.begin(), mTets.end()) &&
        static_cast<int>(mIncidenceStart.size()) == inNodeCount + 1)
        return;

    // Counting sort of the slots by node; slots are visited in ascending order, so each node's list is too.
    mTets.assign(inTets.begin(), inTets.end());
    mIncidenceStart.assign(inNodeCount + 1, 0);
    for (const TetIndices& tet : inTets)
        for (int corner = 0; corner < 4; ++corner)
            ++mIncidenceStart[tet[corner] + 1];
    for (int node = 0; node < inNodeCount; ++node)
        mIncidenceStart[node + 1] += mIncidenceStart[node];
    mIncidence.resize(4 * inTets.size());
    std::vector<int> fill(mIncidenceStart.begin(), mIncidenceStart.end() - 1);
    for (std::size_t tet = 0; tet < inTets.size(); ++tet)
        for (int corner = 0; corner < 4; ++corner)
            mIncidence[fill[inTets[tet][corner]]++] = static_cast<int>(4 * tet) + corner;
}

void TetPassParallel::Gather(std::span<Vec3> outValues) const
{
    ForPieces(outValues.size(), cMinNodesPerPiece,
              [&](std::size_t inFirst, std::size_t inLast)
              {
                  for (std::size_t node = inFirst; node < inLast; ++node)
                  {
                      Vec3 sum = Vec3::Zero();
                      for (int slot = mIncidenceStart[node]; slot < mIncidenceStart[node + 1]; ++slot)
                          sum += mCorners[mIncidence[slot] / 4][mIncidence[slot] % 4];
                      outValues[node] = sum;
                  }
              });
}

} // namespace crumple::fem
