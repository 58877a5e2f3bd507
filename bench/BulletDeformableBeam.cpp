// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "BulletDeformableBeam.h"

// Bullet's inline array code trips GCC's -Wmaybe-uninitialized (default-constructed btVector3 fill values);
// the warning is about Bullet's headers, not this file.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletSoftBody/btDeformableBodySolver.h>
#include <BulletSoftBody/btDeformableGravityForce.h>
#include <BulletSoftBody/btDeformableLagrangianForce.h>
#include <BulletSoftBody/btDeformableLinearElasticityForce.h>
#include <BulletSoftBody/btDeformableMultiBodyConstraintSolver.h>
#include <BulletSoftBody/btDeformableMultiBodyDynamicsWorld.h>
#include <BulletSoftBody/btSoftBody.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#include <cmath>
#include <string>
#include <utility>
#include <vector>

// The float build of Bullet would silently compute the comparison in single precision.
static_assert(sizeof(btScalar) == sizeof(double),
              "BulletDeformableBeam needs Bullet built with BT_USE_DOUBLE_PRECISION");

namespace crumple::bench
{

namespace
{

btVector3 ToBullet(const Vec3& inVector)
{
    return btVector3(inVector.x(), inVector.y(), inVector.z());
}

/// A constant force per node (N, world), added to the implicit momentum equation. Bullet's deformable
/// pipeline ignores btSoftBody::addForce() (its residual is built only from btDeformableLagrangianForce
/// objects), so a load must be one of these: addScaledForces() is called with scale = dt both for the
/// explicit predictor and for the Newton residual, and a constant force has no differential.
class ConstantNodeForce final : public btDeformableLagrangianForce
{
public:
    explicit ConstantNodeForce(std::vector<btVector3> inForces) : mForces(std::move(inForces)) {}

    void addScaledForces(btScalar inScale, TVStack& ioForce) override { AddScaled(inScale, ioForce); }
    void addScaledExplicitForce(btScalar inScale, TVStack& ioForce) override { AddScaled(inScale, ioForce); }
    void addScaledDampingForce(btScalar, TVStack&) override {}
    void addScaledDampingForceDifferential(btScalar, const TVStack&, TVStack&) override {}
    void addScaledElasticForceDifferential(btScalar, const TVStack&, TVStack&) override {}
    void buildDampingForceDifferentialDiagonal(btScalar, TVStack&) override {}

    /// btDeformableMultiBodyDynamicsWorld::addForce() merges forces of the same type, so the load needs a
    /// type that neither the elasticity nor the gravity force uses. Only BT_GRAVITY_FORCE and
    /// BT_MOUSE_PICKING_FORCE are treated specially by the 3.24 pipeline; BT_MASSSPRING_FORCE, unused here,
    /// is handled like any force.
    btDeformableLagrangianForceType getForceType() override { return BT_MASSSPRING_FORCE; }

private:
    void AddScaled(btScalar inScale, TVStack& ioForce) const
    {
        for (int body = 0; body < m_softBodies.size(); ++body)
        {
            btSoftBody* soft_body = m_softBodies[body];
            for (int node = 0; node < soft_body->m_nodes.size(); ++node)
                if (soft_body->m_nodes[node].m_im > 0)
                    ioForce[soft_body->m_nodes[node].index] +=
                        inScale * mForces[static_cast<std::size_t>(node)];
        }
    }

    std::vector<btVector3> mForces; ///< Per node of the (single) body (N, world)
};

/// btDeformableBodySolver with its Newton and CG limits settable (they are protected members without
/// setters).
class TunedDeformableBodySolver final : public btDeformableBodySolver
{
public:
    void SetLimits(int inMaxNewtonIterations, int inCgMaxIterations)
    {
        m_maxNewtonIterations = inMaxNewtonIterations;
        m_cg.m_maxIterations = inCgMaxIterations;
        m_cr.m_maxIterations = inCgMaxIterations;
    }
};

Status ValidateSettings(const fem::TetSolver& inSolver, const BulletDeformableBeamSettings& inSettings)
{
    if (!(std::isfinite(inSettings.mTimeStep) && inSettings.mTimeStep > 0.0))
        return MakeError(EError::InvalidArgument,
                         "BulletDeformableBeamSettings.mTimeStep = " + std::to_string(inSettings.mTimeStep) +
                             " s must be finite and > 0");
    if (!(std::isfinite(inSettings.mMassDamping) && inSettings.mMassDamping >= 0.0))
        return MakeError(EError::InvalidArgument, "BulletDeformableBeamSettings.mMassDamping = " +
                                                      std::to_string(inSettings.mMassDamping) +
                                                      " 1/s must be finite and >= 0");
    if (inSettings.mMaxNewtonIterations < 1 || inSettings.mCgMaxIterations < 1)
        return MakeError(
            EError::InvalidArgument,
            "BulletDeformableBeamSettings.mMaxNewtonIterations and mCgMaxIterations must be >= 1");
    if (inSolver.GetNodeCount() != inSolver.GetMesh().GetNodeCount() ||
        inSolver.GetElementNodes() != inSolver.GetMesh().GetTets())
        return MakeError(
            EError::StateMismatch,
            "BulletDeformableBeam: the TetSolver has been fractured; its connectivity is not the mesh's");
    return Status::Ok();
}

} // namespace

struct BulletDeformableBeam::World
{
    // Destroyed in reverse order: the body and forces before the world, the world before its solvers.
    std::unique_ptr<btSoftBodyRigidBodyCollisionConfiguration> mCollisionConfiguration;
    std::unique_ptr<btCollisionDispatcher> mDispatcher;
    std::unique_ptr<btDbvtBroadphase> mBroadphase;
    std::unique_ptr<TunedDeformableBodySolver> mBodySolver;
    std::unique_ptr<btDeformableMultiBodyConstraintSolver> mConstraintSolver;
    std::unique_ptr<btDeformableMultiBodyDynamicsWorld> mWorld;
    std::unique_ptr<btDeformableLinearElasticityForce> mElasticity;
    std::unique_ptr<btDeformableGravityForce> mGravity;
    std::unique_ptr<ConstantNodeForce> mLoad;
    std::unique_ptr<btSoftBody> mBody;
    double mTimeStep = 0.0;

    World() = default;
    World(const World&) = delete;
    World& operator=(const World&) = delete;
    ~World()
    {
        // The world must not outlive its collision objects' broadphase proxies, nor hold a deleted body.
        if (mWorld && mBody)
            mWorld->removeSoftBody(mBody.get());
    }
};

Result<BulletDeformableBeam> BulletDeformableBeam::Create(const fem::TetSolver& inSolver,
                                                          const BulletDeformableBeamSettings& inSettings)
{
    if (Status valid = ValidateSettings(inSolver, inSettings); !valid)
        return valid.GetError();
    auto world = std::make_unique<World>();
    world->mTimeStep = inSettings.mTimeStep;

    // The world. Implicit Euler with projection, as Bullet's implicit demos (VolumetricDeformable,
    // LargeDeformation) run it: without projection 3.24 solves with conjugate residual preconditioned by
    // KKTPreconditioner, which is only built for the explicit scheme and is left empty in the implicit one.
    // With projection the anchored nodes (mass 0) are projected out of the CG solve.
    world->mCollisionConfiguration = std::make_unique<btSoftBodyRigidBodyCollisionConfiguration>();
    world->mDispatcher = std::make_unique<btCollisionDispatcher>(world->mCollisionConfiguration.get());
    world->mBroadphase = std::make_unique<btDbvtBroadphase>();
    world->mBodySolver = std::make_unique<TunedDeformableBodySolver>();
    world->mBodySolver->SetLimits(inSettings.mMaxNewtonIterations, inSettings.mCgMaxIterations);
    world->mConstraintSolver = std::make_unique<btDeformableMultiBodyConstraintSolver>();
    world->mConstraintSolver->setDeformableSolver(world->mBodySolver.get());
    world->mWorld = std::make_unique<btDeformableMultiBodyDynamicsWorld>(
        world->mDispatcher.get(), world->mBroadphase.get(), world->mConstraintSolver.get(),
        world->mCollisionConfiguration.get(), world->mBodySolver.get());
    world->mWorld->setGravity(btVector3(0.0, 0.0, 0.0));
    world->mWorld->getWorldInfo().m_gravity.setZero();
    world->mWorld->setImplicit(true);
    world->mWorld->setLineSearch(false);
    world->mWorld->setUseProjection(true);

    // The body: the solver's rest nodes and lumped masses, mass 0 (Bullet's anchor) where Crumple anchors.
    const int node_count = inSolver.GetNodeCount();
    std::vector<btVector3> positions(static_cast<std::size_t>(node_count));
    std::vector<btScalar> masses(static_cast<std::size_t>(node_count));
    for (std::size_t i = 0; i < positions.size(); ++i)
    {
        positions[i] = ToBullet(inSolver.GetNodeRestPositions()[i]);
        masses[i] = inSolver.GetInverseMasses()[i] > 0.0 ? inSolver.GetMasses()[i] : 0.0;
    }
    world->mBody = std::make_unique<btSoftBody>(&world->mWorld->getWorldInfo(), node_count, positions.data(),
                                                masses.data());
    btSoftBody& body = *world->mBody;
    for (const fem::TetIndices& tet : inSolver.GetElementNodes())
        body.appendTetra(tet[0], tet[1], tet[2], tet[3]);
    body.initializeDmInverse();
    for (int tet = 0; tet < body.m_tetras.size(); ++tet)
        if (!(body.m_tetras[tet].m_element_measure > 0.0))
            return MakeError(EError::DegenerateGeometry,
                             "BulletDeformableBeam: element " + std::to_string(tet) +
                                 " has a non-positive volume in Bullet's convention");
    // CreateFromTetGenData sizes these; appendTetra does not. Filled with the rest state rather than
    // TetraScratch's uninitialised default; the first step overwrites them.
    btSoftBody::TetraScratch rest;
    rest.m_F.setIdentity();
    rest.m_trace = 3.0;
    rest.m_J = 1.0;
    rest.m_cofF.setIdentity();
    rest.m_corotation.setIdentity();
    body.m_tetraScratches.resize(body.m_tetras.size(), rest);
    body.m_tetraScratchesTn.resize(body.m_tetras.size(), rest);
    // A beam at rest under a sudden load starts with zero velocity: it must not be put to sleep.
    body.m_sleepingThreshold = 0.0;
    body.setActivationState(DISABLE_DEACTIVATION);
    world->mWorld->addSoftBody(&body);

    // Forces. The zero gravity force is not decoration: in 3.24 the implicit predictor
    // (btDeformableBackwardEulerObjective::applyExplicitForce) adds dt * gravity to every velocity with
    // `gravity` left uninitialised unless a BT_GRAVITY_FORCE is present.
    const fem::FemMaterial& material = inSolver.GetMaterial();
    world->mElasticity = std::make_unique<btDeformableLinearElasticityForce>(
        material.GetShearModulus(), material.GetLambda(), inSettings.mMassDamping, 0.0);
    world->mGravity = std::make_unique<btDeformableGravityForce>(btVector3(0.0, 0.0, 0.0));
    std::vector<btVector3> loads(static_cast<std::size_t>(node_count));
    for (std::size_t i = 0; i < loads.size(); ++i)
        loads[i] = ToBullet(inSolver.GetExternalForces()[i]);
    world->mLoad = std::make_unique<ConstantNodeForce>(std::move(loads));
    world->mWorld->addForce(&body, world->mElasticity.get());
    world->mWorld->addForce(&body, world->mGravity.get());
    world->mWorld->addForce(&body, world->mLoad.get());
    return BulletDeformableBeam(std::move(world));
}

BulletDeformableBeam::BulletDeformableBeam(std::unique_ptr<World> inWorld) : mWorld(std::move(inWorld)) {}
BulletDeformableBeam::BulletDeformableBeam(BulletDeformableBeam&& ioOther) noexcept = default;
BulletDeformableBeam& BulletDeformableBeam::operator=(BulletDeformableBeam&& ioOther) noexcept = default;
BulletDeformableBeam::~BulletDeformableBeam() = default;

void BulletDeformableBeam::Step()
{
    // One internal step of exactly dt: maxSubSteps 1, fixedTimeStep dt.
    mWorld->mWorld->stepSimulation(mWorld->mTimeStep, 1, mWorld->mTimeStep);
}

int BulletDeformableBeam::GetNodeCount() const
{
    return mWorld->mBody->m_nodes.size();
}

Vec3 BulletDeformableBeam::GetPosition(int inNode) const
{
    const btVector3& x = mWorld->mBody->m_nodes[inNode].m_x;
    return Vec3(x.x(), x.y(), x.z());
}

Vec3 BulletDeformableBeam::GetRestPosition(int inNode) const
{
    const btVector3& x = mWorld->mBody->m_X[inNode];
    return Vec3(x.x(), x.y(), x.z());
}

bool BulletDeformableBeam::HasNonFinitePosition() const
{
    for (int node = 0; node < mWorld->mBody->m_nodes.size(); ++node)
        if (!GetPosition(node).allFinite())
            return true;
    return false;
}

} // namespace crumple::bench
