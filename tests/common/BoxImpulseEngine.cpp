// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "BoxImpulseEngine.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace crumple::common
{

namespace
{

// A convex polygon clipped to the side (x - inOrigin) . inAxis <= inLimit (Sutherland-Hodgman).
std::vector<Vec3> ClipPolygon(const std::vector<Vec3>& inPolygon, const Vec3& inOrigin, const Vec3& inAxis,
                              double inLimit)
{
    std::vector<Vec3> clipped;
    for (std::size_t i = 0; i < inPolygon.size(); ++i)
    {
        const Vec3& p = inPolygon[i];
        const Vec3& q = inPolygon[(i + 1) % inPolygon.size()];
        const double dp = (p - inOrigin).dot(inAxis) - inLimit;
        const double dq = (q - inOrigin).dot(inAxis) - inLimit;
        if (dp <= 0.0)
            clipped.push_back(p);
        if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0))
            clipped.push_back(p + (dp / (dp - dq)) * (q - p));
    }
    return clipped;
}

// Two unit tangents perpendicular to inNormal and to each other, fixed by the normal alone.
std::array<Vec3, 2> Tangents(const Vec3& inNormal)
{
    const Vec3 helper = std::abs(inNormal.x()) < 0.57 ? Vec3::UnitX() : Vec3::UnitY();
    const Vec3 t1 = inNormal.cross(helper).normalized();
    return {t1, inNormal.cross(t1)};
}

} // namespace

int BoxImpulseEngine::AddBody(const ImpulseBodySettings& inSettings)
{
    Body body;
    body.mState = inSettings;
    if (inSettings.mDynamic)
    {
        body.mInverseMass = 1.0 / inSettings.mMass;
        Vec3 inertia = inSettings.mInertia;
        if (inertia.isZero())
        {
            const Vec3 size = 2.0 * inSettings.mHalfExtents;
            const Vec3 squares = size.cwiseProduct(size);
            inertia = inSettings.mMass / 12.0 *
                      Vec3(squares.y() + squares.z(), squares.x() + squares.z(), squares.x() + squares.y());
        }
        body.mInverseInertia = inertia.cwiseInverse();
    }
    mBodies.push_back(body);
    return static_cast<int>(mBodies.size()) - 1;
}

Mat3 BoxImpulseEngine::InverseInertiaWorld(int inBody) const
{
    const Body& body = mBodies[static_cast<std::size_t>(inBody)];
    const Mat3& r = body.mState.mPose.mRotation;
    return r * body.mInverseInertia.asDiagonal() * r.transpose();
}

ImpulseBodySettings BoxImpulseEngine::ReportedBody(int inBody) const
{
    ImpulseBodySettings body = mBodies[static_cast<std::size_t>(inBody)].mState;
    if (!mSettings.mSinglePrecision)
        return body;
    const auto single = [](const auto& inValue)
    { return inValue.template cast<float>().template cast<double>().eval(); };
    // intent: a float engine's rotation comes from its float quaternion
    body.mPose.mRotation =
        Quat(body.mPose.mRotation).cast<float>().normalized().toRotationMatrix().cast<double>();
    body.mPose.mTranslation = single(body.mPose.mTranslation);
    body.mLinearVelocity = single(body.mLinearVelocity);
    body.mAngularVelocity = single(body.mAngularVelocity);
    return body;
}

Mat3 BoxImpulseEngine::ReportedInverseInertiaWorld(int inBody) const
{
    if (!mSettings.mSinglePrecision)
        return InverseInertiaWorld(inBody);
    const Body& body = mBodies[static_cast<std::size_t>(inBody)];
    const Eigen::Matrix3f r = ReportedBody(inBody).mPose.mRotation.cast<float>();
    const Eigen::Vector3f moments = body.mInverseInertia.cast<float>();
    return (r * moments.asDiagonal() * r.transpose()).eval().cast<double>();
}

const std::vector<ImpulseContact>& BoxImpulseEngine::DetectContacts()
{
    mContacts.clear();
    for (std::size_t a = 0; a < mBodies.size(); ++a)
    {
        if (!mBodies[a].mState.mDynamic || mBodies[a].mState.mShape != EImpulseShape::Box)
            continue;
        for (std::size_t b = 0; b < mBodies.size(); ++b)
        {
            // intent: each pair once: a dynamic box with every static body and with the dynamic ones after it
            if (b == a || (mBodies[b].mState.mDynamic && b < a))
                continue;
            const std::size_t first = mContacts.size();
            if (mBodies[b].mState.mShape == EImpulseShape::Box)
                BoxBoxContacts(static_cast<int>(a), static_cast<int>(b));
            else
                BoxCylinderContacts(static_cast<int>(a), static_cast<int>(b));
            if (mSettings.mOnePointPerPair && mContacts.size() > first + 1)
            {
                // intent: the centroid of the points at their mean depth, the normal their mean
                const auto begin = mContacts.begin() + static_cast<std::ptrdiff_t>(first);
                const double count = static_cast<double>(mContacts.size() - first);
                ImpulseContact one = *begin;
                one.mPointOnA = one.mPointOnB = one.mNormal = Vec3::Zero();
                one.mDepth = 0.0;
                for (auto c = begin; c != mContacts.end(); ++c)
                {
                    one.mPointOnA += c->mPointOnA / count;
                    one.mPointOnB += c->mPointOnB / count;
                    one.mNormal += c->mNormal;
                    one.mDepth += c->mDepth / count;
                }
                one.mNormal.normalize();
                mContacts[first] = one;
                mContacts.resize(first + 1);
            }
        }
    }
    return mContacts;
}

// Separating axes: the six face normals (edge-edge axes are left out: the tests' boxes meet face to face or
// corner to face). The face of least overlap is the reference face, the other box's face most opposed to it
// the incident face; the incident face clipped to the reference face's sides gives the contact points.
void BoxImpulseEngine::BoxBoxContacts(int inA, int inB)
{
    const ImpulseBodySettings& a = mBodies[static_cast<std::size_t>(inA)].mState;
    const ImpulseBodySettings& b = mBodies[static_cast<std::size_t>(inB)].mState;
    const Vec3 between = a.mPose.mTranslation - b.mPose.mTranslation; // from B's centre to A's
    const auto reach = [](const ImpulseBodySettings& inBox, const Vec3& inAxis)
    { return inBox.mHalfExtents.dot((inBox.mPose.mRotation.transpose() * inAxis).cwiseAbs()); };
    double least_a = std::numeric_limits<double>::infinity(), least_b = least_a;
    int axis_a = 0, axis_b = 0;
    for (int k = 0; k < 3; ++k)
    {
        for (const bool of_b : {false, true})
        {
            const Vec3 axis = (of_b ? b : a).mPose.mRotation.col(k);
            const double overlap = reach(a, axis) + reach(b, axis) - std::abs(between.dot(axis));
            if (overlap < -mSettings.mContactMargin)
                return;
            double& least = of_b ? least_b : least_a;
            if (overlap < least)
            {
                least = overlap;
                (of_b ? axis_b : axis_a) = k;
            }
        }
    }
    // intent: B's face unless A's is clearly shallower (a tie between parallel faces takes B's, the static
    // one)
    const bool reference_is_b = !(least_a < least_b - 1.0e-3);
    const ImpulseBodySettings& reference = reference_is_b ? b : a;
    const ImpulseBodySettings& incident = reference_is_b ? a : b;
    const int k = reference_is_b ? axis_b : axis_a;
    const Vec3 toward = incident.mPose.mTranslation - reference.mPose.mTranslation;
    const Vec3 axis = reference.mPose.mRotation.col(k);
    const Vec3 normal =
        toward.dot(axis) >= 0.0 ? axis : Vec3(-axis); // the reference face's, towards the incident box
    const Vec3 face_centre = reference.mPose.mTranslation + reference.mHalfExtents[k] * normal;

    // The incident face: its outward normal most opposed to the reference face's.
    int j = 0;
    double most = -1.0;
    for (int c = 0; c < 3; ++c)
        if (const double d = std::abs(incident.mPose.mRotation.col(c).dot(normal)); d > most)
        {
            most = d;
            j = c;
        }
    const Vec3 incident_normal = incident.mPose.mRotation.col(j).dot(normal) > 0.0
                                     ? Vec3(-incident.mPose.mRotation.col(j))
                                     : Vec3(incident.mPose.mRotation.col(j));
    const Vec3 centre = incident.mPose.mTranslation + incident.mHalfExtents[j] * incident_normal;
    const int p = (j + 1) % 3, q = (j + 2) % 3;
    const Vec3 u = incident.mHalfExtents[p] * incident.mPose.mRotation.col(p);
    const Vec3 v = incident.mHalfExtents[q] * incident.mPose.mRotation.col(q);
    std::vector<Vec3> polygon{centre + u + v, centre - u + v, centre - u - v, centre + u - v};
    for (const int side : {(k + 1) % 3, (k + 2) % 3})
    {
        const Vec3 side_axis = reference.mPose.mRotation.col(side);
        polygon = ClipPolygon(polygon, face_centre, side_axis, reference.mHalfExtents[side]);
        polygon = ClipPolygon(polygon, face_centre, -side_axis, reference.mHalfExtents[side]);
    }
    const double friction = a.mFriction * b.mFriction;
    for (const Vec3& point : polygon)
    {
        const double depth = -(point - face_centre).dot(normal);
        if (depth < -mSettings.mContactMargin)
            continue;
        const Vec3 on_reference = point + depth * normal;
        ImpulseContact contact{inA, inB, Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), depth, friction};
        // intent: the normal from B towards A; the incident point lies on the incident body's surface
        contact.mNormal = reference_is_b ? normal : Vec3(-normal);
        contact.mPointOnA = reference_is_b ? point : on_reference;
        contact.mPointOnB = reference_is_b ? on_reference : point;
        mContacts.push_back(contact);
    }
}

// The cylinder's axis met at the box's bottom and top face heights: at each, the nearest point of that face's
// rectangle to the axis, in the box's frame (a pole against a car's front: two points, the line contact).
void BoxImpulseEngine::BoxCylinderContacts(int inBox, int inCylinder)
{
    const ImpulseBodySettings& box = mBodies[static_cast<std::size_t>(inBox)].mState;
    const ImpulseBodySettings& cylinder = mBodies[static_cast<std::size_t>(inCylinder)].mState;
    const Vec3& h = box.mHalfExtents;
    const double radius = cylinder.mHalfExtents.x();
    const Vec3 origin = box.mPose.ToBody(cylinder.mPose.mTranslation);
    const Vec3 axis = box.mPose.DirectionToBody(cylinder.mPose.mRotation.col(2));
    if (std::abs(axis.z()) < 0.5)
        return; // a box lying across the cylinder: not a case of the tests
    for (const double level : {-h.z(), h.z()})
    {
        const double t = (level - origin.z()) / axis.z();
        if (std::abs(t) > cylinder.mHalfExtents.z())
            continue;
        const Vec3 centre = origin + t * axis;
        const Vec3 nearest(std::clamp(centre.x(), -h.x(), h.x()), std::clamp(centre.y(), -h.y(), h.y()),
                           level);
        Vec3 normal = Vec3::Zero(); // from the cylinder towards the box, box frame
        double depth = 0.0;
        Vec3 on_box = nearest;
        const Vec3 offset(nearest.x() - centre.x(), nearest.y() - centre.y(), 0.0);
        if (offset.norm() > 1.0e-12)
        {
            normal = offset.normalized();
            depth = radius - offset.norm();
        }
        else
        {
            // intent: the axis inside the box: out through the nearest side face
            const double to_x = h.x() - std::abs(centre.x()), to_y = h.y() - std::abs(centre.y());
            const int side = to_x < to_y ? 0 : 1;
            const double sign = centre[side] >= 0.0 ? 1.0 : -1.0;
            normal[side] = -sign;
            depth = radius + std::min(to_x, to_y);
            on_box[side] = sign * h[side];
        }
        if (depth < -mSettings.mContactMargin)
            continue;
        const Vec3 on_cylinder(centre.x() - radius * normal.x(), centre.y() - radius * normal.y(), level);
        ImpulseContact contact;
        contact.mBodyA = inBox;
        contact.mBodyB = inCylinder;
        contact.mPointOnA = box.mPose.ToWorld(on_box);
        contact.mPointOnB = box.mPose.ToWorld(on_cylinder);
        contact.mNormal = box.mPose.mRotation * normal;
        contact.mDepth = depth;
        contact.mFriction = box.mFriction * cylinder.mFriction;
        mContacts.push_back(contact);
    }
}

void BoxImpulseEngine::SolveAndIntegrate(double inDeltaTime)
{
    for (Body& body : mBodies)
        if (body.mState.mDynamic)
            body.mState.mLinearVelocity += inDeltaTime * mSettings.mGravity;

    // One row per contact direction: its lever arms, effective mass, target speed and accumulated impulse.
    struct Row
    {
        Vec3 mArmA, mArmB, mDirection;
        double mMass = 0.0, mTarget = 0.0, mImpulse = 0.0;
    };
    const auto make_row = [this](const ImpulseContact& inContact, const Vec3& inDirection)
    {
        const Body& a = mBodies[static_cast<std::size_t>(inContact.mBodyA)];
        const Body& b = mBodies[static_cast<std::size_t>(inContact.mBodyB)];
        Row row;
        row.mArmA = inContact.mPointOnA - a.mState.mPose.mTranslation;
        row.mArmB = inContact.mPointOnB - b.mState.mPose.mTranslation;
        row.mDirection = inDirection;
        const Vec3 ra = row.mArmA.cross(inDirection), rb = row.mArmB.cross(inDirection);
        const double k = a.mInverseMass + b.mInverseMass +
                         ra.dot(InverseInertiaWorld(inContact.mBodyA) * ra) +
                         rb.dot(InverseInertiaWorld(inContact.mBodyB) * rb);
        row.mMass = k > 0.0 ? 1.0 / k : 0.0;
        return row;
    };
    // intent: the speed of A's point relative to B's along the row, from the real or the split velocities
    const auto speed = [this](const ImpulseContact& inContact, const Row& inRow, bool inPseudo)
    {
        const Body& a = mBodies[static_cast<std::size_t>(inContact.mBodyA)];
        const Body& b = mBodies[static_cast<std::size_t>(inContact.mBodyB)];
        const Vec3 va = inPseudo ? a.mPseudoLinear + a.mPseudoAngular.cross(inRow.mArmA)
                                 : a.mState.mLinearVelocity + a.mState.mAngularVelocity.cross(inRow.mArmA);
        const Vec3 vb = inPseudo ? b.mPseudoLinear + b.mPseudoAngular.cross(inRow.mArmB)
                                 : b.mState.mLinearVelocity + b.mState.mAngularVelocity.cross(inRow.mArmB);
        return (va - vb).dot(inRow.mDirection);
    };
    const auto apply =
        [this](const ImpulseContact& inContact, const Row& inRow, double inImpulse, bool inPseudo)
    {
        for (const int side : {0, 1})
        {
            Body& body = mBodies[static_cast<std::size_t>(side == 0 ? inContact.mBodyA : inContact.mBodyB)];
            if (!body.mState.mDynamic)
                continue;
            const Vec3 impulse = (side == 0 ? inImpulse : -inImpulse) * inRow.mDirection;
            const Vec3 spin = InverseInertiaWorld(side == 0 ? inContact.mBodyA : inContact.mBodyB) *
                              (side == 0 ? inRow.mArmA : inRow.mArmB).cross(impulse);
            (inPseudo ? body.mPseudoLinear : body.mState.mLinearVelocity) += body.mInverseMass * impulse;
            (inPseudo ? body.mPseudoAngular : body.mState.mAngularVelocity) += spin;
        }
    };

    std::vector<std::array<Row, 3>> rows; // normal, two tangents
    rows.reserve(mContacts.size());
    for (const ImpulseContact& contact : mContacts)
    {
        const std::array<Vec3, 2> tangents = Tangents(contact.mNormal);
        std::array<Row, 3> row{make_row(contact, contact.mNormal), make_row(contact, tangents[0]),
                               make_row(contact, tangents[1])};
        const double closing = speed(contact, row[0], false);
        // intent: a gap within the margin may close in this step (an approach up to gap / dt is free); an
        // impact, touching or predicted from a gap the approach closes within the step, rebounds by the
        // restitution now (Jolt's rule for speculative contacts)
        const double free_approach = std::max(-contact.mDepth, 0.0) / inDeltaTime;
        if (closing < -mSettings.mBounceSpeed && closing < -free_approach)
            row[0].mTarget = -mSettings.mRestitution * closing;
        else if (contact.mDepth < 0.0)
            row[0].mTarget = contact.mDepth / inDeltaTime;
        rows.push_back(row);
    }
    for (int sweep = 0; sweep < mSettings.mVelocityIterations; ++sweep)
        for (std::size_t c = 0; c < mContacts.size(); ++c)
        {
            std::array<Row, 3>& row = rows[c];
            const double normal = std::max(
                row[0].mImpulse + row[0].mMass * (row[0].mTarget - speed(mContacts[c], row[0], false)), 0.0);
            apply(mContacts[c], row[0], normal - row[0].mImpulse, false);
            row[0].mImpulse = normal;
            const double limit = mContacts[c].mFriction * normal;
            for (int t = 1; t <= 2; ++t)
            {
                const double friction = std::clamp(
                    row[t].mImpulse - row[t].mMass * speed(mContacts[c], row[t], false), -limit, limit);
                apply(mContacts[c], row[t], friction - row[t].mImpulse, false);
                row[t].mImpulse = friction;
            }
        }

    // intent: penetration beyond the allowance is removed by split velocities, which move the bodies but
    // leave their momentum (and so the impulse a collision took) as the contact solve made it
    for (std::size_t c = 0; c < mContacts.size(); ++c)
    {
        rows[c][0].mImpulse = 0.0;
        rows[c][0].mTarget = mSettings.mPositionCorrection *
                             std::max(mContacts[c].mDepth - mSettings.mAllowedPenetration, 0.0) / inDeltaTime;
    }
    for (int sweep = 0; sweep < mSettings.mPositionIterations; ++sweep)
        for (std::size_t c = 0; c < mContacts.size(); ++c)
        {
            Row& row = rows[c][0];
            if (row.mTarget <= 0.0)
                continue;
            const double push =
                std::max(row.mImpulse + row.mMass * (row.mTarget - speed(mContacts[c], row, true)), 0.0);
            apply(mContacts[c], row, push - row.mImpulse, true);
            row.mImpulse = push;
        }

    for (Body& body : mBodies)
    {
        if (!body.mState.mDynamic)
            continue;
        Transform& pose = body.mState.mPose;
        pose.mTranslation += inDeltaTime * (body.mState.mLinearVelocity + body.mPseudoLinear);
        const Vec3 spin = body.mState.mAngularVelocity + body.mPseudoAngular;
        Quat orientation(pose.mRotation);
        const Quat change(0.0, spin.x(), spin.y(), spin.z());
        orientation.coeffs() += 0.5 * inDeltaTime * (change * orientation).coeffs();
        pose.mRotation = orientation.normalized().toRotationMatrix();
        body.mPseudoLinear.setZero();
        body.mPseudoAngular.setZero();
    }
}

} // namespace crumple::common
