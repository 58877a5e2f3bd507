// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// A destructible prop through both engines: a car's hit on a breakable facing of the wall goes through the
// engine's contacts, the damage world and the prop world to the FEM, cracks it the same way in Bullet and
// ODE, and the pieces it sheds become engine bodies that carry its momentum.
#include "BulletWallCrash.h"
#include "OdeWallCrash.h"

#include <crumple/fem/TetGrid.h>
#include <crumple/props/PropWorld.h>

#include <BrittleMaterial.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace crumple;
using namespace crumple::common;
using namespace crumple::props;

namespace
{

// Bodies and geoms in the engine's own world: what the adapter added or removed there.
int EngineObjects(BulletWallCrash& ioScene)
{
    return ioScene.GetWorld().getNumCollisionObjects();
}
int EngineObjects(OdeWallCrash& ioScene)
{
    return dSpaceGetNumGeoms(ioScene.GetSpace());
}

// A brittle 0.2 m facing on the wall's face (world x in [0, 0.2] inside the wall, y in [-1.2, 1.2], z in
// [0.1, 1.5]), in the frame of the wall's damage body.
FemProp Facing(const plugin::BodyState& inWall)
{
    fem::TetGridSettings grid;
    grid.mOrigin = inWall.mTransform.ToBody(Vec3(0.0, -1.2, 0.1));
    grid.mSize = Vec3(0.2, 2.4, 1.4);
    grid.mCellCount = {1, 12, 7};
    fem::FemMaterialSettings material = BrittleMaterial(fem::EFractureMode::CrackPlane);
    material.mYoungsModulus = 1.0e9;
    material.mPoissonRatio = 0.2;
    fem::TetSolverSettings settings;
    settings.mGravity = Vec3::Zero();
    settings.mIntegrator = fem::EIntegrator::SymplecticEuler; // a brittle prop that is hit (README)
    FemProp prop = FemProp::Create(nullptr, fem::TetGrid(grid).Get(), material, settings, FemPropSettings{}).Get();
    // Held at its rim only (as a panel screwed on at its edges): pieces of its middle can come loose.
    for (int node = 0; node < prop.GetNodeCount(); ++node)
    {
        const Vec3 x = inWall.mTransform.ToWorld(prop.GetCpuSolver()->GetMesh().GetRestPositions()[static_cast<std::size_t>(node)]);
        if (x.x() > 0.199 && (std::abs(x.y()) > 1.19 || x.z() < 0.11 || x.z() > 1.49))
            REQUIRE(prop.SetNodeFixed(node, true).IsValid());
    }
    return prop;
}

struct PropRun
{
    std::vector<std::uint8_t> mBroken; ///< Per link
    double mImpulse = 0.0;             ///< Crumple's impulse on the prop's body over the run (N s)
    int mBrokenLinks = 0;
    int mLinks = 0;
    std::uint64_t mCollisions = 0;
    int mPieces = 0;
    int mBodiesMade = 0;     ///< Engine bodies made for the pieces handed over
    bool mBodiesFinite = true; ///< Their states after more engine steps
    /// A restart after that (RemoveProp, the pieces' bodies removed through the adapter, a fresh facing on
    /// the wall): the prop and the bodies gone from the prop and damage worlds, the adapter holding none of
    /// the bodies (a second removal refused), and the scene stepping on with the fresh facing bound, asleep,
    /// whole
    bool mRemovedGone = false;
    bool mAdapterForgot = false;
    bool mFreshAsleep = false;
};

template <class Scene>
PropRun HitFacing(const EngineCrashSettings& inSettings)
{
    Scene scene(inSettings);
    std::unique_ptr<PropWorld> props = PropWorld::Create(scene.GetDamage()).Get();
    const plugin::BodyId wall = scene.GetWallBody();
    const PropId facing = props->AddProp(wall, Facing(*scene.GetDamage().GetBodyState(wall))).Get();
    const int steps = static_cast<int>(std::lround(inSettings.mDuration / inSettings.mTimeStep));
    for (int i = 0; i < steps; ++i)
    {
        scene.Step();
        REQUIRE(props->Step(inSettings.mTimeStep));
    }
    scene.GetDamage().Flush();
    for (int i = 0; i < 12; ++i)
        REQUIRE(props->Step(inSettings.mTimeStep));
    const fem::TetSolver& solver = *props->GetProp(facing)->GetCpuSolver();
    PropRun run;
    run.mBroken = solver.GetBrokenLinks();
    run.mImpulse = ImpulseOnBody(scene.GetCounter().mLog, wall).norm();
    run.mBrokenLinks = solver.GetBrokenLinkCount();
    run.mLinks = static_cast<int>(solver.GetBrokenLinks().size());
    run.mCollisions = props->GetCollisionCount();
    for (const fem::TetFragment& piece : solver.ComputeFragments())
        run.mPieces += piece.mAnchored ? 0 : 1;

    // The loose pieces become bodies of the engine (and of the damage world), then the scene goes on.
    std::vector<plugin::BodyId> bodies;
    const int engine_objects = EngineObjects(scene);
    const std::vector<LooseFragment> loose = props->TakeLooseFragments().Get();
    for (const LooseFragment& piece : loose)
    {
        if (piece.mDropped)
            continue;
        Result<plugin::BodyId> body = scene.MakeDebrisBody(piece.mRigidBody.mBody);
        REQUIRE(body);
        bodies.push_back(body.Get());
    }
    run.mBodiesMade = static_cast<int>(bodies.size());
    REQUIRE(EngineObjects(scene) == engine_objects + run.mBodiesMade); // one engine object per piece
    for (int i = 0; i < 12; ++i)
    {
        scene.Step();
        REQUIRE(props->Step(inSettings.mTimeStep));
    }
    for (const plugin::BodyId body : bodies)
    {
        const plugin::BodyState* state = scene.GetDamage().GetBodyState(body);
        run.mBodiesFinite = run.mBodiesFinite && state != nullptr && IsFinite(state->mCenterOfMass) && IsFinite(state->mLinearVelocity);
    }

    // A restarted level: the cracked facing and its flying pieces go, a fresh facing goes on the wall.
    REQUIRE(props->RemoveProp(facing));
    for (const plugin::BodyId body : bodies)
        REQUIRE(scene.RemoveMadeBody(body));
    run.mRemovedGone = props->GetProp(facing) == nullptr;
    // intent: each piece was one engine object (a body and its hull, one collision object or geom)
    run.mAdapterForgot = EngineObjects(scene) == engine_objects;
    for (const plugin::BodyId body : bodies)
    {
        run.mRemovedGone = run.mRemovedGone && scene.GetDamage().GetBodyState(body) == nullptr;
        run.mAdapterForgot = run.mAdapterForgot && !scene.RemoveMadeBody(body).IsValid();
    }
    Result<PropId> fresh = props->AddProp(wall, Facing(*scene.GetDamage().GetBodyState(wall)));
    REQUIRE(fresh);
    PropStepReport last;
    for (int i = 0; i < 12; ++i)
    {
        scene.Step();
        Result<PropStepReport> stepped = props->Step(inSettings.mTimeStep);
        REQUIRE(stepped);
        last = stepped.Get();
    }
    run.mFreshAsleep = last.mStepped == 0 && props->GetProp(fresh.Get())->GetBrokenLinkCount() == 0 &&
                       props->FindProp(wall) == fresh.Get();
    return run;
}

} // namespace

TEST_CASE("A car cracks a wall's brittle facing through Bullet and through ODE, its pieces fly as engine "
          "bodies, and "
          "a restart removes them",
          "[bullet][ode][props]")
{
    EngineCrashSettings settings;
    settings.mSpeed = 40.0 / 3.6;
    settings.mDuration = 0.25;
    settings.mTriangles = 2000;
    const PropRun bullet = HitFacing<BulletWallCrash>(settings);
    const PropRun ode = HitFacing<OdeWallCrash>(settings);
    int both = 0, either = 0;
    for (std::size_t link = 0; link < bullet.mBroken.size() && link < ode.mBroken.size(); ++link)
    {
        both += bullet.mBroken[link] != 0 && ode.mBroken[link] != 0 ? 1 : 0;
        either += bullet.mBroken[link] != 0 || ode.mBroken[link] != 0 ? 1 : 0;
    }
    INFO("impulses " << bullet.mImpulse << " / " << ode.mImpulse << " N s; links broken in both " << both << " of " << either);
    INFO("broken links of " << bullet.mLinks << ": Bullet " << bullet.mBrokenLinks << ", ODE " << ode.mBrokenLinks
                            << "; collisions " << bullet.mCollisions << " / " << ode.mCollisions << "; loose pieces "
                            << bullet.mPieces << " / " << ode.mPieces);
    REQUIRE(bullet.mCollisions > 0);
    REQUIRE(ode.mCollisions > 0);
    // What Crumple decides is engine-independent: the impulse the facing takes, within the 3 % its impulses
    // keep to the engines' momentum (CrossEngineTest).
    CHECK(std::abs(bullet.mImpulse - ode.mImpulse) <= 0.03 * std::max(bullet.mImpulse, ode.mImpulse));
    // Both crack and shed pieces, which become engine bodies that stay finite. Which links break follows each
    // engine's contact points (Bullet's four manifold points, ODE's box-box contacts), so the patterns are
    // reported above, not compared (README, known limits).
    CHECK(bullet.mBrokenLinks > 0);
    CHECK(ode.mBrokenLinks > 0);
    CHECK(bullet.mBodiesMade > 0);
    CHECK(ode.mBodiesMade > 0);
    CHECK(bullet.mBodiesFinite);
    CHECK(ode.mBodiesFinite);
    // The restart: the prop and its flying pieces' bodies go from every world, a fresh facing takes the wall.
    CHECK(bullet.mRemovedGone);
    CHECK(ode.mRemovedGone);
    CHECK(bullet.mAdapterForgot);
    CHECK(ode.mAdapterForgot);
    CHECK(bullet.mFreshAsleep);
    CHECK(ode.mFreshAsleep);
}
