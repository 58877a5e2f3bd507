// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

// A convex hull shape whose points can be replaced in place. Private to the Bullet adapter.

#include <crumple/base/Math.h>

#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>

#include <algorithm>
#include <vector>

namespace crumple::bullet
{

/// btConvexHullShape with SetPoints: a prop body's pieces change shape every step its FEM moves, and
/// replacing a child's points keeps the child, the compound's tree leaf and the body's broadphase entry,
/// where a new shape had to leave the world and come back (0.25-0.38 ms per step for the racing fence's
/// 80-104 pieces).
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

/// btCompoundShape that can say its children changed: its contact algorithms then drop their children's
/// manifolds, as they do when a child is added or removed.
class ReplaceableCompound final : public btCompoundShape
{
  public:
    void MarkChildrenChanged() { ++m_updateRevision; }
};

} // namespace crumple::bullet
