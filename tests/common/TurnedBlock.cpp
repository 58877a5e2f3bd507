// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "TurnedBlock.h"

namespace crumple::common
{

plugin::ConvexBodySettings TurnedBlock(double inHullOffsetZ)
{
    plugin::ConvexBodySettings settings;
    settings.mMass = 12.0;
    // m / 12 (b^2 + c^2) and the like, with m / 12 = 1 kg.
    settings.mPrincipalInertia = Vec3(0.1 * 0.1 + 0.2 * 0.2, 0.6 * 0.6 + 0.2 * 0.2, 0.6 * 0.6 + 0.1 * 0.1);
    settings.mOrientation = Eigen::AngleAxisd(0.9, Vec3(1.0, -1.0, 2.0).normalized()).toRotationMatrix();
    settings.mPosition = Vec3(2.0, 1.0, 0.5);
    settings.mLinearVelocity = Vec3(3.0, -1.0, 0.5);
    settings.mAngularVelocity = Vec3(0.5, 2.0, -1.0);
    for (double x : {-0.3, 0.3})
        for (double y : {-0.05, 0.05})
            for (double z : {-0.1, 0.1})
                settings.mHullPoints.push_back(Vec3(x, y, z + inHullOffsetZ));
    return settings;
}

plugin::PropBodySettings TurnedSlab(bool inHeld)
{
    const plugin::ConvexBodySettings block = TurnedBlock();
    plugin::PropBodySettings settings;
    settings.mMass = block.mMass;
    settings.mPrincipalInertia = block.mPrincipalInertia;
    settings.mOrientation = block.mOrientation;
    settings.mPosition = block.mPosition;
    settings.mHeld = inHeld;
    for (double x0 : {-0.3, 0.0})
    {
        std::vector<Vec3>& piece = settings.mPieces.emplace_back();
        for (double x : {x0, x0 + 0.3})
            for (double y : {-0.05, 0.05})
                for (double z : {-0.1, 0.1})
                    piece.push_back(Vec3(x, y, z));
    }
    return settings;
}

} // namespace crumple::common
