// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/FfdDeformer.h>

#include "CellSurfaceIndex.h"

namespace crumple::ffd
{

void FfdDeformer::ForEachVertexGroup(const Vec3& inFirstAlong, const std::function<void(const VertexGroup&)>& inVisit) const
{
    VertexGroup group;
    for (std::size_t z = 0; z < mZones.size(); ++z)
    {
        const FfdLattice& zone = mZones[z];
        const std::array<int, 3>& cells = zone.GetCellCount();
        const Vec3 along = zone.GetSettings().mAxes.transpose() * inFirstAlong;
        Eigen::Index axis = 0;
        along.cwiseAbs().maxCoeff(&axis);
        const bool forward = !(along[axis] < 0.0);
        const std::array<int, 2> others{axis == 0 ? 1 : 0, axis == 2 ? 1 : 2};
        const std::vector<std::uint32_t>& start = mCellStart[z];
        const std::span<const std::uint32_t> bucket(mCellVertices[z]);
        std::array<int, 3> ijk{};
        for (int s = 0; s < cells[static_cast<std::size_t>(axis)]; ++s)
        {
            ijk[static_cast<std::size_t>(axis)] = forward ? s : cells[static_cast<std::size_t>(axis)] - 1 - s;
            for (int b = 0; b < cells[static_cast<std::size_t>(others[1])]; ++b)
                for (int a = 0; a < cells[static_cast<std::size_t>(others[0])]; ++a)
                {
                    ijk[static_cast<std::size_t>(others[0])] = a;
                    ijk[static_cast<std::size_t>(others[1])] = b;
                    const auto local = static_cast<std::size_t>(zone.CellIndex(ijk));
                    if (start[local + 1] == start[local])
                        continue;
                    const int cell = mCellOffset[z] + static_cast<int>(local);
                    // intent: the box of the cell's vertices as stored (their own extremes): nothing to widen
                    const CellMotion& motion = *FindMotion(cell); // the cell holds vertices
                    group.mLow = motion.mLow;
                    group.mHigh = motion.mHigh;
                    group.mMoved = 0.0;
                    group.mVertices = bucket.subspan(start[local], start[local + 1] - start[local]);
                    inVisit(group);
                }
        }
    }
    if (!mSurfaceIndex->LooseVertices().empty())
    {
        group = VertexGroup{};
        group.mBounded = false;
        group.mVertices = mSurfaceIndex->LooseVertices();
        inVisit(group);
    }
}

} // namespace crumple::ffd
