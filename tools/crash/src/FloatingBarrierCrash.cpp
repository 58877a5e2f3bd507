// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "FloatingBarrierCrash.h"

#include "FemBarrierCoupling.h"

#include <algorithm>
#include <cmath>

namespace crumple::crash
{

Result<FloatingBarrierCrashResult> RunFloatingBarrierCrash(const FloatingBarrierCrashSettings& inSettings)
{
    if (!(inSettings.mTimeStep > 0.0) || !(inSettings.mDuration > 0.0) || !std::isfinite(inSettings.mSpeed))
        return MakeError(EError::InvalidArgument, "floating barrier crash: the step and duration must be > 0 s");
    constexpr double b0 = 2.173, b1 = 24.07;

    // The car: a uniform box, its front 5 cm before the barrier's face (x = 0).
    const Vec3 half(2.2, 0.85, 0.7);
    plugin::BodyState car;
    car.mMass = 1575.0;
    const Vec3 size = 2.0 * half;
    const Vec3 inertia = car.mMass / 12.0 *
                         Vec3(size.y() * size.y() + size.z() * size.z(), size.x() * size.x() + size.z() * size.z(),
                              size.x() * size.x() + size.y() * size.y());
    car.mInverseInertiaWorld = inertia.cwiseInverse().asDiagonal();
    car.mTransform.mTranslation = Vec3(-half.x() - 0.05, 0.0, 0.7);
    car.mCenterOfMass = car.mTransform.mTranslation;
    car.mLinearVelocity = Vec3(inSettings.mSpeed, 0.0, 0.0);
    const CarCrushPressure crush{car.mMass * b0 * b1 / size.y() / size.z(), car.mMass * b1 * b1 / size.y() / size.z()};

    plugin::DamageWorldSettings world;
    world.mCountImpactOnce = false; // the coupling reports each step's share of its push (FemBarrierCoupling::Create)
    std::unique_ptr<plugin::DamageWorld> damage_owner = std::move(plugin::DamageWorld::Create(world).Get());
    plugin::DamageWorld& damage = *damage_owner;
    Result<plugin::BodyId> car_body = damage.CreateBody(car);
    if (car_body.HasError())
        return car_body.GetError();
    TargetSpec target;
    target.mType = ETarget::FemBarrier;
    target.mBarrierSize = Vec3(0.2, 3.0, 1.6);
    target.mBarrierMaterial = inSettings.mMaterial;
    target.mBarrierCell = 0.2;
    Result<FemBarrierCoupling> created = FemBarrierCoupling::Create(target, 0.5 * Vec3(0.2, 0.0, 1.6), damage);
    if (created.HasError())
        return created.GetError();
    FemBarrierCoupling& barrier = created.Get();

    FloatingBarrierCrashResult result;
    result.mCampbellCrush = (inSettings.mSpeed - b0) / b1;
    const int steps = static_cast<int>(std::lround(inSettings.mDuration / inSettings.mTimeStep));
    // intent: the free nodes' momentum, read from the solver's velocities and masses
    const auto node_momentum = [&barrier]
    {
        const fem::TetSolver& solver = barrier.GetSolver();
        Vec3 sum = Vec3::Zero();
        for (std::size_t node = 0; node < solver.GetVelocities().size(); ++node)
            if (solver.GetInverseMasses()[node] > 0.0)
                sum += solver.GetVelocities()[node] / solver.GetInverseMasses()[node];
        return sum;
    };
    Vec3 into_nodes = Vec3::Zero();
    for (int step = 0; step < steps; ++step)
    {
        const double time = step * inSettings.mTimeStep;
        const Vec3 nodes_before = node_momentum();
        Result<CarVelocity> after = barrier.Collide(car, car_body.Get(), half, crush, 1.0, 0.4, time, inSettings.mTimeStep, damage);
        if (after.HasError())
            return after.GetError();
        into_nodes += node_momentum() - nodes_before;
        car.mLinearVelocity = after.Get().mLinear;
        car.mAngularVelocity = after.Get().mAngular;
        car.mTransform.mTranslation += inSettings.mTimeStep * car.mLinearVelocity;
        car.mCenterOfMass = car.mTransform.mTranslation;
        if (Result<fem::TetStepResult> stepped = barrier.Step(inSettings.mTimeStep); stepped.HasError())
            return stepped.GetError();
        (void)damage.Update(time + inSettings.mTimeStep);

        // The crush: how far the car's front is past the struck face (mean of the front nodes it covers).
        const fem::TetSolver& solver = barrier.GetSolver();
        double face = 0.0;
        int count = 0;
        for (int node = 0; node < solver.GetNodeCount(); ++node)
        {
            const Vec3& rest = solver.GetNodeRestPositions()[static_cast<std::size_t>(node)];
            // Barrier frame: the car covers |y| < 0.85 m and world z in [0, 1.4] m, i.e. z < 0.6 m here.
            if (rest.x() < -0.1 + 1e-9 && std::abs(rest.y()) < half.y() && rest.z() < 0.6 - 1e-9)
            {
                face += solver.GetPositions()[static_cast<std::size_t>(node)].x() + 0.1; // barrier frame to world
                ++count;
            }
        }
        result.mDeepestCrush = std::max(result.mDeepestCrush, car.mTransform.mTranslation.x() + half.x() - face / count);
    }
    const Vec3 lost = car.mMass * (Vec3(inSettings.mSpeed, 0.0, 0.0) - car.mLinearVelocity);
    result.mMomentumLost = lost.norm();
    result.mMomentumError = (lost - barrier.GetMomentumReceived()).norm();
    result.mNodeMomentumError = (lost - into_nodes).norm();
    result.mEndSpeed = car.mLinearVelocity.x();
    result.mBrokenLinks = barrier.GetSolver().GetBrokenLinkCount();
    result.mFrontPastBarrier = car.mTransform.mTranslation.x() + half.x() - 0.2;
    return result;
}

} // namespace crumple::crash
