// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <btBulletDynamicsCommon.h>

namespace crumple::common
{

/// Bullet's sequential-impulse solver with split impulses for every contact but the ground's, however
/// shallow. Below the world's split threshold (m_splitImpulsePenetrationThreshold) Bullet pushes a
/// penetration out by adding velocity (Baumgarte), on top of the contact's bounce: a car that sank v h into a
/// wall in its last step leaves it faster than Crumple's restitution says, and at low speed that is most of
/// the rebound (a box car into a wall turned 60 degrees at 5 km/h: the engine took 14 % more from it than
/// Crumple's impulse). The ground keeps the world's threshold: resting contacts under it keep Baumgarte,
/// which holds a car on it still (split impulses there rock it by up to 0.064 rad/s at 20 km/h).
class ImpactSplitSolver : public btSequentialImpulseConstraintSolver
{
  public:
    /// inGround: the object whose contacts keep the world's threshold (null: none)
    void SetGround(const btCollisionObject* inGround) { mGround = inGround; }

  protected:
    void convertContacts(btPersistentManifold** ioManifolds, int inCount,
                         const btContactSolverInfo& inInfo) override
    {
        btContactSolverInfo impact = inInfo;
        impact.m_splitImpulsePenetrationThreshold = 0;
        for (int i = 0; i < inCount; ++i)
        {
            const bool ground =
                ioManifolds[i]->getBody0() == mGround || ioManifolds[i]->getBody1() == mGround;
            convertContact(ioManifolds[i], ground ? inInfo : impact);
        }
    }

  private:
    const btCollisionObject* mGround = nullptr;
};

} // namespace crumple::common
