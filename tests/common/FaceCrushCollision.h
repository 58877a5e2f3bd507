// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/plugin/Collision.h>
#include <crumple/plugin/DeformableObject.h>

namespace crumple::common
{

/// A box car of inHalf (m, body frame x along its length, z up) with about 12,000 triangles, of inMaterial,
/// its forward axis inForward: the crush-zone tests' car.
plugin::DeformableObject MakeCrushBoxCar(const Vec3& inHalf, const plugin::DamageMaterial& inMaterial,
                                         const Vec3& inForward = Vec3::UnitX());

/// Four contacts of 2,000 N s on the face of that car whose outward normal is inOutward (+-x: an end, +-y: a
/// side), 1.2 m apart across it and 0.6 m up it; the car is body B of the collision (the normal from B to A
/// is the face's outward normal) and takes inEnergy (J).
plugin::Collision FaceCrushCollision(const Vec3& inHalf, const Vec3& inOutward, double inEnergy);

} // namespace crumple::common
