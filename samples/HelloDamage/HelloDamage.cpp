// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The smallest use of Crumple: a car body, a wall, one contact, one dent. No engine, no GUI.
#include <crumple/plugin/DamageWorld.h>

#include <cstdio>

using namespace crumple;
using namespace crumple::plugin;

int main()
{
    DamageWorld world = DamageWorld::Create().Get();

    // A static wall and a 1,000 kg car driving at 10 m/s along +x (body frame at its centre of mass).
    BodyState wall_state;
    wall_state.mMotionType = EMotionType::Static;
    const BodyId wall = world.CreateBody(wall_state).Get();
    BodyState car_state;
    car_state.mMass = 1000.0;
    car_state.mInverseInertiaWorld = Mat3::Identity() / 800.0;
    car_state.mLinearVelocity = Vec3(10.0, 0.0, 0.0);
    const BodyId car = world.CreateBody(car_state).Get();

    // Its render mesh: a 2 m wide, 1 m tall front panel made of two triangles (a real game passes its mesh).
    DeformableObjectSettings settings;
    settings.mMesh.mPositions = {Vec3(2.0, -1.0, -0.5), Vec3(2.0, 1.0, -0.5), Vec3(2.0, 1.0, 0.5), Vec3(2.0, -1.0, 0.5),
                                 Vec3(1.0, 0.0, 0.0)};
    settings.mMesh.mTriangles = {{0u, 1u, 2u}, {0u, 2u, 3u}, {0u, 4u, 1u}};
    const ObjectId body = world.CreateDeformableObject(car, settings).Get();

    // The engine reports the front panel's centre touching the wall (normal from the wall to the car).
    ContactEvent contact;
    contact.mBodyA = car;
    contact.mBodyB = wall;
    contact.mPointOnA = contact.mPointOnB = Vec3(2.0, 0.0, 0.0);
    contact.mNormal = Vec3(-1.0, 0.0, 0.0);
    contact.mTime = 0.0;
    if (Status status = world.SubmitContacts({&contact, 1}); !status)
    {
        std::fprintf(stderr, "refused: %s\n", status.GetError().mMessage.c_str());
        return 2;
    }

    // 50 ms later the collision's window closes and the dent is applied.
    const UpdateReport report = world.Update(0.05);
    const ffd::FfdDeformer& deformer = world.GetObject(body)->GetDeformer();
    std::printf("%d collision dispatched, %u vertices moved\n", report.mCollisionsDispatched,
                static_cast<unsigned>(report.mVerticesMoved));
    for (std::size_t v = 0; v < 4; ++v)
        std::printf("corner %zu: x %.4f m -> %.4f m\n", v, deformer.GetRestMesh().mPositions[v].x(),
                    deformer.GetPositions()[v].x());
    return report.mCollisionsDispatched == 1 ? 0 : 1;
}
