// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// A game linking the installed package: one body, one deformable object, one dent.
#include <crumple/base/Version.h>
#include <crumple/plugin/DamageWorld.h>

#include <cstdio>

int main()
{
    using namespace crumple;
    using namespace crumple::plugin;
    std::unique_ptr<DamageWorld> world_owner = std::move(DamageWorld::Create().Get());
    DamageWorld& world = *world_owner;
    BodyState wall;
    wall.mMotionType = EMotionType::Static;
    BodyState car;
    car.mMass = 1000.0;
    car.mLinearVelocity = Vec3(10.0, 0.0, 0.0);
    const BodyId car_id = world.CreateBody(car).Get();
    const BodyId wall_id = world.CreateBody(wall).Get();

    DeformableObjectSettings settings;
    settings.mMesh.mPositions = {Vec3(0.5, -0.5, -0.5), Vec3(0.5, 0.5, -0.5), Vec3(0.5, 0.0, 0.5)};
    settings.mMesh.mTriangles = {{0u, 1u, 2u}};
    const ObjectId object = world.CreateDeformableObject(car_id, settings).Get();

    ContactEvent contact;
    contact.mBodyA = car_id;
    contact.mBodyB = wall_id;
    contact.mPointOnA = contact.mPointOnB = Vec3(0.5, 0.0, 0.0);
    contact.mNormal = Vec3(-1.0, 0.0, 0.0);
    if (!world.SubmitContacts({&contact, 1}))
        return 1;
    const UpdateReport report = world.Flush();
    const double x = world.GetObject(object)->GetDeformer().GetPositions()[2].x();
    std::printf("crumple %s: %d collision, apex x = %.4f m\n", VersionString(), report.mCollisionsDispatched, x);
    return report.mCollisionsDispatched == 1 && x < 0.5 ? 0 : 1;
}
