// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "FemBarrierCoupling.h"

#include <crumple/fem/PropMaterialPreset.h>
#include <crumple/fem/TetGrid.h>
#include <crumple/plugin/ContactEvent.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace crumple::crash
{

namespace
{

// Sequential-impulse passes over the contacts of one step: enough for the car's impulse to settle over a
// few hundred nodes (each pass hands every node the car's updated velocity).
constexpr int cSolverPasses = 16;
// Nodes this far outside the car's box (m), beyond what the step's motion can close, are left out.
constexpr double cContactMargin = 0.02;
// The barrier's body in the damage world when the car's whole approach was stopped (kg): as good as immovable.
constexpr double cImmovableMass = 1.0e12;
// No entry face yet.
constexpr std::int8_t cNoFace = -1;
// A node less than this outside the box (m) lies on its surface, for choosing the face it meets.
constexpr double cOnFace = 1.0e-6;

} // namespace

Result<FemBarrierCoupling> FemBarrierCoupling::Create(const TargetSpec& inTarget, const Vec3& inWorldCentre,
                                                      plugin::DamageWorld& ioDamage)
{
    // The coupling hands Crumple each step's share of the barrier's push as a full impulse (its effective
    // mass makes Baraff's impulse equal what it delivered): solved from the remembered post-impulse state
    // instead, every step after the first would count nothing.
    if (ioDamage.GetSettings().mCountImpactOnce)
        return MakeError(EError::InvalidArgument,
                         "fem barrier: the damage world must have DamageWorldSettings.mCountImpactOnce = false");
    const auto* found = std::find(cBarrierMaterialNames.begin(), cBarrierMaterialNames.end(), inTarget.mBarrierMaterial);
    const auto material = found - cBarrierMaterialNames.begin();
    if (found == cBarrierMaterialNames.end())
        return MakeError(EError::InvalidArgument, "fem barrier: unknown material \"" + inTarget.mBarrierMaterial + "\"");
    Result<fem::PropMaterialPreset> preset = fem::MakePropMaterialPreset(static_cast<fem::EPropMaterial>(material));
    if (preset.HasError())
        return preset.GetError();
    fem::TetGridSettings grid;
    grid.mOrigin = -0.5 * inTarget.mBarrierSize;
    grid.mSize = inTarget.mBarrierSize;
    for (int axis = 0; axis < 3; ++axis)
        grid.mCellCount[axis] =
            std::max(1, static_cast<int>(std::lround(inTarget.mBarrierSize[axis] / inTarget.mBarrierCell)));
    Result<fem::TetMesh> mesh = fem::TetGrid(grid);
    if (mesh.HasError())
        return mesh.GetError();
    fem::TetSolverSettings settings;
    settings.mIntegrator = fem::EIntegrator::SymplecticEuler; // follows the stress wave of a hit
    settings.mMaxSubSteps = 100000;
    Result<fem::TetSolver> solver = fem::TetSolver::Create(mesh.Get(), preset.Get().mMaterial, settings);
    if (solver.HasError())
        return solver.GetError();
    // Anchored at its base, as a wall on its footing.
    for (int node = 0; node < solver.Get().GetNodeCount(); ++node)
        if (solver.Get().GetNodeRestPositions()[static_cast<std::size_t>(node)].z() <= grid.mOrigin.z() + 1e-9)
            if (Status status = solver.Get().SetNodeFixed(node, true); status.HasError())
                return status.GetError();

    // Its body in the damage world; Collide sets its state to that of the touching nodes.
    plugin::BodyState state;
    state.mMass = 0.0;
    for (double mass : solver.Get().GetMasses())
        state.mMass += mass;
    state.mInverseInertiaWorld = Mat3::Zero();
    state.mTransform.mTranslation = inWorldCentre;
    state.mCenterOfMass = inWorldCentre;
    Result<plugin::BodyId> body = ioDamage.CreateBody(state);
    if (body.HasError())
        return body.GetError();
    const Vec3 cell(inTarget.mBarrierSize.x() / grid.mCellCount[0], inTarget.mBarrierSize.y() / grid.mCellCount[1],
                    inTarget.mBarrierSize.z() / grid.mCellCount[2]);
    return FemBarrierCoupling(std::move(solver.Get()), inWorldCentre, body.Get(), 0.5 * inTarget.mBarrierSize, cell);
}

void FemBarrierCoupling::UpdateFaceAreas()
{
    // Only cracks change the nodes (they append copies), so the shares are found again only then.
    const std::vector<Vec3>& rest = mSolver.GetNodeRestPositions();
    if (mFaceArea.size() == rest.size())
        return;
    // A cell's face area, halved per face edge the node lies on; the copies a crack makes of a node share it
    // (they keep its rest position exactly).
    std::map<std::pair<double, double>, int> copies;
    for (const Vec3& position : rest)
        if (position.x() <= -mHalfSize.x() + 1e-9)
            ++copies[{position.y(), position.z()}];
    mFaceArea.assign(rest.size(), 0.0);
    for (std::size_t node = 0; node < rest.size(); ++node)
    {
        const Vec3& position = rest[node];
        if (position.x() > -mHalfSize.x() + 1e-9)
            continue;
        double area = mCell.y() * mCell.z();
        for (int axis : {1, 2})
            if (std::abs(std::abs(position[axis]) - mHalfSize[axis]) < 1e-9)
                area *= 0.5;
        mFaceArea[node] = area / copies[{position.y(), position.z()}];
    }
}

void FemBarrierCoupling::FindContacts(const plugin::BodyState& inCar, const Vec3& inHalfExtents, double inReach,
                                      double inMaxCrush)
{
    mContacts.clear();
    const std::vector<Vec3>& positions = mSolver.GetPositions();
    const std::vector<Vec3>& velocities = mSolver.GetVelocities();
    const std::vector<double>& inverse_masses = mSolver.GetInverseMasses();
    const Mat3 inverse_inertia = inCar.InverseInertia();
    mEntryFace.resize(positions.size(), cNoFace); // copies a crack makes start without one
    for (int node = 0; node < mSolver.GetNodeCount(); ++node)
    {
        const auto n = static_cast<std::size_t>(node);
        // Front-face nodes (copies made by cracks inherit their rest position, hence their share too).
        if (inverse_masses[n] == 0.0 || mFaceArea[n] == 0.0)
            continue;
        const Vec3 local = inCar.mTransform.ToBody(positions[n] + mWorldCentre);
        if (((local.cwiseAbs() - inHalfExtents).array() > inReach).any())
        {
            mEntryFace[n] = cNoFace;
            continue;
        }

        // The box face the node meets. Clearly outside, it is the face it is furthest out of, and the contact
        // is from the nearest point of the box. Touching or inside, it is the face it came in through (the
        // front, in a frontal crush, however deep the crush and wherever the top or a side is nearer, and also
        // for a node that lies in the plane of the top); one first met there takes the face it is out of, or
        // else the face advancing fastest on it, and one no face advances on is left where it is.
        NodeContact contact;
        contact.mNode = node;
        Eigen::Index out_axis = 0;
        const double out_distance = (local.cwiseAbs() - inHalfExtents).maxCoeff(&out_axis);
        const auto out_face = static_cast<std::int8_t>(2 * out_axis + (local[out_axis] < 0.0 ? 0 : 1));
        Vec3 face_point = local.cwiseMax(-inHalfExtents).cwiseMin(inHalfExtents);
        Vec3 normal = local - face_point;
        if (out_distance > cContactMargin)
        {
            contact.mGap = normal.norm();
            normal /= contact.mGap;
            mEntryFace[n] = out_face;
        }
        else
        {
            if (mEntryFace[n] == cNoFace && out_distance > cOnFace)
                mEntryFace[n] = out_face;
            if (mEntryFace[n] == cNoFace)
            {
                const Vec3 relative = inCar.mTransform.DirectionToBody(
                    inCar.mLinearVelocity +
                    inCar.mAngularVelocity.cross(inCar.mTransform.ToWorld(local) - inCar.mCenterOfMass) - velocities[n]);
                double fastest = 0.0;
                for (int a = 0; a < 3; ++a)
                {
                    const int side = local[a] < 0.0 ? 0 : 1;
                    const double speed = side == 1 ? relative[a] : -relative[a];
                    if (speed > fastest)
                    {
                        fastest = speed;
                        mEntryFace[n] = static_cast<std::int8_t>(2 * a + side);
                    }
                }
                if (mEntryFace[n] == cNoFace)
                    continue;
            }
            const int axis = mEntryFace[n] / 2;
            const double side = mEntryFace[n] % 2 == 1 ? 1.0 : -1.0;
            const double depth = inHalfExtents[axis] - side * local[axis]; // < 0: in front of the face
            // Deeper than the car's front can crush: a node the car has passed, not one it is meeting.
            if (depth > inMaxCrush + inReach)
                continue;
            contact.mGap = -depth;
            normal = Vec3::Zero();
            normal[axis] = side;
            face_point = local;
            face_point[axis] = side * inHalfExtents[axis];
        }
        contact.mFace = mEntryFace[n];
        contact.mNormal = inCar.mTransform.mRotation * normal;
        contact.mArm = inCar.mTransform.ToWorld(face_point) - inCar.mCenterOfMass;
        const Vec3 arm_cross_normal = contact.mArm.cross(contact.mNormal);
        contact.mInverseEffectiveMass = inverse_masses[n] + inCar.InverseMass() +
                                        arm_cross_normal.dot(inverse_inertia * arm_cross_normal);
        mContacts.push_back(contact);
    }
}

Status FemBarrierCoupling::ReportContacts(const plugin::BodyState& inCar, plugin::BodyId inCarBody,
                                          const Vec3& inHalfExtents, double inEdgeSnap, double inTime,
                                          double inTimeStep, plugin::DamageWorld& ioDamage) const
{
    // The barrier's body for this step: the pushed nodes as one rigid body that does not turn, moving as
    // they did before the step.
    const std::vector<Vec3>& positions = mSolver.GetPositions();
    plugin::BodyState barrier;
    barrier.mMass = 0.0;
    barrier.mInverseInertiaWorld = Mat3::Zero();
    Vec3 moment = Vec3::Zero(), momentum = Vec3::Zero(), delivered = Vec3::Zero();
    for (const NodeContact& contact : mContacts)
    {
        if (contact.mImpulse == 0.0)
            continue;
        const auto n = static_cast<std::size_t>(contact.mNode);
        const double mass = mSolver.GetMasses()[n];
        barrier.mMass += mass;
        moment += mass * (positions[n] + mWorldCentre);
        momentum += mass * mSolver.GetVelocities()[n];
        delivered += contact.mImpulse * contact.mNormal;
    }
    if (barrier.mMass == 0.0)
        return Status::Ok(); // nothing pushed
    barrier.mCenterOfMass = moment / barrier.mMass;
    barrier.mTransform.mTranslation = barrier.mCenterOfMass;
    barrier.mLinearVelocity = momentum / barrier.mMass;
    // Its mass: the one whose inelastic impulse with the car, approach / (1/M_car + 1/M), is the impulse the
    // crushing front delivered, so that Crumple dents the car by what it really took (the nodes' own mass
    // would ask for the rigid impactor's impulse on every step of a crush).
    const double delivered_impulse = delivered.norm();
    const double approach = (inCar.mLinearVelocity - barrier.mLinearVelocity).dot(delivered / delivered_impulse);
    const double inverse_mass = approach / delivered_impulse - inCar.InverseMass();
    if (approach > 0.0)
        barrier.mMass = inverse_mass > 0.0 ? 1.0 / inverse_mass : cImmovableMass;
    if (Status status = ioDamage.SetBodyState(mBody, barrier); status.HasError())
        return status;
    if (Status status = ioDamage.SetBodyState(inCarBody, inCar); status.HasError())
        return status;

    // Per car face, the pushing contacts at the corners of their patch (extremes of +-u +-v in the face).
    std::vector<plugin::ContactEvent> events;
    for (int face = 0; face < 6; ++face)
    {
        const int u = (face / 2 + 1) % 3, v = (face / 2 + 2) % 3;
        std::array<const NodeContact*, 4> corners{};
        std::array<double, 4> best{};
        best.fill(-std::numeric_limits<double>::infinity());
        for (const NodeContact& contact : mContacts)
        {
            if (contact.mImpulse == 0.0 || contact.mFace != face)
                continue;
            const Vec3 local = inCar.mTransform.DirectionToBody(contact.mArm);
            const std::array<double, 4> score{local[u] + local[v], local[u] - local[v], -local[u] + local[v],
                                              -local[u] - local[v]};
            for (std::size_t k = 0; k < 4; ++k)
                if (score[k] > best[k])
                {
                    best[k] = score[k];
                    corners[k] = &contact;
                }
        }
        for (std::size_t k = 0; k < 4; ++k)
        {
            const NodeContact* contact = corners[k];
            if (contact == nullptr || std::find(corners.begin(), corners.begin() + static_cast<std::ptrdiff_t>(k), contact) !=
                                          corners.begin() + static_cast<std::ptrdiff_t>(k))
                continue; // no patch on this face, or a corner already taken
            plugin::ContactEvent event;
            event.mBodyA = inCarBody;
            event.mBodyB = mBody;
            Vec3 corner = inCar.mTransform.ToBody(inCar.mCenterOfMass + contact->mArm);
            for (int axis : {u, v})
                if (std::abs(corner[axis]) > inHalfExtents[axis] - inEdgeSnap)
                    corner[axis] = corner[axis] < 0.0 ? -inHalfExtents[axis] : inHalfExtents[axis];
            event.mPointOnA = inCar.mTransform.ToWorld(corner);
            event.mPointOnB = positions[static_cast<std::size_t>(contact->mNode)] + mWorldCentre;
            event.mNormal = -contact->mNormal; // from the barrier towards the car
            event.mPenetrationDepth = -contact->mGap;
            event.mTime = inTime;
            events.push_back(event);
        }
    }
    return ioDamage.SubmitContacts(events, inTimeStep);
}

Result<CarVelocity> FemBarrierCoupling::Collide(const plugin::BodyState& inCar, plugin::BodyId inCarBody,
                                                const Vec3& inHalfExtents, const CarCrushPressure& inCrush,
                                                double inMaxCrush, double inEdgeSnap, double inTime, double inTimeStep,
                                                plugin::DamageWorld& ioDamage)
{
    if (!(inTimeStep > 0.0) || !std::isfinite(inTimeStep) || !inCar.mLinearVelocity.allFinite() ||
        !inCar.mAngularVelocity.allFinite() || !inCar.mTransform.mTranslation.allFinite() || !inHalfExtents.allFinite() ||
        !(inCrush.mAtZero >= 0.0) || !(inCrush.mPerMetre >= 0.0) || !(inMaxCrush >= 0.0) || !(inEdgeSnap >= 0.0))
        return MakeError(EError::InvalidArgument, "fem barrier: the car's state and the time step must be finite, "
                                                  "the step > 0 s, the crush pressures, the max crush and the edge snap >= 0");
    CarVelocity car{inCar.mLinearVelocity, inCar.mAngularVelocity};
    // Reach: what the step's relative motion can close, twice over, plus a margin.
    const double reach =
        2.0 * (car.mLinear.norm() + car.mAngular.norm() * inHalfExtents.norm()) * inTimeStep + cContactMargin;
    UpdateFaceAreas();
    FindContacts(inCar, inHalfExtents, reach, inMaxCrush);
    if (mContacts.empty())
        return car;
    for (NodeContact& contact : mContacts)
        contact.mMaxImpulse = std::isinf(inCrush.mPerMetre) // a rigid front: no cap
                                  ? std::numeric_limits<double>::infinity()
                                  : (inCrush.mAtZero + inCrush.mPerMetre * std::max(0.0, -contact.mGap)) *
                                        mFaceArea[static_cast<std::size_t>(contact.mNode)] * inTimeStep;

    // Sequential impulses, in node order (deterministic).
    const std::vector<double>& inverse_masses = mSolver.GetInverseMasses();
    const Mat3 inverse_inertia = inCar.InverseInertia();
    std::vector<Vec3> node_velocity(mContacts.size());
    for (std::size_t k = 0; k < mContacts.size(); ++k)
        node_velocity[k] = mSolver.GetVelocities()[static_cast<std::size_t>(mContacts[k].mNode)];
    for (int pass = 0; pass < cSolverPasses; ++pass)
        for (std::size_t k = 0; k < mContacts.size(); ++k)
        {
            NodeContact& contact = mContacts[k];
            const Vec3 car_point = car.mLinear + car.mAngular.cross(contact.mArm);
            const double separation_speed = (node_velocity[k] - car_point).dot(contact.mNormal);
            // A gap may close within the step, no more; an overlap may not grow.
            const double allowed = contact.mGap > 0.0 ? -contact.mGap / inTimeStep : 0.0;
            const double accumulated = std::clamp(
                contact.mImpulse + (allowed - separation_speed) / contact.mInverseEffectiveMass, 0.0, contact.mMaxImpulse);
            const Vec3 impulse = (accumulated - contact.mImpulse) * contact.mNormal;
            contact.mImpulse = accumulated;
            node_velocity[k] += inverse_masses[static_cast<std::size_t>(contact.mNode)] * impulse;
            car.mLinear -= inCar.InverseMass() * impulse;
            car.mAngular -= inverse_inertia * contact.mArm.cross(impulse);
        }

    // Crumple dents the car from the contacts that pushed, with the states before they did.
    if (Status status = ReportContacts(inCar, inCarBody, inHalfExtents, inEdgeSnap, inTime, inTimeStep, ioDamage);
        status.HasError())
        return status.GetError();

    // The nodes take their impulses.
    for (const NodeContact& contact : mContacts)
    {
        if (contact.mImpulse == 0.0)
            continue;
        if (Status status = mSolver.ApplyImpulse(contact.mNode, contact.mImpulse * contact.mNormal); status.HasError())
            return status.GetError();
        mMomentumReceived += contact.mImpulse * contact.mNormal;
    }
    return car;
}

} // namespace crumple::crash
