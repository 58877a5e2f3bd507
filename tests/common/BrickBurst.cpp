// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "BrickBurst.h"

#include "DrawVec3.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace crumple::common
{

using namespace crumple::plugin;

namespace
{

constexpr double cLength = 0.24, cDepth = 0.115, cHeight = 0.07; // m: x, y, z
constexpr double cBrickMass = 2.5;                               // kg

BodyState Brick(const Vec3& inCentre, const Vec3& inVelocity, const Vec3& inSpin)
{
    BodyState brick;
    brick.mMass = cBrickMass;
    const double k = 12.0 / cBrickMass;
    brick.mInverseInertiaWorld =
        Vec3(k / (cDepth * cDepth + cHeight * cHeight), k / (cLength * cLength + cHeight * cHeight),
             k / (cLength * cLength + cDepth * cDepth))
            .asDiagonal();
    brick.mTransform.mTranslation = inCentre;
    brick.mCenterOfMass = inCentre;
    brick.mLinearVelocity = inVelocity;
    brick.mAngularVelocity = inSpin;
    return brick;
}

} // namespace

BrickBurst MakeBrickBurst(int inColumns, int inRows, std::uint32_t inSeed,
                          const DamageWorldSettings& inSettings)
{
    Result<std::unique_ptr<DamageWorld>> created = DamageWorld::Create(inSettings);
    if (!created)
        throw std::runtime_error("MakeBrickBurst: " + created.GetError().mMessage);
    BrickBurst burst{std::move(created.Get()), {}};
    DamageWorld& world = *burst.mWorld;
    BodyState ground;
    ground.mMotionType = EMotionType::Static;
    const BodyId ground_id = world.CreateBody(ground).Get();

    std::mt19937 random(inSeed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), share(0.0, 1.0);
    std::vector<BodyId> bricks;
    for (int row = 0; row < inRows; ++row)
        for (int column = 0; column < inColumns; ++column)
        {
            const Vec3 centre(column * cLength, 0.0, 0.5 * cHeight + row * cHeight);
            // intent: out of the wall (+y) fastest where the car struck (the middle), the upper rows falling onto
            // the lower ones (the wall collapses), a little at random along and across it
            const double from_hit = std::abs(column - 0.5 * (inColumns - 1)) / std::max(inColumns, 1);
            const Vec3 velocity = DrawVec3([&] { return unit(random); }).cwiseProduct(Vec3(1.0, 1.0, 0.5)) +
                                  Vec3(0.0, 8.0 - 10.0 * from_hit, -1.0 - 0.6 * row);
            const Vec3 spin = 5.0 * DrawVec3([&] { return unit(random); });
            bricks.push_back(world.CreateBody(Brick(centre, velocity, spin)).Get());
        }
    // intent: four contact points on a shared face, normal from B towards A, overlaps of up to 2 mm
    const auto add_face = [&](BodyId inA, BodyId inB, const Vec3& inCentre, const Vec3& inNormal,
                              const Vec3& inU, const Vec3& inV)
    {
        for (const double u : {-1.0, 1.0})
            for (const double v : {-1.0, 1.0})
            {
                ContactEvent contact;
                contact.mBodyA = inA;
                contact.mBodyB = inB;
                const double depth = 0.002 * share(random);
                const Vec3 point = inCentre + 0.8 * (u * inU + v * inV);
                contact.mPointOnA = point - 0.5 * depth * inNormal;
                contact.mPointOnB = point + 0.5 * depth * inNormal;
                contact.mNormal = inNormal;
                contact.mPenetrationDepth = depth;
                contact.mFriction = 0.6;
                contact.mTime = 1.0;
                burst.mContacts.push_back(contact);
            }
    };
    const Vec3 half_y(0.0, 0.5 * cDepth, 0.0);
    for (int row = 0; row < inRows; ++row)
        for (int column = 0; column < inColumns; ++column)
        {
            const BodyId self = bricks[static_cast<std::size_t>(row * inColumns + column)];
            const Vec3 centre(column * cLength, 0.0, 0.5 * cHeight + row * cHeight);
            if (column + 1 < inColumns) // its right neighbour, A, pushed along +x
                add_face(bricks[static_cast<std::size_t>(row * inColumns + column + 1)], self,
                         centre + Vec3(0.5 * cLength, 0.0, 0.0), Vec3::UnitX(), half_y,
                         Vec3(0.0, 0.0, 0.5 * cHeight));
            if (row + 1 < inRows) // the brick above, A, pushed up
                add_face(bricks[static_cast<std::size_t>((row + 1) * inColumns + column)], self,
                         centre + Vec3(0.0, 0.0, 0.5 * cHeight), Vec3::UnitZ(), half_y,
                         Vec3(0.5 * cLength, 0.0, 0.0));
            if (row == 0)
                add_face(self, ground_id, centre - Vec3(0.0, 0.0, 0.5 * cHeight), Vec3::UnitZ(), half_y,
                         Vec3(0.5 * cLength, 0.0, 0.0));
        }
    return burst;
}

} // namespace crumple::common
