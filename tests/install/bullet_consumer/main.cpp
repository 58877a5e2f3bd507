// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// A Bullet game linking only crumple::bullet from the installed package: a box falls on the ground and the
// adapter reports the contacts to the damage world.
#include <crumple/bullet/BulletAdapter.h>

#include <btBulletDynamicsCommon.h>

#include <cstdio>

int main()
{
    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher(&configuration);
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
    world.setGravity(btVector3(0, 0, -9.81f));
    std::unique_ptr<crumple::plugin::DamageWorld> damage = std::move(crumple::plugin::DamageWorld::Create().Get());
    std::unique_ptr<crumple::bullet::BulletAdapter> adapter = std::move(crumple::bullet::BulletAdapter::Create(world, *damage).Get());
    btStaticPlaneShape ground_shape(btVector3(0, 0, 1), 0);
    btCollisionObject ground;
    ground.setCollisionShape(&ground_shape);
    world.addCollisionObject(&ground);
    btBoxShape box_shape(btVector3(0.5f, 0.5f, 0.5f));
    btVector3 inertia;
    box_shape.calculateLocalInertia(10.0f, inertia);
    btDefaultMotionState motion(btTransform(btQuaternion::getIdentity(), btVector3(0, 0, 2)));
    btRigidBody box(btRigidBody::btRigidBodyConstructionInfo(10.0f, &motion, &box_shape, inertia));
    world.addRigidBody(&box);
    if (!adapter->AddBody(ground) || !adapter->AddBody(box))
        return 1;
    int contacts = 0;
    for (int step = 0; step < 120; ++step)
    {
        world.stepSimulation(1.0f / 60.0f, 1, 1.0f / 60.0f);
        contacts += adapter->GetLastStepStats().mContactsReported;
    }
    world.removeRigidBody(&box);
    world.removeCollisionObject(&ground);
    std::printf("bullet consumer: %d contacts reported to the damage world\n", contacts);
    return contacts > 0 ? 0 : 1;
}
