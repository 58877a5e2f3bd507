// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "WallCrashScene.h"
#include "BoxMesh.h"

#include <crumple/plugin/BaraffImpulse.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace crumple::common
{

using namespace crumple::plugin;

Result<WallCrashScene> WallCrashScene::Create(const WallCrashSettings& inSettings)
{
    Result<std::unique_ptr<DamageWorld>> world = DamageWorld::Create(inSettings.mWorld);
    if (!world)
        return world.GetError();
    WallCrashScene scene(inSettings, std::move(world).Get());

    // Car: body frame at the centre of mass, x forward; yawed about z, front face just short of the wall x = 0.
    const Vec3& h = inSettings.mHalfExtents;
    const double yaw = inSettings.mYawDegrees * std::numbers::pi / 180.0;
    scene.mCarState.mMass = inSettings.mMass;
    scene.mCarState.mTransform.mRotation = Eigen::AngleAxisd(yaw, Vec3::UnitZ()).toRotationMatrix();
    const double reach = std::abs(h.x() * std::cos(yaw)) + std::abs(h.y() * std::sin(yaw));
    scene.mCarState.mTransform.mTranslation = Vec3(-reach - 0.01, 0.0, 0.0);
    scene.mCarState.mCenterOfMass = scene.mCarState.mTransform.mTranslation;
    scene.mCarState.mLinearVelocity = Vec3(inSettings.mSpeed, 0.0, 0.0);
    const double m = inSettings.mMass;
    const Vec3 size = 2.0 * h;
    scene.mLocalInverseInertia = Vec3(12.0 / (m * (size.y() * size.y() + size.z() * size.z())),
                                      12.0 / (m * (size.x() * size.x() + size.z() * size.z())),
                                      12.0 / (m * (size.x() * size.x() + size.y() * size.y())))
                                     .asDiagonal();
    scene.UpdateInertia();

    // Wall: static, its frame at the wall plane.
    scene.mWallState.mMotionType = EMotionType::Static;

    Result<BodyId> car = scene.mWorld->CreateBody(scene.mCarState);
    Result<BodyId> wall = scene.mWorld->CreateBody(scene.mWallState);
    if (!car || !wall)
        return MakeError(EError::InvalidArgument, "WallCrashScene: invalid car or wall state");
    scene.mCar = car.Get();
    scene.mWall = wall.Get();

    DeformableObjectSettings object;
    object.mMesh = MakeBoxMesh(h, BoxSegmentsForTriangles(h, inSettings.mTriangles));
    object.mMaterial = inSettings.mMaterial;
    object.mFittedControlCount = inSettings.mControlCount;
    Result<ObjectId> car_object = scene.mWorld->CreateDeformableObject(scene.mCar, object);
    if (!car_object)
        return car_object.GetError();
    scene.mCarObject = car_object.Get();

    // Candidate contact points: a grid on the box surface.
    const ffd::TriangleMesh samples = MakeBoxMesh(h, {inSettings.mSamplesPerEdge, inSettings.mSamplesPerEdge,
                                                      inSettings.mSamplesPerEdge});
    scene.mSamples = samples.mPositions;
    return scene;
}

void WallCrashScene::UpdateInertia()
{
    const Mat3& r = mCarState.mTransform.mRotation;
    mCarState.mInverseInertiaWorld = r * mLocalInverseInertia * r.transpose();
}

void WallCrashScene::Step()
{
    // Pre-solve snapshot, as an adapter takes it before the engine's solver.
    Status set = mWorld->SetBodyState(mCar, mCarState);
    (void)set;

    // Narrow phase: the deepest samples behind the wall plane x = 0, normal from wall (B) to car (A) is -x.
    struct Candidate
    {
        Vec3 mPoint;
        double mDepth;
    };
    std::vector<Candidate> candidates;
    for (const Vec3& sample : mSamples)
    {
        const Vec3 p = mCarState.mTransform.ToWorld(sample);
        if (p.x() > 0.0)
            candidates.push_back({p, p.x()});
    }
    // Keep a manifold like Bullet's: the deepest point, then the points that spread the manifold most
    // (farthest from those kept) among those nearly as deep.
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const Candidate& a, const Candidate& b) { return a.mDepth > b.mDepth; });
    std::vector<Candidate> manifold;
    if (!candidates.empty())
    {
        const double floor_depth = candidates.front().mDepth - 0.05;
        std::erase_if(candidates, [&](const Candidate& c) { return c.mDepth < floor_depth; });
        manifold.push_back(candidates.front());
        while (manifold.size() < static_cast<std::size_t>(mSettings.mMaxContacts))
        {
            double best_distance = 0.0;
            const Candidate* best = nullptr;
            for (const Candidate& c : candidates)
            {
                double nearest = std::numeric_limits<double>::infinity();
                for (const Candidate& kept : manifold)
                    nearest = std::min(nearest, (kept.mPoint - c.mPoint).norm());
                if (nearest > best_distance + 1.0e-9)
                {
                    best_distance = nearest;
                    best = &c;
                }
            }
            if (best == nullptr)
                break;
            manifold.push_back(*best);
        }
    }
    candidates = std::move(manifold);

    std::vector<ContactEvent> events;
    std::vector<ImpulseContact> solver_contacts;
    double max_depth = 0.0;
    for (const Candidate& c : candidates)
    {
        ContactEvent event;
        event.mBodyA = mCar;
        event.mBodyB = mWall;
        event.mPointOnA = c.mPoint;
        event.mPointOnB = Vec3(0.0, c.mPoint.y(), c.mPoint.z());
        event.mNormal = -Vec3::UnitX();
        event.mPenetrationDepth = c.mDepth;
        event.mTime = mTime;
        events.push_back(event);
        solver_contacts.push_back({0.5 * (event.mPointOnA + event.mPointOnB), event.mNormal});
        max_depth = std::max(max_depth, c.mDepth);
    }
    mContactCount += static_cast<int>(events.size());
    if (!events.empty())
    {
        Status submitted = mWorld->SubmitContacts(events);
        (void)submitted;
        // The "engine's solver": apply the same impulses, then push the car out of the wall.
        const std::vector<double> impulses =
            SimultaneousImpulses(mCarState, mWallState, solver_contacts, mSettings.mWorld.mRestitution, 0.0);
        for (std::size_t i = 0; i < impulses.size(); ++i)
        {
            const Vec3 impulse = impulses[i] * solver_contacts[i].mNormal;
            const Vec3 r = solver_contacts[i].mPoint - mCarState.mCenterOfMass;
            mCarState.mLinearVelocity += impulse / mCarState.mMass;
            mCarState.mAngularVelocity += mCarState.mInverseInertiaWorld * r.cross(impulse);
        }
        mCarState.mTransform.mTranslation.x() -= max_depth;
    }

    // Integrate (semi-implicit Euler; rotation by the exact axis-angle of w dt).
    const double dt = mSettings.mTimeStep;
    mCarState.mTransform.mTranslation += dt * mCarState.mLinearVelocity;
    const double angle = mCarState.mAngularVelocity.norm() * dt;
    if (angle > 0.0)
    {
        const Mat3 rotation = Eigen::AngleAxisd(angle, mCarState.mAngularVelocity.normalized()).toRotationMatrix();
        Mat3 r = rotation * mCarState.mTransform.mRotation;
        // Re-orthonormalize to keep the state a proper rotation over long runs.
        mCarState.mTransform.mRotation = Quat(r).normalized().toRotationMatrix();
    }
    mCarState.mCenterOfMass = mCarState.mTransform.mTranslation;
    UpdateInertia();
    mTime += dt;
    mWorld->Update(mTime);
}

void WallCrashScene::Run()
{
    const int steps = static_cast<int>(std::lround(mSettings.mDuration / mSettings.mTimeStep));
    for (int i = 0; i < steps; ++i)
        Step();
    mWorld->Flush();
}

} // namespace crumple::common
