// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "HeldWall.h"

namespace crumple::common
{

namespace
{

constexpr double cBallMass = 10.0; // kg
constexpr double cBallSpeed = 5.0; // m/s

} // namespace

plugin::PropBodySettings HeldWall()
{
    plugin::PropBodySettings settings;
    settings.mMass = 50.0;
    // m / 12 (b^2 + c^2) about each axis of a 0.1 x 4 x 1 m plate
    const double a = 0.1, b = 4.0, c = 1.0;
    settings.mPrincipalInertia = settings.mMass / 12.0 * Vec3(b * b + c * c, a * a + c * c, a * a + b * b);
    std::vector<Vec3>& piece = settings.mPieces.emplace_back();
    for (double x : {-0.5 * a, 0.5 * a})
        for (double y : {-0.5 * b, 0.5 * b})
            for (double z : {-0.5 * c, 0.5 * c})
                piece.push_back(Vec3(x, y, z));
    return settings;
}

plugin::ConvexBodySettings WallBall(double inY)
{
    // intent: an octahedron, a tip towards the wall: the engines touch it at one point on the line of its
    // centre of mass, so the blow does not turn it (a cube's face meets a face at one corner first)
    plugin::ConvexBodySettings settings;
    settings.mMass = cBallMass;
    const double radius = 0.1;
    settings.mPrincipalInertia = Vec3::Constant(cBallMass * radius * radius / 5.0);
    settings.mPosition = Vec3(-0.3, inY, 0.0);
    settings.mLinearVelocity = Vec3(cBallSpeed, 0.0, 0.0);
    for (int axis = 0; axis < 3; ++axis)
        for (double sign : {-1.0, 1.0})
            settings.mHullPoints.push_back(sign * radius * Vec3::Unit(axis));
    return settings;
}

double WallBallImpulse(double inSpeedAfter)
{
    return cBallMass * (cBallSpeed - inSpeedAfter);
}

double WallBallReducedMass(double inContactMass)
{
    return cBallMass * inContactMass / (cBallMass + inContactMass);
}

} // namespace crumple::common
