// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

// A convex hull shape whose points can be replaced in place. Private to the Bullet adapter.

#include <crumple/base/Math.h>

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace crumple::bullet
{

/// btConvexHullShape with SetPoints: a prop body's pieces change shape every step its FEM moves, and
/// replacing a kept hull's points spares a new hull's allocations (the same bits as a new hull of them).
class ReplaceableHull final : public btConvexHullShape
{
  public:
    /// The hull of inPoints (at least one), with a margin Bullet adds outside it kept small against the
    /// hull's size: min(1 cm, 5 % of its smallest extent)
    void SetPoints(const std::vector<Vec3>& inPoints)
    {
        m_unscaledPoints.resize(static_cast<int>(inPoints.size()));
        Vec3 low = inPoints[0], high = low;
        for (std::size_t i = 0; i < inPoints.size(); ++i)
        {
            const Vec3& p = inPoints[i];
            m_unscaledPoints[static_cast<int>(i)] =
                btVector3(btScalar(p.x()), btScalar(p.y()), btScalar(p.z()));
            low = low.cwiseMin(p);
            high = high.cwiseMax(p);
        }
        setMargin(btScalar(std::min(0.01, 0.05 * (high - low).minCoeff())));
        recalcLocalAabb();
    }
};

} // namespace crumple::bullet
