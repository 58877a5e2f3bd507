// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "BoxImpulseWallCrash.h"

#include <cmath>
#include <numbers>

namespace crumple::common
{

using namespace crumple::plugin;

bool BoxImpulseWallCrash::Supports(const EngineCrashSettings& inSettings)
{
    return inSettings.mSceneryBoxes == 0 && inSettings.mAttach;
}

namespace
{

// The engine's own settings with the scene's gravity and Crumple's restitution (as the other scenes bounce).
BoxImpulseEngineSettings SceneEngine(const EngineCrashSettings& inSettings, BoxImpulseEngineSettings inEngine)
{
    inEngine.mGravity = Vec3(0.0, 0.0, inSettings.mFloating ? 0.0 : -9.81);
    inEngine.mRestitution = inSettings.mWorld.mRestitution;
    return inEngine;
}

// The engine resolves a hit it predicts from a gap whole, rebound included (as Jolt does): the glue says so.
DamageWorldSettings SceneWorld(DamageWorldSettings inWorld)
{
    inWorld.mSpeculativeContacts = ESpeculativeContacts::ResolveWhole;
    return inWorld;
}

} // namespace

BoxImpulseWallCrash::BoxImpulseWallCrash(const EngineCrashSettings& inSettings,
                                         const BoxImpulseEngineSettings& inEngine)
    : mSettings(inSettings), mEngine(SceneEngine(inSettings, inEngine)),
      mDamageOwner(std::move(DamageWorld::Create(SceneWorld(inSettings.mWorld)).Get())),
      mDamage(*mDamageOwner)
{
    // intent: the coefficients of the Bullet scene (a pair's is the product of its bodies'): each pair but
    // the car's with the ground takes mFriction, that one mGroundFriction
    const double friction = std::sqrt(inSettings.mFriction);
    const auto add_static =
        [&](EImpulseShape inShape, const Vec3& inHalfExtents, const Transform& inPose, double inFriction)
    {
        ImpulseBodySettings body;
        body.mShape = inShape;
        body.mHalfExtents = inHalfExtents;
        body.mPose = inPose;
        body.mFriction = inFriction;
        return mEngine.AddBody(body);
    };
    const auto place = [](const Vec3& inCentre, double inYaw)
    {
        Transform pose;
        pose.mRotation = Eigen::AngleAxisd(inYaw, Vec3::UnitZ()).toRotationMatrix();
        pose.mTranslation = inCentre;
        return pose;
    };
    if (!inSettings.mFloating)
        add_static(EImpulseShape::Box, Vec3(200.0, 200.0, 1.0), place(Vec3(0.0, 0.0, -1.0), 0.0),
                   friction > 0.0 ? inSettings.mGroundFriction / friction : 0.0);
    if (inSettings.mTargetVehicle)
    {
        // A second car, a dynamic box on the ground, deformable too.
        const TargetVehicleSettings& target = *inSettings.mTargetVehicle;
        const double yaw = target.mYawDegrees * std::numbers::pi / 180.0;
        ImpulseBodySettings body;
        body.mDynamic = true;
        body.mMass = target.mMass;
        body.mHalfExtents = target.mHalfExtents;
        body.mPose = TargetVehicleStart(target);
        body.mLinearVelocity = target.mSpeed * Vec3(std::cos(yaw), std::sin(yaw), 0.0);
        body.mFriction = friction;
        mTarget = mEngine.AddBody(body);
    }
    else if (!inSettings.mDriveOnly && !inSettings.mFloating)
    {
        if (inSettings.mPoleRadius > 0.0)
            add_static(EImpulseShape::Cylinder, Vec3(inSettings.mPoleRadius, inSettings.mPoleRadius, 3.0),
                       place(Vec3(0.0, 0.0, 3.0), 0.0), friction);
        else if (inSettings.mOverlapFraction < 1.0)
            add_static(EImpulseShape::Box, Vec3(1.0, 5.0, 3.0),
                       place(Vec3(1.0, CrashWallLeftEdge(inSettings) + 5.0, 3.0), 0.0), friction);
        else
        {
            const double angle = inSettings.mWallAngleDegrees * std::numbers::pi / 180.0;
            add_static(EImpulseShape::Box, Vec3(1.0, 10.0, 3.0),
                       place(Vec3(std::cos(angle), std::sin(angle), 3.0), angle), friction);
        }
    }
    ImpulseBodySettings car;
    car.mDynamic = true;
    car.mMass = inSettings.mMass;
    car.mInertia = inSettings.mInertia.value_or(Vec3::Zero());
    car.mHalfExtents = inSettings.mHalfExtents;
    car.mPose = CrashCarStart(inSettings);
    car.mLinearVelocity = Vec3(inSettings.mSpeed, 0.0, 0.0);
    car.mFriction = friction;
    mCar = mEngine.AddBody(car);

    // Every engine body becomes a Crumple body; the car (and the target vehicle) carry deformable objects.
    for (int body = 0; body <= mCar; ++body)
        mIds.push_back(mDamage.CreateBody(StateOf(body)).Get());
    mCarObject =
        mDamage.CreateDeformableObject(mIds[static_cast<std::size_t>(mCar)], CrashCarObject(inSettings))
            .Get();
    if (mTarget >= 0)
        mTargetObject = mDamage
                            .CreateDeformableObject(mIds[static_cast<std::size_t>(mTarget)],
                                                    TargetVehicleObject(*inSettings.mTargetVehicle))
                            .Get();
    mDamage.AddListener(&mCounter);
}

BodyState BoxImpulseWallCrash::StateOf(int inBody) const
{
    // intent: what the engine reports, float values as they are for a single-precision engine
    const ImpulseBodySettings body = mEngine.ReportedBody(inBody);
    BodyState state;
    state.mMotionType = body.mDynamic ? EMotionType::Dynamic : EMotionType::Static;
    state.mMass = body.mDynamic ? body.mMass : 1.0;
    state.mInverseInertiaWorld = body.mDynamic ? mEngine.ReportedInverseInertiaWorld(inBody) : Mat3::Zero();
    state.mTransform = body.mPose;
    state.mCenterOfMass = body.mPose.mTranslation;
    state.mLinearVelocity = body.mLinearVelocity;
    state.mAngularVelocity = body.mAngularVelocity;
    // intent: where a crush of the car meets this body: its shape's box in its frame (a cylinder's too)
    const Vec3 half = body.mShape == EImpulseShape::Box
                          ? body.mHalfExtents
                          : Vec3(body.mHalfExtents.x(), body.mHalfExtents.x(), body.mHalfExtents.z());
    state.mHasShapeBounds = true;
    state.mShapeMin = -half;
    state.mShapeMax = half;
    return state;
}

BodyState BoxImpulseWallCrash::GetCarState() const
{
    return StateOf(mCar);
}

double BoxImpulseWallCrash::KineticEnergy() const
{
    double energy = 0.0;
    for (const int body : {mCar, mTarget})
        if (body >= 0)
        {
            const BodyState state = StateOf(body);
            energy += 0.5 * state.mMass * state.mLinearVelocity.squaredNorm() +
                      0.5 * state.mAngularVelocity.dot(state.mInverseInertiaWorld.inverse() *
                                                       state.mAngularVelocity);
        }
    return energy;
}

void BoxImpulseWallCrash::Step()
{
    // intent: the contacts at the step's start, the car's velocities before the solver changes them (a
    // Baraff impulse needs pre-solve velocities), then the step, then its contacts and the time
    const std::vector<ImpulseContact>& contacts = mEngine.DetectContacts();
    for (const int body : {mCar, mTarget})
        if (body >= 0)
            mRefusedCalls +=
                mDamage.SetBodyState(mIds[static_cast<std::size_t>(body)], StateOf(body)) ? 0 : 1;
    mEngine.SolveAndIntegrate(mSettings.mTimeStep);
    mTime += mSettings.mTimeStep;
    mEvents.clear();
    for (const ImpulseContact& contact : contacts)
    {
        ContactEvent event;
        event.mBodyA = mIds[static_cast<std::size_t>(contact.mBodyA)];
        event.mBodyB = mIds[static_cast<std::size_t>(contact.mBodyB)];
        event.mPointOnA = contact.mPointOnA;
        event.mPointOnB = contact.mPointOnB;
        event.mNormal = contact.mNormal;
        event.mPenetrationDepth = contact.mDepth;
        event.mFriction = contact.mFriction;
        event.mTime = mTime;
        mEvents.push_back(event);
    }
    if (!mEvents.empty())
        mRefusedCalls += mDamage.SubmitContacts(mEvents, mSettings.mTimeStep) ? 0 : 1;
    mDamage.Update(mTime);
}

EngineCrashResult BoxImpulseWallCrash::Run()
{
    return RunEngineCrash(*this, mSettings, true);
}

} // namespace crumple::common
