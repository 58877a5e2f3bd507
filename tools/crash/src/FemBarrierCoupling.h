// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>
#include <crumple/crash/CrashScenario.h>
#include <crumple/fem/TetSolver.h>
#include <crumple/plugin/BodyState.h>
#include <crumple/plugin/DamageWorld.h>

#include <cstdint>
#include <vector>

namespace crumple::crash
{

/// How hard the car's front pushes back as it crushes: Campbell's linear model, force per unit width
/// F / w = A + B C at crush C, spread over the car's height h as a pressure p(C) = (A + B C) / h. From the
/// no-damage speed b0 and slope b1 (impact speed v = b0 + b1 C), A = m b0 b1 / w and B = m b1^2 / w.
struct CarCrushPressure
{
    double mAtZero = 0.0;   ///< A / h (Pa)
    double mPerMetre = 0.0; ///< B / h (Pa/m); infinite: a rigid front (hard contact)
};

/// The car's velocities after the barrier's contacts (world).
struct CarVelocity
{
    Vec3 mLinear = Vec3::Zero();  ///< m/s
    Vec3 mAngular = Vec3::Zero(); ///< rad/s
};

/// A destructible barrier, a tetrahedral FEM prop, and a rigid car box meeting it: a two-way coupling solved
/// outside the rigid-body engine, which never sees the barrier. Each engine step, before the engine steps:
///  1. Contact: every free node of the barrier near the car's collision box is a contact, its normal the
///     normal of the box face it is nearest to (out of the car), its gap the distance to that face (< 0
///     inside).
///  2. Damage: the contacts that pushed go to the damage world between the car and the barrier's own body
///     (for the step a rigid body moving as the pushed nodes did, of the mass that makes Crumple's inelastic
///     impulse the one delivered), as an engine's contact manifold: per car face at most four points, the
///     corners of the contact patch, put on the face's edges when within a lattice cell of them (a barrier
///     a little lower than the car). Crumple's dent model is calibrated on such manifolds; dozens of node
///     contacts a few centimetres apart, or a patch stopping short of the edge, would instead ask the FFD
///     solve for controls that swing well past the dent.
///  3. Solve: sequential impulses between each node (its lumped mass) and the car (mass, world inertia),
///     inelastic and without friction; a node with a gap may approach until the gap closes within the step
///     (speculative contact, so nothing tunnels). The car is not rigid: a node's impulse is capped at what
///     the car's crushing front can push over the node's share of the face in one step, p(C) a dt with C the
///     node's depth inside the car's box (the crush there). A barrier that holds therefore stops the car
///     over Campbell's crush instead of at once, and is loaded by the car's crush pressure, not by a rigid
///     impactor's. The car takes the opposite impulses: the caller gives it the returned velocities, and
///     linear momentum passes over exactly.
///  4. The FEM steps with the nodes' new velocities and may crack; loose pieces are debris the car still
///     meets. Only the barrier's front-face nodes meet the car, anchored ones (its base) never.
/// The barrier's frame is the world's translated to its centre (no rotation), its front face at
/// x = centre.x - size.x / 2.
class FemBarrierCoupling
{
public:
    /// Builds the barrier's tet grid from the target's size, cell and material preset, anchored at its base,
    /// and its body in the damage world.
    /// @param[in] inTarget       an ETarget::FemBarrier target
    /// @param[in] inWorldCentre  the barrier box's centre in the world (m)
    static Result<FemBarrierCoupling> Create(const TargetSpec& inTarget, const Vec3& inWorldCentre,
                                             plugin::DamageWorld& ioDamage);

    /// Steps 1 to 3 above for one engine step (the damage world hears of the contacts that pushed). ioDamage must be the world given to Create.
    /// @param[in] inCar          the car's state before the step, as Crumple reads it from the engine
    /// @param[in] inCarBody      the car's body in ioDamage
    /// @param[in] inHalfExtents  the car's collision box, centred on its body frame (m)
    /// @param[in] inTime         the simulation time the contacts are reported at (s)
    /// @param[in] inTimeStep     the engine step (s), > 0
    /// @return the car's velocities after the contacts; refused (nothing changed) on non-finite input
    /// @param[in] inCrush        the car front's crush pressure law
    /// @param[in] inMaxCrush     nodes deeper inside the car's box than this (m) are behind its crushable front
    /// @param[in] inEdgeSnap     a patch corner reported to Crumple this close (m) to an edge of the car's face
    ///                           is put on the edge: the car's FFD lattice spacing (a narrower band cannot bend
    ///                           by itself, and a dent that stops short of the edge leaves the edge's controls
    ///                           free to swing past it)
    Result<CarVelocity> Collide(const plugin::BodyState& inCar, plugin::BodyId inCarBody, const Vec3& inHalfExtents,
                                const CarCrushPressure& inCrush, double inMaxCrush, double inEdgeSnap, double inTime,
                                double inTimeStep, plugin::DamageWorld& ioDamage);
    /// Step 4: the FEM over one engine step (s).
    Result<fem::TetStepResult> Step(double inTimeStep) { return mSolver.Step(inTimeStep); }

    const fem::TetSolver& GetSolver() const { return mSolver; }
    /// Momentum the car has handed to the barrier so far (world, N s)
    const Vec3& GetMomentumReceived() const { return mMomentumReceived; }
    /// Contacts of the last Collide
    int GetContactCount() const { return static_cast<int>(mContacts.size()); }

private:
    struct NodeContact
    {
        int mNode = 0;
        Vec3 mNormal = Vec3::Zero();  // world, out of the car towards the node
        Vec3 mArm = Vec3::Zero();     // from the car's centre of mass to the contact point on its face (m)
        double mGap = 0.0;            // m, < 0 when the node is inside the car
        double mInverseEffectiveMass = 0.0;
        double mImpulse = 0.0;        // accumulated along mNormal on the node (N s), >= 0
        double mMaxImpulse = 0.0;     // what the crushing car can push in the step (N s)
        int mFace = 0;                // the car box face it meets: 2 axis + (side > 0)
    };

    FemBarrierCoupling(fem::TetSolver inSolver, const Vec3& inWorldCentre, plugin::BodyId inBody,
                       const Vec3& inHalfSize, const Vec3& inCell)
        : mSolver(std::move(inSolver)), mWorldCentre(inWorldCentre), mBody(inBody), mHalfSize(inHalfSize), mCell(inCell) {}
    /// Each node's share of the front face (m^2; 0 off it), when cracks have added nodes since
    void UpdateFaceAreas();
    void FindContacts(const plugin::BodyState& inCar, const Vec3& inHalfExtents, double inReach, double inMaxCrush);
    Status ReportContacts(const plugin::BodyState& inCar, plugin::BodyId inCarBody, const Vec3& inHalfExtents,
                          double inEdgeSnap, double inTime, double inTimeStep, plugin::DamageWorld& ioDamage) const;

    fem::TetSolver mSolver;
    Vec3 mWorldCentre;        // barrier frame origin in the world (m)
    plugin::BodyId mBody;     // the barrier's body in the damage world
    Vec3 mHalfSize;           // the barrier's half size (m); its front face is x = -mHalfSize.x()
    Vec3 mCell;               // its grid cell (m)
    std::vector<double> mFaceArea; // per node: its share of the front face (m^2), 0 off it
    std::vector<NodeContact> mContacts;
    std::vector<std::int8_t> mEntryFace; // per node: the car box face (2 axis + (side > 0)) it came in through, -1: none
    Vec3 mMomentumReceived = Vec3::Zero();
};

} // namespace crumple::crash
