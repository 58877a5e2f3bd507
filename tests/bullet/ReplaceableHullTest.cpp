// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// A prop body's pieces replaced: Bullet collides with the new pieces at once, whatever their count.

#include <crumple/bullet/BulletAdapter.h>

#include <btBulletDynamicsCommon.h>
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

using namespace crumple;
using namespace crumple::plugin;

namespace
{

constexpr double cStep = 1.0 / 60.0; // s
constexpr double cBallRadius = 0.2;  // m

// The eight corners of a 1 m cube centred at (inX, 0, 0), body frame.
std::vector<Vec3> CubeAt(double inX)
{
    std::vector<Vec3> corners;
    for (int corner = 0; corner < 8; ++corner)
        corners.push_back(
            Vec3(inX + ((corner & 1) ? 0.5 : -0.5), (corner & 2) ? 0.5 : -0.5, (corner & 4) ? 0.5 : -0.5));
    return corners;
}

// A world with gravity and a held prop body of one cube at the origin, and balls the game drops on it (bodies
// of the game's own, unknown to the damage world).
struct PieceWorld
{
    PieceWorld() : mDispatcher(&mConfiguration), mWorld(&mDispatcher, &mBroadphase, &mSolver, &mConfiguration)
    {
        mWorld.setGravity(btVector3(0, 0, btScalar(-9.81)));
        mDamage = std::move(DamageWorld::Create().Get());
        mAdapter = std::move(bullet::BulletAdapter::Create(mWorld, *mDamage).Get());
        PropBodySettings prop;
        prop.mMass = 100.0;
        prop.mPrincipalInertia = Vec3::Constant(20.0);
        prop.mPieces = {CubeAt(0.0)};
        mProp = mAdapter->CreatePropBody(prop).Get();
    }
    ~PieceWorld()
    {
        for (auto& ball : mBalls)
            mWorld.removeRigidBody(ball.get());
        mAdapter.reset();
    }
    // A ball dropped from rest with its centre at (inX, 0, 1.5)
    btRigidBody* DropBall(double inX)
    {
        btRigidBody::btRigidBodyConstructionInfo info(btScalar(1.0), nullptr, &mBallShape,
                                                      btVector3(0.1f, 0.1f, 0.1f));
        info.m_startWorldTransform.setOrigin(btVector3(btScalar(inX), 0, btScalar(1.5)));
        mBalls.push_back(std::make_unique<btRigidBody>(info));
        mWorld.addRigidBody(mBalls.back().get());
        return mBalls.back().get();
    }
    void Step(int inSteps)
    {
        for (int step = 0; step < inSteps; ++step)
            mWorld.stepSimulation(btScalar(cStep), 1, btScalar(cStep));
    }
    btCompoundShape& Compound()
    {
        return *static_cast<btCompoundShape*>(mAdapter->GetConvexBody(mProp)->getCollisionShape());
    }

    btDefaultCollisionConfiguration mConfiguration;
    btCollisionDispatcher mDispatcher;
    btDbvtBroadphase mBroadphase;
    btSequentialImpulseConstraintSolver mSolver;
    btDiscreteDynamicsWorld mWorld;
    std::unique_ptr<DamageWorld> mDamage;
    std::unique_ptr<bullet::BulletAdapter> mAdapter;
    BodyId mProp;
    btSphereShape mBallShape{btScalar(cBallRadius)};
    std::vector<std::unique_ptr<btRigidBody>> mBalls;
};

// A ball resting on a cube's top (0.5 m) has its centre a radius above it, within Bullet's margins.
bool RestsOnTop(const btRigidBody& inBall)
{
    return std::abs(static_cast<double>(inBall.getCenterOfMassPosition().z()) - (0.5 + cBallRadius)) <= 0.03;
}

} // namespace

TEST_CASE("Bullet: a prop body's replaced pieces collide where they are now, whatever their count",
          "[bullet][props]")
{
    PieceWorld world;
    const int objects = world.mWorld.getNumCollisionObjects();
    const btCollisionShape* const first_child = world.Compound().getChildShape(0);

    // The cube moves 3 m along x: the same count, so the hull is kept and its points replaced. The body left
    // the world and came back (Bullet's contacts then come in the order a new shape gives them): it is the
    // world's last object again, after the game's ball added since.
    btRigidBody* before_call = world.DropBall(10.0);
    REQUIRE(world.mAdapter->SetPropPieces(world.mProp, {CubeAt(3.0)}));
    CHECK(world.mWorld.getNumCollisionObjects() == objects + 1);
    CHECK(world.mWorld.getCollisionObjectArray()[objects] == world.mAdapter->GetConvexBody(world.mProp));
    CHECK(world.mWorld.getCollisionObjectArray()[objects - 1] == before_call);
    REQUIRE(world.Compound().getNumChildShapes() == 1);
    CHECK(world.Compound().getChildShape(0) == first_child);
    const auto* hull = static_cast<const btConvexHullShape*>(world.Compound().getChildShape(0));
    REQUIRE(hull->getNumPoints() == 8);
    for (int i = 0; i < 8; ++i)
        CHECK(hull->getUnscaledPoints()[i] ==
              btVector3(btScalar(CubeAt(3.0)[static_cast<std::size_t>(i)].x()),
                        btScalar(CubeAt(3.0)[static_cast<std::size_t>(i)].y()),
                        btScalar(CubeAt(3.0)[static_cast<std::size_t>(i)].z())));
    // The replaced hull is a new hull of the same points, bit for bit: margin and bounds.
    PropBodySettings fresh_settings;
    fresh_settings.mMass = 100.0;
    fresh_settings.mPrincipalInertia = Vec3::Constant(20.0);
    fresh_settings.mPosition = Vec3(0.0, 50.0, 0.0);
    fresh_settings.mPieces = {CubeAt(3.0)};
    const BodyId fresh = world.mAdapter->CreatePropBody(fresh_settings).Get();
    const btCollisionShape& fresh_hull =
        *static_cast<btCompoundShape*>(world.mAdapter->GetConvexBody(fresh)->getCollisionShape())
             ->getChildShape(0);
    CHECK(hull->getMargin() == fresh_hull.getMargin());
    btVector3 low, high, fresh_low, fresh_high;
    hull->getAabb(btTransform::getIdentity(), low, high);
    fresh_hull.getAabb(btTransform::getIdentity(), fresh_low, fresh_high);
    CHECK((low == fresh_low && high == fresh_high));

    btRigidBody* on_new = world.DropBall(3.0);
    btRigidBody* on_old = world.DropBall(0.0);
    world.Step(90);
    CHECK(RestsOnTop(*on_new));
    CHECK(on_old->getCenterOfMassPosition().z() < btScalar(-1.0)); // nothing is left where the cube was

    // Two cubes (one more child), then one again (one fewer): each time the engine meets exactly those.
    REQUIRE(world.mAdapter->SetPropPieces(world.mProp, {CubeAt(3.0), CubeAt(-3.0)}));
    CHECK(world.Compound().getNumChildShapes() == 2);
    btRigidBody* on_added = world.DropBall(-3.0);
    world.Step(90);
    CHECK(RestsOnTop(*on_new));
    CHECK(RestsOnTop(*on_added));
    REQUIRE(world.mAdapter->SetPropPieces(world.mProp, {CubeAt(-3.0)}));
    CHECK(world.Compound().getNumChildShapes() == 1);
    world.Step(90);
    CHECK(on_new->getCenterOfMassPosition().z() < btScalar(-1.0));
    CHECK(RestsOnTop(*on_added));
    CHECK(world.mWorld.getNumCollisionObjects() == objects + 5);

    // Refused pieces change nothing: the ball still rests on the cube.
    std::vector<Vec3> flat = CubeAt(0.0);
    for (Vec3& point : flat)
        point.z() = 0.0;
    const Status refused = world.mAdapter->SetPropPieces(world.mProp, {CubeAt(0.0), flat});
    REQUIRE(refused.HasError());
    CHECK(refused.GetError().mCode == EError::DegenerateGeometry);
    CHECK(refused.GetError().mMessage.find("mPieces[1]") != std::string::npos);
    CHECK(world.Compound().getNumChildShapes() == 1);
    world.Step(30);
    CHECK(RestsOnTop(*on_added));
}
