// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/plugin/BodyState.h>

class btCollisionObject;

namespace crumple::bullet
{

/// The state a Baraff impulse needs, read from a Bullet collision object (a btRigidBody or a static
/// btCollisionObject). The body frame is Bullet's world transform of the object, i.e. the centre-of-mass
/// frame for rigid bodies: deformable meshes attached to it are given in that frame. The state's shape bounds
/// are the collision shape's bounding box in that frame.
CRUMPLE_API plugin::BodyState BulletBodyState(const btCollisionObject& inObject);

} // namespace crumple::bullet
