// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "FaceCrushCollision.h"

#include "BoxMesh.h"

namespace crumple::common
{

using namespace crumple::plugin;

DeformableObject MakeCrushBoxCar(const Vec3& inHalf, const DamageMaterial& inMaterial, const Vec3& inForward)
{
    DeformableObjectSettings settings;
    settings.mMesh = MakeBoxMesh(inHalf, BoxSegmentsForTriangles(inHalf, 12000));
    settings.mMaterial = inMaterial;
    settings.mFittedMaxTotalDeformation = 1.5;
    settings.mForwardAxis = inForward;
    return DeformableObject::Create(settings).Get();
}

Collision FaceCrushCollision(const Vec3& inHalf, const Vec3& inOutward, double inEnergy)
{
    const Vec3 along = inOutward.x() != 0.0 ? Vec3::UnitY() : Vec3::UnitX();
    Collision collision;
    collision.mBodyA = BodyId{0};
    collision.mBodyB = BodyId{1};
    collision.mCrushEnergyB = inEnergy;
    for (double s : {-0.6, 0.6})
        for (double z : {-0.3, 0.3})
        {
            CollisionContact contact;
            contact.mLocalPointOnB =
                Vec3(inOutward.x() * inHalf.x(), inOutward.y() * inHalf.y(), z) + s * along;
            contact.mLocalPointOnA = contact.mLocalPointOnB;
            contact.mLocalNormalOnB = inOutward;
            contact.mLocalNormalOnA = -inOutward;
            contact.mImpulse = 2000.0;
            contact.mAbsorbedEnergy = inEnergy / 4.0;
            collision.mContacts.push_back(contact);
        }
    return collision;
}

} // namespace crumple::common
