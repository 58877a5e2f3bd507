// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Math.h>

#include <vector>

namespace crumple::common
{

/// The shape of a BoxImpulseEngine body.
enum class EImpulseShape
{
    Box,      ///< A box of mHalfExtents about its body frame's origin
    Cylinder, ///< A static cylinder along its body frame's z: radius mHalfExtents.x(), half height
              ///< mHalfExtents.z()
};

/// A body of BoxImpulseEngine (SI units; the body frame's origin is its centre of mass).
struct ImpulseBodySettings
{
    EImpulseShape mShape = EImpulseShape::Box;
    bool mDynamic = false;        ///< false: static (infinite mass, never moves)
    double mMass = 0.0;           ///< kg, > 0 for a dynamic body
    Vec3 mInertia = Vec3::Zero(); ///< Principal moments about the body axes (kg m^2); zero: the solid box's
    Vec3 mHalfExtents = Vec3::Ones();     ///< Box half size (m); a cylinder's radius (x) and half height (z)
    Transform mPose;                      ///< Body frame to world
    Vec3 mLinearVelocity = Vec3::Zero();  ///< World frame (m/s)
    Vec3 mAngularVelocity = Vec3::Zero(); ///< World frame (rad/s)
    double mFriction =
        0.0; ///< A pair's Coulomb coefficient is the product of its two bodies' (Bullet's rule)
};

/// One contact point of a step, as the engine solves it.
struct ImpulseContact
{
    int mBodyA = -1;               ///< The first body (a dynamic box)
    int mBodyB = -1;               ///< The second body
    Vec3 mPointOnA = Vec3::Zero(); ///< On A's surface, world frame (m)
    Vec3 mPointOnB = Vec3::Zero(); ///< On B's surface, world frame (m)
    Vec3 mNormal = Vec3::UnitZ();  ///< Unit, from B towards A
    double mDepth = 0.0;           ///< Overlap along the normal (m), < 0 for a gap within the contact margin
    double mFriction = 0.0;        ///< The pair's Coulomb coefficient
};

struct BoxImpulseEngineSettings
{
    Vec3 mGravity{0.0, 0.0, -9.81}; ///< m/s^2, world frame
    double mRestitution = 0.1;      ///< Rebound of contacts that close faster than mBounceSpeed
    double mBounceSpeed = 0.5;      ///< m/s: slower contacts stop without rebound (resting)
    double mContactMargin = 0.002;  ///< Gaps up to this (m) are reported and solved speculatively
    /// One contact per body pair and step: the manifold's centroid at its mean depth, as engines that reduce
    /// a manifold to one point report it
    bool mOnePointPerPair = false;
    /// The engine hands its states over in single precision (as Jolt, PhysX or Bullet's default build): the
    /// reported pose, velocities and world inverse inertia (computed as R D R^T in float) are float values
    bool mSinglePrecision = false;
    int mVelocityIterations = 30;       ///< Sequential-impulse sweeps over the contacts per step
    int mPositionIterations = 10;       ///< Sweeps of the split-impulse position correction per step
    double mPositionCorrection = 0.2;   ///< Share of a penetration removed per step, by position only
    double mAllowedPenetration = 0.001; ///< m, left uncorrected so that resting contacts persist
};

/// A small rigid-body engine of boxes and static cylinders, written for the tests as a stand-in for an engine
/// that Crumple has no adapter for. It knows nothing of Crumple: contacts by the separating axis test and
/// face clipping (box-box) or the nearest point of a box's top and bottom rim (box-cylinder), solved by
/// sequential impulses with a friction pyramid (two fixed tangents, Bullet's and ODE's model) and
/// restitution, and split impulses that move penetrating bodies apart without adding velocity (Catto,
/// "Iterative Dynamics with Temporal Coherence", GDC 2005). Semi-implicit Euler; no gyroscopic term; one
/// island, no sleeping.
class BoxImpulseEngine
{
  public:
    explicit BoxImpulseEngine(const BoxImpulseEngineSettings& inSettings = {}) : mSettings(inSettings) {}

    /// Adds a body; its index is the count of bodies added before.
    int AddBody(const ImpulseBodySettings& inSettings);
    /// Finds the contacts at the bodies' current poses (the step's start), pairs of a dynamic box with any
    /// other body; SolveAndIntegrate solves these.
    const std::vector<ImpulseContact>& DetectContacts();
    /// Applies gravity, solves the contacts DetectContacts found, and moves the bodies by inDeltaTime (s).
    void SolveAndIntegrate(double inDeltaTime);

    const ImpulseBodySettings& GetBody(int inBody) const
    {
        return mBodies[static_cast<std::size_t>(inBody)].mState;
    }
    /// World inverse inertia (1/(kg m^2)); zero for a static body
    Mat3 InverseInertiaWorld(int inBody) const;
    /// The body's state as the engine reports it to a game (its float values with mSinglePrecision): pose,
    /// velocities, and the world inverse inertia
    ImpulseBodySettings ReportedBody(int inBody) const;
    Mat3 ReportedInverseInertiaWorld(int inBody) const;

  private:
    struct Body
    {
        ImpulseBodySettings mState;
        double mInverseMass = 0.0;
        Vec3 mInverseInertia = Vec3::Zero(); ///< Body axes
        Vec3 mPseudoLinear = Vec3::Zero();   ///< Split-impulse velocities: move the body, then are dropped
        Vec3 mPseudoAngular = Vec3::Zero();
    };
    void BoxBoxContacts(int inA, int inB);
    void BoxCylinderContacts(int inBox, int inCylinder);

    BoxImpulseEngineSettings mSettings;
    std::vector<Body> mBodies;
    std::vector<ImpulseContact> mContacts;
};

} // namespace crumple::common
