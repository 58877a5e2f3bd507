// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>
#include <crumple/base/Result.h>
#include <crumple/plugin/Ids.h>

#include <algorithm>
#include <string>
#include <vector>

namespace crumple::plugin
{

/// The engine body of a destructible prop (a fence, a barrier, a crate) that an adapter creates and owns
/// (BulletAdapter::CreatePropBody, OdeAdapter::CreatePropBody; props::MakePropBody fills it from a prop's
/// mesh). Its shape is a compound of convex pieces, so that it can lose the pieces that break loose
/// (SetPropPieces) while the rest stands.
///
/// A held prop (one anchored to the ground: a fence's posts, a wall's facing) is a dynamic body that the
/// adapter puts back at its pose after every engine step, without gravity, at rest or moving as fast as the
/// material the last step struck (the adapters' SetHeldVelocity with props::PropWorld::GetContactVelocity:
/// then a member the car already pushes at its own speed takes no new impulse). Within a step a car
/// meets it as a free body of the prop's mass: the engine's contact takes from the car the momentum it
/// takes to set that mass moving, and Crumple computes the same impulse (from the pre-solve velocities and
/// this mass) and hands it to the prop's FEM, where it cracks what it breaks. A prop that breaks lets the
/// car through with the speed a real one leaves it (a static body would stop the car dead in the first
/// step); one that holds is hit again at every step the car keeps pushing, so it slows the car over a few
/// steps as a yielding barrier does. A free prop (a crate) is an ordinary dynamic body.
/// The body frame sits at the centre of mass along the principal axes of inertia (what engines need).
struct CRUMPLE_API PropBodySettings
{
    double mMass = 1.0;                    ///< kg, in [1e-12, cMaxBodyMass] (a float engine's range)
    Vec3 mPrincipalInertia = Vec3::Ones(); ///< About the centre of mass along the body axes (kg m^2), each in
                                           ///< [1e-12, 1e30] and at most the sum of the other two (as every real
                                           ///< mass distribution)
    Vec3 mPosition = Vec3::Zero();         ///< Centre of mass, world frame (m)
    Mat3 mOrientation = Mat3::Identity();  ///< Body axes in world coordinates (columns): a rotation
    /// The collision shape, body frame (m): the union of each piece's convex hull (Bullet) or bounding box
    /// along the body axes (ODE). At least one piece; each at least 4 points that span a volume.
    std::vector<std::vector<Vec3>> mPieces;
    bool mHeld = true; ///< Put back at its pose after every engine step (above); false: a free body
};

/// Checks the settings at an adapter's boundary (the ranges of ConvexBodySettings, every piece a hull);
/// the message names the offending field.
CRUMPLE_API Status ValidatePropBodySettings(const PropBodySettings& inSettings);

/// Checks a prop body's pieces alone (SetPropPieces): at least one, each at least 4 finite points within
/// 1e9 m that span a volume.
CRUMPLE_API Status ValidatePropPieces(const std::vector<std::vector<Vec3>>& inPieces);

/// Checks a held body's velocity (SetHeldVelocity): finite, at most cMaxBodySpeed (m/s).
CRUMPLE_API Status ValidateHeldVelocity(const Vec3& inVelocity);

/// Checks a held body's contact mass (SetHeldMass): 0 (the body's own mass and inertia) or in
/// [1e-12, cMaxBodyMass] kg.
CRUMPLE_API Status ValidateHeldMass(double inMass);

/// For the adapters: the held prop body inBody among the bodies an adapter owns (each an Owned with its
/// damage body mBody and mHeld), or the error inCaller reports for any other body (OutOfRange).
template <class Owned>
Result<Owned*> FindHeldPropBody(std::vector<Owned>& ioOwned, BodyId inBody, const char* inCaller)
{
    const auto owned = std::find_if(ioOwned.begin(), ioOwned.end(),
                                    [&](const Owned& inOwned) { return inOwned.mBody == inBody; });
    if (owned == ioOwned.end() || !owned->mHeld)
        return MakeError(EError::OutOfRange, std::string(inCaller) + ": body " +
                                                 std::to_string(inBody.mValue) +
                                                 " is not a held prop body of this adapter");
    return &*owned;
}

} // namespace crumple::plugin
